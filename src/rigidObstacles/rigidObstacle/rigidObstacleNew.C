/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "rigidObstacle.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::rigidObstacle> Foam::rigidObstacle::New
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    const word obstacleType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(obstacleType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'type': unknown rigid obstacle '" << obstacleType
            << "' in dictionary " << dict.name() << nl << nl
            << "Valid types: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return cstrIter()(dict, caseDir);
}


// ************************************************************************* //

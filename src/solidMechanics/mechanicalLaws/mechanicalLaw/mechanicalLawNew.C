/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "mechanicalLaw.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::mechanicalLaw> Foam::mechanicalLaw::New
(
    const dictionary& dict
)
{
    const word lawType(dict.get<word>("type"));

    Info<< "Selecting mechanical law " << lawType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown mechanicalLaw type '" << lawType
            << "' for keyword 'type' in dictionary " << dict.name() << nl
            << "Valid types: "
            << dictionaryConstructorTablePtr_->sortedToc() << nl
            << exit(FatalIOError);
    }

    return autoPtr<mechanicalLaw>(cstrIter()(dict));
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "lubricationWeightModel.H"
#include "error.H"

namespace Foam
{
    defineTypeNameAndDebug(lubricationWeightModel, 0);
    defineRunTimeSelectionTable(lubricationWeightModel, dictionary);
}


Foam::autoPtr<Foam::lubricationWeightModel>
Foam::lubricationWeightModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'type': unknown lubrication weight model '"
            << modelType << "' in dictionary " << dict.name() << nl << nl
            << "Valid models: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return cstrIter()(dict);
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionStateLaw.H"
#include "frictionParameters.H"
#include "error.H"
#include "dimensionSets.H"

namespace Foam
{
    defineTypeNameAndDebug(frictionStateLaw, 0);
    defineRunTimeSelectionTable(frictionStateLaw, dictionary);
}


Foam::frictionStateLaw::frictionStateLaw(const dictionary& dict)
:
    VStar_(frictionParameters::positive(dict, "VStar"))
{}


Foam::dimensionSet Foam::frictionStateLaw::stateDimensions() const
{
    // phi of the ageing and slip laws: the mean age of the contacts [F11]
    return dimTime;
}


Foam::autoPtr<Foam::frictionStateLaw> Foam::frictionStateLaw::New
(
    const dictionary& dict
)
{
    const word lawType(dict.get<word>("stateLaw"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'stateLaw': unknown state law '" << lawType
            << "' in dictionary " << dict.name() << nl << nl
            << "Valid state laws: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return cstrIter()(dict);
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "constant.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"
#include "strictDictionary.H"

namespace Foam
{
namespace lubricationWeightModels
{
    defineTypeNameAndDebug(constant, 0);
    addToRunTimeSelectionTable(lubricationWeightModel, constant, dictionary);
}
}


Foam::lubricationWeightModels::constant::constant(const dictionary& dict)
:
    alpha_(frictionParameters::unitInterval(dict, "alpha"))
{
    strictDictionary::check
    (
        dict, {"type", "alpha"}, "lubrication weight constant"
    );
}


void Foam::lubricationWeightModels::constant::alpha
(
    const scalar v,
    scalar& a,
    scalar& dadv
) const
{
    a = alpha_;
    dadv = 0;
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "stribeck.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"
#include "strictDictionary.H"

namespace Foam
{
namespace lubricationWeightModels
{
    defineTypeNameAndDebug(stribeck, 0);
    addToRunTimeSelectionTable(lubricationWeightModel, stribeck, dictionary);
}
}


Foam::lubricationWeightModels::stribeck::stribeck(const dictionary& dict)
:
    D_(frictionParameters::nonNegative(dict, "filmThickness")),
    Db_(frictionParameters::positive(dict, "referenceFilmThickness")),
    vb_(frictionParameters::positive(dict, "referenceVelocity")),
    n_(frictionParameters::positive(dict, "n", 1))
{
    strictDictionary::check
    (
        dict,
        {
            "type", "filmThickness", "referenceFilmThickness",
            "referenceVelocity", "n"
        },
        "lubrication weight stribeck"
    );
}


void Foam::lubricationWeightModels::stribeck::alpha
(
    const scalar v,
    scalar& a,
    scalar& dadv
) const
{
    // [F19]
    const scalar c = (D_/Db_)/vb_;
    const scalar xi = c*v;
    if (xi <= 0)
    {
        a = 0;
        dadv = n_ == 1 ? c : 0;
        return;
    }
    const scalar xin = std::pow(xi, n_);
    a = xin/(1 + xin);
    dadv = n_*xin/xi*c/((1 + xin)*(1 + xin));
}

// ************************************************************************* //

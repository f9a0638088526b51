/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "ageing.H"
#include "relaxationStep.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionStateLaws
{
    defineTypeNameAndDebug(ageing, 0);
    addToRunTimeSelectionTable(frictionStateLaw, ageing, dictionary);
}
}


Foam::frictionStateLaws::ageing::ageing(const dictionary& dict)
:
    frictionStateLaw(dict),
    L_(frictionParameters::positive(dict, "L"))
{}


void Foam::frictionStateLaws::ageing::evolve
(
    const scalar phi0,
    const scalar v,
    const scalar dt,
    scalar& phi1,
    scalar& dphi1dv
) const
{
    // [F13] with c = 1, x = v dt/L
    scalar dphi1dx;
    relaxationStep(phi0, v*dt/L_, dt, phi1, dphi1dx);
    dphi1dv = dphi1dx*dt/L_;
}


Foam::scalar Foam::frictionStateLaws::ageing::steadyState(const scalar v) const
{
    return L_/v;
}


Foam::scalar Foam::frictionStateLaws::ageing::rate
(
    const scalar phi,
    const scalar v
) const
{
    // [F27]
    return 1 - v*phi/L_;
}

// ************************************************************************* //

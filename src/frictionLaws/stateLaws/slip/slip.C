/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "slip.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionStateLaws
{
    defineTypeNameAndDebug(slip, 0);
    addToRunTimeSelectionTable(frictionStateLaw, slip, dictionary);
}
}


Foam::frictionStateLaws::slip::slip(const dictionary& dict)
:
    frictionStateLaw(dict),
    L_(frictionParameters::positive(dict, "L"))
{}


void Foam::frictionStateLaws::slip::evolve
(
    const scalar phi0,
    const scalar v,
    const scalar dt,
    scalar& phi1,
    scalar& dphi1dv
) const
{
    // [F14]; v is floored so that the hold limit (phi unchanged) is reached
    // smoothly: (1 - exp(-x)) ln(v) -> 0 as v -> 0
    const scalar vf = std::max(v, scalar(1e-300));
    const scalar x = vf*dt/L_;
    const scalar y0 = std::log(vf*phi0/L_);
    const scalar omE = -std::expm1(-x);
    phi1 = phi0*std::exp(-y0*omE);
    dphi1dv = phi1*(-omE/vf - y0*std::exp(-x)*dt/L_);
}


Foam::scalar Foam::frictionStateLaws::slip::steadyState(const scalar v) const
{
    return L_/v;
}


Foam::scalar Foam::frictionStateLaws::slip::rate
(
    const scalar phi,
    const scalar v
) const
{
    // [F27]; no change in a hold (v phi ln(v phi) -> 0)
    const scalar y = v*phi/L_;
    return y > 0 ? -y*std::log(y) : 0;
}

// ************************************************************************* //

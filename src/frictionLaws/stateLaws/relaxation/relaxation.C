/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "relaxation.H"
#include "checkedFunction1.H"
#include "relaxationStep.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"
#include "dimensionSets.H"

namespace Foam
{
namespace frictionStateLaws
{
    defineTypeNameAndDebug(relaxation, 0);
    addToRunTimeSelectionTable(frictionStateLaw, relaxation, dictionary);
}
}


Foam::frictionStateLaws::relaxation::relaxation(const dictionary& dict)
:
    frictionStateLaw(dict),
    tRelax_(frictionParameters::positive(dict, "relaxationTime")),
    gamma_(frictionParameters::nonNegative(dict, "gamma", 1)),
    lnPhiRef_(0)
{
    if (dict.found("phiSs"))
    {
        phiSs_ = checkedFunction1<scalar>("phiSs", dict);
    }
    lnPhiRef_ = std::log(steadyState(VStar_));
}


void Foam::frictionStateLaws::relaxation::phiSs
(
    const scalar v,
    scalar& p,
    scalar& dp
) const
{
    const scalar vf = std::max(v, scalar(1e-300));
    if (phiSs_.valid())
    {
        const scalar h = 1e-6*vf;
        p = phiSs_->value(vf);
        dp = (phiSs_->value(vf + h) - phiSs_->value(std::max(vf - h, 0.0)))
            /(vf + h - std::max(vf - h, 0.0));
    }
    else
    {
        p = std::pow(VStar_/vf, gamma_);
        dp = -gamma_*p/vf;
    }
}


void Foam::frictionStateLaws::relaxation::evolve
(
    const scalar phi0,
    const scalar v,
    const scalar dt,
    scalar& phi1,
    scalar& dphi1dv
) const
{
    // [F15]: c = 1/t**, x = dt/(t** phi_ss(v))
    scalar p, dp;
    phiSs(v, p, dp);
    const scalar x = dt/(tRelax_*p);
    scalar dphi1dx;
    relaxationStep(phi0, x, dt/tRelax_, phi1, dphi1dx);
    dphi1dv = dphi1dx*(-x*dp/p);
}


Foam::scalar Foam::frictionStateLaws::relaxation::steadyState
(
    const scalar v
) const
{
    scalar p, dp;
    phiSs(v, p, dp);
    return p;
}


Foam::scalar Foam::frictionStateLaws::relaxation::rate
(
    const scalar phi,
    const scalar v
) const
{
    // [F27]: -(phi - phi_ss)/(t** phi_ss)
    return (1 - phi/steadyState(v))/tRelax_;
}


Foam::dimensionSet Foam::frictionStateLaws::relaxation::stateDimensions() const
{
    return dimless;
}

// ************************************************************************* //

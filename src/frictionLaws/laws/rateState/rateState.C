/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "rateState.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(rateState, 0);
    addToRunTimeSelectionTable(frictionLaw, rateState, dictionary);
}
}


Foam::frictionLaws::rateState::rateState(const dictionary& dict)
:
    frictionLaw(dict),
    regularised_(false),
    a_(frictionParameters::nonNegative(dict, "a")),
    b_(frictionParameters::nonNegative(dict, "b")),
    muStar_(frictionParameters::nonNegative(dict, "muStar")),
    VStar_(frictionParameters::positive(dict, "VStar")),
    Vc_(frictionParameters::positive(dict, "creepVelocity", 1e-6*VStar_)),
    phiInit_(0),
    stateLaw_(frictionStateLaw::New(dict))
{
    const word form(dict.getOrDefault<word>("form", "standard"));
    if (form == "regularised" || form == "regularized")
    {
        regularised_ = true;
        frictionParameters::check(dict, "a", a_, 0, frictionParameters::open);
    }
    else if (form != "standard")
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'form' must be 'standard' or 'regularised', got '"
            << form << "' (dictionary " << dict.name() << ")"
            << exit(FatalIOError);
    }

    const scalar v0 =
        frictionParameters::positive(dict, "initialSlipRate", VStar_);
    phiInit_ = stateLaw_->steadyState(v0);

    layout_.add
    (
        stateLaw_->stateName(), frictionStateEntry::SCALAR, phiSlot,
        stateLaw_->stateDimensions(), true, true, stateLaw_->oldStateName()
    );
    wordList own
    ({
        "a", "b", "muStar", "VStar", "creepVelocity", "form",
        "initialSlipRate"
    });
    own.append(stateLaw_->keywords());
    checkKeywords(dict, own);
}


void Foam::frictionLaws::rateState::mu
(
    const scalar v,
    const scalar phi,
    scalar& muValue,
    scalar& dmudv,
    scalar& dmudlnphi
) const
{
    const scalar lnPhi = stateLaw_->lnNormalised(phi);

    if (!regularised_)
    {
        // [F11] (with creep regularisation)
        const scalar veff2 = v*v + Vc_*Vc_;
        muValue = muStar_ + 0.5*a_*std::log(veff2/(VStar_*VStar_))
            + b_*lnPhi;
        dmudv = a_*v/veff2;
        dmudlnphi = b_;
        return;
    }

    // [F12], in log form for large arguments
    const scalar q = std::min((muStar_ + b_*lnPhi)/a_, scalar(700));
    const scalar lw = v > 0 ? std::log(v/(2*VStar_)) + q : -GREAT;
    if (lw > 30)
    {
        muValue = a_*(lw + std::log(2.0));
        dmudv = a_/v;
        dmudlnphi = b_;
    }
    else
    {
        const scalar w = v > 0 ? std::exp(lw) : 0;
        const scalar s = std::sqrt(1 + w*w);
        muValue = a_*std::asinh(w);
        dmudv = a_*std::exp(q)/(2*VStar_)/s;
        dmudlnphi = b_*w/s;
    }
}


void Foam::frictionLaws::rateState::steadyRateStates
(
    const scalar v,
    const scalar,
    rateStates& x
) const
{
    x[0] = stateLaw_->steadyState(v);
}


Foam::scalar Foam::frictionLaws::rateState::slidingTraction
(
    const scalar v,
    const rateStates& x,
    const scalar tN
) const
{
    scalar m, dmdv, dmdlnphi;
    mu(v, x[0], m, dmdv, dmdlnphi);
    return max(m, scalar(0))*tN;
}


void Foam::frictionLaws::rateState::stateRates
(
    const scalar v,
    const rateStates& x,
    const scalar,
    rateStates& xdot
) const
{
    xdot[0] = stateLaw_->rate(x[0], v);
}


void Foam::frictionLaws::rateState::rateStatesOf
(
    const frictionState& s,
    rateStates& x
) const
{
    x[0] = s.scalars[phiSlot];
}


Foam::frictionState Foam::frictionLaws::rateState::initialState() const
{
    frictionState s;
    s.scalars[phiSlot] = phiInit_;
    return s;
}


void Foam::frictionLaws::rateState::update
(
    const frictionState& old,
    const frictionInput& in,
    frictionResult& out
) const
{
    if (!normalContact(in, out))
    {
        openContact(old, in, out);
        return;
    }

    out.state = old;

    const scalar tN = out.tN;
    const scalar dt = in.dt;
    const scalar KN = KN_;
    const tensor P = projector(in.n);
    const vector xiTrial = KT_*(P & (in.gT - old.plasticSlip));      // [F3]
    const scalar phi0 = old.scalars[phiSlot];
    const frictionStateLaw& sl = *stateLaw_;

    // Threshold at slip increment dg: v = dg/dt, phi_{n+1}(v), mu(v, phi)
    auto threshold = [&](scalar dg, slipThreshold& thr)
    {
        const scalar v = dg/dt;
        scalar phi1, dphi1dv, m, dmdv, dmdlnphi;
        sl.evolve(phi0, v, dt, phi1, dphi1dv);
        mu(v, phi1, m, dmdv, dmdlnphi);
        if (m > 0)
        {
            thr.Y = m*tN;
            thr.dYdDg = tN*(dmdv + dmdlnphi*dphi1dv/phi1)/dt;
            thr.dYdgN = m*KN;
        }
        else
        {
            thr.Y = 0;
            thr.dYdDg = 0;
            thr.dYdgN = 0;
        }
        thr.dYdgT = Zero;
    };

    radialReturn::output rr;
    // The last step's rate is the natural first guess of the slip increment
    const scalar dgGuess =
        old.status == frictionState::SLIP ? old.slipRate*dt : -1;
    radialReturn::solve
    (
        xiTrial, Zero, KT_, KT_, P, threshold, rr, nullptr, dgGuess
    );
    setFromReturn(old, in, rr, out);

    const scalar v = rr.dg/dt;
    scalar phi1, dphi1dv;
    sl.evolve(phi0, v, dt, phi1, dphi1dv);
    out.state.scalars[phiSlot] = phi1;
    out.state.slipRate = v;
}

// ************************************************************************* //

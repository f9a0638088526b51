/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "lubricatedRateState.H"
#include "checkedFunction1.H"
#include "relaxationStep.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"
#include "dimensionSets.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(lubricatedRateState, 0);
    addToRunTimeSelectionTable(frictionLaw, lubricatedRateState, dictionary);
}
}


Foam::frictionLaws::lubricatedRateState::lubricatedRateState
(
    const dictionary& dict
)
:
    frictionLaw(dict),
    M_(frictionParameters::nonNegative(dict, "M")),
    D0_(frictionParameters::positive(dict, "D0")),
    Vs_(frictionParameters::positive(dict, "creepVelocity")),
    muS_(0),
    muD_(0),
    vc_(1),
    etaB_(frictionParameters::nonNegative(dict, "filmViscosity")),
    Df_(frictionParameters::nonNegative(dict, "filmMemoryDistance", 0)),
    steadyFreshContact_(false),
    lubrication_(lubricationWeightModel::New(dict.subDict("lubrication")))
{
    if (dict.found("mu0"))
    {
        mu0Fn_ = checkedFunction1<scalar>("mu0", dict);
    }
    else
    {
        muS_ = frictionParameters::nonNegative(dict, "muStatic");
        muD_ = frictionParameters::nonNegative(dict, "muDynamic");
        vc_ = frictionParameters::positive(dict, "criticalVelocity");
    }

    const word fresh(dict.getOrDefault<word>("freshContactAge", "creep"));
    if (fresh == "steadySliding")
    {
        steadyFreshContact_ = true;
    }
    else if (fresh != "creep")
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'freshContactAge' must be creep or steadySliding,"
            << " got '" << fresh << "'" << exit(FatalIOError);
    }

    // The lubrication weight is a state variable with a film memory
    // [F30] (written for restart), an output of the rate otherwise
    layout_.add
    (
        "contactAge", frictionStateEntry::SCALAR, thetaSlot, dimTime, true,
        true
    );
    layout_.add
    (
        "lubricationWeight", frictionStateEntry::SCALAR, alphaSlot, dimless,
        Df_ > 0, true
    );

    // Well-posedness at input time [F21], on the rates and pressures the
    // case declares (defaults: creep velocity to 1 m/s, 1 MPa to 1 GPa)
    const Pair<scalar> v =
        frictionParameters::range(dict, "slipRateRange", {Vs_, 1});
    const Pair<scalar> p =
        frictionParameters::range(dict, "contactPressureRange", {1e6, 1e9});
    checkWellPosedness(v.first(), v.second(), p.first(), p.second());
    checkKeywords
    (
        dict,
        {
            "M", "D0", "creepVelocity", "muStatic", "muDynamic",
            "criticalVelocity", "mu0", "mu0Coeffs", "filmViscosity",
            "filmMemoryDistance", "lubrication", "freshContactAge",
            "slipRateRange", "contactPressureRange"
        }
    );
}


void Foam::frictionLaws::lubricatedRateState::mu0
(
    const scalar v,
    scalar& m,
    scalar& dmdv
) const
{
    if (mu0Fn_.valid())
    {
        m = mu0Fn_->value(v);
        const scalar h = 1e-6*max(v, vc_*1e-6);
        const scalar vm = max(v - h, scalar(0));
        dmdv = (mu0Fn_->value(v + h) - mu0Fn_->value(vm))/(v + h - vm);
        return;
    }
    // [F18]
    const scalar e = std::exp(-v/vc_);
    m = muD_ + (muS_ - muD_)*e;
    dmdv = -(muS_ - muD_)*e/vc_;
}


void Foam::frictionLaws::lubricatedRateState::slidingThreshold
(
    const scalar vp,
    const scalar theta,
    const scalar tN,
    scalar& Y,
    scalar& dYdvp,
    scalar& dYdtheta
) const
{
    // Y = f mu0 tN with f = 1 + M ln(theta v_eff/D0) cut at zero [F17],
    // v_eff = sqrt(v_p^2 + V_s^2), mu0(v_p) [F18]
    const scalar veff2 = vp*vp + Vs_*Vs_;
    const scalar f = 1 + 0.5*M_*std::log(theta*theta*veff2/(D0_*D0_));
    if (f <= 0)
    {
        Y = 0;
        dYdvp = 0;
        dYdtheta = 0;
        return;
    }
    scalar m0, dm0dvp;
    mu0(vp, m0, dm0dvp);
    Y = f*m0*tN;
    dYdvp = (M_*vp/veff2*m0 + f*dm0dvp)*tN;
    dYdtheta = M_/theta*m0*tN;
}


Foam::frictionState
Foam::frictionLaws::lubricatedRateState::initialState() const
{
    frictionState s;
    s.scalars[thetaSlot] = D0_/Vs_;
    if (Df_ > 0)
    {
        // [F30]: a fresh contact's film as in creep at V_s
        scalar da;
        lubrication_->alpha(Vs_, s.scalars[alphaSlot], da);
    }
    return s;
}


void Foam::frictionLaws::lubricatedRateState::contactAge
(
    const frictionState& old,
    const scalar vp,
    const scalar dt,
    scalar& theta1,
    scalar& dtheta1dvp
) const
{
    // Age at the start of the step: a face closing now starts in steady
    // sliding at its first slip rate with steadySliding [F17b]
    scalar theta0 = old.scalars[thetaSlot];
    scalar dtheta0dvp = 0;
    if (steadyFreshContact_ && old.status == frictionState::OPEN)
    {
        const scalar veff2 = vp*vp + Vs_*Vs_;
        theta0 = D0_/std::sqrt(veff2);
        dtheta0dvp = -theta0*vp/veff2;
    }

    // Exact contact-age step ([F29]) at constant sliding rate [F13]
    const scalar x = vp*dt/D0_;
    scalar dtheta1dx;
    relaxationStep(theta0, x, dt, theta1, dtheta1dx);
    dtheta1dvp = dtheta1dx*dt/D0_ + std::exp(-x)*dtheta0dvp;
}


void Foam::frictionLaws::lubricatedRateState::lubricationWeight
(
    const frictionState& old,
    const scalar v,
    const scalar dt,
    scalar& alpha,
    scalar& dalphadv
) const
{
    scalar aSs, daSs;
    lubrication_->alpha(v, aSs, daSs);
    if (Df_ <= 0 || (steadyFreshContact_ && old.status == frictionState::OPEN))
    {
        // [F19]; a fresh contact with steadySliding starts at alpha_ss
        alpha = aSs;
        dalphadv = daSs;
        return;
    }

    // [F30]: exact step of d alpha/dt = -(v/D_f)(alpha - alpha_ss(v)) at
    // constant v
    const scalar a0 = old.scalars[alphaSlot];
    const scalar e = std::exp(-v*dt/Df_);
    alpha = aSs + (a0 - aSs)*e;
    dalphadv = daSs*(1 - e) - (a0 - aSs)*e*dt/Df_;
}


void Foam::frictionLaws::lubricatedRateState::update
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

    // Sliding threshold Y = f mu0 tN at a trial sliding increment dg, the
    // rate of ageing and of mu0 being the sliding rate dg/dt [F16]-[F18]
    auto threshold = [&](scalar dg, slipThreshold& thr)
    {
        const scalar vp = dg/dt;
        scalar theta1, dtheta1dvp, dYdvp, dYdtheta;
        contactAge(old, vp, dt, theta1, dtheta1dvp);
        slidingThreshold(vp, theta1, tN, thr.Y, dYdvp, dYdtheta);
        thr.dYdDg = (dYdvp + dYdtheta*dtheta1dvp)/dt;
        thr.dYdgN = thr.Y/tN*KN;
        thr.dYdgT = Zero;
    };

    const vector xiTrial = KT_*(P & (in.gT - old.plasticSlip));      // [F3]
    radialReturn::output rr;
    // The last step's sliding rate is the natural first guess
    const scalar dgGuess =
        old.status == frictionState::SLIP ? old.slipRate*dt : -1;
    radialReturn::solve
    (
        xiTrial, Zero, KT_, KT_, P, threshold, rr, nullptr, dgGuess
    );
    setFromReturn(old, in, rr, out);

    const scalar vp = rr.dg/dt;
    scalar theta1, dtheta1dvp;
    contactAge(old, vp, dt, theta1, dtheta1dvp);

    // The film shears at the total slip rate of the step [F16], [F20]
    const vector vv = (P & (in.gT - old.totalSlip))/dt;
    const scalar v = mag(vv);
    const vector vHat = v > 0 ? vv/v : vector::zero;
    scalar alpha, dalphadv;
    lubricationWeight(old, v, dt, alpha, dalphadv);
    const vector viscous = etaB_*vv;
    out.tT = blend(alpha, rr.F, viscous);
    out.dtTdgT =
        (1 - alpha)*rr.dFdgT
      + ((viscous - rr.F)*(dalphadv/dt*vHat))
      + (alpha*etaB_/dt)*P;
    out.dtTdgN = (1 - alpha)*rr.dFdgN;

    out.state.scalars[thetaSlot] = theta1;
    out.state.scalars[alphaSlot] = alpha;
    out.state.slipRate = vp;
}


// * * * * * * * * * * * * * * * * Rate form * * * * * * * * * * * * * * * //

void Foam::frictionLaws::lubricatedRateState::steadyRateStates
(
    const scalar v,
    const scalar,
    rateStates& x
) const
{
    // theta_ss = D0/v ([F29]), alpha_ss(v) [F30]
    x[0] = D0_/v;
    if (Df_ > 0)
    {
        scalar da;
        lubrication_->alpha(v, x[1], da);
    }
}


Foam::scalar Foam::frictionLaws::lubricatedRateState::slidingTraction
(
    const scalar v,
    const rateStates& x,
    const scalar tN
) const
{
    // [F20] with the threshold of update(): (1 - alpha) f mu0 tN
    // + alpha eta_b v
    scalar Y, dYdv, dYdtheta, alpha, da;
    slidingThreshold(v, x[0], tN, Y, dYdv, dYdtheta);
    if (Df_ > 0)
    {
        alpha = x[1];
    }
    else
    {
        lubrication_->alpha(v, alpha, da);
    }
    return blend(alpha, Y, etaB_*v);
}


void Foam::frictionLaws::lubricatedRateState::stateRates
(
    const scalar v,
    const rateStates& x,
    const scalar,
    rateStates& xdot
) const
{
    // [F29], [F30]
    xdot[0] = 1 - x[0]*v/D0_;
    if (Df_ > 0)
    {
        scalar aSs, da;
        lubrication_->alpha(v, aSs, da);
        xdot[1] = -v/Df_*(x[1] - aSs);
    }
}


void Foam::frictionLaws::lubricatedRateState::rateStatesOf
(
    const frictionState& s,
    rateStates& x
) const
{
    x[0] = s.scalars[thetaSlot];
    x[1] = s.scalars[alphaSlot];
}


// ************************************************************************* //

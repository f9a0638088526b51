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
#include "relaxationStep.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"

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
    steadyFreshContact_(false),
    lubrication_(lubricationWeightModel::New(dict.subDict("lubrication")))
{
    if (dict.found("mu0"))
    {
        mu0Fn_ = Function1<scalar>::New("mu0", dict);
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

    scalarList range
    (
        dict.getOrDefault<scalarList>("slipRateRange", scalarList({Vs_, 1}))
    );
    if (range.size() != 2 || !(range[0] > 0) || !(range[1] > range[0]))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'slipRateRange' must be (vMin vMax) with"
            << " 0 < vMin < vMax, got " << range << exit(FatalIOError);
    }
    checkRateSensitivity(range[0], range[1]);
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
    // [F18] (L24)
    const scalar e = std::exp(-v/vc_);
    m = muD_ + (muS_ - muD_)*e;
    dmdv = -(muS_ - muD_)*e/vc_;
}


Foam::scalar Foam::frictionLaws::lubricatedRateState::f
(
    const scalar v,
    const scalar theta
) const
{
    // [F17] (L23, L26)
    return max(1 + 0.5*M_*std::log(theta*theta*(v*v + Vs_*Vs_)/(D0_*D0_)), 0);
}


Foam::scalar Foam::frictionLaws::lubricatedRateState::minRateSensitivity
(
    const scalar vMin,
    const scalar vMax,
    scalar& vAtMin
) const
{
    const label nSample = 400;
    scalar aMin = GREAT;
    vAtMin = vMin;
    for (label i = 0; i <= nSample; ++i)
    {
        const scalar v =
            vMin*std::pow(vMax/vMin, scalar(i)/nSample);
        scalar m, dm;
        mu0(v, m, dm);
        const scalar aEff = M_*m + v*dm;
        if (aEff < aMin)
        {
            aMin = aEff;
            vAtMin = v;
        }
    }
    return aMin;
}


bool Foam::frictionLaws::lubricatedRateState::checkRateSensitivity
(
    const scalar vMin,
    const scalar vMax
) const
{
    scalar vAt;
    const scalar aMin = minRateSensitivity(vMin, vMax, vAt);
    if (aMin < 0)
    {
        WarningInFunction
            << "lubricatedRateState: the rate sensitivity a_eff = M mu0"
            << " + |v| mu0'(|v|) is negative (min " << aMin << " at |v| = "
            << vAt << " m/s) in the slip-rate range [" << vMin << ", "
            << vMax << "] m/s: sliding is ill-posed there (strain"
            << " localisation, mesh-dependent results). Increase M or v_c,"
            << " or reduce mu_s - mu_d." << endl;
        return true;
    }
    return false;
}


Foam::frictionState
Foam::frictionLaws::lubricatedRateState::initialState() const
{
    frictionState s;
    s.contactAge = D0_/Vs_;
    return s;
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
    const tensor P = projector(in.n);

    // Step's slip rate [F16]
    const vector vv = (P & (in.gT - old.totalSlip))/dt;
    const scalar v = mag(vv);
    const vector vHat = v > 0 ? vv/v : vector::zero;

    const scalar veff2 = v*v + Vs_*Vs_;

    // Age at the start of the step: a face closing now starts in steady
    // sliding at its first slip rate with steadySliding [F17b]
    scalar theta0 = old.contactAge;
    scalar dtheta0dv = 0;
    if (steadyFreshContact_ && old.status == frictionState::OPEN)
    {
        const scalar veff = std::sqrt(veff2);
        theta0 = D0_/veff;
        dtheta0dv = -theta0*v/veff2;
    }

    // Exact contact-age update at |v| (L22) [F13]
    scalar theta1, dthetadx;
    const scalar x = v*dt/D0_;
    relaxationStep(theta0, x, dt, theta1, dthetadx);
    const scalar dthetadv = dthetadx*dt/D0_ + std::exp(-x)*dtheta0dv;

    // Ageing factor (L23, L26) [F17] and mu0 (L24) [F18]
    const scalar fRaw = 1 + 0.5*M_*std::log(theta1*theta1*veff2/(D0_*D0_));
    const scalar fv = max(fRaw, 0);
    const scalar dfdv = fRaw > 0 ? M_*(dthetadv/theta1 + v/veff2) : 0;
    scalar m0, dm0dv;
    mu0(v, m0, dm0dv);

    const scalar Y = fv*m0*tN;
    const vector dYdgT = tN*(dfdv*m0 + fv*dm0dv)/dt*vHat;
    const scalar dYdgN = fv*m0*KN_;

    auto threshold = [&](scalar, slipThreshold& thr)
    {
        thr.Y = Y;
        thr.dYdDg = 0;
        thr.dYdgN = dYdgN;
        thr.dYdgT = dYdgT;
    };

    const vector xiTrial = KT_*(P & (in.gT - old.plasticSlip));      // [F3]
    radialReturn::output rr;
    radialReturn::solve(xiTrial, Zero, KT_, KT_, P, threshold, rr);
    setFromReturn(old, in, rr, out);

    // Assemble L21 [F20]
    scalar alpha, dalphadv;
    lubrication_->alpha(v, alpha, dalphadv);
    const vector viscous = etaB_*vv;
    out.tT = (1 - alpha)*rr.F + alpha*viscous;
    out.dtTdgT =
        (1 - alpha)*rr.dFdgT
      + ((viscous - rr.F)*(dalphadv/dt*vHat))
      + (alpha*etaB_/dt)*P;
    out.dtTdgN = (1 - alpha)*rr.dFdgN;

    out.state.contactAge = theta1;
    out.state.lubricationWeight = alpha;
    out.state.slipRate = v;
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Time-step independence. Each law is driven through a velocity-step
    history (v1 -> v2 = 10 v1, the step on every grid) with a soft contact
    stiffness, so that the elastic transient spans a few steps; the step is
    halved four times and mu at the coarse output times is compared with a
    reference run at 1/256 of the coarsest step.

    Expected:
      coulomb, curnier: rate independent; on a monotone 1-D path the
        return mapping is exact -> error at round-off for every step;
      lubricatedRateState on a velocity step: ageing and mu0 see the
        sliding (plastic) slip rate, the backward difference of the plastic
        slip, which lags the prescribed step -> first order, last order in
        [0.8, 1.3];
      rateState (ageing, slip, relaxation): the plastic rate is the
        backward difference of the slip -> first order (observed order of
        the last two halvings in [0.8, 1.3]);
      lubricatedRateState on a smooth (sinusoidal) slip-rate history: the
        threshold uses the step's mean rate at the end of the step (a
        backward-Euler evaluation) -> first order, last order in [0.8, 1.3].

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "frictionPointDriver.H"
#include "mathematicalConstants.H"
#include <functional>

using namespace Foam;

typedef std::function<scalar(scalar)> slipFn;

// mu at the times k*outDt, k = 1..nOut
static scalarList run
(
    const frictionLaw& law, const scalar p, const slipFn& S,
    const scalar dt, const scalar outDt, const label nOut
)
{
    frictionPointDriver drv(law, p);
    const label sub = label(std::round(outDt/dt));
    scalarList mu(nOut);
    for (label k = 0; k < nOut; ++k)
    {
        for (label j = 1; j <= sub; ++j)
        {
            const scalar t = (k*sub + j)*dt;
            drv.step(S(t), dt);
        }
        mu[k] = drv.last().tT.x()/drv.last().tN;
    }
    return mu;
}


// Errors for dt0/2^i, i = 0..4; returns the observed orders
static void study
(
    const std::string& name, const std::string& lawDict, const scalar p,
    const slipFn& S, const scalar dt0, const scalar tEnd,
    scalarList& err, scalarList& order
)
{
    autoPtr<frictionLaw> law = frictionTest::law(lawDict);
    const label nOut = label(std::round(tEnd/dt0));
    const scalarList ref = run(*law, p, S, dt0/256, dt0, nOut);
    err.setSize(5);
    order.setSize(4);
    for (label i = 0; i < 5; ++i)
    {
        const scalarList mu = run(*law, p, S, dt0/std::pow(2.0, i), dt0, nOut);
        err[i] = 0;
        forAll(mu, k) err[i] = max(err[i], mag(mu[k] - ref[k]));
    }
    Info<< "    " << name.c_str() << ": max |mu - mu_ref| = " << err;
    for (label i = 0; i < 4; ++i)
    {
        order[i] = std::log(max(err[i], 1e-300)/max(err[i+1], 1e-300))
            /std::log(2.0);
    }
    Info<< ", observed orders " << order << endl;
}


int main()
{
    const scalar pi = constant::mathematical::pi;
    scalarList err, order;

    // Rate-state family: tN = 1e6 Pa, elastic slip mu tN/KT ~ L = 1e-5 m
    const scalar v1 = 1e-6, v2 = 1e-5, t1 = 20;
    const slipFn stepS = [=](scalar t)
    {
        return t <= t1 ? v1*t : v1*t1 + v2*(t - t1);
    };
    const std::string rs =
        "type rateState; KN 1e12; KT 6e10; a 0.01; b 0.015; muStar 0.6;"
        " VStar 1e-6; L 1e-5; creepVelocity 1e-12; ";
    const std::string rateLaws[3] =
    {
        rs + "stateLaw ageing;",
        rs + "stateLaw slip;",
        "type rateState; stateLaw relaxation; KN 1e12; KT 3.7e10;"
        " muStar 0.369; a 0.0349; b 0.0489; VStar 1e-6;"
        " relaxationTime 2.729; gamma 0.723; creepVelocity 1e-12;"
    };
    const char* names[3] = {"rateState ageing", "rateState slip", "rateState relaxation"};
    for (label i = 0; i < 3; ++i)
    {
        study(names[i], rateLaws[i], 1e6, stepS, 0.5, 25, err, order);
        unitTest::checkTrue
        (
            std::string(names[i]) + ": first order (last two orders in [0.8, 1.3])",
            order[2] > 0.8 && order[2] < 1.3 && order[3] > 0.8 && order[3] < 1.3
        );
        unitTest::checkBelow(std::string(names[i]) + ": error at dt0/16", err[4], 2e-3);
    }

    // Rate-independent laws: exact on this path
    const std::string riLaws[2] =
    {
        "type coulomb; KN 1e12; KT 6e10; mu 0.6;",
        "type curnier; KN 1e12; KT 6e10; criterion coulomb; f 0.6;"
        " QT 1e9; Q 1e9;"
    };
    const char* riNames[2] = {"coulomb", "curnier (tear, wear)"};
    for (label i = 0; i < 2; ++i)
    {
        study(riNames[i], riLaws[i], 1e6, stepS, 0.5, 25, err, order);
        unitTest::checkBelow(std::string(riNames[i]) + ": exact (max error)", max(err), 1e-12);
    }

    // Lubricated law, pear-tube set, KT = 1e13: elastic slip ~ D0
    const std::string lub =
        "type lubricatedRateState; KN 1e13; KT 1e13; M 0.1; D0 1e-6;"
        " creepVelocity 1e-9; mu0 constant 0.1; filmViscosity 3e9;"
        " lubrication { type stribeck; filmThickness 1e-6;"
        " referenceFilmThickness 1e-6; referenceVelocity 1e-3; n 1; }";
    {
        const scalar w1 = 1e-4, w2 = 1e-3, s1 = 0.02;
        const slipFn S = [=](scalar t)
        {
            return t <= s1 ? w1*t : w1*s1 + w2*(t - s1);
        };
        study("lubricated, velocity step", lub, 1e8, S, 5e-4, 0.025, err, order);
        unitTest::checkTrue
        (
            "lubricated, velocity step: first order (last order in [0.8, 1.3])",
            order[3] > 0.8 && order[3] < 1.3
        );
        unitTest::checkBelow("lubricated, velocity step: error at dt0/16", err[4], 2e-3);
    }
    {
        const scalar w = 1e-4, T = 0.02;
        const slipFn S = [=](scalar t)
        {
            return w*(t + 0.9*T/(2*pi)*(1 - std::cos(2*pi*t/T)));
        };
        study("lubricated, sinusoidal rate", lub, 1e8, S, 1e-3, 0.04, err, order);
        unitTest::checkTrue
        (
            "lubricated, sinusoidal: first order (last order in [0.8, 1.3])",
            order[3] > 0.8 && order[3] < 1.3
        );
    }

    return unitTest::exitCode();
}

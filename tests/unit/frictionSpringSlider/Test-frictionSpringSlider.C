/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Stability of steady sliding on a spring (doc/theory.md [F22], [F22b],
    [F31], [V6]): the critical stiffness k_c and frequency omega_c that
    slidingStability computes from each law's rate form, without and with
    block mass M, against

    1. the closed forms of one state variable, k_c = -g F_ss' (1 + M g/F_v),
       omega_c^2 = -g^2 F_ss'/F_v, with g, F_ss', F_v written out for
       - the ageing and slip laws [F27]: g = V/L, F_ss' = -(b - a) sigma/V,
         F_v = a sigma/V (so k* = (b - a) sigma/L);
       - the relaxation law, paper board: g = 1/(t** (V* / V)^gamma),
         F_ss' = sigma (a - b gamma)/V, F_v = a sigma/V;
       - the lubricated law without film [F29]: g = V/D0,
         F_ss' = tN mu0'(V), F_v = tN (M mu0/V + mu0'(V));
       (tolerance 1e-6, central differences of the rate form);
    2. the eigenvalues of the perturbation system: growing at 0.999 k_c,
       decaying at 1.001 k_c;
    3. direct spring-slider simulation (frictionPointDriver, backward
       Euler, 2000 steps per period, machine spring in series with KT so
       that the pair is k): a perturbation of the state by 1e-3 decays at
       1.03 k_c (at 0.9 to 2 times the rate of the leading eigenvalue:
       backward Euler adds damping) and grows at 0.97 k_c, for the ageing,
       slip, relaxation and lubricated laws and the lubricated law with
       film memory [F30] (two state variables, no closed form), without
       and with mass;
    4. a load-point history: a velocity step V -> 10 V on a stiff machine
       (k = 100 k_c) gives the rigid-contact step response of the ageing
       law [F23] within the machine's compliance.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "frictionPointDriver.H"
#include "slidingStability.H"
#include "mathematicalConstants.H"

using namespace Foam;

namespace
{

//- Amplitude of max |v/V - 1| in the last two periods over the first two
scalar amplitudeRatio
(
    const frictionLaw& law,
    const scalar tN,
    const scalar V,
    const scalar k,
    const scalar M,
    const scalar omega,
    const scalar relaxationTime,
    const label nPeriods,
    scalar& tSpan
)
{
    frictionPointDriver drv(law, tN);
    const label perPeriod = 2000;
    const scalar period = 2*constant::mathematical::pi/omega;
    const scalar dt = period/perPeriod;

    // steady sliding at V over 50 relaxation times of the slowest state
    // (2000 steps: the states are exact at constant rate)
    const scalar dtRunIn = 50*relaxationTime/2000;
    for (label i = 0; i < 2000; ++i)
    {
        drv.step(drv.slip() + V*dtRunIn, dtRunIn);
    }
    const scalar kMachine = 1/(1/k - 1/law.KT());
    drv.setSpringStretch(drv.last().tT.x()/kMachine);
    // the law's first own variable: phi, the contact age
    for (const frictionStateEntry& e : law.stateLayout().entries())
    {
        if (e.slot >= frictionState::firstLawSlot)
        {
            drv.state().scalarSlot(e.slot) *= 1 + 1e-3;
            break;
        }
    }

    scalar early = 0, late = 0;
    const label n = nPeriods*perPeriod;
    for (label i = 0; i < n; ++i)
    {
        drv.springSliderStep(M, kMachine, V, dt);
        const scalar amp = mag(drv.state().slipRate/V - 1);
        if (i < 2*perPeriod) early = max(early, amp);
        if (i >= n - 2*perPeriod) late = max(late, amp);
    }
    tSpan = (nPeriods - 2)*period;
    return late/early;
}


struct lawCase
{
    std::string name;
    std::string dict;
    scalar tN;
    scalar V;
    //- Closed form: g, F_ss', F_v (g = 0: none)
    scalar g, dFss, Fv;
    //- Mass giving k_c(M) ~ 1.2 k_c(0), for the mass cases
    bool withMass;
};

} // End anonymous namespace


int main()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar sigma = 1e6;
    std::vector<lawCase> cases;

    {
        const scalar a = 0.01, b = 0.015, L = 1e-5, V = 1e-6;
        const std::string rs =
            "type rateState; KN 1e12; KT 1e13; a 0.01; b 0.015; muStar 0.6;"
            " VStar 1e-6; L 1e-5; creepVelocity 1e-15; ";
        cases.push_back
        ({
            "ageing", rs + "stateLaw ageing;", sigma, V,
            V/L, -(b - a)*sigma/V, a*sigma/V, true
        });
        cases.push_back
        ({
            "slip", rs + "stateLaw slip;", sigma, 3*V,
            3*V/L, -(b - a)*sigma/(3*V), a*sigma/(3*V), false
        });
    }
    {
        const scalar a = 0.0349, b = 0.0489, gamma = 0.723, tR = 2.729;
        const scalar V = 1e-5, VStar = 1e-6;
        cases.push_back
        ({
            "relaxation (paper board)",
            "type rateState; stateLaw relaxation; KN 1e12; KT 1e13;"
            " muStar 0.369; a 0.0349; b 0.0489; VStar 1e-6;"
            " relaxationTime 2.729; gamma 0.723; creepVelocity 1e-15;",
            sigma, V,
            1/(tR*std::pow(VStar/V, gamma)), sigma*(a - b*gamma)/V,
            a*sigma/V, false
        });
    }
    const std::string lub =
        "type lubricatedRateState; KN 1e13; KT 1e16; M 0.1; D0 1e-6;"
        " creepVelocity 1e-9; muStatic 0.12; muDynamic 0.07;"
        " criticalVelocity 1e-3; filmViscosity 3e9;"
        " slipRateRange (1e-9 1e-3); contactPressureRange (1e6 1e8); ";
    {
        // without film, at V = 0.2 v_c: velocity weakening, a_eff > 0
        const scalar tN = 1e8, V = 2e-4, M = 0.1;
        const scalar e = std::exp(-V/1e-3);
        const scalar mu0 = 0.07 + 0.05*e, dmu0 = -0.05*e/1e-3;
        cases.push_back
        ({
            "lubricated, no film", lub + "lubrication { type constant;"
            " alpha 0; }", tN, V,
            V/1e-6, tN*dmu0, tN*(M*mu0/V + dmu0), false
        });
        // film memory, Stribeck film: no closed form (two state variables)
        cases.push_back
        ({
            "lubricated, film memory",
            lub + "filmMemoryDistance 5e-6; lubrication { type stribeck;"
            " filmThickness 1e-6; referenceFilmThickness 1e-6;"
            " referenceVelocity 1e-3; n 1; }", tN, 3e-4, 0, 0, 0, true
        });
    }

    for (const lawCase& c : cases)
    {
        Info<< "Law " << c.name.c_str() << ", V = " << c.V << " m/s" << endl;
        autoPtr<frictionLaw> law = frictionTest::law(c.dict);
        const slidingStability stab(*law, c.tN);
        const slidingStability::critical c0 = stab.criticalStiffness(c.V, 0);
        // a mass that raises k_c by 20 %: M omega_c^2 = 0.2 k_c(0)
        const scalar M = 0.2*c0.kc/sqr(c0.omegac);
        const slidingStability::critical cM = stab.criticalStiffness(c.V, M);
        unitTest::checkTrue
        (
            c.name + ": Hopf onset", c0.kind == slidingStability::HOPF
        );

        if (c.g > 0)
        {
            const scalar kc0 = -c.g*c.dFss;
            const scalar kcM = kc0*(1 + M*c.g/c.Fv);
            const scalar om = c.g*std::sqrt(-c.dFss/c.Fv);
            unitTest::checkRel(c.name + ": k_c, M = 0", c0.kc, kc0, 1e-6);
            unitTest::checkRel
            (
                c.name + ": k_c = k_c(0) (1 + M g/F_v)", cM.kc, kcM, 1e-6
            );
            unitTest::checkRel
            (
                c.name + ": omega_c^2 = -g^2 F_ss'/F_v", c0.omegac, om, 1e-6
            );
        }
        unitTest::checkRel
        (
            c.name + ": omega_c independent of M, k_c(M) = k_c(0)"
            " + M omega_c^2", cM.kc, c0.kc + M*sqr(c0.omegac), 1e-8
        );

        // The eigenvalues of the perturbation system agree
        for (const scalar m : {scalar(0), M})
        {
            const scalar kc = m > 0 ? cM.kc : c0.kc;
            scalar w;
            const scalar sBelow = stab.growthRate(c0.lin, m, 0.999*kc, w);
            const scalar sAbove = stab.growthRate(c0.lin, m, 1.001*kc, w);
            unitTest::checkTrue
            (
                c.name + (m > 0 ? ", mass" : "") + ": eigenvalues grow at"
                " 0.999 k_c, decay at 1.001 k_c", sBelow > 0 && sAbove < 0
            );
        }

        // Direct simulation at 0.97 and 1.03 k_c
        scalar gMin = GREAT;
        for (label i = 0; i < c0.lin.Fx.size(); ++i)
        {
            gMin = min(gMin, mag(c0.lin.Gx(i, i)));
        }
        for (const scalar m : {scalar(0), M})
        {
            if (m > 0 && !c.withMass) continue;
            const scalar kc = m > 0 ? cM.kc : c0.kc;
            scalar tSpan, w;
            const scalar rUp =
                amplitudeRatio(*law, c.tN, c.V, 0.97*kc, m, c0.omegac, 1/gMin, 20, tSpan);
            const scalar sUp = stab.growthRate(c0.lin, m, 0.97*kc, w);
            const scalar rDown =
                amplitudeRatio(*law, c.tN, c.V, 1.03*kc, m, c0.omegac, 1/gMin, 20, tSpan);
            const scalar sDown = stab.growthRate(c0.lin, m, 1.03*kc, w);
            Info<< "    M = " << m << ": amplitude ratio over " << tSpan
                << " s at 0.97 k_c " << rUp << " (eigenvalue "
                << std::exp(sUp*tSpan) << "), at 1.03 k_c " << rDown
                << " (eigenvalue " << std::exp(sDown*tSpan) << ")" << endl;
            const std::string tag = c.name + (m > 0 ? ", mass" : "");
            unitTest::checkTrue(tag + ": grows at 0.97 k_c", rUp > 1);
            unitTest::checkTrue(tag + ": decays at 1.03 k_c", rDown < 1);
            // backward Euler damps a little more than the eigenvalue
            // (measured 1.0-1.5 times its decay over 18 periods)
            const scalar q = std::log(rDown)/(sDown*tSpan);
            unitTest::checkTrue
            (
                tag + ": decay over 18 periods 0.9-2 times the eigenvalue's"
                " (" + std::to_string(q) + ")", q > 0.9 && q < 2
            );
        }
    }

    Info<< "Load-point velocity step on a stiff machine ([F23])" << endl;
    {
        autoPtr<frictionLaw> law = frictionTest::law(cases[0].dict);
        const scalar a = 0.01, b = 0.015, L = 1e-5, v1 = 1e-6, v2 = 1e-5;
        const scalar k = 100*(b - a)*sigma/L;
        frictionPointDriver drv(*law, sigma);
        const scalar dt = 0.01*L/v2;
        for (label i = 0; i < 20000; ++i) drv.step(drv.slip() + v1*dt, dt);
        drv.setTime(0);
        drv.setSpringStretch(drv.last().tT.x()/k);
        const scalar s0 = drv.slip();
        autoPtr<Function1<scalar>> V = Function1<scalar>::New
        (
            "loadPointVelocity",
            frictionTest::dict
            (
                "loadPointVelocity table ((0 1e-6) (1 1e-6) (1.000001 1e-5)"
                " (100 1e-5));"
            )
        );
        DynamicList<frictionPointDriver::sample> rows;
        drv.runSpringSlider(0, k, V(), 1 + 60*L/v2, dt, rows);
        // after 40 L of slip at v2, the steady friction at v2 [F28]
        const scalar muSs = 0.6 + (a - b)*std::log(v2/1e-6);
        unitTest::checkAbs
        (
            "steady friction after the step, mu_ss(10 V)",
            rows.last().mu, muSs, 1e-6
        );
        scalar peak = 0;
        for (const auto& r : rows) peak = max(peak, r.mu);
        // the machine (100 k_c) lowers the rigid-contact peak
        // mu_ss(v1) + a ln(v2/v1) by a little
        const scalar peakRigid = 0.6 + a*std::log(v2/v1);
        unitTest::checkTrue
        (
            "peak below the rigid-contact direct effect, above mu_ss(v1)",
            peak < peakRigid && peak > 0.6
        );
        Info<< "    slip " << drv.slip() - s0 << " m, peak " << peak
            << " (rigid " << peakRigid << ")" << endl;
    }

    unitTest::checkTrue
    (
        "no iteration-limit hits",
        frictionLaw::reportIterationLimitHits() == 0
    );
    return unitTest::exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.

Description
    Spring-slider stability ([V6], [F22], [F22b]), quasi-static
    (M = 0) and with inertia, by frictionPointDriver:
    steady sliding at V is perturbed (state theta x 1.05) and the amplitude
    of the slip-rate oscillation is compared between the first and the last
    two oscillation periods. Stable (decays) at k = 1.1 k*, unstable
    (grows) at k = 0.9 k*.

    Case 1: ageing law, k* = (b - a) sigma/L.
    Case 2: paper board, relaxation law [F27] with power-law phi_ss; the
    same linearisation gives k* = sigma (b gamma - a) G_phi / V with
    G_phi = 1/(t** phi_ss(V)) (doc/theory.md [F22]).
    The contact stiffness KT acts in series with k: the spring is set to
    k = 1/(1/k_target - 1/KT) so that the series stiffness is k_target.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "frictionPointDriver.H"
#include "mathematicalConstants.H"

using namespace Foam;

// Ratio of the oscillation amplitude (max |v/V - 1|) late vs early
static scalar amplitudeRatio
(
    const frictionLaw& law,
    const scalar sigma,
    const scalar V,
    const scalar kTarget,
    const scalar period,
    const label nPeriods,
    const label stepsPerPeriod,
    const scalar M = 0
)
{
    frictionPointDriver drv(law, sigma);

    // Steady sliding at V
    const scalar dt = period/stepsPerPeriod;
    for (label i = 0; i < 20*stepsPerPeriod; ++i)
    {
        drv.step(drv.slip() + V*dt, dt);
    }

    const scalar k = 1/(1/kTarget - 1/law.KT());
    drv.setSpringStretch(drv.last().tT.x()/k);
    const word phi(law.stateLayout().entries().last().name);
    law.stateLayout().setValue
    (
        drv.state(), phi, 1.05*law.stateLayout().value(drv.state(), phi)
    );

    scalar early = 0, late = 0;
    const label n = nPeriods*stepsPerPeriod;
    for (label i = 0; i < n; ++i)
    {
        drv.springSliderStep(M, k, V, dt);
        const scalar amp = mag(drv.state().slipRate/V - 1);
        if (i < 2*stepsPerPeriod) early = max(early, amp);
        if (i >= n - 2*stepsPerPeriod) late = max(late, amp);
    }
    Info<< "        k = " << kTarget << " Pa/m, M = " << M << ": early amplitude " << early
        << ", late " << late << endl;
    return late/early;
}


int main()
{
    FatalError.throwExceptions();

    const scalar sigma = 1e6;

    Info<< "Ageing law ([F11] + [F27])" << endl;
    {
        const scalar a = 0.01, b = 0.015, L = 1e-5, V = 1e-6;
        autoPtr<frictionLaw> law = frictionTest::law
        (
            "type rateState; stateLaw ageing; KN 1e12; KT 1e13;"
            " a 0.01; b 0.015; muStar 0.6; VStar 1e-6; L 1e-5;"
            " creepVelocity 1e-15;"
        );
        const scalar kStar = (b - a)*sigma/L;
        // Hopf frequency: omega^2 = (b - a)/(a tau^2), tau = L/V
        const scalar period = 2*constant::mathematical::pi*(L/V)
            /std::sqrt((b - a)/a);

        const scalar rs = amplitudeRatio(*law, sigma, V, 1.1*kStar, period, 20, 1000);
        const scalar ru = amplitudeRatio(*law, sigma, V, 0.9*kStar, period, 20, 1000);
        unitTest::checkBelow("k = 1.1 k*: amplitude decays (ratio)", rs, 0.5);
        unitTest::checkTrue("k = 0.9 k*: amplitude grows (ratio > 2)", ru > 2);

        // With inertia, [F22b]: k_c = k* (1 + M G_phi/F_v), G_phi = V/L,
        // F_v = a sigma/V; M chosen so that k_c = 1.2 k*: now 1.1 k* is
        // unstable and 1.3 k* stable
        const scalar M = 0.2*a*sigma*L/(V*V);
        const scalar rsM = amplitudeRatio(*law, sigma, V, 1.3*kStar, period, 20, 1000, M);
        const scalar ruM = amplitudeRatio(*law, sigma, V, 1.1*kStar, period, 20, 1000, M);
        unitTest::checkBelow("M: k_c = 1.2 k*, k = 1.3 k*: decays", rsM, 0.5);
        unitTest::checkTrue("M: k_c = 1.2 k*, k = 1.1 k*: grows", ruM > 2);
    }

    Info<< "Paper board ([F27], relaxation law)" << endl;
    {
        const scalar a = 0.0349, b = 0.0489, gamma = 0.723, tR = 2.729;
        const scalar V = 1e-6, VStar = 1e-6;
        autoPtr<frictionLaw> law = frictionTest::law
        (
            "type rateState; stateLaw relaxation; KN 1e12; KT 1e13;"
            " muStar 0.369; a 0.0349; b 0.0489; VStar 1e-6;"
            " relaxationTime 2.729; gamma 0.723; creepVelocity 1e-15;"
        );
        const scalar phiSs = std::pow(VStar/V, gamma);
        const scalar tau = tR*phiSs;
        const scalar kStar = sigma*(b*gamma - a)/(V*tau);
        const scalar period = 2*constant::mathematical::pi
            *std::sqrt(sigma*a*tau/(kStar*V));
        Info<< "    k* = " << kStar << " Pa/m, period " << period << " s"
            << endl;

        const scalar rs = amplitudeRatio(*law, sigma, V, 1.1*kStar, period, 40, 4000);
        const scalar ru = amplitudeRatio(*law, sigma, V, 0.9*kStar, period, 40, 4000);
        unitTest::checkBelow("k = 1.1 k*: amplitude decays (ratio)", rs, 0.7);
        unitTest::checkTrue("k = 0.9 k*: amplitude grows (ratio > 1.4)", ru > 1.4);
    }

    unitTest::checkTrue
    (
        "no iteration-limit hits",
        frictionLaw::reportIterationLimitHits() == 0
    );
    return unitTest::exitCode();
}

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The lubricated law with a film memory (doc/theory.md [F30]): alpha
    relaxes to alpha_ss(|v|) over the slip D_f. Slidingblock parameters
    (M = 0.1, D0 = 1 um, mu_s = 0.12, mu_d = 0.07, v_c = 1 mm/s,
    eta_b = 3e9 Pa s/m, Stribeck D = D_b, v_b = 1 mm/s, n = 1), D_f = 5 um,
    tN = 1e8 Pa, stiff contact (KT = 1e16):
      - steady sliding: alpha = alpha_ss(v) and the traction of [F20];
        the rate form's steady traction [F31] is the one update() reaches;
      - velocity step at imposed rate: alpha(d) = alpha_ss(v2)
        + (alpha_ss(v1) - alpha_ss(v2)) e^(-d/D_f) (exact: alpha is advanced
        exactly at the film's rate), and in the step itself the traction
        follows the direct effect (alpha held), not the jump of the
        published form;
      - D_f -> 0 recovers the published form;
      - the rate form's state rates are those of update() (small steps);
      - consistent tangent vs central differences (1e-6);
      - the well-posedness check: a set ill posed at 1 GPa in the published
        form is well posed with the film memory [F21];
      - D_f < 0 rejected naming the keyword.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "frictionPointDriver.H"
#include "lubricatedRateState.H"

using namespace Foam;

static std::string lubricated
(
    const std::string& Df,
    const std::string& KT = "1e16",
    const std::string& M = "0.1",
    const std::string& pMax = "1e8"
)
{
    return
        "type lubricatedRateState; KN 1e13; KT " + KT + "; M " + M + ";"
        " D0 1e-6; creepVelocity 1e-9; muStatic 0.12; muDynamic 0.07;"
        " criticalVelocity 1e-3; filmViscosity 3e9; filmMemoryDistance " + Df
      + "; slipRateRange (1e-9 1e-3); contactPressureRange (1e6 " + pMax
      + "); lubrication { type stribeck; filmThickness 1e-6;"
        " referenceFilmThickness 1e-6; referenceVelocity 1e-3; n 1; }";
}


static scalar alphaSs(const scalar v)
{
    return v/1e-3/(1 + v/1e-3);
}


int main()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    const scalar p = 1e8, Df = 5e-6;

    autoPtr<frictionLaw> law = frictionTest::law(lubricated("5e-6"));
    const frictionStateLayout& layout = law->stateLayout();

    Info<< "Declared state" << endl;
    unitTest::checkTrue
    (
        "lubricationWeight written for restart with the film memory",
        layout.entries().last().name == "lubricationWeight"
     && layout.entries().last().write
    );

    Info<< "Steady sliding" << endl;
    {
        frictionPointDriver drv(*law, p);
        const scalar v = 3e-4, dt = 0.05*1e-6/v;
        for (label i = 0; i < 4000; ++i) drv.step(drv.slip() + v*dt, dt);
        unitTest::checkRel
        (
            "alpha = alpha_ss(v)",
            layout.value(drv.state(), "lubricationWeight"), alphaSs(v), 1e-12
        );
        unitTest::checkRel
        (
            "tT = rate form's steady traction [F31]",
            drv.last().tT.x(), law->steadyTraction(v, p), 1e-9
        );
    }

    Info<< "Velocity step 1e-4 -> 1e-3 m/s" << endl;
    autoPtr<frictionLaw> published = frictionTest::law(lubricated("0"));
    {
        // KT = 1e18: the elastic slip of the traction change (6e-13 m) is
        // 1e-3 of the slip in the first step (1e-4 D_f, over which alpha
        // and theta change by 1e-4 relative)
        autoPtr<frictionLaw> stiff =
            frictionTest::law(lubricated("5e-6", "1e18"));
        autoPtr<frictionLaw> stiffPub =
            frictionTest::law(lubricated("0", "1e18"));
        const scalar v1 = 1e-4, v2 = 1e-3;
        frictionPointDriver drv(*stiff, p), pub(*stiffPub, p);
        scalar dt = 0.05*1e-6/v1;
        for (label i = 0; i < 4000; ++i)
        {
            drv.step(drv.slip() + v1*dt, dt);
            pub.step(pub.slip() + v1*dt, dt);
        }
        const scalar s0 = drv.slip();
        const scalar tT0 = drv.last().tT.x(), tTpub0 = pub.last().tT.x();
        frictionLaw::rateStates x(scalar(0));
        stiff->rateStatesOf(drv.state(), x);
        dt = 1e-4*Df/v2;

        drv.step(drv.slip() + v2*dt, dt);
        pub.step(pub.slip() + v2*dt, dt);
        // held state: F(v2, x) - F(v1, x); published: alpha jumps too
        const scalar direct =
            stiff->slidingTraction(v2, x, p)
          - stiff->slidingTraction(v1, x, p);
        Info<< "    traction change in the step: film memory "
            << drv.last().tT.x() - tT0 << " Pa (direct effect " << direct
            << " Pa), published " << pub.last().tT.x() - tTpub0 << " Pa"
            << endl;
        unitTest::checkRel
        (
            "film memory: first-step change = the direct effect F(v2, x)"
            " - F(v1, x)", drv.last().tT.x() - tT0, direct, 0.02
        );

        dt = 1e-3*Df/v2;
        scalar err = 0;
        for (label i = 0; i < 4000; ++i)
        {
            drv.step(drv.slip() + v2*dt, dt);
            const scalar d = drv.slip() - s0;
            const scalar expected =
                alphaSs(v2) + (alphaSs(v1) - alphaSs(v2))*std::exp(-d/Df);
            err = max
            (
                err,
                mag(layout.value(drv.state(), "lubricationWeight") - expected)
            );
        }
        unitTest::checkBelow
        (
            "alpha(d) = alpha_ss2 + (alpha_ss1 - alpha_ss2) e^(-d/D_f), max"
            " abs error over 4 D_f (round-off of 4000 steps)", err, 1e-12
        );
    }

    Info<< "D_f -> 0: the published form" << endl;
    {
        // on any history that keeps sliding (|v| > 0): in a true hold
        // (v = 0) the film memory keeps alpha whatever D_f (no slip, no
        // renewal of the film), the published form takes alpha_ss(0)
        autoPtr<frictionLaw> tiny = frictionTest::law(lubricated("1e-14"));
        frictionPointDriver a(*tiny, p), b(*published, p);
        scalar err = 0;
        for (const scalar v : {1e-4, 1e-3, 1e-8, 3e-4, -1e-3})
        {
            const scalar dt = 1e-4;
            for (label i = 0; i < 200; ++i)
            {
                a.step(a.slip() + v*dt, dt);
                b.step(b.slip() + v*dt, dt);
                err = max(err, mag(a.last().tT.x() - b.last().tT.x())/p);
            }
        }
        unitTest::checkBelow
        (
            "D_f = 1e-14 m vs published: max |tT difference|/tN over steps,"
            " a slow slide (1e-8 m/s) and a reversal", err, 1e-12
        );
    }

    Info<< "Rate form [F31] against update()" << endl;
    {
        frictionPointDriver drv(*law, p);
        const scalar v = 2e-4;
        scalar dt = 0.05*1e-6/v;
        for (label i = 0; i < 200; ++i) drv.step(drv.slip() + v*dt, dt);
        frictionLaw::rateStates x0(scalar(0)), x1(scalar(0)), xdot(scalar(0));
        law->rateStatesOf(drv.state(), x0);
        dt = 1e-6*1e-6/v;
        drv.step(drv.slip() + v*dt, dt);
        law->rateStatesOf(drv.state(), x1);
        // theta ages at the sliding rate, alpha follows the film's (the
        // total) rate [F16]; both are v in the rate form (rigid contact)
        law->stateRates(drv.state().slipRate, x0, p, xdot);
        unitTest::checkRel
        (
            "d theta/dt = (theta1 - theta0)/dt (dt = 1e-6 D0/v)",
            (x1[0] - x0[0])/dt, xdot[0], 1e-5
        );
        law->stateRates(v, x0, p, xdot);
        unitTest::checkRel
        (
            "d alpha/dt = (alpha1 - alpha0)/dt",
            (x1[1] - x0[1])/dt, xdot[1], 1e-5
        );
        const scalar a1 = layout.value(drv.state(), "lubricationWeight");
        drv.step(drv.slip(), 100);
        unitTest::checkAbs
        (
            "a hold (v = 0) keeps alpha",
            layout.value(drv.state(), "lubricationWeight"), a1, 0
        );
    }

    Info<< "Consistent tangent vs FD" << endl;
    {
        autoPtr<frictionLaw> soft = frictionTest::law
        (
            "type lubricatedRateState; KN 1e13; KT 1e13; M 0.1; D0 1e-6;"
            " creepVelocity 1e-9; muStatic 0.12; muDynamic 0.07;"
            " criticalVelocity 1e-3; filmViscosity 3e9;"
            " filmMemoryDistance 5e-6; slipRateRange (1e-9 1e-3);"
            " contactPressureRange (1e6 1e8);"
            " lubrication { type stribeck; filmThickness 1e-6;"
            " referenceFilmThickness 1e-6; referenceVelocity 1e-3; n 1; }"
        );
        const frictionStateLayout& sl = soft->stateLayout();
        const vector n(0.36, 0.48, 0.8);
        vector t1(0.8, -0.6, 0); t1 -= (t1 & n)*n; t1 /= mag(t1);
        const vector t2 = n ^ t1;
        frictionState old = soft->initialState();
        old.status = frictionState::SLIP;
        sl.setValue(old, "contactAge", 2e-3);
        sl.setValue(old, "lubricationWeight", 0.4);
        old.totalSlip = 1e-6*t1;
        old.plasticSlip = 0.2e-6*t1;
        frictionInput in;
        in.n = n;
        in.gN = 1e-5;
        in.dt = 1e-3;
        in.gT = old.totalSlip + 1.5e-6*t1 + 0.5e-6*t2;
        frictionResult r;
        soft->update(old, in, r);
        unitTest::checkTrue("sliding", r.state.status == 2);
        unitTest::checkBelow
        (
            "tangent vs FD (slip, alpha relaxing)",
            frictionTest::tangentError(*soft, old, in, 1e-5), 1e-6
        );
        in.gT = old.plasticSlip + 0.3e-6*t1 - 0.2e-6*t2;
        in.dt = 10;
        soft->update(old, in, r);
        unitTest::checkTrue("sticking", r.state.status == 1);
        unitTest::checkBelow
        (
            "tangent vs FD (stick)",
            frictionTest::tangentError(*soft, old, in, 1e-5), 1e-6
        );
    }

    Info<< "Well-posedness [F21]" << endl;
    {
        // M = 0.5: the ageing term outweighs the mu0 decay, but at 1 GPa the
        // instantaneous Stribeck weakening of the published form does not
        autoPtr<frictionLaw> pub =
            frictionTest::law(lubricated("0", "1e16", "0.5", "1e9"));
        autoPtr<frictionLaw> mem =
            frictionTest::law(lubricated("5e-6", "1e16", "0.5", "1e9"));
        unitTest::checkTrue
        (
            "published form: ill posed at high pressure",
            pub->checkWellPosedness(1e-9, 1, 1e6, 1e9)
        );
        unitTest::checkTrue
        (
            "film memory: well posed on 1e-9 to 1 m/s, 1 MPa to 1 GPa",
            !mem->checkWellPosedness(1e-9, 1, 1e6, 1e9)
        );
    }

    Info<< "Input check" << endl;
    {
        bool threw = false;
        try
        {
            frictionTest::law(lubricated("-1e-6"));
        }
        catch (const Foam::IOerror& e)
        {
            threw =
                std::string(e.message()).find("filmMemoryDistance")
             != std::string::npos;
        }
        unitTest::checkTrue("D_f < 0 rejected, message names the keyword", threw);
    }

    unitTest::checkTrue
    (
        "no iteration-limit hits",
        frictionLaw::reportIterationLimitHits() == 0
    );
    return unitTest::exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Coulomb law (doc/theory.md [F8]; [F1], [F29] with
    alpha = 0): stick below the threshold (tT = KT gT exactly), |tT| = mu tN
    in slip, return direction along the trial traction, consistent tangent
    against central finite differences (1e-6 relative), static/dynamic
    coefficients, open contact, input checks. The state's serialisation
    is tested for every law in frictionStateLayout.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"

using namespace Foam;

int main()
{
    // Pear-tube magnitudes: KN = KT = 1e13 Pa/m, tN = 1e8 Pa
    autoPtr<frictionLaw> law =
        frictionTest::law("type coulomb; KN 1e13; KT 1e13; mu 0.1;");

    const vector n(0.36, 0.48, 0.8);             // unit, tilted plane
    vector t1(0.8, -0.6, 0); t1 -= (t1 & n)*n; t1 /= mag(t1);
    const vector t2 = n ^ t1;

    frictionState old = law->initialState();
    old.status = frictionState::STICK;
    frictionInput in;
    in.n = n;
    in.gN = 1e-5;                                 // tN = 1e8 Pa
    in.dt = 1e-3;
    const scalar tN = 1e13*in.gN;
    const scalar Y = 0.1*tN;                      // 1e7 Pa

    Info<< "Stick below the threshold" << endl;
    {
        in.gT = 0.5e-6*t1 + 0.3e-6*t2;           // |KT gT| = 5.8e6 < Y
        frictionResult r;
        law->update(old, in, r);
        unitTest::checkRel("tN = KN gN", r.tN, tN, 1e-14);
        unitTest::checkAbs("stick: tT - KT gT", mag(r.tT - 1e13*in.gT), 0, 1e-6);
        unitTest::checkTrue("stick status", r.state.status == 1);
        unitTest::checkAbs("stick: no plastic slip", mag(r.state.plasticSlip), 0, 0);
        unitTest::checkBelow
        (
            "stick: tangent error vs FD",
            frictionTest::tangentError(*law, old, in), 1e-6
        );
    }

    Info<< "Slip above the threshold" << endl;
    {
        old.plasticSlip = 0.4e-6*t1 - 0.2e-6*t2;
        in.gT = 3e-6*t1 + 2e-6*t2;
        const vector trial = 1e13*(in.gT - old.plasticSlip);
        frictionResult r;
        law->update(old, in, r);
        unitTest::checkRel("slip: |tT| = mu tN", mag(r.tT), Y, 1e-13);
        unitTest::checkAbs
        (
            "slip: direction = trial direction",
            mag(r.tT/mag(r.tT) - trial/mag(trial)), 0, 1e-14
        );
        unitTest::checkAbs("slip: tT in the tangent plane", mag(r.tT & n), 0, 1e-6);
        unitTest::checkTrue("slip status", r.state.status == 2);
        unitTest::checkRel
        (
            "slip: plastic increment = (|trial| - Y)/KT",
            mag(r.state.plasticSlip - old.plasticSlip),
            (mag(trial) - Y)/1e13, 1e-12
        );
        unitTest::checkBelow
        (
            "slip: tangent error vs FD",
            frictionTest::tangentError(*law, old, in), 1e-6
        );
        unitTest::checkRel
        (
            "slip: dtT/dgN = mu KN m",
            mag(r.dtTdgN), 0.1*1e13, 1e-12
        );
    }

    Info<< "Static and dynamic coefficients" << endl;
    {
        autoPtr<frictionLaw> sd = frictionTest::law
        (
            "type coulomb; KN 1e13; KT 1e13; mu 0.1; muStatic 0.15;"
        );
        frictionState s0 = sd->initialState();
        s0.status = frictionState::STICK;
        in.gT = 1.2e-6*t1;                        // 1.2e7: between the two
        frictionResult r;
        sd->update(s0, in, r);
        unitTest::checkTrue("at rest, below muStatic: stick", r.state.status == 1);
        in.gT = 1.6e-6*t1;                        // above muStatic tN
        sd->update(s0, in, r);
        unitTest::checkRel("break loose: returns to mu tN", mag(r.tT), Y, 1e-13);
        s0.status = frictionState::SLIP;
        in.gT = 1.2e-6*t1;
        sd->update(s0, in, r);
        unitTest::checkTrue("sliding, above mu tN: keeps sliding", r.state.status == 2);
    }

    Info<< "Open contact" << endl;
    {
        in.gN = -1e-6;
        frictionResult r;
        law->update(old, in, r);
        unitTest::checkAbs("open: tN", r.tN, 0, 0);
        unitTest::checkAbs("open: tT", mag(r.tT), 0, 0);
        unitTest::checkTrue("open status", r.state.status == 0);
        in.gN = 1e-5;
    }

    Info<< "Input checks" << endl;
    {
        FatalIOError.throwExceptions();
        FatalError.throwExceptions();
        bool threw = false;
        try
        {
            frictionTest::law("type coulomb; KN 1e13; KT -1; mu 0.1;");
        }
        catch (const Foam::IOerror& e)
        {
            threw = std::string(e.message()).find("KT") != std::string::npos;
        }
        unitTest::checkTrue("negative KT rejected, message names KT", threw);

        threw = false;
        try
        {
            frictionTest::law("type coulomb; KN 1e13; KT 1e13; mu -0.1;");
        }
        catch (const Foam::IOerror&) { threw = true; }
        unitTest::checkTrue("negative mu rejected", threw);

        threw = false;
        try
        {
            frictionTest::law("type coulombe; KN 1e13; KT 1e13; mu 0.1;");
        }
        catch (const Foam::IOerror&) { threw = true; }
        unitTest::checkTrue("unknown type rejected", threw);
    }

    Info<< "Iteration-limit hits: " << frictionLaw::nIterationLimitHits()
        << endl;
    unitTest::checkTrue("no iteration-limit hits", frictionLaw::nIterationLimitHits() == 0);

    return unitTest::exitCode();
}

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Curnier's law (doc/theory.md [F9], [F10], [F25], [F26]):
      - each criterion's yield surface: after a return the traction lies on
        the surface (coulomb with adhesion, anisotropicCoulomb along e1, e2
        and 45 degrees, paraboloid, power n = 3), and a trial inside sticks;
      - non-associated slip ([F26]): sliding under compression leaves tN and
        the normal slip unchanged and the slip increment is tangent;
      - tear: after forward slip s, reverse slip starts at Y - QT s and
        forward at Y + QT s (Bauschinger-like);
      - wear: the threshold falls as C + f tN - Q Dc;
      - consistent tangent vs finite differences for every criterion.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "curnier.H"

using namespace Foam;

static const std::string pen = "type curnier; KN 1e12; KT 1e12; ";

// Traction after a slip gT along direction d from a virgin state (trial
// traction KT gT a few times the threshold: the return computes F as a
// difference, so its relative round-off grows like |trial|/Y)
static frictionResult slideAlong
(
    const frictionLaw& law,
    const vector& d,
    const scalar gN,
    const scalar gT = 1e-5
)
{
    frictionState old = law.initialState();
    frictionInput in;
    in.gN = gN;
    in.gT = gT*d;
    in.n = vector(0, 0, 1);
    in.dt = 1;
    frictionResult r;
    law.update(old, in, r);
    return r;
}


int main()
{
    FatalIOError.throwExceptions();
    const scalar gN = 1e-6, tN = 1e6;           // KN gN
    const vector ex(1, 0, 0), ey(0, 1, 0);
    const vector e45 = (ex + ey)/std::sqrt(2.0);

    Info<< "Yield surfaces" << endl;
    {
        autoPtr<frictionLaw> law =
            frictionTest::law(pen + "criterion coulomb; f 0.3; C 2e4;");
        frictionResult r = slideAlong(*law, e45, gN);
        unitTest::checkRel("coulomb: |F| = C + f tN", mag(r.tT), 2e4 + 0.3*tN, 1e-12);
        frictionState old = law->initialState();
        frictionInput in; in.gN = gN; in.gT = 1e-7*ex; in.n = vector(0, 0, 1);
        law->update(old, in, r);
        unitTest::checkTrue("coulomb: inside sticks", r.state.status == 1);
    }
    {
        autoPtr<frictionLaw> law = frictionTest::law
        (
            pen + "criterion anisotropicCoulomb; f 0.3; a 1.2; b 0.5;"
            " direction1 (1 0 0);"
        );
        const scalar Y = 0.3*tN;
        frictionResult r = slideAlong(*law, ex, gN);
        unitTest::checkRel("anisotropic: along e1 |F| = a Y", mag(r.tT), 1.2*Y, 1e-12);
        r = slideAlong(*law, ey, gN);
        unitTest::checkRel("anisotropic: along e2 |F| = b Y", mag(r.tT), 0.5*Y, 1e-12);
        r = slideAlong(*law, e45, gN);
        const scalar F1 = r.tT.x(), F2 = r.tT.y();
        unitTest::checkRel
        (
            "anisotropic: 45 deg on the ellipse",
            std::sqrt(sqr(F1/1.2) + sqr(F2/0.5)), Y, 1e-12
        );
        unitTest::checkRel("anisotropic: slip along F (radial)", F1/F2, 1, 1e-12);
    }
    {
        autoPtr<frictionLaw> law =
            frictionTest::law(pen + "criterion paraboloid;");
        frictionResult r = slideAlong(*law, e45, gN, 1e-8);
        unitTest::checkRel("paraboloid: |F|^2 = p_ref tN", sqr(mag(r.tT)), tN, 1e-12);
    }
    {
        autoPtr<frictionLaw> law = frictionTest::law
        (
            pen + "criterion power; f 0.5; n 3; referencePressure 1e3;"
        );
        frictionResult r = slideAlong(*law, ex, gN, 1e-7);
        unitTest::checkRel
        (
            "power n = 3: (|F|/p_ref)^3 = f tN/p_ref",
            std::pow(mag(r.tT)/1e3, 3), 0.5*tN/1e3, 1e-12
        );
    }

    Info<< "Non-associated slip ([F26])" << endl;
    {
        autoPtr<frictionLaw> law =
            frictionTest::law(pen + "criterion coulomb; f 0.3;");
        const vector n(0.36, 0.48, 0.8);
        vector t1(0.8, -0.6, 0); t1 -= (t1 & n)*n; t1 /= mag(t1);
        frictionState old = law->initialState();
        frictionInput in; in.gN = gN; in.n = n; in.dt = 1;
        scalar maxNormal = 0, maxTN = 0, maxDSN = 0;
        for (label i = 1; i <= 50; ++i)
        {
            in.gT = 2e-6*i*t1;
            frictionResult r;
            law->update(old, in, r);
            maxNormal = max(maxNormal, mag((r.state.plasticSlip - old.plasticSlip) & n));
            maxTN = max(maxTN, mag(r.tN - tN));
            maxDSN = max(maxDSN, mag(law->stateLayout().value(r.state, "normalSlip")));
            old = r.state;
        }
        unitTest::checkTrue("sliding", old.status == 2);
        unitTest::checkAbs("slip increment normal component", maxNormal, 0, 1e-20);
        unitTest::checkAbs("normal slip DS_N stays 0 (no lift-off)", maxDSN, 0, 0);
        unitTest::checkAbs("tN = KN gN throughout", maxTN, 0, 1e-8);
    }

    Info<< "Tear: Bauschinger-like reverse threshold" << endl;
    {
        const scalar QT = 1e10, Y = 0.3*tN;
        autoPtr<frictionLaw> law = frictionTest::law
        (
            pen + "criterion coulomb; f 0.3; QT 1e10;"
        );
        frictionState old = law->initialState();
        frictionInput in; in.gN = gN; in.n = vector(0, 0, 1); in.dt = 1;
        frictionResult r;
        // forward to 5e-6 total slip, in small steps
        scalar g = 0, forwardF = 0;
        for (label i = 0; i < 100; ++i)
        {
            g += 5e-8; in.gT = g*ex; law->update(old, in, r); old = r.state;
            forwardF = r.tT.x();
        }
        const scalar sp =
            law->stateLayout().vectorValue(old, "tearSlip").x();
        unitTest::checkRel("forward threshold Y + QT s", forwardF, Y + QT*sp, 1e-10);
        // reverse until slip restarts
        scalar reverseF = 0;
        for (label i = 0; i < 10000; ++i)
        {
            g -= 1e-9; in.gT = g*ex;
            frictionState prev = old;
            law->update(prev, in, r);
            if (r.state.status == 2) { reverseF = -r.tT.x(); break; }
            old = r.state;
        }
        unitTest::checkRel("reverse threshold Y - QT s", reverseF, Y - QT*sp, 2e-3);
        unitTest::checkTrue("reverse threshold below forward one", reverseF < Y);
    }

    Info<< "Wear: threshold falls with cumulated slip" << endl;
    {
        const scalar Q = 1e9;
        autoPtr<frictionLaw> law = frictionTest::law
        (
            pen + "criterion coulomb; f 0.3; Q 1e9;"
        );
        frictionState old = law->initialState();
        frictionInput in; in.gN = gN; in.n = vector(0, 0, 1); in.dt = 1;
        frictionResult r;
        scalar err = 0, first = 0, last = 0;
        for (label i = 1; i <= 100; ++i)
        {
            in.gT = 1e-6*i*ex; law->update(old, in, r); old = r.state;
            if (r.state.status == 2)
            {
                err = max(err, mag(r.tT.x() - (0.3*tN - Q*old.cumulatedSlip))/(0.3*tN));
                if (first == 0) first = r.tT.x();
                last = r.tT.x();
            }
        }
        unitTest::checkBelow("|F| = f tN - Q Dc (rel)", err, 1e-12);
        unitTest::checkTrue("threshold decreased", last < 0.8*first);
    }

    Info<< "Consistent tangent vs FD" << endl;
    {
        const std::string crits[4] =
        {
            "criterion coulomb; f 0.3; C 1e4; QT 1e10; Q 1e9;",
            "criterion anisotropicCoulomb; f 0.3; a 1.2; b 0.5;"
            " direction1 (1 1 0); QT 1e10; Q 1e9;",
            "criterion paraboloid; QT 1e10; Q 1e9;",
            "criterion power; f 0.5; n 3; referencePressure 1e3; Q 1e9;"
        };
        for (const std::string& c : crits)
        {
            autoPtr<frictionLaw> law = frictionTest::law(pen + c);
            const vector n(0.36, 0.48, 0.8);
            vector t1(0.8, -0.6, 0); t1 -= (t1 & n)*n; t1 /= mag(t1);
            const vector t2 = n ^ t1;
            frictionState old = law->initialState();
            old.plasticSlip = 1e-6*t1;
            law->stateLayout().setVectorValue(old, "tearSlip", 0.5e-6*t1);
            old.cumulatedSlip = 2e-6;
            frictionInput in; in.gN = gN; in.n = n; in.dt = 1;
            in.gT = old.plasticSlip + 0.5e-6*t1 + 0.4e-6*t2;
            frictionResult r;
            law->update(old, in, r);
            const word name(c.substr(10, c.find(';') - 10));
            unitTest::checkTrue(name + ": sliding", r.state.status == 2);
            unitTest::checkBelow
            (
                name + ": tangent vs FD",
                frictionTest::tangentError(*law, old, in, 1e-5), 1e-6
            );
        }
    }

    Info<< "Input checks" << endl;
    {
        bool threw = false;
        try { frictionTest::law(pen + "criterion power; f 0.5; n -1;"); }
        catch (const Foam::IOerror&) { threw = true; }
        unitTest::checkTrue("n <= 0 rejected", threw);
        threw = false;
        try { frictionTest::law(pen + "criterion cone; f 0.5;"); }
        catch (const Foam::IOerror&) { threw = true; }
        unitTest::checkTrue("unknown criterion rejected", threw);
    }

    return unitTest::exitCode();
}

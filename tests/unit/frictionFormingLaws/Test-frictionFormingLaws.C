/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The forming laws point-wise (doc/theory.md section 8.10, [F35]-[F39]):
    shearFactor slides at exactly m k for any pressure; the general
    friction model is Coulomb with mu0 = f/h(f) as p/k -> 0 (h(0) = 2 + pi,
    the flat punch), tends to f k as p/k grows, is C1 at its transition;
    cappedCoulomb switches where mu tN = m k; tabulated interpolates
    linearly in p and v and clamps outside; every law's consistent tangent
    against central finite differences (1e-6 relative, [F7]); the input
    checks (m outside [0, 1], a table not increasing in p or v, a law that
    needs k without it).

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "generalFriction.H"
#include "tabulated.H"
#include "mathematicalConstants.H"
#include "OFstream.H"
#include "OSspecific.H"

using namespace Foam;

namespace
{

const scalar KN = 1e13;

//- A point pressed to tN, slid along t1 far enough to slide (or by gT)
frictionInput pressed(const scalar tN, const scalar k, const vector& gT)
{
    frictionInput in;
    in.n = vector(0, 0, 1);
    in.gN = tN/KN;
    in.gT = gT;
    in.dt = 1;
    in.shearYield = k;
    return in;
}

bool throwsIO(const std::string& d, const std::string& word)
{
    try
    {
        frictionTest::law(d);
    }
    catch (const Foam::IOerror& e)
    {
        return std::string(e.message()).find(word) != std::string::npos;
    }
    return false;
}

} // End namespace


int main()
{
    FatalIOError.throwExceptions();
    FatalError.throwExceptions();

    const scalar k = 2e8/std::sqrt(3.0);             // sigma_y = 200 MPa
    const vector t1(1, 0, 0);
    const vector far(1e-4, 0, 0);                     // trial 1e9 Pa

    Info<< "shearFactor: slides at m k for any pressure [F36]" << endl;
    {
        autoPtr<frictionLaw> law =
            frictionTest::law("type shearFactor; KN 1e13; KT 1e13; m 0.3;");
        const frictionState old = law->initialState();
        for (const scalar tN : {1e4, 1e6, 1e8, 1e9})
        {
            frictionResult r;
            law->update(old, pressed(tN, k, far), r);
            unitTest::checkRel
            (
                "tN " + std::to_string(tN) + ": |tT| = m k",
                mag(r.tT), 0.3*k, 1e-13
            );
            unitTest::checkTrue("sliding", r.state.status == 2);
            unitTest::checkBelow
            (
                "slip tangent vs FD",
                frictionTest::tangentError(*law, old, pressed(tN, k, far)),
                1e-6
            );
        }
        frictionResult r;
        const frictionInput in = pressed(1e8, k, 2e-6*t1);   // 2e7 < m k
        law->update(old, in, r);
        unitTest::checkTrue("below m k: stick", r.state.status == 1);
        unitTest::checkRel("stick: tT = KT gT", mag(r.tT), 2e7, 1e-13);
        unitTest::checkBelow
        (
            "stick tangent vs FD",
            frictionTest::tangentError(*law, old, in), 1e-6
        );
        unitTest::checkRel
        (
            "k shown in the state", r.state.scalars[0], k, 1e-15
        );
        law->update(old, pressed(1e8, 2*k, far), r);
        unitTest::checkRel("twice k: twice the shear", mag(r.tT), 0.6*k, 1e-13);
    }

    Info<< "generalFriction: Wanheim-Bay [F38]" << endl;
    {
        const scalar pi = constant::mathematical::pi;
        unitTest::checkRel
        (
            "h(0) = 2 + pi (flat punch)",
            frictionLaws::generalFriction::asperityPressureRatio(0),
            2 + pi, 1e-15
        );
        unitTest::checkRel
        (
            "h(1) = 1 + pi/2 (mu0 = 0.38898 for f = 1)",
            frictionLaws::generalFriction::asperityPressureRatio(1),
            1 + pi/2, 1e-15
        );
        const scalar h = 1 + pi/2 + std::acos(0.5) + std::sqrt(0.75);
        unitTest::checkRel
        (
            "f = 0.5: mu0 = 0.5/h = 0.111507",
            0.5/h, 0.111507, 1e-5
        );

        autoPtr<frictionLaw> law = frictionTest::law
        (
            "type generalFriction; KN 1e13; KT 1e13; f 0.5;"
            " transitionRealArea 0.5;"
        );
        const auto& gf =
            refCast<const frictionLaws::generalFriction>(law());
        const frictionState old = law->initialState();
        frictionResult r;

        law->update(old, pressed(1e-3*k, k, far), r);
        unitTest::checkRel
        (
            "p/k = 1e-3: tau = mu0 p", mag(r.tT), 0.5/h*1e-3*k, 1e-10
        );
        law->update(old, pressed(60*k, k, far), r);
        unitTest::checkRel("p/k = 60: tau -> f k", mag(r.tT), 0.5*k, 1e-10);
        law->update(old, pressed(10*k, k, far), r);
        unitTest::checkRel
        (
            "p/k = 10: alpha = 1 - 0.5 exp(-(10 - 0.5 h)/(0.5 h))",
            mag(r.tT), 0.5*k*(1 - 0.5*std::exp(-(10 - 0.5*h)/(0.5*h))), 1e-13
        );
        unitTest::checkTrue
        (
            "p/k = 10: tau below Coulomb mu0 p and below f k",
            mag(r.tT) < 0.5/h*10*k && mag(r.tT) < 0.5*k
        );

        // C1 at the transition (p/k)T = alphaT h
        const scalar pkT = 0.5*h;
        scalar dm, dp;
        const scalar am = gf.realAreaRatio(pkT*(1 - 1e-12), dm);
        const scalar ap = gf.realAreaRatio(pkT*(1 + 1e-12), dp);
        unitTest::checkRel("transition: alpha continuous", ap, am, 1e-11);
        unitTest::checkRel("transition: alpha = alphaT", am, 0.5, 1e-11);
        unitTest::checkRel("transition: slope continuous", dp, dm, 1e-11);

        for (const scalar pk : {0.5, 2.0, 4.0, 20.0})
        {
            unitTest::checkBelow
            (
                "p/k " + std::to_string(pk) + ": slip tangent vs FD",
                frictionTest::tangentError
                (
                    *law, old, pressed(pk*k, k, far)
                ),
                1e-6
            );
        }
    }

    Info<< "cappedCoulomb: min(mu tN, m k) [F37]" << endl;
    {
        autoPtr<frictionLaw> law = frictionTest::law
        (
            "type cappedCoulomb; KN 1e13; KT 1e13; mu 0.2; m 0.5;"
        );
        const frictionState old = law->initialState();
        const scalar pSwitch = 0.5*k/0.2;
        frictionResult r;
        law->update(old, pressed(0.5*pSwitch, k, far), r);
        unitTest::checkRel("below the switch: mu tN", mag(r.tT), 0.1*pSwitch, 1e-13);
        unitTest::checkRel("below: dtT/dgN = mu KN", mag(r.dtTdgN), 0.2*KN, 1e-12);
        law->update(old, pressed(2*pSwitch, k, far), r);
        unitTest::checkRel("above the switch: m k", mag(r.tT), 0.5*k, 1e-13);
        unitTest::checkAbs("above: dtT/dgN = 0", mag(r.dtTdgN), 0, 0);
        frictionResult rm, rp;
        law->update(old, pressed(pSwitch*(1 - 1e-9), k, far), rm);
        law->update(old, pressed(pSwitch*(1 + 1e-9), k, far), rp);
        unitTest::checkRel("switch at mu tN = m k (continuous)", mag(rp.tT), mag(rm.tT), 1e-8);
        unitTest::checkRel("at the switch both are m k", mag(rm.tT), 0.5*k, 1e-8);
        for (const scalar f : {0.5, 2.0})
        {
            unitTest::checkBelow
            (
                "p/p* " + std::to_string(f) + ": slip tangent vs FD",
                frictionTest::tangentError
                (
                    *law, old, pressed(f*pSwitch, k, far)
                ),
                1e-6
            );
        }
    }

    Info<< "tabulated: mu(p, v), m(p, v), clamped [F39]" << endl;
    {
        const std::string table =
            " table ((0 ((0 0.12) (1e-3 0.10))) (2e8 ((0 0.10) (1e-3 0.06))));";
        autoPtr<frictionLaw> law = frictionTest::law
        (
            "type tabulated; KN 1e13; KT 1e13; quantity mu;" + table
        );
        const auto& tab = refCast<const frictionLaws::tabulated>(law());
        unitTest::checkTrue("a table in v is rate dependent", law->rateDependent());
        unitTest::checkTrue("mu table: no k needed", !law->needsShearYield());
        scalar dp, dv;
        unitTest::checkRel
        (
            "bilinear: mu(1e8, 5e-4) = (0.11 + 0.08)/2",
            tab.value(1e8, 5e-4, true, dp, dv), 0.095, 1e-14
        );
        unitTest::checkRel("slope in p", dp, (0.08 - 0.11)/2e8, 1e-12);
        unitTest::checkRel("slope in v", dv, 0.5*(-20 - 40), 1e-12);
        unitTest::checkRel
        (
            "clamped above p and v: the corner 0.06",
            tab.value(3e8, 1, true, dp, dv), 0.06, 1e-15
        );
        unitTest::checkAbs("clamped: no slope", mag(dp) + mag(dv), 0, 0);

        // sliding: |tT| = mu(tN, v) tN at the step's rate
        const frictionState old = law->initialState();
        frictionInput in = pressed(1e8, -1, vector(1.2e-5, 3e-6, 0));
        in.dt = 0.02;
        frictionResult r;
        law->update(old, in, r);
        const scalar v = r.state.slipRate;
        unitTest::checkTrue("slides at a rate inside the table", v > 0 && v < 1e-3);
        unitTest::checkRel
        (
            "sliding: |tT| = mu(tN, v) tN",
            mag(r.tT), tab.value(1e8, v, true, dp, dv)*1e8, 1e-12
        );
        unitTest::checkBelow
        (
            "rate-dependent slip tangent vs FD",
            frictionTest::tangentError(*law, old, in), 1e-6
        );

        autoPtr<frictionLaw> lm = frictionTest::law
        (
            "type tabulated; KN 1e13; KT 1e13; quantity m;"
            " table ((0 ((0 0.3))) (1e9 ((0 0.5))));"
        );
        unitTest::checkTrue("m table needs k", lm->needsShearYield());
        lm->update(old, pressed(5e8, k, far), r);
        unitTest::checkRel("m(5e8) k = 0.4 k", mag(r.tT), 0.4*k, 1e-13);
        unitTest::checkBelow
        (
            "m table: slip tangent vs FD",
            frictionTest::tangentError(*lm, old, pressed(5e8, k, far)), 1e-6
        );

        // OpenFOAM's reader from a file
        {
            OFstream os("frictionTable.tmp");
            os  << "((0 ((0 0.12) (1e-3 0.10))) (2e8 ((0 0.10) (1e-3 0.06))))"
                << endl;
        }
        autoPtr<frictionLaw> lf = frictionTest::law
        (
            "type tabulated; KN 1e13; KT 1e13; quantity mu;"
            " file \"frictionTable.tmp\";"
        );
        unitTest::checkRel
        (
            "file: the same table",
            refCast<const frictionLaws::tabulated>(lf()).value
            (
                1e8, 5e-4, true, dp, dv
            ),
            0.095, 1e-14
        );
        Foam::rm(fileName("frictionTable.tmp"));
    }

    Info<< "tabulated: temperature [F39]" << endl;
    {
        const std::string tables =
            " temperatures (293 1173);"
            " tables ( ((0 ((0 0.1))) (1e9 ((0 0.3))))"
            "          ((0 ((0 0.2))) (1e9 ((0 0.6)))) );";
        autoPtr<frictionLaw> hot = frictionTest::law
        (
            "type tabulated; KN 1e13; KT 1e13; quantity mu;"
            " temperature 953;" + tables
        );
        const auto& t = refCast<const frictionLaws::tabulated>(hot());
        scalar dp, dv;
        // 953 K is 3/4 of the way: mu(5e8) = 0.25 (1/4) + 0.75 (3/4) 0.4
        unitTest::checkRel
        (
            "953 K, 5e8 Pa: 0.25*0.2 + 0.75*0.4",
            t.value(5e8, 0, true, dp, dv), 0.35, 1e-14
        );
        unitTest::checkRel
        (
            "slope in p between the temperatures",
            dp, 0.25*0.2/1e9 + 0.75*0.4/1e9, 1e-12
        );
        frictionResult r;
        frictionInput in = pressed(5e8, -1, far);
        hot->update(hot->initialState(), in, r);
        unitTest::checkRel("sliding at 0.35 tN", mag(r.tT), 0.35*5e8, 1e-13);
        unitTest::checkBelow
        (
            "temperature table: slip tangent vs FD",
            frictionTest::tangentError(*hot, hot->initialState(), in), 1e-6
        );
        autoPtr<frictionLaw> cold = frictionTest::law
        (
            "type tabulated; KN 1e13; KT 1e13; quantity mu;"
            " temperature 200;" + tables
        );
        unitTest::checkRel
        (
            "below the tables' temperatures: the coldest table (clamped)",
            refCast<const frictionLaws::tabulated>(cold()).value
            (
                5e8, 0, true, dp, dv
            ),
            0.2, 1e-14
        );
        unitTest::checkTrue
        (
            "temperatures not increasing rejected, naming 'temperatures'",
            throwsIO
            (
                "type tabulated; KN 1; KT 1; quantity mu; temperature 300;"
                " temperatures (400 300);"
                " tables ( ((0 ((0 0.1)))) ((0 ((0 0.1)))) );",
                "'temperatures'"
            )
        );
        unitTest::checkTrue
        (
            "one table too few rejected, naming 'tables'",
            throwsIO
            (
                "type tabulated; KN 1; KT 1; quantity mu; temperature 300;"
                " temperatures (300 400); tables ( ((0 ((0 0.1)))) );",
                "'tables'"
            )
        );
    }

    Info<< "Input checks" << endl;
    {
        unitTest::checkTrue
        (
            "shearFactor m = 1.2 rejected, naming m",
            throwsIO("type shearFactor; KN 1 ; KT 1; m 1.2;", "'m'")
        );
        unitTest::checkTrue
        (
            "shearFactor m = -0.1 rejected",
            throwsIO("type shearFactor; KN 1 ; KT 1; m -0.1;", "'m'")
        );
        unitTest::checkTrue
        (
            "cappedCoulomb m = 2 rejected",
            throwsIO("type cappedCoulomb; KN 1; KT 1; mu 0.1; m 2;", "'m'")
        );
        unitTest::checkTrue
        (
            "generalFriction f = 1.5 rejected",
            throwsIO("type generalFriction; KN 1; KT 1; f 1.5;", "'f'")
        );
        unitTest::checkTrue
        (
            "table decreasing in p rejected, naming 'table'",
            throwsIO
            (
                "type tabulated; KN 1; KT 1; quantity mu;"
                " table ((1e8 ((0 0.1))) (0 ((0 0.1))));",
                "'table'"
            )
        );
        unitTest::checkTrue
        (
            "table not increasing in v rejected, naming 'table'",
            throwsIO
            (
                "type tabulated; KN 1; KT 1; quantity mu;"
                " table ((0 ((1e-3 0.1) (1e-3 0.2))));",
                "'table'"
            )
        );
        unitTest::checkTrue
        (
            "m table above 1 rejected",
            throwsIO
            (
                "type tabulated; KN 1; KT 1; quantity m;"
                " table ((0 ((0 1.1))));",
                "'table'"
            )
        );

        autoPtr<frictionLaw> law =
            frictionTest::law("type shearFactor; KN 1e13; KT 1e13; m 0.3;");
        bool threw = false;
        try
        {
            frictionResult r;
            law->update(law->initialState(), pressed(1e8, -1, far), r);
        }
        catch (const Foam::error& e)
        {
            threw = std::string(e.message()).find("shear flow stress")
                != std::string::npos;
        }
        unitTest::checkTrue("shearFactor without k stops, saying so", threw);
    }

    unitTest::checkTrue
    (
        "no iteration-limit hits", frictionLaw::nIterationLimitHits() == 0
    );

    return unitTest::exitCode();
}

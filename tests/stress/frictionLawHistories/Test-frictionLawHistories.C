/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Stress test of the point-wise friction laws: every law is driven by
    frictionPointDriver (constant pressure p = 1e7 Pa, slip along x) through
    one history of extreme slip-rate changes, each taken in a single step:

        A  run-in   v = 1e-9 m/s     400 steps of 1000 s  (40 L of slip)
        B  jump     v = 1e-3 m/s     400 steps of 1e-3 s  (x 1e6 in a step)
        C  reversal v = -1e-3 m/s    400 steps of 1e-3 s
        D  hold     v = 0            one step of 1e6 s
        E  restart  v = 1e-3 m/s     400 steps of 1e-3 s  (from rest)
        F  drop     v = 1e-9 m/s     400 steps of 1000 s  (x 1e-6 in a step)

    Expected of every law at every step: finite tractions, state and
    consistent tangent, tN = p, and no return-mapping solve at its iteration
    limit. At the end of each sliding segment (40 memory lengths at
    constant rate) the steady friction of the law at that rate, signed
    (tolerance 1e-6 p):
        coulomb [F8]: mu p;  curnier [F9]: C + f p;
        rateState, ageing and slip ([F28] with the creep term of [F11]):
            mu* + a ln(v_eff/V*) + b ln(V* / v);
        relaxation ([F28]): mu* + a ln(v_eff/V*) + b gamma ln(V* / v);
        regularised ([F12]): a asinh(v/(2V*) exp((mu* + b ln(V* / v))/a));
        lubricated ([F29], [F17]): (1 - alpha) f_ss mu0(v) p + alpha eta_b v
            with f_ss = 1 + M/2 ln(1 + V_s^2/v^2);
        forming laws at the body's k = 3 p ([F35]): shearFactor [F36] m k;
            cappedCoulomb [F37] min(mu p, m k); generalFriction [F38]
            f/h(f) p (p/k below the transition); tabulated [F39] mu(|v|).
    The lubricated law is exact for piecewise-constant rates ([F13], theory
    8.7), so on its sliding steps after the jump and after the hold it must
    follow, to 1e-9, the contact-age solution of doc/theory.md [F23]
    generalised to any start: theta(d) = theta_0 e^(-d/D0) + D0/v
    (1 - e^(-d/D0)), f = 1 + M ln(theta v_eff/D0). In the hold the
    rate-independent and lubricated points stick with their traction
    unchanged (the viscous part drops out) and the contact age grows by the
    hold time exactly ([F17]); rate-and-state points relax (the traction may
    only fall). After the hold, laws with ageing (coulomb with mu_s > mu,
    rateState ageing, lubricated) break loose above their steady friction.

    Lubrication limits: zero film thickness (Stribeck D = 0: alpha = 0 at
    every rate), alpha exactly 0 and 1 (alpha = 1: tT = eta_b v at every
    step, the hold included), mu = 0 (coulomb and mu0 = 0: tT = 0, resp.
    alpha eta_b v). Rate sensitivity [F21]: the pear-tube set must be
    flagged (d tT/d ln v < 0; without film its minimum is
    tN (M mu_d - (mu_s - mu_d) e^-(1+M))), M = 0.5 without film must not.

    Prints the law x history matrix (ok, FAIL, or the fatal message if a law
    refused its input).

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "frictionPointDriver.H"
#include "mathematicalConstants.H"
#include "lubricatedRateState.H"
#include <functional>
#include <vector>

using namespace Foam;

namespace
{

const scalar p = 1e7;

//- Shear flow stress of the body for the forming laws [F35] (p/k = 1/3);
//  the other laws ignore it
const scalar kBody = 3e7;

struct segment
{
    const char* name;
    scalar v;
    label nSteps;
    scalar dt;
};

const std::vector<segment> history =
{
    {"runIn",    1e-9, 400, 1e3},
    {"jump1e6",  1e-3, 400, 1e-3},
    {"reversal", -1e-3, 400, 1e-3},
    {"hold1e6s", 0, 1, 1e6},
    {"restart",  1e-3, 800, 1e-3},
    {"drop1e-6", 1e-9, 400, 1e3}
};

enum { RUNIN, JUMP, REVERSAL, HOLD, RESTART, DROP };

//- Steady friction traction / p at slip rate |v| > 0 (unsigned)
typedef std::function<scalar(scalar)> steadyFn;

//- Lubricated parameters, for the exact contact-age check
struct lubricated
{
    scalar M, D0, Vs, etaB;
};

struct lawCase
{
    std::string name;
    std::string dict;
    steadyFn steady;
    //- Breaks loose above its steady friction after the hold
    bool ages;
    //- Sticks in a hold with its traction unchanged
    bool holdSticks;
    //- Lubricated law: exact contact-age checks
    bool lubricatedLaw;
    lubricated lub;
};

struct row
{
    frictionPointDriver::sample s;
    frictionResult r;
};

bool finite(const frictionResult& r)
{
    bool ok = std::isfinite(r.tN) && std::isfinite(r.dtNdgN);
    for (direction i = 0; i < 3; ++i)
    {
        ok = ok && std::isfinite(r.tT[i]) && std::isfinite(r.dtTdgN[i])
            && std::isfinite(r.state.totalSlip[i])
            && std::isfinite(r.state.plasticSlip[i]);
    }
    for (direction i = 0; i < 9; ++i)
    {
        ok = ok && std::isfinite(r.dtTdgT[i]);
    }
    for (label i = 0; i < frictionState::nScalars; ++i)
    {
        ok = ok && std::isfinite(r.state.scalars[i]);
    }
    for (label i = 0; i < frictionState::nVectors; ++i)
    {
        ok = ok && std::isfinite(mag(r.state.vectors[i]));
    }
    return ok
        && std::isfinite(r.state.slipRate)
        && std::isfinite(r.state.cumulatedSlip);
}


//- One law through the history; fills the outcome per segment ("ok",
//  "FAIL") and returns false if the law refused its input
bool drive
(
    const lawCase& c,
    std::vector<std::string>& outcome,
    std::string& message
)
{
    outcome.assign(history.size(), "ok");
    autoPtr<frictionLaw> law;
    try
    {
        law = frictionTest::law(c.dict);
    }
    catch (const Foam::error& e)
    {
        message = e.message();
        outcome.assign(history.size(), "refused");
        return false;
    }

    const long hits0 = frictionLaw::nIterationLimitHits();
    const frictionStateLayout& layout = law->stateLayout();
    frictionPointDriver drv(*law, p);
    drv.setShearYield(kBody);
    std::vector<std::vector<row>> rows(history.size());
    for (size_t si = 0; si < history.size(); ++si)
    {
        const segment& g = history[si];
        for (label i = 0; i < g.nSteps; ++i)
        {
            row rw;
            rw.s = drv.step(drv.slip() + g.v*g.dt, g.dt);
            rw.r = drv.last();
            rows[si].push_back(rw);
        }
    }

    // Failed items are printed as details; each law reports its summary
    // checks below (the steady error, the exact lubricated error, and
    // everything else as one boolean)
    bool allOk = true;
    auto fail = [&](const size_t si, const std::string& what, bool ok)
    {
        if (!ok)
        {
            Info<< "        " << c.name.c_str() << ", " << history[si].name
                << ": NOT " << what.c_str() << endl;
            outcome[si] = "FAIL";
            allOk = false;
        }
    };

    scalar steadyErr = 0, lubErr = 0;
    label nLubSlide = 0;
    for (size_t si = 0; si < history.size(); ++si)
    {
        const segment& g = history[si];
        const std::vector<row>& rs = rows[si];

        // Finite everything, tN = p
        bool fin = true;
        scalar tNerr = 0;
        for (const row& rw : rs)
        {
            fin = fin && finite(rw.r);
            tNerr = max(tNerr, mag(rw.r.tN - p)/p);
        }
        fail(si, "finite tractions, state and tangent", fin);
        fail(si, "tN = p", tNerr < 1e-12);
        if (!fin)
        {
            steadyErr = GREAT;
            continue;
        }

        const scalar tEnd = rs.back().r.tT.x()/p;
        if (g.v != 0)
        {
            // Steady sliding at the end of the segment (1e-6)
            const scalar expected = sign(g.v)*c.steady(mag(g.v));
            steadyErr = max(steadyErr, mag(tEnd - expected));
            fail
            (
                si, "steady at the end: tT/p " + std::to_string(tEnd)
              + ", expected " + std::to_string(expected),
                mag(tEnd - expected) <= 1e-6
            );
        }
        else
        {
            // Hold: no law may raise the traction; sticking laws keep it
            const scalar before = rows[si - 1].back().r.tT.x();
            const scalar after = rs.back().r.tT.x();
            if (c.holdSticks)
            {
                // lubricated: the viscous part alpha eta_b v drops out and
                // the frictional part F_T is weighted by alpha at v = 0
                scalar expected = before;
                if (c.lubricatedLaw)
                {
                    const row& last = rows[si - 1].back();
                    const scalar alpha =
                        layout.value(last.r.state, "lubricationWeight");
                    const scalar alphaHold =
                        layout.value(rs.back().r.state, "lubricationWeight");
                    const scalar FT =
                        alpha < 1
                      ? (before - alpha*c.lub.etaB*last.s.slipRate)
                       /(1 - alpha)
                      : 0;
                    expected = (1 - alphaHold)*FT;
                }
                // tolerance: round-off of KT (gT - gTp), KT ulp(gT) ~ 1e-5 Pa
                fail
                (
                    si, "sticking with its traction (" + std::to_string(after)
                  + " Pa, expected " + std::to_string(expected) + ")",
                    rs.back().r.state.status == frictionState::STICK
                 && mag(after - expected) <= 1e-9*p
                );
            }
            else
            {
                fail
                (
                    si, "relaxing (the traction may only fall)",
                    mag(after) <= mag(before)*(1 + 1e-12)
                 && after*before >= 0
                );
            }
        }

        // Lubricated: exact contact age in the hold, the jump and the
        // restart, and exact traction on the sliding steps: each step from
        // the previous one at its sliding rate v_p (ageing, mu0) and the
        // prescribed total rate v (film) [F16]
        if (c.lubricatedLaw && (si == JUMP || si == RESTART || si == HOLD))
        {
            const lubricated& L = c.lub;
            scalar thetaPrev =
                layout.value(rows[si - 1].back().r.state, "contactAge");
            auto lawPtr =
                dynamic_cast<const frictionLaws::lubricatedRateState*>
                (law.get());
            label nSlide = 0;
            for (size_t i = 0; i < rs.size(); ++i)
            {
                const scalar v = mag(g.v);
                const scalar vp = rs[i].r.state.slipRate;
                const scalar x = vp*g.dt/L.D0;
                const scalar theta =
                    vp > 0
                  ? thetaPrev*std::exp(-x) - L.D0/vp*std::expm1(-x)
                  : thetaPrev + g.dt;
                thetaPrev = layout.value(rs[i].r.state, "contactAge");
                scalar err = mag(thetaPrev - theta)/theta;
                if (rs[i].r.state.status == frictionState::SLIP)
                {
                    ++nSlide;
                    const scalar f =
                        1 + L.M*std::log(theta*std::hypot(vp, L.Vs)/L.D0);
                    scalar m0, dm0, alpha, da;
                    lawPtr->mu0(vp, m0, dm0);
                    lawPtr->lubrication().alpha(v, alpha, da);
                    const scalar tT =
                        sign(g.v)*((1 - alpha)*max(f, 0)*m0*p
                      + alpha*L.etaB*v);
                    err = max(err, mag(rs[i].r.tT.x() - tT)/p);
                }
                lubErr = max(lubErr, err);
            }
            nLubSlide += nSlide;
            fail
            (
                si, "following the exact contact age and traction",
                lubErr <= 1e-9
            );
            if (si != HOLD)
            {
                fail(si, "sliding", nSlide > 0);
            }
        }

        // Static friction after the hold
        if (si == RESTART && c.ages)
        {
            scalar peak = 0;
            for (const row& rw : rs)
            {
                peak = max(peak, rw.r.tT.x()/p);
            }
            const scalar steady = c.steady(mag(g.v));
            fail
            (
                si, "breaking loose above its steady friction (peak "
              + std::to_string(peak) + ", steady " + std::to_string(steady)
              + ")",
                peak > steady*(1 + 1e-3)
            );
        }
    }

    const long hits = frictionLaw::nIterationLimitHits() - hits0;
    if (hits)
    {
        Info<< "        " << c.name.c_str() << ": " << label(hits)
            << " return-mapping solves at their iteration limit" << endl;
        for (auto& o : outcome) if (o == "ok") o = "FAIL";
        allOk = false;
    }

    unitTest::checkBelow
    (
        c.name + ": max |tT/p - steady value| at the ends of the 5 sliding"
        " segments ([F28], [F12], [F8], [F9], [F17])", steadyErr, 1e-6
    );
    if (c.lubricatedLaw)
    {
        unitTest::checkBelow
        (
            c.name + ": contact age and traction vs the exact theta(d) over"
            " the jump, the hold and the restart ("
          + std::to_string(nLubSlide) + " sliding steps; [F13], [F17])",
            lubErr, 1e-9
        );
    }
    unitTest::checkTrue
    (
        c.name + ": finite, tN = p, hold"
      + std::string(c.ages ? ", static peak after the hold" : "")
      + ", no iteration-limit hit (details above if not)", allOk
    );
    return true;
}

} // End anonymous namespace


int main()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const std::string pen = "KN 1e13; KT 1e15; ";

    // rate-and-state parameters ([F11], [F27])
    const scalar a = 0.01, b = 0.015, muStar = 0.6, VStar = 1e-6, Vc = 1e-12;
    const std::string rs =
        pen + "a 0.01; b 0.015; muStar 0.6; VStar 1e-6; L 1e-5;"
        " creepVelocity 1e-12; ";
    auto rsSteady = [=](scalar v)
    {
        return muStar + 0.5*a*std::log((v*v + Vc*Vc)/(VStar*VStar))
            + b*std::log(VStar/v);
    };
    // paper board, relaxation law [F27]
    const scalar aR = 0.0349, bR = 0.0489, muR = 0.369, gammaR = 0.723;
    auto relaxSteady = [=](scalar v)
    {
        return muR + 0.5*aR*std::log((v*v + Vc*Vc)/(VStar*VStar))
            + bR*gammaR*std::log(VStar/v);
    };
    auto regSteady = [=](scalar v)
    {
        return a*std::asinh
        (
            v/(2*VStar)*std::exp((muStar + b*std::log(VStar/v))/a)
        );
    };

    // lubricated law ([F29]): slidingBlock set, KT stiff
    const lubricated lub{0.1, 1e-6, 1e-9, 3e9};
    auto lubDict = [&](const std::string& mu0, const std::string& lubr)
    {
        return
            "type lubricatedRateState; " + pen + "M 0.1; D0 1e-6;"
            " creepVelocity 1e-9; " + mu0 + " filmViscosity 3e9;"
            " slipRateRange (1e-9 1e-3); lubrication { " + lubr + " }";
    };
    const std::string mu0Std =
        "muStatic 0.12; muDynamic 0.07; criticalVelocity 1e-3;";
    auto lubSteady = [=](scalar muS, scalar muD, std::function<scalar(scalar)>
        alphaOf)
    {
        return [=](scalar v)
        {
            const scalar f = 1 + 0.5*lub.M*std::log1p(sqr(lub.Vs/v));
            const scalar m0 = muD + (muS - muD)*std::exp(-v/1e-3);
            const scalar al = alphaOf(v);
            return (1 - al)*f*m0 + al*lub.etaB*v/p;
        };
    };
    auto stribeckAlpha = [](scalar v)
    {
        const scalar xi = v/1e-3;
        return xi/(1 + xi);
    };
    auto constAlpha = [](scalar al)
    {
        return [=](scalar) { return al; };
    };
    const std::string stribeck =
        "type stribeck; filmThickness 1e-6; referenceFilmThickness 1e-6;"
        " referenceVelocity 1e-3; n 1;";
    const std::string noFilm =
        "type stribeck; filmThickness 0; referenceFilmThickness 1e-6;"
        " referenceVelocity 1e-3; n 1;";

    const std::vector<lawCase> cases =
    {
        {"frictionless", "type frictionless; " + pen,
            [](scalar) { return 0.0; }, false, false, false, lub},
        {"coulomb", "type coulomb; mu 0.3; muStatic 0.4; " + pen,
            [](scalar) { return 0.3; }, false, true, false, lub},
        {"coulomb mu=0", "type coulomb; mu 0; " + pen,
            [](scalar) { return 0.0; }, false, true, false, lub},
        {"curnier C+f tN", "type curnier; criterion coulomb; f 0.3; C 1e5; "
          + pen, [](scalar) { return 0.3 + 1e5/p; }, false, true, false, lub},
        {"rateState ageing", "type rateState; stateLaw ageing; " + rs,
            rsSteady, true, false, false, lub},
        {"rateState slip", "type rateState; stateLaw slip; " + rs,
            rsSteady, false, false, false, lub},
        {"rateState relaxation", "type rateState; stateLaw relaxation; "
          + pen + "a 0.0349; b 0.0489; muStar 0.369; VStar 1e-6;"
            " relaxationTime 2.729; gamma 0.723; creepVelocity 1e-12;",
            relaxSteady, false, false, false, lub},
        {"rateState regularised", "type rateState; form regularised;"
            " stateLaw ageing; " + rs, regSteady, false, false, false, lub},
        {"lubricated stribeck", lubDict(mu0Std, stribeck),
            lubSteady(0.12, 0.07, stribeckAlpha), true, true, true, lub},
        {"lubricated film D=0", lubDict(mu0Std, noFilm),
            lubSteady(0.12, 0.07, constAlpha(0)), true, true, true, lub},
        {"lubricated alpha=0", lubDict(mu0Std, "type constant; alpha 0;"),
            lubSteady(0.12, 0.07, constAlpha(0)), true, true, true, lub},
        {"lubricated alpha=1", lubDict(mu0Std, "type constant; alpha 1;"),
            lubSteady(0.12, 0.07, constAlpha(1)), false, true, true, lub},
        {"lubricated mu0=0",
            lubDict("muStatic 0; muDynamic 0; criticalVelocity 1e-3;",
                "type constant; alpha 0.3;"),
            lubSteady(0, 0, constAlpha(0.3)), false, true, true, lub},
        // forming laws ([F36]-[F39]) at p/k = 1/3
        {"shearFactor m=0.3", "type shearFactor; m 0.3; " + pen,
            [](scalar) { return 0.3*kBody/p; }, false, true, false, lub},
        {"cappedCoulomb capped", "type cappedCoulomb; mu 0.5; m 0.1; " + pen,
            [](scalar) { return 0.1*kBody/p; }, false, true, false, lub},
        {"generalFriction f=0.5", "type generalFriction; f 0.5; " + pen,
            [](scalar)
            {
                return 0.5/(1 + constant::mathematical::piByTwo
                    + std::acos(0.5) + std::sqrt(0.75));
            }, false, true, false, lub},
        {"tabulated mu(v)", "type tabulated; quantity mu;"
            " table ((0 ((1e-9 0.2) (1e-3 0.1)))); " + pen,
            [](scalar v)
            {
                return 0.2 - 0.1*(std::abs(v) - 1e-9)/(1e-3 - 1e-9);
            }, false, true, false, lub}
    };

    std::vector<std::vector<std::string>> matrix;
    std::vector<std::string> messages;
    for (const lawCase& c : cases)
    {
        Info<< nl << "Law " << c.name.c_str() << endl;
        std::vector<std::string> outcome;
        std::string message;
        drive(c, outcome, message);
        matrix.push_back(outcome);
        messages.push_back(message);
        if (!message.empty())
        {
            unitTest::checkTrue(c.name + ": accepted", false);
        }
    }

    // Lubrication limits that the matrix cannot show
    Info<< nl << "Lubrication limits" << endl;
    {
        autoPtr<frictionLaw> law =
            frictionTest::law(lubDict(mu0Std, noFilm));
        frictionPointDriver drv(*law, p);
        scalar alphaMax = 0;
        for (const scalar v : {1e-9, 1e-3, 1.0, 1e3})
        {
            for (label i = 0; i < 5; ++i)
            {
                drv.step(drv.slip() + v*1e-3, 1e-3);
                alphaMax = max
                (
                    alphaMax,
                    law->stateLayout().value(drv.state(), "lubricationWeight")
                );
            }
        }
        unitTest::checkAbs
        (
            "zero film: alpha = 0 at rates 1e-9 to 1e3 m/s ([F19])",
            alphaMax, 0, 0
        );

        autoPtr<frictionLaw> film =
            frictionTest::law(lubDict(mu0Std, "type constant; alpha 1;"));
        frictionPointDriver d1(*film, p);
        scalar err = 0;
        for (const segment& g : history)
        {
            for (label i = 0; i < min(g.nSteps, label(20)); ++i)
            {
                d1.step(d1.slip() + g.v*g.dt, g.dt);
                err = max(err, mag(d1.last().tT.x() - lub.etaB*g.v));
            }
        }
        unitTest::checkBelow
        (
            "alpha = 1: |tT - eta_b v| [Pa] at every step, hold included"
            " (Newtonian film, [F20])", err, 1e-6
        );
    }

    Info<< nl << "Negative rate sensitivity [F21]" << endl;
    {
        // pear-tube set: mu_s 0.15, mu_d 0.1, M 0.1; the warning is printed
        // by the constructor (slipRateRange up to 1 m/s)
        autoPtr<frictionLaw> law = frictionTest::law
        (
            "type lubricatedRateState; " + pen + "M 0.1; D0 1e-6;"
            " creepVelocity 1e-9; muStatic 0.15; muDynamic 0.1;"
            " criticalVelocity 1e-3; filmViscosity 3e9;"
            " lubrication { " + stribeck + " }"
        );
        unitTest::checkTrue
        (
            "pear set: warning issued (d tT/d ln v < 0)",
            law->checkWellPosedness(1e-9, 1, 1e6, 1e9)
        );
        autoPtr<frictionLaw> dry = frictionTest::law
        (
            "type lubricatedRateState; " + pen + "M 0.1; D0 1e-6;"
            " creepVelocity 1e-9; muStatic 0.15; muDynamic 0.1;"
            " criticalVelocity 1e-3; filmViscosity 3e9;"
            " lubrication { type constant; alpha 0; }"
        );
        unitTest::checkRel
        (
            "pear set, alpha = 0: min d tT/d ln v / tN"
            " = M mu_d - (mu_s - mu_d) e^-(1+M)",
            dry->steadySensitivity(1e-9, 1, p, p).minimum/p,
            0.1*0.1 - 0.05*std::exp(-1.1), 1e-3
        );
        // the ill-posed law still runs the whole history
        frictionPointDriver drv(*law, p);
        bool fin = true;
        for (const segment& g : history)
        {
            for (label i = 0; i < g.nSteps; ++i)
            {
                drv.step(drv.slip() + g.v*g.dt, g.dt);
                fin = fin && finite(drv.last());
            }
        }
        unitTest::checkTrue("pear set: finite over the whole history", fin);

        autoPtr<frictionLaw> stable = frictionTest::law
        (
            "type lubricatedRateState; " + pen + "M 0.5; D0 1e-6;"
            " creepVelocity 1e-9; muStatic 0.15; muDynamic 0.1;"
            " criticalVelocity 1e-3; filmViscosity 3e9;"
            " lubrication { type constant; alpha 0; }"
        );
        unitTest::checkTrue
        (
            "M = 0.5, alpha = 0: no warning (d tT/d ln v > 0 on 1e-9 to"
            " 1 m/s, 1 MPa to 1 GPa)",
            !stable->checkWellPosedness(1e-9, 1, 1e6, 1e9)
        );
    }

    // Law x history matrix
    Info<< nl << "Outcome matrix (ok: finite and correct; FAIL; refused:"
        << " the law did not accept its input)" << nl;
    std::string head = "    law                     ";
    for (const segment& g : history)
    {
        std::string n(g.name);
        n.resize(10, ' ');
        head += n;
    }
    Info<< head.c_str() << nl;
    for (size_t i = 0; i < cases.size(); ++i)
    {
        std::string line = "    " + cases[i].name;
        line.resize(28, ' ');
        for (const std::string& o : matrix[i])
        {
            std::string cell(o);
            cell.resize(10, ' ');
            line += cell;
        }
        Info<< line.c_str() << nl;
        if (!messages[i].empty())
        {
            Info<< "        " << messages[i].c_str() << nl;
        }
    }
    Info<< endl;

    return unitTest::exitCode();
}


// ************************************************************************* //

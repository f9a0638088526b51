/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Benchmark of the point-wise friction laws (not a timed test):
    1. cost of one update per face [ns]: a loop over nFaces faces with
       varied slips (about half sticking, half sliding), as a contact
       boundary condition would call it in one Newton iteration; median of
       nRepeat repetitions;
    2. error against a reference solution versus time step, for the
       velocity-step history (soft contact, reference at dt0/256) and the
       spring-slider (ageing law, k = 1.1 k*, reference at dt0/64).
    Prints a table; the run script writes it to
    tests/benchmarks/results/frictionLaws.txt.

\*---------------------------------------------------------------------------*/

#include "frictionLaw.H"
#include "frictionPointDriver.H"
#include "safeguardedNewton.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include <chrono>
#include <algorithm>
#include <vector>
#include <cstdio>

using namespace Foam;

static autoPtr<frictionLaw> makeLaw(const std::string& s)
{
    IStringStream is(s);
    dictionary d(is);
    return frictionLaw::New(d);
}

struct lawCase { const char* name; std::string dict; scalar p; scalar slipScale; scalar dt; };


int main(int argc, char* argv[])
{
    const label nFaces = 100000;
    const label nRepeat = 21;

    const std::string rs =
        "type rateState; KN 1e12; KT 1e13; a 0.01; b 0.015; muStar 0.6;"
        " VStar 1e-6; L 1e-5; ";
    const std::string lub =
        "type lubricatedRateState; KN 1e13; KT 1e13; M 0.1; D0 1e-6;"
        " creepVelocity 1e-9; muStatic 0.15; muDynamic 0.1;"
        " criticalVelocity 1e-3; filmViscosity 3e9; slipRateRange (1e-6 1e-5);"
        " lubrication { type stribeck; filmThickness 1e-6;"
        " referenceFilmThickness 1e-6; referenceVelocity 1e-3; n 1; }";

    // name, dictionary, pressure, slip scale (~ threshold/KT), dt
    const std::vector<lawCase> cases =
    {
        {"frictionless", "type frictionless; KN 1e13;", 1e8, 1e-6, 1e-3},
        {"coulomb", "type coulomb; KN 1e13; KT 1e13; mu 0.1;", 1e8, 1e-6, 1e-3},
        {"curnier coulomb+tear+wear",
         "type curnier; KN 1e13; KT 1e13; criterion coulomb; f 0.1;"
         " QT 1e11; Q 1e11;", 1e8, 1e-6, 1e-3},
        {"curnier paraboloid",
         "type curnier; KN 1e13; KT 1e13; criterion paraboloid;"
         " referencePressure 1e6;", 1e8, 1e-6, 1e-3},
        {"rateState ageing [F11]", rs + "stateLaw ageing;", 1e6, 6e-8, 0.1},
        {"rateState slip [F11]", rs + "stateLaw slip;", 1e6, 6e-8, 0.1},
        {"rateState ageing [F12]",
         rs + "stateLaw ageing; form regularised;", 1e6, 6e-8, 0.1},
        {"rateState relaxation [F27]",
         "type rateState; stateLaw relaxation; KN 1e12; KT 1e13;"
         " muStar 0.369; a 0.0349; b 0.0489; VStar 1e-6;"
         " relaxationTime 2.729; gamma 0.723;", 1e6, 4e-8, 0.1},
        {"lubricatedRateState", lub, 1e8, 1e-6, 1e-3}
    };

    OStringStream table;
    table << "# triboFoam friction-law benchmark\n"
        << "# 1. cost per face-update: " << nFaces << " faces, median of "
        << nRepeat << " repeats (single thread)\n"
        << "# law                          ns/update  slipping-frac  Newton-it/solve  target\n";

    for (const lawCase& c : cases)
    {
        autoPtr<frictionLaw> law = makeLaw(c.dict);
        std::vector<frictionState> old(nFaces, law->initialState());
        std::vector<frictionInput> in(nFaces);
        std::vector<frictionResult> out(nFaces);
        const vector n(0, 0, 1);
        for (label i = 0; i < nFaces; ++i)
        {
            // slips from 0 to 3x the threshold slip, varied directions
            const scalar s = 3*c.slipScale*((i*7919) % nFaces)/scalar(nFaces);
            const scalar ang = 0.001*i;
            in[i].gN = c.p/law->KN();
            in[i].gT = s*vector(std::cos(ang), std::sin(ang), 0);
            in[i].n = n;
            in[i].dt = c.dt;
            old[i].status = frictionState::STICK;
        }
        std::vector<double> t(nRepeat);
        safeguardedNewton::resetCounters();
        for (label r = 0; r < nRepeat; ++r)
        {
            const auto t0 = std::chrono::steady_clock::now();
            for (label i = 0; i < nFaces; ++i)
            {
                law->update(old[i], in[i], out[i]);
            }
            const auto t1 = std::chrono::steady_clock::now();
            t[r] = std::chrono::duration<double, std::nano>(t1 - t0).count()
                /nFaces;
        }
        std::sort(t.begin(), t.end());
        label nSlip = 0;
        for (const frictionResult& o : out) nSlip += (o.state.status == 2);
        const bool rateDep = law->rateDependent();
        const scalar itPerSolve =
            safeguardedNewton::nIterations()
           /max(scalar(safeguardedNewton::nSolves()), scalar(1));
        char line[256];
        std::snprintf
        (
            line, sizeof(line), "%-30s %10.1f %12.2f %10.2f      %s\n",
            c.name, t[nRepeat/2], scalar(nSlip)/nFaces, itPerSolve,
            rateDep ? "< 1000" : "< 200"
        );
        table << line;
    }

    // 2a. Velocity-step error versus dt (soft contact, as frictionTimeStep)
    table << "#\n# 2a. velocity step v1 -> 10 v1: max |mu - mu_ref| at the"
        << " coarse output times (reference dt0/256)\n"
        << "# law                          dt0          dt0/2        dt0/4"
        << "        dt0/8        dt0/16\n";
    {
        struct vs { const char* name; std::string dict; scalar p, v1, t1, tEnd, dt0; };
        const std::string rsSoft =
            "type rateState; KN 1e12; KT 6e10; a 0.01; b 0.015; muStar 0.6;"
            " VStar 1e-6; L 1e-5; ";
        const std::vector<vs> vcases =
        {
            {"coulomb", "type coulomb; KN 1e12; KT 6e10; mu 0.6;", 1e6, 1e-6, 20, 25, 0.5},
            {"curnier coulomb+tear+wear", "type curnier; KN 1e12; KT 6e10;"
             " criterion coulomb; f 0.6; QT 1e9; Q 1e9;", 1e6, 1e-6, 20, 25, 0.5},
            {"rateState ageing [F11]", rsSoft + "stateLaw ageing;", 1e6, 1e-6, 20, 25, 0.5},
            {"rateState slip [F11]", rsSoft + "stateLaw slip;", 1e6, 1e-6, 20, 25, 0.5},
            {"rateState ageing [F12]", rsSoft + "stateLaw ageing; form regularised;",
             1e6, 1e-6, 20, 25, 0.5},
            {"lubricatedRateState", lub, 1e8, 1e-4, 0.02, 0.025, 5e-4}
        };
        for (const vs& c : vcases)
        {
            autoPtr<frictionLaw> law = makeLaw(c.dict);
            const label nOut = label(std::round(c.tEnd/c.dt0));
            auto S = [&](scalar t)
            {
                return t <= c.t1 ? c.v1*t : c.v1*c.t1 + 10*c.v1*(t - c.t1);
            };
            auto runMu = [&](scalar dt)
            {
                frictionPointDriver drv(*law, c.p);
                const label sub = label(std::round(c.dt0/dt));
                std::vector<scalar> mu(nOut);
                for (label k = 0; k < nOut; ++k)
                {
                    for (label j = 1; j <= sub; ++j)
                    {
                        drv.step(S((k*sub + j)*dt), dt);
                    }
                    mu[k] = drv.last().tT.x()/drv.last().tN;
                }
                return mu;
            };
            const std::vector<scalar> ref = runMu(c.dt0/256);
            char line[256];
            std::snprintf(line, sizeof(line), "%-30s", c.name);
            table << line;
            for (label i = 0; i < 5; ++i)
            {
                const std::vector<scalar> mu = runMu(c.dt0/std::pow(2.0, i));
                scalar e = 0;
                for (label k = 0; k < nOut; ++k) e = max(e, mag(mu[k] - ref[k]));
                std::snprintf(line, sizeof(line), " %12.3e", e);
                table << line;
            }
            table << "\n";
        }
    }

    // 2b. Spring-slider error versus dt (ageing law, k = 1.1 k*, M = 0)
    table << "#\n# 2b. spring-slider, ageing law, k = 1.1 k*: max |mu - mu_ref|"
        << " over 10 periods (reference: period/12800)\n"
        << "# steps/period                 100          200          400"
        << "          800          1600\n";
    {
        const scalar a = 0.01, b = 0.015, L = 1e-5, V = 1e-6, sigma = 1e6;
        autoPtr<frictionLaw> law = makeLaw
        (
            rs + "stateLaw ageing; creepVelocity 1e-15;"
        );
        const scalar kStar = (b - a)*sigma/L;
        const scalar k = 1/(1/(1.1*kStar) - 1/law->KT());
        const scalar period =
            2*constant::mathematical::pi*(L/V)/std::sqrt((b - a)/a);
        const label nOut = 100;
        auto runMu = [&](label perPeriod)
        {
            frictionPointDriver drv(*law, sigma);
            const scalar dt0 = 10*period/nOut;
            const label sub = label(std::round(dt0/(period/perPeriod)));
            const scalar dt = dt0/sub;
            // exact steady start: theta = L/V, spring at the steady force
            for (label i = 0; i < 4000; ++i) drv.step(drv.slip() + V*0.05, 0.05);
            drv.setSpringStretch(drv.last().tT.x()/k);
            const frictionStateLayout& layout = law->stateLayout();
            layout.setValue
            (
                drv.state(), "contactAge",
                1.05*layout.value(drv.state(), "contactAge")
            );
            std::vector<scalar> mu(nOut);
            for (label o = 0; o < nOut; ++o)
            {
                for (label j = 0; j < sub; ++j) drv.springSliderStep(0, k, V, dt);
                mu[o] = drv.last().tT.x()/sigma;
            }
            return mu;
        };
        const std::vector<scalar> ref = runMu(12800);
        table << "rateState ageing [F11]        ";
        for (const label n : {100, 200, 400, 800, 1600})
        {
            const std::vector<scalar> mu = runMu(n);
            scalar e = 0;
            for (label o = 0; o < nOut; ++o) e = max(e, mag(mu[o] - ref[o]));
            char line[64];
            std::snprintf(line, sizeof(line), " %12.3e", e);
            table << line;
        }
        table << "\n";
    }

    table << "# iteration-limit hits: " << frictionLaw::nIterationLimitHits()
        << "\n";

    std::fputs(table.str().c_str(), stdout);
    return 0;
}

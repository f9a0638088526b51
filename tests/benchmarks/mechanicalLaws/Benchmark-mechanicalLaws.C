/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Benchmark of the mechanical laws' point-wise update (not a timed test):
    nanoseconds per call of stress() and of stressAndTangent(), for the
    elastic laws and for the finite-strain J2 law on elastic and plastic
    states, in plane strain (be with a decoupled zz component, as the 2-D
    solver passes it) and in general 3-D. A loop over nSamples varied
    material points (random principal axes, plastic pre-stretch, elastic
    strain at a given fraction of the yield stress). Timed by the thread's
    CPU clock, so time spent waiting for a core (the machine is shared) is
    not counted; the fastest of nRepeat repetitions is reported (the least
    disturbed by other processes' use of the caches). The run script writes the table to
    tests/benchmarks/results/mechanicalLaws.txt.

\*---------------------------------------------------------------------------*/

#include "mechanicalLawTestTools.H"
#include <time.h>
#include <algorithm>
#include <vector>
#include <random>
#include <cstdio>

using namespace Foam;
using namespace mechanicalLawTest;

struct samples
{
    std::vector<tensor> F;
    std::vector<materialState> old;
};

// Material points with plastic history epsP (pre-stretch up to 30 %) and a
// trial von Mises stress 'ratio' times the yield stress (elastic below 1)
static samples makeSamples
(
    const label n,
    const bool planar,
    const scalar ratio,
    const scalar epsP,
    const scalar yield,
    const scalar G
)
{
    std::mt19937 gen(12345);
    std::uniform_real_distribution<double> u(-1, 1);
    auto randomAxis = [&]()
    {
        return planar ? vector(0, 0, 1) : vector(u(gen), u(gen), u(gen) + 2);
    };
    samples s;
    for (label i = 0; i < n; ++i)
    {
        const tensor Qp(rotation(randomAxis(), 3*u(gen)));
        const scalar a = 1 + 0.3*u(gen);
        const scalar b = 1 + 0.3*u(gen);
        const tensor Fp(principal(Qp, vector(a, b, 1/(a*b))));
        const tensor FpInv(inv(Fp));
        materialState old;
        old.CpInv = symm(FpInv & FpInv.T());
        old.epsilonP = epsP;

        // Elastic strain: deviatoric part sized for the trial stress,
        // volumetric part 1e-3
        const tensor Qe(rotation(randomAxis(), 3*u(gen)));
        vector d(u(gen), u(gen), u(gen));
        d -= (d.x() + d.y() + d.z())/3*vector::one;
        d *= ratio*yield/(Foam::sqrt(1.5)*2*G*mag(d));
        d += 1e-3*u(gen)*vector::one;
        const tensor Ue(principal(Qe, vector(1, 1, 1) + d));
        const tensor R(rotation(randomAxis(), 3*u(gen)));
        s.F.push_back(R & Ue & Fp);
        s.old.push_back(old);
    }
    return s;
}


// CPU time of this thread [ns]
static double cpuNow()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e9*t.tv_sec + t.tv_nsec;
}


static double fastest(const std::vector<double>& t)
{
    return *std::min_element(t.begin(), t.end());
}


int main()
{
    // Keep the table free of the laws' selection messages
    messageStream::level = 0;

    const label nSamples = 20000;
    const label nRepeat = 15;

    const std::string elastic = "rho 7900; E 193e9; nu 0.29; ";
    const std::string swiftLaw =
        "type vonMisesPlastic; " + elastic
      + "yieldStress { type swift; K 1270e6; eps0 0.03; n 0.45; }";
    const std::string tableLaw =
        "type vonMisesPlastic; " + elastic
      + "yieldStress table ((0 262e6) (0.05 430e6) (0.1 510e6) (0.2 620e6)"
        " (0.4 760e6) (0.8 940e6) (2 1300e6));";

    struct lawCase
    {
        const char* name;
        std::string dict;
        bool planar;
        scalar ratio;
    };
    const std::vector<lawCase> cases =
    {
        {"linearElastic 3-D", "type linearElastic; " + elastic, false, 0.5},
        {"neoHookean 3-D", "type neoHookean; " + elastic, false, 0.5},
        {"vonMises swift 2-D elastic", swiftLaw, true, 0.5},
        {"vonMises swift 2-D plastic", swiftLaw, true, 1.5},
        {"vonMises swift 3-D elastic", swiftLaw, false, 0.5},
        {"vonMises swift 3-D plastic", swiftLaw, false, 1.5},
        {"vonMises table 2-D plastic", tableLaw, true, 1.5},
        {"vonMises table 3-D plastic", tableLaw, false, 1.5}
    };

    std::printf
    (
        "# triboFoam mechanical-law benchmark: ns per call (thread CPU"
        " time), %d material points, fastest of %d repeats\n"
        "# elastic: trial stress 0.5 x yield; plastic: 1.5 x yield"
        " (epsP = 0.2, plastic pre-stretch up to 30 %%)\n"
        "# law / state                     stress   stress+tangent"
        "   plastic-fraction\n",
        int(nSamples), int(nRepeat)
    );

    for (const lawCase& c : cases)
    {
        autoPtr<mechanicalLaw> m = law(c.dict);
        const scalar epsP = 0.2;
        const scalar yield = 1270e6*Foam::pow(0.03 + epsP, 0.45);
        const samples s =
            makeSamples(nSamples, c.planar, c.ratio, epsP, yield, m->mu());

        std::vector<materialState> upd(nSamples);
        double sink = 0;
        std::vector<double> tS(nRepeat), tT(nRepeat);
        stressTangent D;
        for (label r = 0; r < nRepeat; ++r)
        {
            double t0 = cpuNow();
            for (label i = 0; i < nSamples; ++i)
            {
                sink += m->stress(s.F[i], s.old[i], upd[i]).xx();
            }
            tS[r] = (cpuNow() - t0)/nSamples;

            t0 = cpuNow();
            for (label i = 0; i < nSamples; ++i)
            {
                sink += m->stressAndTangent(s.F[i], s.old[i], upd[i], D).xx();
                sink += D(0, 0);
            }
            tT[r] = (cpuNow() - t0)/nSamples;
        }
        label nPlastic = 0;
        for (label i = 0; i < nSamples; ++i)
        {
            nPlastic += (upd[i].epsilonP > s.old[i].epsilonP);
        }
        std::printf
        (
            "%-32s %8.1f %12.1f %14.2f\n",
            c.name, fastest(tS), fastest(tT), scalar(nPlastic)/nSamples
        );
        if (!std::isfinite(sink))
        {
            std::printf("# non-finite stress in %s\n", c.name);
            return 1;
        }
    }
    return 0;
}


// ************************************************************************* //

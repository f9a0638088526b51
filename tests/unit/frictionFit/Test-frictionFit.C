/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Least-squares fit of law parameters to a friction record
    (doc/theory.md [F34]): Levenberg-Marquardt of Eigen, confidence
    intervals from the Jacobian at the solution.

    Synthetic records of the ageing law ([F11], [F27]: a = 0.01,
    b = 0.015, L = 10 um, mu* = 0.6, V* = 1 um/s, 1 MPa), velocity steps
    1 -> 10 -> 1 um/s, 0.05 s sampling over 40 s (800 rows), made by the
    fit's own model at the true parameters:
      - noise-free, imposed slip rate: a, b, L from a start 20-50 % off
        within 1e-4 relative;
      - noise-free, load-point velocity on a machine of 2 k_c: the same;
      - Gaussian noise 1e-4 on mu, 30 records (fixed seed): the 95 %
        intervals cover the truth in at least 85 % of the records for
        every parameter;
      - bad input: a parameter the law does not have, fewer rows than
        parameters, non-increasing times: errors naming the keyword.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "frictionFit.H"
#include <random>

using namespace Foam;

namespace
{

const scalar aT = 0.01, bT = 0.015, LT = 1e-5;

const std::string ageing(const std::string& a, const std::string& b,
    const std::string& L)
{
    return
        "type rateState; stateLaw ageing; KN 1e12; KT 1e13; muStar 0.6;"
        " VStar 1e-6; creepVelocity 1e-12; a " + a + "; b " + b + "; L "
      + L + ";";
}

frictionFit::record velocitySteps()
{
    frictionFit::record r;
    const label n = 800;
    r.t.setSize(n);
    r.drive.setSize(n);
    r.mu.setSize(n, 0);
    for (label i = 0; i < n; ++i)
    {
        r.t[i] = 0.05*i;
        r.drive[i] = r.t[i] > 10 && r.t[i] <= 25 ? 1e-5 : 1e-6;
    }
    return r;
}

//- The record made by the model itself at the true parameters
frictionFit::record synthetic(const frictionFit::settings& s)
{
    frictionFit::record r = velocitySteps();
    const frictionFit truth
    (
        frictionTest::dict(ageing("0.01", "0.015", "1e-5")),
        wordList({"a", "b", "L"}), r, s, dictionary::null
    );
    r.mu = truth.simulate(truth.start());
    return r;
}

const dictionary startLaw = frictionTest::dict(ageing("0.012", "0.012", "1.5e-5"));
const wordList abL({"a", "b", "L"});

scalar worstError(const frictionFit::result& res)
{
    return max
    (
        max(mag(res.value[0]/aT - 1), mag(res.value[1]/bT - 1)),
        mag(res.value[2]/LT - 1)
    );
}

} // End anonymous namespace


int main()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    frictionFit::settings rigid;
    rigid.pressure = 1e6;
    rigid.runInTime = 300;

    Info<< "Noise-free velocity steps, imposed slip rate" << endl;
    {
        const frictionFit f(startLaw, abL, synthetic(rigid), rigid, dictionary::null);
        const frictionFit::result r = f.fit(0.95);
        Info<< "    a " << r.value[0] << ", b " << r.value[1] << ", L "
            << r.value[2] << " (" << r.nEvaluations << " evaluations, rms "
            << r.rms << ")" << endl;
        unitTest::checkBelow("a, b, L: max relative error", worstError(r), 1e-4);
    }

    Info<< "Noise-free, load-point velocity on a machine of 2 k_c" << endl;
    {
        frictionFit::settings spring = rigid;
        spring.drive = frictionFit::LOAD_POINT;
        spring.stiffness = 2*(bT - aT)*1e6/LT;
        const frictionFit f(startLaw, abL, synthetic(spring), spring, dictionary::null);
        const frictionFit::result r = f.fit(0.95);
        Info<< "    a " << r.value[0] << ", b " << r.value[1] << ", L "
            << r.value[2] << " (" << r.nEvaluations << " evaluations)" << endl;
        unitTest::checkBelow("a, b, L: max relative error", worstError(r), 1e-4);
    }

    Info<< "Noise 1e-4 on mu, 30 records" << endl;
    {
        const frictionFit::record clean = synthetic(rigid);
        std::mt19937 gen(20261124);
        std::normal_distribution<double> noise(0, 1e-4);
        const label n = 30;
        labelList cover(3, Zero);
        scalar worst = 0;
        for (label k = 0; k < n; ++k)
        {
            frictionFit::record r = clean;
            forAll(r.mu, i) r.mu[i] += noise(gen);
            const frictionFit f(startLaw, abL, r, rigid, dictionary::null);
            const frictionFit::result res = f.fit(0.95);
            const scalar truth[3] = {aT, bT, LT};
            for (label j = 0; j < 3; ++j)
            {
                cover[j] += mag(res.value[j] - truth[j]) <= res.halfWidth[j];
            }
            worst = max(worst, worstError(res));
            if (k == 0)
            {
                Info<< "    first record: a " << res.value[0] << " +- "
                    << res.halfWidth[0] << ", b " << res.value[1] << " +- "
                    << res.halfWidth[1] << ", L " << res.value[2] << " +- "
                    << res.halfWidth[2] << ", rms " << res.rms << endl;
            }
        }
        Info<< "    coverage a " << cover[0] << "/" << n << ", b " << cover[1]
            << "/" << n << ", L " << cover[2] << "/" << n << "; worst"
            << " relative error " << worst << endl;
        for (label j = 0; j < 3; ++j)
        {
            unitTest::checkTrue
            (
                "95 % interval covers " + abL[j] + " in >= 85 % of records",
                cover[j] >= 0.85*n
            );
        }
    }

    Info<< "Bad input" << endl;
    {
        auto rejects = [&]
        (
            const wordList& p,
            const frictionFit::record& r,
            const std::string& key
        )
        {
            try
            {
                frictionFit f(startLaw, p, r, rigid, dictionary::null);
            }
            catch (const Foam::IOerror& e)
            {
                return std::string(e.message()).find(key) != std::string::npos;
            }
            return false;
        };
        const frictionFit::record r = velocitySteps();
        unitTest::checkTrue
        (
            "unknown parameter 'c': error names keyword 'parameters'",
            rejects(wordList({"a", "c"}), r, "'parameters'")
        );
        frictionFit::record few = r;
        few.t.setSize(3);
        few.drive.setSize(3);
        few.mu.setSize(3);
        unitTest::checkTrue
        (
            "3 rows for 3 parameters: error names keyword 'record'",
            rejects(abL, few, "'record'")
        );
        frictionFit::record back = r;
        back.t[5] = back.t[3];
        unitTest::checkTrue
        (
            "non-increasing time: error names keyword 'record'",
            rejects(abL, back, "'record'")
        );
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

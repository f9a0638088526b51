/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The Newton solver's line search on its own (doc/theory.md [S14],
    [S14b], [S14d], [S16b]): |R| along the correction is a function of
    the fraction l written here, so every fraction the search asks for,
    the one it takes and why are known exactly:
      - a residual linear along the step: the full step, one trial;
      - an overshooting step, |R(l)| = |1 - 4 l|: 1 and 1/2 fail, 1/4 is
        the root;
      - [S14d] the reference is the largest of the last lineSearchMemory
        norms: a step that raises |R| by 20 % fails with memory 1 and
        passes with memory 3 after a larger norm;
      - no fraction passes Armijo's test: the largest fraction that does
        not raise |R| is taken (evaluated again last, so the caller holds
        it), else the smallest (1/32), else with fullStepFallback the full
        step, whose norm is the first trial's;
      - [S14b] a decrease only near the contact onset at 0.15 of the step,
        between the halvings: found there with stopAtContactOnset
        afterLineSearch (and counted as an onset stop), not without;
      - [S16b] a predicted guess with no passing fraction: rejected before
        any fallback is evaluated;
      - trials whose residual is not finite (GREAT) are rejected.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "newtonLineSearch.H"
#include "IStringStream.H"

using namespace Foam;
using namespace unitTest;

//- |R| along the step as a function of l, recording the fractions asked
struct alongStep
{
    std::function<scalar(scalar)> f;
    DynamicList<scalar> asked;

    newtonLineSearch::trialNorm trial()
    {
        return [this](const scalar l)
        {
            asked.append(l);
            return f(l);
        };
    }
};


static newtonLineSearch::onsetFraction noOnset()
{
    return []() { return scalar(1); };
}


int main()
{
    const newtonLineSearch plain(controls(""), true);
    const DynamicList<scalar> lastNormOne(1, scalar(1));

    Info<< "A residual linear along the step" << endl;
    {
        alongStep R{[](scalar l) { return mag(1 - l); }, {}};
        const auto out =
            plain.search(1, plain.referenceNorm(lastNormOne), R.trial(),
                noOnset(), false);
        checkAbs("full step taken", out.lambda, 1, 0);
        checkTrue("decreased", out.decreased);
        checkAbs("one trial", R.asked.size(), 1, 0);
        checkAbs("norm at the step", out.norm, 0, 0);
    }

    Info<< "An overshooting step |R(l)| = |1 - 4 l|" << endl;
    {
        alongStep R{[](scalar l) { return mag(1 - 4*l); }, {}};
        const auto out = plain.search(1, 1, R.trial(), noOnset(), false);
        checkAbs("fraction 1/4", out.lambda, 0.25, 0);
        checkTrue("decreased", out.decreased);
        checkAbs("trials 1, 1/2, 1/4", R.asked.size(), 3, 0);
        checkTrue("not an onset stop", !out.onsetStop);
    }

    Info<< "[S14d] the reference norm of lineSearchMemory" << endl;
    {
        DynamicList<scalar> norms;
        norms.append(2);
        norms.append(1.5);
        norms.append(1);
        const newtonLineSearch memory3(controls("lineSearchMemory 3;"), true);
        const newtonLineSearch memory2(controls("lineSearchMemory 2;"), true);
        checkAbs("memory 1: the last norm", plain.referenceNorm(norms), 1, 0);
        checkAbs("memory 2: the larger of the last two",
            memory2.referenceNorm(norms), 1.5, 0);
        checkAbs("memory 3: the largest of three",
            memory3.referenceNorm(norms), 2, 0);

        // |R| 20 % above the last norm along the whole step
        alongStep R1{[](scalar) { return scalar(1.2); }, {}};
        const auto out1 =
            plain.search(1, plain.referenceNorm(norms), R1.trial(),
                noOnset(), false);
        checkTrue("memory 1: no fraction passes", !out1.decreased);
        alongStep R3{[](scalar) { return scalar(1.2); }, {}};
        const auto out3 =
            memory3.search(1, memory3.referenceNorm(norms), R3.trial(),
                noOnset(), false);
        checkTrue("memory 3: the full step passes", out3.decreased);
        checkAbs("memory 3: fraction 1", out3.lambda, 1, 0);
    }

    Info<< "No fraction passes Armijo's test" << endl;
    {
        // |R| equal to the last one up to half the step, higher beyond
        alongStep flat{[](scalar l) { return l <= 0.5 ? 1 : 2; }, {}};
        const auto out = plain.search(1, 1, flat.trial(), noOnset(), false);
        checkTrue("flat: not decreased", !out.decreased);
        checkAbs("flat: the largest fraction not raising |R|", out.lambda,
            0.5, 0);
        checkAbs("flat: six halvings, then 1/2 again", flat.asked.size(), 7,
            0);
        checkAbs("flat: the last trial is the one taken", flat.asked.last(),
            0.5, 0);
        checkAbs("flat: its norm", out.norm, 1, 0);

        alongStep up{[](scalar) { return scalar(2); }, {}};
        const auto outUp = plain.search(1, 1, up.trial(), noOnset(), false);
        checkAbs("rising: the smallest fraction", outUp.lambda, 1.0/32, 0);
        checkAbs("rising: six trials", up.asked.size(), 6, 0);
        checkAbs("rising: the last trial is the one taken", up.asked.last(),
            1.0/32, 0);

        const newtonLineSearch fallback
        (
            controls("fullStepFallback yes;"), true
        );
        alongStep upFull{[](scalar l) { return 2 + l; }, {}};
        const auto outFull =
            fallback.search(1, 1, upFull.trial(), noOnset(), false);
        checkAbs("fullStepFallback: the full step", outFull.lambda, 1, 0);
        checkAbs("fullStepFallback: its iterate evaluated last",
            upFull.asked.last(), 1, 0);
        checkAbs("fullStepFallback: the first trial's norm", outFull.norm, 3,
            0);
    }

    Info<< "[S14b] a decrease only near the contact onset" << endl;
    {
        // |R| falls only for fractions in [0.14, 0.16], between the
        // halvings 1/4 and 1/8; the first face closes at 0.15 of the step
        const auto f = [](scalar l)
        {
            return l >= 0.14 && l <= 0.16 ? 0.5 : 2;
        };
        label nOnsetAsked = 0;
        const newtonLineSearch::onsetFraction onset = [&]()
        {
            ++nOnsetAsked;
            return scalar(0.15);
        };
        alongStep R{f, {}};
        const auto out = plain.search(1, 1, R.trial(), onset, false);
        checkTrue("afterLineSearch: decreased", out.decreased);
        checkAbs("afterLineSearch: the fraction to the onset", out.lambda,
            0.15, 0);
        checkTrue("afterLineSearch: an onset stop", out.onsetStop);
        checkAbs("afterLineSearch: onset asked once", nOnsetAsked, 1, 0);

        const newtonLineSearch never(controls(""), false);
        alongStep Rn{f, {}};
        const auto outNever = never.search(1, 1, Rn.trial(), onset, false);
        checkTrue("never: no decrease", !outNever.decreased);
        checkAbs("never: the smallest fraction", outNever.lambda, 1.0/32, 0);
        checkAbs("never: onset not asked", nOnsetAsked, 1, 0);
    }

    Info<< "[S16b] a predicted guess without a passing fraction" << endl;
    {
        const newtonLineSearch fallback
        (
            controls("fullStepFallback yes;"), true
        );
        alongStep flat{[](scalar l) { return l <= 0.5 ? 1 : 2; }, {}};
        const auto out = fallback.search(1, 1, flat.trial(), noOnset(), true);
        checkTrue("rejected", out.rejectPredictor);
        checkAbs("no fallback evaluated after the six trials",
            flat.asked.size(), 6, 0);

        alongStep R{[](scalar l) { return mag(1 - 4*l); }, {}};
        const auto outOk = fallback.search(1, 1, R.trial(), noOnset(), true);
        checkTrue("a passing fraction: not rejected", !outOk.rejectPredictor);
    }

    Info<< "Trials whose residual is not finite" << endl;
    {
        alongStep R{[](scalar l) { return l > 0.3 ? GREAT : 0.5; }, {}};
        const auto out = plain.search(1, 1, R.trial(), noOnset(), false);
        checkAbs("the first finite fraction", out.lambda, 0.25, 0);
        checkTrue("decreased", out.decreased);
    }

    return exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "newtonLineSearch.H"
#include "boundedEntry.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Backtracking: the fractions 1, 1/2, ..., 1/32 of the step
static const label nBacktrackingTrials = 6;

//- [S14b] The fractions 1, 1/2, 1/4 and 1/8 of the step to the onset
static const label nOnsetTrials = 4;

//- Armijo's test of |R| at the fraction l against |R|ref
static bool sufficientDecrease
(
    const scalar norm,
    const scalar l,
    const scalar normRef
)
{
    return norm <= (1 - 1e-4*l)*normRef;
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::newtonLineSearch::newtonLineSearch
(
    const dictionary& dict,
    const bool onsetAfterSearch
)
:
    memory_
    (
        strictDictionary::readBounded<label>
        (
            dict, "lineSearchMemory", 1,
            [](const label m) { return m >= 1; },
            "an integer >= 1 (1: |R| must fall at every iteration)"
        )
    ),
    fullStepFallback_(dict.lookupOrDefault<bool>("fullStepFallback", false)),
    onsetAfterSearch_(onsetAfterSearch)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::newtonLineSearch::referenceNorm
(
    const DynamicList<scalar>& recentNorms
) const
{
    scalar normRef = 0;
    for
    (
        label k = max(recentNorms.size() - memory_, 0);
        k < recentNorms.size();
        ++k
    )
    {
        normRef = max(normRef, recentNorms[k]);
    }
    return normRef;
}


Foam::newtonLineSearch::outcome Foam::newtonLineSearch::search
(
    const scalar normR,
    const scalar normRef,
    const trialNorm& trial,
    const onsetFraction& onset,
    const bool predicted
) const
{
    outcome out;
    scalar lambda = 1;
    scalar normFull = GREAT;
    scalar lambdaFlat = -1;
    for (label ls = 0; ls < nBacktrackingTrials; ++ls)
    {
        out.norm = trial(lambda);
        if (ls == 0)
        {
            normFull = out.norm;
        }
        if (sufficientDecrease(out.norm, lambda, normRef))
        {
            out.decreased = true;
            break;
        }
        if (lambdaFlat < 0 && out.norm <= normR)
        {
            lambdaFlat = lambda;
        }
        if (ls < nBacktrackingTrials - 1)
        {
            // (the last fraction tried stays in lambda: it is the one
            // taken when none decreases |R|)
            lambda *= 0.5;
        }
    }

    const scalar onsetLambda =
        !out.decreased && onsetAfterSearch_ ? onset() : 1;
    if (onsetLambda < 1)
    {
        // [S14b] no fraction of the step lowers |R|: the fractions of the
        // step to the first contact onset along it are tried
        const scalar lambdaSmallest = lambda;
        lambda = onsetLambda;
        for (label ls = 0; ls < nOnsetTrials && !out.decreased; ++ls)
        {
            out.norm = trial(lambda);
            out.decreased = sufficientDecrease(out.norm, lambda, normRef);
            if (!out.decreased)
            {
                lambda *= 0.5;
            }
        }
        out.onsetStop = out.decreased;
        if (!out.decreased && lambdaFlat < 0 && !fullStepFallback_)
        {
            // none did: the smallest fraction, as without the stop
            lambda = lambdaSmallest;
            out.norm = trial(lambda);
        }
    }

    if (!out.decreased && predicted)
    {
        // [S16b] the predictor lies across an active-set switch: no
        // fraction of the step from it helps, the solve restarts
        out.rejectPredictor = true;
        out.lambda = lambda;
        return out;
    }

    if (!out.decreased && normFull < GREAT && fullStepFallback_)
    {
        // the trial again, so that the caller holds the full step's
        // iterate (its norm is the first trial's)
        lambda = 1;
        trial(lambda);
        out.norm = normFull;
    }
    else if (!out.decreased && lambdaFlat > 0)
    {
        lambda = lambdaFlat;
        out.norm = trial(lambda);
    }
    out.lambda = lambda;
    return out;
}


// ************************************************************************* //

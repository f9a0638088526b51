/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "timeStepController.H"
#include "OStringStream.H"
#include "Switch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::timeStepController::predictorType>
Foam::timeStepController::predictorTypeNames
({
    { predictorType::NONE, "none" },
    { predictorType::EXTRAPOLATE, "extrapolate" },
    { predictorType::TANGENT, "tangent" },
    { predictorType::TANGENT_FIRST, "tangentFirst" },
});


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::timeStepController::predictorType
Foam::timeStepController::readPredictor(const dictionary& dict)
{
    const entry* ePtr = dict.findEntry("predictor", keyType::LITERAL);
    if (!ePtr)
    {
        // [S18c] the tangent at the run's first step, then the
        // extrapolation
        return TANGENT_FIRST;
    }

    // One word: a name of the choice, or the former switch's yes/no
    ITstream& is = ePtr->stream();
    const token tok(is);
    if (tok.isWord() && is.eof())
    {
        const word& w = tok.wordToken();
        if (predictorTypeNames.found(w))
        {
            return predictorTypeNames.get(w);
        }
        // 'none' is also a switch value (false): the choice's name wins
        const Switch sw(w, true);
        if (sw.valid())
        {
            return sw ? EXTRAPOLATE : NONE;
        }
    }

    FatalIOErrorInFunction(dict)
        << "Keyword 'predictor' in dictionary " << dict.name() << ": "
        << ePtr->stream().toString().c_str() << " is not a predictor;"
        << " expected extrapolate (the default), tangent, tangentFirst or"
        << " none (or yes = extrapolate, no = none)" << nl
        << exit(FatalIOError);
    return NONE;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::timeStepController::timeStepController
(
    const dictionary& dict,
    const scalar userDeltaT
)
:
    userDeltaT_(userDeltaT),
    maxCutBacks_(dict.lookupOrDefault<label>("maxCutBacks", 10)),
    cutBackFactor_(dict.lookupOrDefault<scalar>("cutBackFactor", 0.5)),
    growth_(dict.lookupOrDefault<scalar>("timeStepGrowth", 1.5)),
    minDeltaTRatio_(dict.lookupOrDefault<scalar>("minDeltaTRatio", 1e-6)),
    predictor_(readPredictor(dict)),
    deltaT_(userDeltaT),
    nFailures_(0),
    retrying_(false),
    stoppedBySize_(false)
{
    if
    (
        maxCutBacks_ < 0 || !(cutBackFactor_ > 0) || !(cutBackFactor_ < 1)
     || !(growth_ >= 1) || !(minDeltaTRatio_ > 0) || !(userDeltaT > 0)
    )
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": expected maxCutBacks >= 0"
            << " (got " << maxCutBacks_ << "), 0 < cutBackFactor < 1 (got "
            << cutBackFactor_ << "), timeStepGrowth >= 1 (got " << growth_
            << "), minDeltaTRatio > 0 (got " << minDeltaTRatio_
            << ") and deltaT > 0 in controlDict (got " << userDeltaT << ")"
            << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::timeStepController::action Foam::timeStepController::converged()
{
    retrying_ = false;
    nFailures_ = 0;
    deltaT_ = min(growth_*deltaT_, userDeltaT_);
    return ACCEPT;
}


Foam::timeStepController::action Foam::timeStepController::failed
(
    const scalar dt
)
{
    // The time extrapolation misleads at a kink of the load path (a hold
    // after a ramp), the tangent where the step's response is far from
    // linear: the same step is tried once from the last solution
    if (predict())
    {
        retrying_ = true;
        return RETRY;
    }
    retrying_ = false;

    ++nFailures_;
    const bool tooSmall = cutBackFactor_*dt < minDeltaTRatio_*userDeltaT_;
    if (nFailures_ > maxCutBacks_ || tooSmall)
    {
        stoppedBySize_ = nFailures_ <= maxCutBacks_;
        return STOP;
    }
    deltaT_ = cutBackFactor_*dt;
    return CUT_BACK;
}


Foam::string Foam::timeStepController::stopMessage
(
    const scalar failedTime,
    const scalar failedDeltaT,
    const string& reason,
    const scalar t0,
    const bool t0IsStartTime
) const
{
    // The form 'last converged time, T, is written' is parsed by the test
    // suite (tests/bin/stressTools.py); nFailures counts the failed
    // attempts, one more than the cut-backs made
    OStringStream os;
    os  << "The step to time " << failedTime << " did not converge after "
        << nFailures_ - 1 << " cut-backs of the time step (last deltaT "
        << failedDeltaT << " s, reason: " << reason.c_str() << ")";
    if (stoppedBySize_)
    {
        // not the cut-back limit: the smallest step allowed
        os  << ": a further cut-back, to " << cutBackFactor_*failedDeltaT
            << " s, would be below minDeltaTRatio " << minDeltaTRatio_
            << " times deltaT " << userDeltaT_ << " s of controlDict"
            << " (maxCutBacks " << maxCutBacks_ << " not reached)";
    }
    os  << "." << nl
        << "The last converged time, " << t0 << ", is written"
        << (t0IsStartTime ? " (the start time: no step converged);" : ";")
        << " check the loading, the boundary conditions and the solid"
        << " controls in system/fvSolution";
    return os.str();
}


Foam::dictionary Foam::timeStepController::state() const
{
    dictionary dict;
    dict.add("deltaT", deltaT_);
    dict.add("userDeltaT", userDeltaT_);
    return dict;
}


bool Foam::timeStepController::setState(const dictionary& dict)
{
    nFailures_ = 0;
    retrying_ = false;

    // A deltaT changed in controlDict since the write is the user's new
    // step: it starts there
    if (dict.lookupOrDefault<scalar>("userDeltaT", -1) != userDeltaT_)
    {
        deltaT_ = userDeltaT_;
        return false;
    }
    deltaT_ = dict.get<scalar>("deltaT");
    return true;
}


// ************************************************************************* //

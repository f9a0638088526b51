/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

\*---------------------------------------------------------------------------*/

#include "solidTimeLoop.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- [S14e] Continuations failed in a row after which they are off for the
//  run: a case whose failures have another cause does not pay for them at
//  every step
static const label maxContinuationFailures = 3;

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

// [S14e] The step solved from the predictor again with every contact onset
// widened by the factor onsetContinuation, then from there with the onsets
// as given (the answer is the given system's). Returns the failed
// attempt's result where there is no onset to widen, the factor is 1 or
// the continuations are off; else the given system's solve where the
// continuation took the step, and the failed attempt's result where it
// did not. The Newton iterations of every solve are added to nNewton, the
// Krylov iterations and residual evaluations of every solve to the result
Foam::newtonSolver::result Foam::solidTimeLoop::continueWithWiderOnset
(
    const newtonSolver::result& failed,
    label& nNewton
)
{
    const scalar factor = newton_.onsetContinuation();
    if (factor <= 1 || nContinuationFailures_ >= maxContinuationFailures)
    {
        return failed;
    }

    // the predictor with the onsets as given, then the wider ones
    solid_.beginStep(x_, xStart_, controller_.predictor());
    if (!solid_.widenContactOnset(factor))
    {
        return failed;
    }
    Info<< "    continuing the step with the contact onset " << factor
        << " times wider, then as given: the exact-Jacobian Newton stopped ("
        << failed.reason.c_str() << ") after " << failed.newtonIterations
        << " iterations, force residual " << failed.forceResidual << ", "
        << failed.contactOnsetStops << " steps stopped at a contact onset"
        << endl;

    const newtonSolver::result wide =
        newton_.solve(solid_, x_, xStart_, false);
    solid_.widenContactOnset(1);
    nNewton += wide.newtonIterations;

    newtonSolver::result given;
    if (wide.converged)
    {
        given = newton_.solve(solid_, x_, xStart_, false);
        nNewton += given.newtonIterations;
    }
    Info<< "    continuation: " << wide.newtonIterations
        << (wide.converged ? "" : " (not converged)") << " + "
        << given.newtonIterations << " Newton iterations"
        << (given.converged ? "" : ", not converged") << endl;

    nContinuationFailures_ =
        given.converged ? 0 : nContinuationFailures_ + 1;
    if (nContinuationFailures_ == maxContinuationFailures)
    {
        Info<< "    continuation retries off for the rest of the run: the"
            << " last " << maxContinuationFailures << " failed" << endl;
    }

    // the failed attempt's diagnostics where the continuation did not
    // take the step (the retry that follows reports them)
    newtonSolver::result res = given.converged ? given : failed;
    res.krylovIterations =
        failed.krylovIterations + wide.krylovIterations
      + given.krylovIterations;
    res.residualEvaluations =
        failed.residualEvaluations + wide.residualEvaluations
      + given.residualEvaluations;
    return res;
}


// [C5b] Augmented Lagrangian contact with augmentBetweenIterations no: the
// converged step is solved again, from where it stands, with the contacts'
// updated multipliers until their penetrations are below their tolerances
// (with the default the Newton solver updates them between its iterations
// and returns them converged; no contact augmented: no re-solve). A solve
// after an update is followed by another check and most likely another
// update, so it stops at looser tolerances (1000 times the controls');
// when the multipliers have converged at such an iterate, a last solve to
// the controls' tolerances (and another check) follows. Every solve's
// Newton iterations are added to nNewton
void Foam::solidTimeLoop::augmentBetweenSolves
(
    const bool jacobianFree,
    newtonSolver::result& res,
    label& nNewton
)
{
    bool loose = false;
    for (label aug = 1; res.converged && !res.multipliersConverged; ++aug)
    {
        const bool update = solid_.augment(x_);
        if (!update && !loose)
        {
            break;
        }
        loose = update;
        const label krylov = res.krylovIterations;
        const label evaluations = res.residualEvaluations;
        res = newton_.solve
        (
            solid_, x_, xStart_, jacobianFree, loose ? 1e3 : 1
        );
        nNewton += res.newtonIterations;
        res.krylovIterations += krylov;
        res.residualEvaluations += evaluations;
        Info<< "    augmentation " << aug << ": "
            << res.newtonIterations << " Newton iterations"
            << (loose ? " (loose tolerances)" : " (final solve)")
            << (res.converged ? "" : ", not converged") << endl;
    }
}


void Foam::solidTimeLoop::rejectFacesPressedThrough
(
    newtonSolver::result& res
)
{
    // [C2e] a face pressed through the other surface beyond the search
    // distance carries no force and would sink further in the steps to
    // come: the solve is no solution (a smaller step, whose prediction
    // errs less, keeps the faces in reach)
    if (!res.converged)
    {
        return;
    }
    const label n = solid_.contactFacesPressedThrough(x_);
    if (n)
    {
        res.converged = false;
        res.accepted = false;
        res.reason =
            Foam::name(n)
          + " contact faces pressed through the other surface, beyond the"
            " search distance";
    }
}


// The exact-Jacobian Newton from the predictor, its continuation retry
// [S14e], then the Jacobian-free retry from the last solution (a bounded
// correction where the exact Jacobian is singular) [S18]. Returns the last
// solve's result with the Newton iterations of every solve
Foam::newtonSolver::result Foam::solidTimeLoop::solveLoadStep
(
    timeStepController::action& action
)
{
    newtonSolver::result res;
    label nNewton = 0;
    action = timeStepController::RETRY;
    bool retry = false;
    while (action == timeStepController::RETRY)
    {
        solid_.beginStep(x_, xStart_, controller_.predictor());
        res = newton_.solve(solid_, x_, xStart_, retry);
        nNewton += res.newtonIterations;
        if (!res.converged && !retry)
        {
            res = continueWithWiderOnset(res, nNewton);
        }
        augmentBetweenSolves(retry, res, nNewton);
        rejectFacesPressedThrough(res);

        action =
            res.converged
          ? controller_.converged()
          : controller_.failed(runTime_.deltaTValue());
        retry = action == timeStepController::RETRY;
        if (retry)
        {
            // The last resort before a cut-back: say what failed
            Info<< "    retrying the step without the predictor,"
                << " Jacobian-free: the exact-Jacobian Newton stopped ("
                << res.reason.c_str() << ") after " << res.newtonIterations
                << " iterations, force residual " << res.forceResidual
                << endl;
        }
    }
    res.newtonIterations = nNewton;
    return res;
}


void Foam::solidTimeLoop::acceptStep
(
    const newtonSolver::result& res,
    const label nCutBacks,
    const scalar t0
)
{
    solid_.commit(x_);
    output_.report();

    ++nSteps_;
    nNewton_ += res.newtonIterations;

    const scalar stepTime = stepClock_.timeIncrement();
    Info<< "    converged: " << res.newtonIterations
        << " Newton iterations, " << res.krylovIterations
        << " Krylov iterations, " << res.residualEvaluations
        << " residual evaluations, force residual " << res.forceResidual
        << ", " << stepTime << " s" << endl;

    performance_.write(res, nCutBacks);

    const bool written = writes_.due(t0);
    if (written)
    {
        // the output fields (sigma, pointD, ...) follow this schedule, not
        // Time's own write test
        writeNow();
    }
    if (runTime_.functionObjects().size())
    {
        executeFunctions(written);
    }

    Info<< "    ExecutionTime = " << runTime_.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime_.elapsedClockTime() << " s"
        << nl << endl;
}


// With action STOP the run stops with the controller's message after
// writing the last converged state (not at the run's start, which is on
// disk)
void Foam::solidTimeLoop::rejectStep
(
    const TimeState& lastConverged,
    const newtonSolver::result& res,
    const timeStepController::action action
)
{
    Info<< "    step not converged (" << res.reason.c_str()
        << ") after " << res.newtonIterations << " Newton iterations,"
        << " force residual " << res.forceResidual << endl;

    const scalar failedTime = runTime_.value();
    const scalar failedDeltaT = runTime_.deltaTValue();
    const scalar t0 = lastConverged.value();
    const bool atStart = t0 <= startValue_;
    runTime_.TimeState::operator=(lastConverged);
    // The failed attempt's iterate goes with it: the solid holds the last
    // converged state again (what a write shows)
    solid_.restoreCommitted();

    if (action == timeStepController::STOP)
    {
        if (!atStart)
        {
            writeNow();
        }
        FatalErrorInFunction
            << controller_.stopMessage
               (
                   failedTime, failedDeltaT, res.reason, t0, atStart
               ).c_str()
            << nl << exit(FatalError);
    }

    Info<< "    cutting the time step back to " << controller_.deltaT()
        << " s and retrying (" << controller_.nFailures() << " of "
        << controller_.maxCutBacks() << ")" << nl << endl;
}


// The output fields derived for the functions where the step was not
// written. OpenFOAM's list also writes its state (uniform/functionObjects)
// where Time's own write test says so; where the write schedule did not
// write the step (a restart from a time off the write interval,
// writeSchedule.H), that would leave a time directory without fields,
// which is taken away again
void Foam::solidTimeLoop::executeFunctions(const bool written)
{
    if (!written)
    {
        output_.update();
    }
    const bool strayState = runTime_.writeTime() && !written;
    const bool timeDirExisted = isDir(runTime_.timePath());
    runTime_.functionObjects().execute();
    if (strayState && !timeDirExisted)
    {
        rmDir(runTime_.timePath());
    }
}


// [S19] the restart record last: it marks the directory complete [S19b]
void Foam::solidTimeLoop::writeNow()
{
    output_.update();
    restartState_.set("time", runTime_.value());
    restartState_.set("timeStepController", controller_.state());
    restartState_.set("continuationFailures", nContinuationFailures_);
    restartState_.set("solid", solid_.state());
    writer_.write(restartState_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidTimeLoop::solidTimeLoop
(
    Time& runTime,
    totalLagrangianSolid& solid,
    solidOutputFields& output,
    newtonSolver& newton,
    timeStepController& controller,
    solidRestartState& restartState,
    timeDirectoryWriter& writer
)
:
    runTime_(runTime),
    solid_(solid),
    output_(output),
    newton_(newton),
    controller_(controller),
    restartState_(restartState),
    writer_(writer),
    writes_(runTime),
    performance_(runTime),
    startValue_(runTime.value()),
    userDeltaT_(runTime.deltaTValue()),
    nSteps_(0),
    nNewton_(0),
    nAccepted_(0),
    nContinuationFailures_
    (
        restartState.lookupOrDefault<label>("continuationFailures", 0)
    ),
    x_(),
    xStart_(),
    stepClock_()
{
    // controlDict's functions, as in OpenFOAM's solvers: read now, run
    // after every converged step (a rejected attempt never reaches them),
    // the output fields derived first so that they see the step's state
    runTime_.functionObjects().start();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::solidTimeLoop::running() const
{
    return runTime_.value() < runTime_.endTime().value() - 1e-9*userDeltaT_;
}


void Foam::solidTimeLoop::step()
{
    const scalar t0 = runTime_.value();

    // A rejected step must not advance Time's write index (else the
    // retried step skips its write time and adjustableRunTime aims at the
    // next one): the whole time state is restored on a cut-back
    const TimeState lastConverged(runTime_);

    runTime_.setDeltaT(writes_.step(t0, controller_.deltaT()), false);
    ++runTime_;

    Info<< "Time = " << runTime_.timeName() << ", deltaT = "
        << runTime_.deltaTValue() << endl;

    stepClock_.timeIncrement();

    const label nCutBacks = controller_.nFailures();
    timeStepController::action action;
    const newtonSolver::result res = solveLoadStep(action);

    if (res.accepted)
    {
        ++nAccepted_;
        Info<< "    accepted: Newton stalled at force residual "
            << res.forceResidual << " (acceptableForceTolerance)" << endl;
    }

    if (res.converged)
    {
        acceptStep(res, nCutBacks, t0);
    }
    else
    {
        rejectStep(lastConverged, res, action);
    }
}


void Foam::solidTimeLoop::end()
{
    if (runTime_.functionObjects().size())
    {
        runTime_.functionObjects().end();
    }

    Info<< "Steps: " << nSteps_ << ", Newton iterations: " << nNewton_
        << " (" << scalar(nNewton_)/max(nSteps_, 1) << " per step)";
    if (nAccepted_)
    {
        Info<< ", " << nAccepted_ << " accepted at acceptableForceTolerance";
    }
    Info<< endl;
}


// ************************************************************************* //

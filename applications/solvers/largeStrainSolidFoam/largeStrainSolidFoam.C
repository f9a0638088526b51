/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Application
    largeStrainSolidFoam

Group
    grpStressAnalysisSolvers

Description
    Large-strain solid mechanics in the total Lagrangian description: a
    cell-centred finite-volume discretisation of the momentum balance,
    elastic or elastoplastic at finite strain, plane strain, axisymmetric
    or 3-D, quasi-static or with inertia, solved at every time step by
    Newton's method with the exact Jacobian (doc/theory.md). Steps that do
    not converge are cut back and retried (timeStepController); the run
    stops with a message after maxCutBacks consecutive failures, keeping
    the last converged time directory. A restart from any written time
    takes the same steps as the uninterrupted run. A time directory is
    complete when its uniform/solidState, written last, is there; a
    restart from latestTime steps back from an incomplete one, a restart
    missing a history field stops naming it, and one run at a time uses a
    case folder (doc/theory.md [S19b]).

    The functions of controlDict (OpenFOAM's function objects: probes,
    fieldMinMax, surfaces, ...) run after every converged step, never
    after a rejected attempt, with the output fields (sigma, epsilonPEq,
    ...) derived for them at that step.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "totalLagrangianSolid.H"
#include "solidOutputFields.H"
#include "newtonSolver.H"
#include "timeStepController.H"
#include "solidRestartState.H"
#include "solverPerformanceFile.H"
#include "clockTime.H"
#include "writeSchedule.H"
#include "keepFreedMemory.H"
#include "timeControls.H"
#include "caseLock.H"
#include "timeDirectoryWriter.H"
#include "strictDictionary.H"
#include "numberRange.H"
#include <functional>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{

//- [S14e] The continuation retry of a step whose exact-Jacobian Newton
//  failed: the step solved from the predictor again with every contact
//  onset widened by the factor onsetContinuation, then from there with
//  the onsets as given (the answer is the given system's). Returns the
//  failed attempt's result where there is no onset to widen, the factor
//  is 1 or the run's last maxContinuationFailures continuations failed
//  (they are then off for the run: a case whose failures have another
//  cause does not pay for them at every step); else the given system's
//  solve where the continuation took the step, and the failed attempt's
//  result where it did not. The Newton iterations of every solve are
//  added to nNewton, the Krylov iterations and residual evaluations of
//  every solve to the result
static const label maxContinuationFailures = 3;

newtonSolver::result continueWithWiderOnset
(
    totalLagrangianSolid& solid,
    newtonSolver& nonlinearSolver,
    Eigen::VectorXd& x,
    Eigen::VectorXd& xStart,
    const timeStepController::predictorType predictor,
    const newtonSolver::result& failed,
    label& nNewton,
    label& nFailuresInARow
)
{
    const scalar factor = nonlinearSolver.onsetContinuation();
    if (factor <= 1 || nFailuresInARow >= maxContinuationFailures)
    {
        return failed;
    }

    // the predictor with the onsets as given, then the wider ones
    solid.beginStep(x, xStart, predictor);
    if (!solid.widenContactOnset(factor))
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
        nonlinearSolver.solve(solid, x, xStart, false);
    solid.widenContactOnset(1);
    nNewton += wide.newtonIterations;

    newtonSolver::result given;
    if (wide.converged)
    {
        given = nonlinearSolver.solve(solid, x, xStart, false);
        nNewton += given.newtonIterations;
    }
    Info<< "    continuation: " << wide.newtonIterations
        << (wide.converged ? "" : " (not converged)") << " + "
        << given.newtonIterations << " Newton iterations"
        << (given.converged ? "" : ", not converged") << endl;

    nFailuresInARow = given.converged ? 0 : nFailuresInARow + 1;
    if (nFailuresInARow == maxContinuationFailures)
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



//- [C5b] Augmented Lagrangian contact with augmentBetweenIterations no:
//  the converged step is solved again, from where it stands, with the
//  contacts' updated multipliers until their penetrations are below their
//  tolerances (with the default the Newton solver updates them between
//  its iterations and returns them converged; no contact augmented: no
//  re-solve). A solve after an update is followed by another check and
//  most likely another update, so it stops at looser tolerances (1000
//  times the controls'); when the multipliers have converged at such an
//  iterate, a last solve to the controls' tolerances (and another check)
//  follows. Every solve's Newton iterations are added to nNewton
void augmentBetweenSolves
(
    totalLagrangianSolid& solid,
    newtonSolver& nonlinearSolver,
    Eigen::VectorXd& x,
    const Eigen::VectorXd& xStart,
    const bool jacobianFree,
    newtonSolver::result& res,
    label& nNewton
)
{
    bool loose = false;
    for (label aug = 1; res.converged && !res.multipliersConverged; ++aug)
    {
        const bool update = solid.augment(x);
        if (!update && !loose)
        {
            break;
        }
        loose = update;
        const label krylov = res.krylovIterations;
        const label evaluations = res.residualEvaluations;
        res = nonlinearSolver.solve
        (
            solid, x, xStart, jacobianFree, loose ? 1e3 : 1
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


//- One load step at the step size Time holds, attempted until the
//  controller stops retrying: the exact-Jacobian Newton from the
//  predictor, its continuation retry [S14e], then the Jacobian-free retry
//  from the last solution (a bounded correction where the exact Jacobian
//  is singular) [S18]. Returns the last solve's result with the Newton
//  iterations of every solve; action: the controller's verdict
newtonSolver::result solveLoadStep
(
    totalLagrangianSolid& solid,
    newtonSolver& nonlinearSolver,
    timeStepController& controller,
    const Time& runTime,
    Eigen::VectorXd& x,
    Eigen::VectorXd& xStart,
    label& nContinuationFailures,
    timeStepController::action& action
)
{
    newtonSolver::result res;
    label nNewton = 0;
    action = timeStepController::RETRY;
    bool retry = false;
    while (action == timeStepController::RETRY)
    {
        solid.beginStep(x, xStart, controller.predictor());
        res = nonlinearSolver.solve(solid, x, xStart, retry);
        nNewton += res.newtonIterations;
        if (!res.converged && !retry)
        {
            res = continueWithWiderOnset
            (
                solid, nonlinearSolver, x, xStart, controller.predictor(),
                res, nNewton, nContinuationFailures
            );
        }
        augmentBetweenSolves
        (
            solid, nonlinearSolver, x, xStart, retry, res, nNewton
        );

        action =
            res.converged
          ? controller.converged()
          : controller.failed(runTime.deltaTValue());
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

//- controlDict's functions after a converged step, the output fields
//  derived for them where the step was not written. OpenFOAM's list also
//  writes its state (uniform/functionObjects) where Time's own write test
//  says so; where the write schedule did not write the step (a restart
//  from a time off the write interval, writeSchedule.H), that would leave
//  a time directory without fields, which is taken away again
void executeFunctions
(
    Time& runTime,
    solidOutputFields& output,
    const bool written
)
{
    if (!written)
    {
        output.update();
    }
    const bool strayState = runTime.writeTime() && !written;
    const bool timeDirExisted = isDir(runTime.timePath());
    runTime.functionObjects().execute();
    if (strayState && !timeDirExisted)
    {
        rmDir(runTime.timePath());
    }
}

//- A load step that did not converge: Time and the solid back to the last
//  converged state, and the step cut back, or with action STOP the run
//  stopped with the controller's message after writing that state
//  (writeConverged; not at the run's start, which is on disk)
void rejectStep
(
    Time& runTime,
    const TimeState& lastConverged,
    totalLagrangianSolid& solid,
    const timeStepController& controller,
    const newtonSolver::result& res,
    const timeStepController::action action,
    const bool atStart,
    const std::function<void()>& writeConverged
)
{
    Info<< "    step not converged (" << res.reason.c_str()
        << ") after " << res.newtonIterations << " Newton iterations,"
        << " force residual " << res.forceResidual << endl;

    const scalar failedTime = runTime.value();
    const scalar failedDeltaT = runTime.deltaTValue();
    const scalar t0 = lastConverged.value();
    runTime.TimeState::operator=(lastConverged);
    // The failed attempt's iterate goes with it: the solid holds the last
    // converged state again (what a write shows)
    solid.restoreCommitted();

    if (action == timeStepController::STOP)
    {
        if (!atStart)
        {
            writeConverged();
        }
        FatalErrorInFunction
            << controller.stopMessage
               (
                   failedTime, failedDeltaT, res.reason, t0, atStart
               ).c_str()
            << nl << exit(FatalError);
    }

    Info<< "    cutting the time step back to " << controller.deltaT()
        << " s and retrying (" << controller.nFailures() << " of "
        << controller.maxCutBacks() << ")" << nl << endl;
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Large-strain finite-volume solid solver (total Lagrangian,"
        " Newton-Krylov) for metal forming with frictional contact"
    );

    keepFreedMemory();

    #include "setRootCase.H"

    // [S19b] no number OpenFOAM's reading would stop on with SIGFPE,
    // controls Time would divide by, one run per case, a start time that
    // was written completely
    strictDictionary::checkNumberRanges(args.globalPath()/"system");
    strictDictionary::checkNumberRanges(args.globalPath()/"constant");
    checkTimeControls(args);
    #include "createTime.H"
    const caseLock lock(runTime, args.executable());
    timeDirectoryWriter::selectStartTime(runTime);
    strictDictionary::checkNumberRanges(runTime.timePath());
    timeDirectoryWriter writer(runTime);

    #include "createMesh.H"
    #include "createFields.H"
    #include "readSolidControls.H"

    const writeSchedule writes(runTime);
    const scalar userDeltaT = runTime.deltaTValue();
    label nSteps = 0;
    label nNewtonTotal = 0;
    label nAccepted = 0;
    // [S14e] continuations failed in a row (off at 3), carried by a restart
    label nContinuationFailures =
        restartState.lookupOrDefault<label>("continuationFailures", 0);

    solverPerformanceFile performance(runTime);

    // Write the last converged state with what a restart needs [S19],
    // the restart record last: it marks the directory complete [S19b]
    auto writeNow = [&]()
    {
        output.update();
        restartState.set("time", runTime.value());
        restartState.set("timeStepController", controller.state());
        restartState.set("continuationFailures", nContinuationFailures);
        restartState.set("solid", solid.state());
        writer.write(restartState);
    };

    // controlDict's functions, as in OpenFOAM's solvers: read now, run
    // after every converged step (a rejected attempt never reaches them),
    // the output fields derived first so that they see the step's state
    runTime.functionObjects().start();

    Eigen::VectorXd x, xStart;
    clockTime stepClock;

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.value() < runTime.endTime().value() - 1e-9*userDeltaT)
    {
        const scalar t0 = runTime.value();

        // A rejected step must not advance Time's write index (else the
        // retried step skips its write time and adjustableRunTime aims at
        // the next one): the whole time state is restored on a cut-back
        const TimeState lastConverged(runTime);

        runTime.setDeltaT(writes.step(t0, controller.deltaT()), false);
        ++runTime;

        Info<< "Time = " << runTime.timeName() << ", deltaT = "
            << runTime.deltaTValue() << endl;

        stepClock.timeIncrement();

        const label nCutBacks = controller.nFailures();
        timeStepController::action action;
        const newtonSolver::result res =
            solveLoadStep
            (
                solid, nonlinearSolver, controller, runTime, x, xStart,
                nContinuationFailures, action
            );

        if (res.accepted)
        {
            ++nAccepted;
            Info<< "    accepted: Newton stalled at force residual "
                << res.forceResidual << " (acceptableForceTolerance)" << endl;
        }

        if (!res.converged)
        {
            rejectStep
            (
                runTime, lastConverged, solid, controller, res, action,
                t0 <= startValue, writeNow
            );
            continue;
        }

        solid.commit(x);
        output.report();

        ++nSteps;
        nNewtonTotal += res.newtonIterations;

        const scalar stepTime = stepClock.timeIncrement();
        Info<< "    converged: " << res.newtonIterations
            << " Newton iterations, " << res.krylovIterations
            << " Krylov iterations, " << res.residualEvaluations
            << " residual evaluations, force residual " << res.forceResidual
            << ", " << stepTime << " s" << endl;

        performance.write(res, nCutBacks);

        const bool written = writes.due(t0);
        if (written)
        {
            // the output fields (sigma, pointD, ...) follow this schedule,
            // not Time's own write test
            writeNow();
        }
        if (runTime.functionObjects().size())
        {
            executeFunctions(runTime, output, written);
        }

        Info<< "    ExecutionTime = " << runTime.elapsedCpuTime() << " s"
            << "  ClockTime = " << runTime.elapsedClockTime() << " s"
            << nl << endl;
    }

    if (runTime.functionObjects().size())
    {
        runTime.functionObjects().end();
    }

    Info<< "Steps: " << nSteps << ", Newton iterations: " << nNewtonTotal
        << " (" << scalar(nNewtonTotal)/max(nSteps, 1) << " per step)";
    if (nAccepted)
    {
        Info<< ", " << nAccepted << " accepted at acceptableForceTolerance";
    }
    Info<< nl
        << "End\n" << endl;

    return 0;
}


// ************************************************************************* //

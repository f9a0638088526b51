/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Application
    largeStrainSolidFoam

Group
    grpStressAnalysisSolvers

Description
    Large-strain solid mechanics in the total Lagrangian description: a
    cell-centred finite-volume discretisation of the momentum balance,
    elastic or elastoplastic at finite strain, quasi-static or with
    inertia, solved at every time step by a Jacobian-free Newton-Krylov
    method preconditioned with the compact elastic operator
    (doc/theory.md). Steps that do not converge are cut back and retried;
    the run stops with a message after maxCutBacks consecutive failures,
    keeping the last converged time directory.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "pointFields.H"
#include "totalLagrangianSolid.H"
#include "newtonKrylov.H"
#include "OFstream.H"
#include "clockTime.H"
#include "writeSchedule.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Large-strain finite-volume solid solver (total Lagrangian,"
        " Newton-Krylov) for metal forming with frictional contact"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"
    #include "readSolidControls.H"

    const writeSchedule writes(runTime);
    const scalar userDeltaT = runTime.deltaTValue();
    scalar deltaT = userDeltaT;
    label nCutBacks = 0;
    label nSteps = 0;
    label nNewtonTotal = 0;
    label nAccepted = 0;

    autoPtr<OFstream> perfFile;
    if (Pstream::master())
    {
        mkDir(runTime.globalPath()/"postProcessing");
        perfFile.reset
        (
            new OFstream
            (
                runTime.globalPath()/"postProcessing"/"solverPerformance.dat",
                IOstream::ASCII, IOstream::currentVersion,
                IOstream::UNCOMPRESSED, true
            )
        );
        perfFile()
            << "# time deltaT newtonIterations krylovIterations"
            << " residualEvaluations forceResidual cutBacks wallTime" << nl;
    }

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

        runTime.setDeltaT(writes.step(t0, deltaT), false);
        ++runTime;

        Info<< "Time = " << runTime.timeName() << ", deltaT = "
            << runTime.deltaTValue() << endl;

        stepClock.timeIncrement();
        solid.beginStep(x, xStart, predictor);
        newtonKrylov::result res = nonlinearSolver.solve(solid, x, xStart);

        // The time extrapolation misleads at a kink of the load path (a
        // hold after a ramp): retry the same step from the last solution
        if (!res.converged && predictor)
        {
            Info<< "    retrying the step without the predictor" << endl;
            solid.beginStep(x, xStart, false);
            const label nNewton = res.newtonIterations;
            res = nonlinearSolver.solve(solid, x, xStart);
            res.newtonIterations += nNewton;
        }

        if (res.accepted)
        {
            ++nAccepted;
            Info<< "    accepted: Newton stalled at force residual "
                << res.forceResidual << " (acceptableForceTolerance)" << endl;
        }

        if (!res.converged)
        {
            Info<< "    step not converged (" << res.reason << ") after "
                << res.newtonIterations << " Newton iterations, force residual "
                << res.forceResidual << endl;

            const scalar failedTime = runTime.value();
            const scalar failedDeltaT = runTime.deltaTValue();
            const bool tooSmall =
                cutBackFactor*runTime.deltaTValue() < minDeltaTRatio*userDeltaT;

            if (++nCutBacks > maxCutBacks || tooSmall)
            {
                // Keep the last converged state on disk
                runTime.TimeState::operator=(lastConverged);
                if (t0 > runTime.startTime().value())
                {
                    solid.prepareWrite();
                    runTime.writeNow();
                }

                // nCutBacks counts the failed attempts: one more than the
                // cut-backs made
                FatalErrorInFunction
                    << "The step to time " << failedTime
                    << " did not converge after " << nCutBacks - 1
                    << " cut-backs of the time step (last deltaT "
                    << failedDeltaT << " s, reason: " << res.reason
                    << ")." << nl
                    << "The last converged time, " << t0 << ", is written"
                    << (
                           t0 > runTime.startTime().value()
                         ? ";"
                         : " (the start time: no step converged);"
                       )
                    << " check the loading, the boundary conditions"
                    << " and the solid controls in system/fvSolution" << nl
                    << exit(FatalError);
            }

            deltaT = cutBackFactor*runTime.deltaTValue();
            runTime.TimeState::operator=(lastConverged);
            Info<< "    cutting the time step back to " << deltaT
                << " s and retrying (" << nCutBacks << " of " << maxCutBacks
                << ")" << nl << endl;
            continue;
        }

        solid.commit(x);
        solid.reportForces();

        ++nSteps;
        nNewtonTotal += res.newtonIterations;

        const scalar stepTime = stepClock.timeIncrement();
        Info<< "    converged: " << res.newtonIterations
            << " Newton iterations, " << res.krylovIterations
            << " Krylov iterations, " << res.residualEvaluations
            << " residual evaluations, force residual " << res.forceResidual
            << ", " << stepTime << " s" << endl;

        if (perfFile.valid())
        {
            perfFile()
                << runTime.value() << ' ' << runTime.deltaTValue() << ' '
                << res.newtonIterations << ' ' << res.krylovIterations << ' '
                << res.residualEvaluations << ' ' << res.forceResidual << ' '
                << nCutBacks << ' ' << runTime.elapsedCpuTime() << endl;
        }

        nCutBacks = 0;
        deltaT = min(timeStepGrowth*deltaT, userDeltaT);

        if (writes.due(t0))
        {
            // the output fields (sigma, pointD, ...) follow this schedule,
            // not Time's own write test
            solid.prepareWrite();
            runTime.writeNow();
        }

        Info<< "    ExecutionTime = " << runTime.elapsedCpuTime() << " s"
            << "  ClockTime = " << runTime.elapsedClockTime() << " s"
            << nl << endl;
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

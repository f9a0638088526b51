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
#include "solidTimeLoop.H"
#include "keepFreedMemory.H"
#include "timeControls.H"
#include "caseLock.H"
#include "strictDictionary.H"
#include "numberRange.H"

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

    solidTimeLoop loop
    (
        runTime, solid, output, nonlinearSolver, controller, restartState,
        writer
    );

    Info<< "\nStarting time loop\n" << endl;

    while (loop.running())
    {
        loop.step();
    }

    loop.end();

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "linearSolver.H"
#include "fallbackSolver.H"
#include "PstreamReduceOps.H"
#include "OSspecific.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Members of the family that live in libraries of their own, loaded on
//  first use: the programs that never select them need not link them (nor
//  the libraries they bring, e.g. PETSc and MPI)
const char* libraryOf(const Foam::word& solverType)
{
    return solverType == "petsc" ? "liblinearSolversPetsc.so" : nullptr;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::linearSolver> Foam::linearSolver::New
(
    const dictionary& dict,
    const blockSparseMatrix& matrix
)
{
    // The dictionary the solver is built from: the user's, or with the
    // default's choice of preconditioner added
    dictionary solverDict(dict.parent(), dict);

    word solverType;
    if (dict.readIfPresent("type", solverType))
    {
        Info<< "Linear solver: " << solverType << " (from " << dict.name()
            << ")" << endl;
    }
    else
    {
        solverType = defaultChoice(solverDict, matrix);
    }

    // [S16d] a solver behind this one, where it fails
    if (solverDict.isDict("fallback"))
    {
        dictionary fallbackDict
        (
            solverDict.parent(), solverDict.subDict("fallback")
        );
        solverDict.remove("fallback");
        if
        (
            fallbackDict.lookupOrDefault<word>("type", word()) == "petsc"
         && !fallbackDict.found("prefix")
        )
        {
            // PETSc's options of the two kept apart
            fallbackDict.add
            (
                "prefix", word(solverDict.parent().dictName() + "_fallback_")
            );
        }
        return autoPtr<linearSolver>
        (
            new linearSolvers::fallbackSolver
            (
                solverDict, matrix, select(solverType, solverDict, matrix),
                fallbackDict
            )
        );
    }
    return select(solverType, solverDict, matrix);
}


Foam::word Foam::linearSolver::defaultChoice
(
    dictionary& solverDict,
    const blockSparseMatrix& matrix
)
{
    // A sparse direct factorisation wins on small 2-D problems (serial:
    // Eigen's LU, parallel: PETSc's MUMPS, so that a parallel run takes
    // the serial run's Newton iterations); its fill grows faster than
    // the cell count, so 3-D and large runs default to an iterative
    // solver with multigrid. Serial, from nestedDissectionCells on,
    // UMFPACK with METIS: its fill grows slower than Eigen's COLAMD's
    // ([S16]; on the ring wedge 0.73 times eigenLU's CPU per Newton
    // iteration at 24 576 cells, 1.2-1.35 times at 6 144, 1.1 times at
    // 1 536). Serial 2-D from krylovCells on, GMRES with GAMG, and that
    // direct solver behind it where GMRES fails [S16d]
    const dictionary& dict = solverDict;
    const label directCellLimit =
        dict.lookupOrDefault<label>("directCellLimit", 50000);
    const label nestedDissectionCells =
        dict.lookupOrDefault<label>("nestedDissectionCells", 10000);
    const label krylovCells =
        dict.lookupOrDefault<label>("krylovCells", 5000);
    const label nCells = returnReduce(matrix.nRows(), sumOp<label>());
    const bool direct = matrix.nComponents() < 3 && nCells <= directCellLimit;
    const word directType =
        nCells < nestedDissectionCells ? "eigenLU" : "umfpack";
    const bool directBehind =
        direct && !Pstream::parRun() && nCells >= krylovCells
     && !dict.found("fallback");
    word solverType =
        !direct || Pstream::parRun() || directBehind ? "petsc" : directType;
    const bool addMumps =
        direct && Pstream::parRun() && !dict.found("preconditioner");
    if (addMumps)
    {
        solverDict.add("preconditioner", word("mumps"));
    }
    if (directBehind)
    {
        addKrylovDefaults(solverDict, directType);
    }
    Info<< "Linear solver: " << solverType
        << (addMumps ? " with preconditioner mumps" : "")
        << (
               directBehind
             ? " with preconditioner "
             + solverDict.get<word>("preconditioner") + ", " + directType
             + " where it fails"
             : word()
           ).c_str()
        << " (default for "
        << (Pstream::parRun() ? "a parallel run" : "a serial run")
        << " with " << matrix.nComponents() << " unknowns per cell and "
        << nCells << " cells; directCellLimit " << directCellLimit
        << (
               direct && !Pstream::parRun()
             ? ", krylovCells " + Foam::name(krylovCells)
             + ", nestedDissectionCells " + Foam::name(nestedDissectionCells)
             : string()
           ).c_str()
        << ")" << endl;

    // Without the PETSc library: the serial sparse LU, or in parallel
    // its block-Jacobi form as a preconditioner
    const char* lib = libraryOf(solverType);
    std::string loadError;
    if
    (
        !dictionaryConstructorTablePtr_->found(solverType)
     && !(lib && Foam::dlOpen(lib, loadError))
    )
    {
        solverType =
            Pstream::parRun() ? "blockJacobiLU"
          : directBehind ? directType
          : "eigenLU";
        solverDict.remove("preconditioner");
        solverDict.remove("options");
        solverDict.remove("fallback");
        Info<< "    (petsc is not built: " << solverType << " instead)"
            << endl;
    }
    return solverType;
}


void Foam::linearSolver::addKrylovDefaults
(
    dictionary& solverDict,
    const word& directType
)
{
    // GAMG's levels smoothed by Richardson with SOR, as in 3-D: PETSc's
    // Chebyshev with point Jacobi rests on an eigenvalue estimate for a
    // symmetric operator (doc/performance.md section 12); the user's
    // entries (a preconditioner of their own, 'options') win
    if (!solverDict.found("preconditioner"))
    {
        solverDict.add("preconditioner", word("gamg"));
    }
    if (!solverDict.found("maxIterations"))
    {
        // a solve that needs more costs more than the factorisation
        // behind it
        solverDict.add("maxIterations", label(100));
    }
    // GAMG's entries with GAMG only: under another preconditioner PETSc
    // would never read them, which is an error after the first solve
    if (solverDict.get<word>("preconditioner") == "gamg")
    {
        if (!solverDict.found("nearNullSpace"))
        {
            // a one-cell aggregate's 2 unknowns carry the 2 translations,
            // not the 3 rigid-body modes (whose coarse rows are then zero,
            // and block SOR fails on them: the flat punch at 3 200 cells,
            // 16 set-ups; shifting those pivots made GMRES break down in
            // 34 of the ring's 100 steps, doc/performance.md 17.1)
            solverDict.add("nearNullSpace", word("translations"));
        }
        dictionary options(solverDict.subOrEmptyDict("options"));
        if (!options.found("mg_levels_ksp_type"))
        {
            options.add("mg_levels_ksp_type", word("richardson"));
        }
        if (!options.found("mg_levels_pc_type"))
        {
            options.add("mg_levels_pc_type", word("sor"));
        }
        solverDict.set("options", options);
    }

    dictionary fallback;
    fallback.add("type", directType);
    solverDict.add("fallback", fallback);
}


Foam::autoPtr<Foam::linearSolver> Foam::linearSolver::select
(
    const word& solverType,
    const dictionary& solverDict,
    const blockSparseMatrix& matrix
)
{
    const dictionary& dict = solverDict;
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(solverType);

    const char* lib = libraryOf(solverType);
    if (!cstrIter.found() && lib)
    {
        // The handle is never closed: the library (and PETSc's exit
        // hooks) stays loaded until the program ends
        std::string loadError;
        if (!Foam::dlOpen(lib, loadError))
        {
            FatalIOErrorInFunction(dict)
                << "Linear solver '" << solverType << "' (keyword 'type' in"
                << " dictionary " << dict.name() << ") is in " << lib
                << ", which could not be loaded:" << nl << "    "
                << loadError.c_str() << nl
                << "It is built by ./Allwmake when PETSc is installed"
                << " (Debian package petsc-dev)" << exit(FatalIOError);
        }
        cstrIter = dictionaryConstructorTablePtr_->cfind(solverType);
    }

    if (!cstrIter.found())
    {
        wordHashSet valid(dictionaryConstructorTablePtr_->toc());
        valid.insert("petsc");
        FatalIOErrorInFunction(dict)
            << "Unknown linear solver '" << solverType << "' for keyword"
            << " 'type' in dictionary " << dict.name() << nl
            << "Valid types: " << valid.sortedToc() << nl
            << exit(FatalIOError);
    }

    return autoPtr<linearSolver>(cstrIter()(solverDict, matrix));
}


// ************************************************************************* //

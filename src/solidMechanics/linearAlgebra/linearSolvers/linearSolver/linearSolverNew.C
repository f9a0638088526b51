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
        // A sparse direct factorisation wins on small 2-D problems (serial:
        // Eigen's LU, parallel: PETSc's MUMPS, so that a parallel run takes
        // the serial run's Newton iterations); its fill grows faster than
        // the cell count, so 3-D and large runs default to an iterative
        // solver with multigrid. Serial, from nestedDissectionCells on,
        // UMFPACK with METIS: its fill grows slower than Eigen's COLAMD's
        // ([S16]; on the ring wedge 0.73 times eigenLU's CPU per Newton
        // iteration at 24 576 cells, 1.2-1.35 times at 6 144, 1.1 times at
        // 1 536)
        const label directCellLimit =
            dict.lookupOrDefault<label>("directCellLimit", 50000);
        const label nestedDissectionCells =
            dict.lookupOrDefault<label>("nestedDissectionCells", 10000);
        const label nCells =
            returnReduce(matrix.nRows(), sumOp<label>());
        const bool direct =
            matrix.nComponents() < 3 && nCells <= directCellLimit;
        solverType =
            !direct || Pstream::parRun() ? "petsc"
          : nCells < nestedDissectionCells ? "eigenLU"
          : "umfpack";
        const bool addMumps =
            direct && Pstream::parRun() && !dict.found("preconditioner");
        if (addMumps)
        {
            solverDict.add("preconditioner", word("mumps"));
        }
        Info<< "Linear solver: " << solverType
            << (addMumps ? " with preconditioner mumps" : "")
            << " (default for "
            << (Pstream::parRun() ? "a parallel run" : "a serial run")
            << " with " << matrix.nComponents() << " unknowns per cell and "
            << nCells << " cells; directCellLimit " << directCellLimit
            << (
                   direct && !Pstream::parRun()
                 ? ", nestedDissectionCells "
                 + Foam::name(nestedDissectionCells)
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
            solverType = Pstream::parRun() ? "blockJacobiLU" : "eigenLU";
            if (addMumps)
            {
                solverDict.remove("preconditioner");
            }
            Info<< "    (petsc is not built: " << solverType << " instead)"
                << endl;
        }
    }

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

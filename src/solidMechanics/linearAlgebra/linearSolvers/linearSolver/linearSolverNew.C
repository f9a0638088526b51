/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearSolver.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::linearSolver> Foam::linearSolver::New
(
    const dictionary& dict,
    const blockSparseMatrix& matrix
)
{
    word solverType;
    if (dict.readIfPresent("type", solverType))
    {
        Info<< "Linear solver: " << solverType << " (from " << dict.name()
            << ")" << endl;
    }
    else
    {
        // A sparse direct factorisation wins on small 2-D problems; its
        // fill grows faster than the cell count, so 3-D, parallel and
        // large runs default to an iterative solver with multigrid
        const label directCellLimit =
            dict.lookupOrDefault<label>("directCellLimit", 50000);
        const label nCells =
            returnReduce(matrix.nRows(), sumOp<label>());
        const bool direct =
            !Pstream::parRun()
         && matrix.nComponents() < 3
         && nCells <= directCellLimit;
        solverType = direct ? "eigenLU" : "petsc";
        Info<< "Linear solver: " << solverType << " (default for "
            << (Pstream::parRun() ? "a parallel run" : "a serial run")
            << " with " << matrix.nComponents() << " unknowns per cell and "
            << nCells << " cells; directCellLimit " << directCellLimit
            << ")" << endl;

        // Without the PETSc library: the serial sparse LU, or in parallel
        // its block-Jacobi form as a preconditioner
        if (!dictionaryConstructorTablePtr_->found(solverType))
        {
            solverType = Pstream::parRun() ? "blockJacobiLU" : "eigenLU";
            Info<< "    (petsc is not built: " << solverType << " instead)"
                << endl;
        }
    }

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(solverType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown linear solver '" << solverType << "' for keyword"
            << " 'type' in dictionary " << dict.name() << nl
            << "Valid types: "
            << dictionaryConstructorTablePtr_->sortedToc() << nl
            << exit(FatalIOError);
    }

    return autoPtr<linearSolver>(cstrIter()(dict, matrix));
}


// ************************************************************************* //

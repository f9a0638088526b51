/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "eigenLU.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace linearSolvers
{
    defineTypeNameAndDebug(eigenLU, 0);
    addToRunTimeSelectionTable(linearSolver, eigenLU, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearSolvers::eigenLU::eigenLU
(
    const dictionary& dict,
    const blockSparseMatrix& matrix,
    const bool blockJacobi
)
:
    linearSolver(dict, matrix),
    analysed_(false),
    blockJacobi_(blockJacobi)
{}


Foam::linearSolvers::eigenLU::eigenLU
(
    const dictionary& dict,
    const blockSparseMatrix& matrix
)
:
    eigenLU(dict, matrix, false)
{
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'type' in dictionary " << dict.name() << " is "
            << "eigenLU, a serial solver; a parallel run needs a"
            << " distributed one (type petsc)" << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::linearSolvers::eigenLU::update()
{
    A_ = blockJacobi_ ? matrix_.localBlock() : matrix_.eigenMatrix();
    if (!analysed_)
    {
        lu_.analyzePattern(A_);
        analysed_ = true;
    }
    lu_.factorize(A_);
    return lu_.info() == Eigen::Success;
}


Foam::linearSolver::performance Foam::linearSolvers::eigenLU::solve
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    const scalar relTol
)
{
    performance p;
    x = lu_.solve(b);
    const scalar normB = b.norm();
    p.relativeResidual =
        normB > 0 ? scalar((b - A_*x).norm()/normB) : scalar(0);
    p.converged = x.allFinite();
    if (!p.converged)
    {
        p.reason = "the LU solve returned non-finite values";
    }
    return p;
}


// ************************************************************************* //

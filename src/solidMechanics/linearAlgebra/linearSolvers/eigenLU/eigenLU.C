/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "eigenLU.H"
#include "addToRunTimeSelectionTable.H"
#include "strictDictionary.H"
#include "eigenVector.H"

namespace Foam
{
namespace linearSolvers
{
    defineTypeNameAndDebug(eigenLU, 0);
    addToRunTimeSelectionTable(linearSolver, eigenLU, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::linearSolvers::eigenLU::factorise()
{
    if (!analysed_)
    {
        lu_.analyzePattern(A_);
        analysed_ = true;
    }
    lu_.factorize(A_);
    factorised_ = lu_.info() == Eigen::Success;
    factorsCurrent_ = factorised_;
    return factorised_;
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
    factorised_(false),
    factorsCurrent_(false),
    blockJacobi_(blockJacobi),
    // a preconditioner (block Jacobi) is applied as it is
    reuse_(!blockJacobi && dict.lookupOrDefault<bool>("reuse", true)),
    maxReuseIterations_
    (
        dict.lookupOrDefault<label>("maxReuseIterations", 10)
    )
{
    if (maxReuseIterations_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'maxReuseIterations' in dictionary " << dict.name()
            << " must be >= 1, got " << maxReuseIterations_ << nl
            << exit(FatalIOError);
    }
    strictDictionary::check
    (
        dict,
        defaultChoiceKeywords
        (
            dict,
            {
                "type", "directCellLimit", "nestedDissectionCells",
                "krylovCells", "reuse",
                "maxReuseIterations"
            }
        ),
        "linear solver " + dict.getOrDefault<word>("type", "eigenLU")
    );
    gmres_.preconditioner().set(lu_);
    gmres_.setMaxIterations(maxReuseIterations_);
    gmres_.set_restart(maxReuseIterations_ + 1);
}


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

Foam::string Foam::linearSolvers::eigenLU::description() const
{
    return
        reuse_
      ? "sparse LU (Eigen, COLAMD ordering), factors reused by GMRES for up"
        " to " + Foam::name(maxReuseIterations_) + " iterations"
      : "sparse LU (Eigen, COLAMD ordering)";
}


bool Foam::linearSolvers::eigenLU::update()
{
    A_ = blockJacobi_ ? matrix_.localBlock() : matrix_.eigenMatrix();
    if (reuse_ && factorised_)
    {
        // solve() decides whether the earlier factors still do
        factorsCurrent_ = false;
        return true;
    }
    return factorise();
}


Foam::linearSolver::performance Foam::linearSolvers::eigenLU::solve
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    const scalar relTol
)
{
    performance p;
    const scalar normB = b.norm();

    if (!factorsCurrent_)
    {
        // the current matrix, preconditioned by the earlier factors
        gmres_.compute(A_);
        gmres_.setTolerance(relTol);
        const Eigen::VectorXd x0(x);
        x = gmres_.solveWithGuess(b, x0);
        p.iterations = gmres_.iterations();

        // Eigen's GMRES is left preconditioned: its error is the
        // preconditioned residual, which outdated factors (a contact
        // active set that has changed since) can make small while the
        // true one is not
        if (gmres_.info() == Eigen::Success && allFinite(x))
        {
            p.relativeResidual =
                normB > 0 ? scalar((b - A_*x).norm()/normB) : scalar(0);
            if (p.relativeResidual <= relTol)
            {
                p.converged = true;
                return p;
            }
        }
        if (!factorise())
        {
            x.setConstant(NAN);
            p.reason =
                "the matrix could not be factorised (singular), linear"
                " solver eigenLU of " + dict_.name();
            return p;
        }
    }

    x = lu_.solve(b);
    p.relativeResidual =
        normB > 0 ? scalar((b - A_*x).norm()/normB) : scalar(0);
    p.converged = allFinite(x);
    if (!p.converged)
    {
        p.reason = "the LU solve returned non-finite values";
    }
    return p;
}


// ************************************************************************* //

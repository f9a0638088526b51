/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "kluLU.H"
#include "addToRunTimeSelectionTable.H"
#include "strictDictionary.H"
#include "eigenVector.H"

namespace Foam
{
namespace linearSolvers
{
    defineTypeNameAndDebug(kluLU, 0);
    addToRunTimeSelectionTable(linearSolver, kluLU, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::linearSolvers::kluLU::factorise()
{
    if (numeric_)
    {
        klu_free_numeric(&numeric_, &common_);
    }
    numeric_ = klu_factor
    (
        colStart(), rowIndex(), values(), symbolic_,
        &common_
    );
    refactored_ = false;
    factorsCurrent_ = numeric_ && common_.status == KLU_OK;
    if (debug && factorsCurrent_)
    {
        // the fill decides the cost of every (re)factorisation
        Info<< "        klu: " << columns_.n() << " unknowns, "
            << columns_.nnz() << " entries, factors L "
            << numeric_->lnz << " U " << numeric_->unz << ", "
            << common_.flops << " flops, " << symbolic_->nblocks
            << " diagonal blocks" << endl;
    }
    return factorsCurrent_;
}


Foam::scalar Foam::linearSolvers::kluLU::solveFactors
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x
)
{
    x = b;
    klu_solve(symbolic_, numeric_, x.size(), 1, x.data(), &common_);
    // the residual of the matrix the columns were gathered from
    Eigen::VectorXd Ax;
    matrix_.multiply(x, Ax);
    const scalar normB = b.norm();
    return normB > 0 ? scalar((b - Ax).norm()/normB) : scalar(0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearSolvers::kluLU::kluLU
(
    const dictionary& dict,
    const blockSparseMatrix& matrix
)
:
    linearSolver(dict, matrix),
    columns_(matrix),
    symbolic_(nullptr),
    numeric_(nullptr),
    factorsCurrent_(false),
    refactored_(false),
    fresh_(true),
    refactorTolerance_
    (
        dict.lookupOrDefault<scalar>("refactorTolerance", 1e-10)
    )
{
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'type' in dictionary " << dict.name() << " is "
            << "klu, a serial solver; a parallel run needs a"
            << " distributed one (type petsc)" << nl << exit(FatalIOError);
    }
    if (!(refactorTolerance_ > 0 && refactorTolerance_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'refactorTolerance' in dictionary " << dict.name()
            << " must be in (0, 1), got " << refactorTolerance_ << nl
            << exit(FatalIOError);
    }
    strictDictionary::check
    (
        dict,
        defaultChoiceKeywords
        (
            dict,
            {
                "type", "directCellLimit", "nestedDissectionCells", "krylovCells",
                "refactorTolerance"
            }
        ),
        "linear solver klu"
    );

    klu_defaults(&common_);
    symbolic_ = klu_analyze
    (
        columns_.n(), colStart(), rowIndex(), &common_
    );
    if (!symbolic_)
    {
        FatalErrorInFunction
            << "KLU could not analyse the pattern of " << columns_.n()
            << " unknowns (status " << common_.status << ")"
            << abort(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::linearSolvers::kluLU::~kluLU()
{
    if (numeric_)
    {
        klu_free_numeric(&numeric_, &common_);
    }
    if (symbolic_)
    {
        klu_free_symbolic(&symbolic_, &common_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::linearSolvers::kluLU::description() const
{
    return
        "sparse LU (KLU, AMD ordering), pivots of a load step's first"
        " factorisation reused while the solves stay accurate to "
      + Foam::name(refactorTolerance_);
}


bool Foam::linearSolvers::kluLU::update()
{
    columns_.gather(matrix_);
    if (fresh_ || !numeric_)
    {
        fresh_ = false;
        return factorise();
    }
    // the pivots of this step's first factorisation; a zero pivot
    // (klu_refactor fails) asks for a pivot search
    refactored_ = true;
    factorsCurrent_ =
        klu_refactor
        (
            colStart(), rowIndex(), values(), symbolic_,
            numeric_, &common_
        ) == 1
     && common_.status == KLU_OK;
    return factorsCurrent_ || factorise();
}


Foam::linearSolver::performance Foam::linearSolvers::kluLU::solve
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    const scalar
)
{
    performance p;
    bool ok = factorsCurrent_;
    if (ok)
    {
        p.relativeResidual = solveFactors(b, x);
    }
    if (ok && refactored_ && !(p.relativeResidual <= refactorTolerance_))
    {
        // the reused pivots have grown: pivot again
        if (debug)
        {
            Info<< "        klu: relative residual " << p.relativeResidual
                << " with reused pivots, factorising again" << endl;
        }
        ok = factorise();
        if (ok)
        {
            p.relativeResidual = solveFactors(b, x);
        }
    }
    if (!ok)
    {
        x.setConstant(NAN);
        p.reason =
            "the matrix could not be factorised (singular), linear solver"
            " klu of " + dict_.name();
        return p;
    }
    p.converged = allFinite(x);
    if (!p.converged)
    {
        p.reason = "the KLU solve returned non-finite values";
    }
    return p;
}


// ************************************************************************* //

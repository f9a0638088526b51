/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "fallbackSolver.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearSolvers::fallbackSolver::fallbackSolver
(
    const dictionary& dict,
    const blockSparseMatrix& matrix,
    autoPtr<linearSolver>&& first,
    const dictionary& fallbackDict
)
:
    linearSolver(dict, matrix),
    first_(std::move(first)),
    fallback_(),
    fallen_(false)
{
    if (!fallbackDict.found("type"))
    {
        FatalIOErrorInFunction(fallbackDict)
            << "Dictionary " << fallbackDict.name() << " names no 'type':"
            << " expected the linear solver that takes over where "
            << dict.lookupOrDefault<word>("type", "the first") << " fails"
            << " (e.g. type eigenLU;)" << nl << exit(FatalIOError);
    }

    // constructed now, so that a bad entry stops the run before its first
    // step (its pattern is analysed when it first factorises)
    fallback_ = linearSolver::New(fallbackDict, matrix);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::linearSolvers::fallbackSolver::fallBack(const string& why)
{
    Info<< "        linear solver " << first_->type() << " failed ("
        << why.c_str() << "): " << fallback_->type()
        << " for the rest of the load step" << endl;
    fallen_ = true;
    return fallback_->update();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::linearSolvers::fallbackSolver::description() const
{
    return
        first_->description() + "; where it fails, for the rest of the load"
        " step: " + fallback_->description();
}


void Foam::linearSolvers::fallbackSolver::forgetHistory()
{
    first_->forgetHistory();
    fallback_->forgetHistory();
    fallen_ = false;
}


bool Foam::linearSolvers::fallbackSolver::preconditionerOnly() const
{
    return (fallen_ ? fallback_ : first_)->preconditionerOnly();
}


bool Foam::linearSolvers::fallbackSolver::inexact() const
{
    return (fallen_ ? fallback_ : first_)->inexact();
}


bool Foam::linearSolvers::fallbackSolver::update()
{
    if (fallen_)
    {
        return fallback_->update();
    }
    if (first_->update())
    {
        return true;
    }
    const string why(first_->updateFailure());
    return fallBack(why.empty() ? string("its set-up failed") : why);
}


Foam::string Foam::linearSolvers::fallbackSolver::updateFailure() const
{
    return (fallen_ ? fallback_ : first_)->updateFailure();
}


Foam::linearSolver::performance Foam::linearSolvers::fallbackSolver::solve
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    const scalar relTol
)
{
    if (fallen_)
    {
        return fallback_->solve(b, x, relTol);
    }

    const Eigen::VectorXd x0(x);
    const performance tried = first_->solve(b, x, relTol);
    if (tried.converged)
    {
        return tried;
    }

    // the failed system solved again behind it, from the same guess; the
    // Krylov iterations spent on the failure counted
    x = x0;
    if (!fallBack(tried.reason.empty() ? string("no reason") : tried.reason))
    {
        performance failed = tried;
        failed.reason =
            tried.reason + "; the fallback " + fallback_->type()
          + " could not be set up either";
        return failed;
    }
    performance p = fallback_->solve(b, x, relTol);
    p.iterations += tried.iterations;
    return p;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "petscSolver.H"
#include "petscSession.H"
#include "addToRunTimeSelectionTable.H"
#include "PstreamReduceOps.H"
#include <cmath>
#include <sstream>

namespace Foam
{
namespace linearSolvers
{
    defineTypeNameAndDebug(petscSolver, 0);
    addToRunTimeSelectionTable(linearSolver, petscSolver, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- PETSc's name of a failed set-up and what it means here
std::string explain(const PCFailedReason reason)
{
    std::string s = PCFailedReasons[reason];
    switch (reason)
    {
        case PC_FACTOR_STRUCT_ZEROPIVOT:
        case PC_FACTOR_NUMERIC_ZEROPIVOT:
            return s + " (a zero pivot: the matrix is singular)";
        case PC_FACTOR_OUTMEMORY:
            return s + " (out of memory in the factorisation)";
        case PC_SUBPC_ERROR:
            return s + " (the factorisation of a processor's block failed:"
                " zero pivot)";
        default:
            return s;
    }
}

//- A PETSc error of the numbers (a zero pivot, a floating-point exception,
//  an external solver's numerical failure), which a smaller load step may
//  avoid, unlike an error of the configuration
bool numerical(const PetscErrorCode ierr)
{
    return
        ierr == PETSC_ERR_MAT_LU_ZRPVT || ierr == PETSC_ERR_MAT_CH_ZRPVT
     || ierr == PETSC_ERR_FP || ierr == PETSC_ERR_LIB
     || ierr == PETSC_ERR_NOT_CONVERGED || ierr == PETSC_ERR_CONV_FAILED;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::linearSolvers::petscSolver::check
(
    const PetscErrorCode ierr,
    const char* what
) const
{
    if (ierr)
    {
        FatalIOErrorInFunction(dict_)
            << "PETSc failed " << what << " for the linear solver of "
            << dict_.name() << " (options prefix " << options_.prefix()
            << "):" << nl
            << "    " << petscSession::message(ierr).c_str() << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearSolvers::petscSolver::petscSolver
(
    const dictionary& dict,
    const blockSparseMatrix& matrix
)
:
    linearSolver(dict, matrix),
    options_
    (
        dict.lookupOrDefault<word>("prefix", defaultPrefix(dict)), dict
    ),
    kspName_(),
    pcName_(),
    maxIterations_(500),
    view_(false),
    rigidBodyModes_(true),
    shiftZeroPivots_(false),
    shifted_(false),
    reuse_(false),
    refreshIterations_(30),
    reused_(false),
    lastConverged_(false),
    lastIterations_(0),
    nSetUps_(0),
    nReuses_(0),
    A_(matrix),
    ksp_(nullptr),
    r_(nullptr),
    nModes_(-1),
    inexact_(true),
    setUp_(false),
    setUpFailure_("update() was not called"),
    checkedOptions_(false),
    description_()
{
    petscSession::start();
    petscSession::fpeGuard guard;

    readKeywords();
    check(A_.create(options_.prefix().c_str()), "creating the matrix");
    check(VecDuplicate(A_.x(), &r_), "creating a vector");
    createKsp();

    description_ = describe();
    Info<< "Linear solver petsc: " << description_.c_str() << endl;

    // A direct solve (MUMPS or PETSc's LU as the preconditioner, whatever
    // the Krylov method around it) is exact to round-off
    {
        KSPType ksp = nullptr;
        PC pc = nullptr;
        PCType pcType = nullptr;
        check(KSPGetType(ksp_, &ksp), "querying the Krylov method");
        check(KSPGetPC(ksp_, &pc), "getting the preconditioner");
        check(PCGetType(pc, &pcType), "querying the preconditioner");
        const std::string pcs(pcType ? pcType : "");
        inexact_ =
            std::string(ksp ? ksp : "") != KSPPREONLY
         && pcs != PCLU && pcs != PCCHOLESKY;
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::linearSolvers::petscSolver::~petscSolver()
{
    if (reuse_)
    {
        Info<< "Linear solver petsc: " << nSetUps_ << " preconditioner"
            << " set-ups, " << nReuses_ << " reuses" << endl;
    }
    if (petscSession::running())
    {
        petscSession::fpeGuard guard;
        KSPDestroy(&ksp_);
        VecDestroy(&r_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::linearSolvers::petscSolver::update()
{
    petscSession::fpeGuard guard;

    check(A_.assemble(), "assembling the matrix");
    if (nModes_ < 0)
    {
        // ILU, Jacobi, MUMPS: no near-null space to set or log (BoomerAMG
        // keeps it: its vector interpolation, an option, uses it)
        nModes_ = 0;
        if (aggregationMultigrid() || pcName_ == "boomerAMG")
        {
            setNearNullSpace();
        }
        if (shiftZeroPivots())
        {
            // KSPSetFromOptions reads the shift: a solver afresh
            check(KSPDestroy(&ksp_), "destroying the solver");
            createKsp();
        }
    }

    // reusePreconditioner: the preconditioner of an earlier Jacobian
    // preconditions this one while the Krylov solves stay cheap with it
    // (the values change by a few per cent between Newton iterations).
    // The Krylov method works on the new matrix, so the Newton step is
    // the exact one to the tolerance; but a weaker preconditioner makes
    // GMRES stop right at the inexact Newton tolerance, which cost Newton
    // iterations on the 3-D ring (doc/performance.md section 12)
    const bool reuse =
        reuse_ && setUp_ && lastConverged_
     && lastIterations_ <= refreshIterations_;
    check
    (
        KSPSetReusePreconditioner(ksp_, reuse ? PETSC_TRUE : PETSC_FALSE),
        "setting the preconditioner reuse"
    );
    check
    (
        KSPSetOperators(ksp_, A_.mat(), A_.mat()),
        "setting the operator"
    );
    if (reuse)
    {
        reused_ = true;
        ++nReuses_;
        return true;
    }
    reused_ = false;
    return setUpPreconditioner();
}


void Foam::linearSolvers::petscSolver::setNearNullSpace()
{
    if (rigidBodyModes_)
    {
        check
        (
            A_.setRigidBodyModes(nModes_),
            "building the rigid-body modes"
        );
    }
    if (nModes_ > 0)
    {
        Info<< "Linear solver petsc: near-null space: " << nModes_
            << " rigid-body modes of the cell centres" << endl;
    }
    else if (rigidBodyModes_)
    {
        // The description said the modes
        Info<< "Linear solver petsc: near-null space: the "
            << matrix_.nComponents() << " translations of the block size"
            << " (no cell coordinates given for the rigid-body modes)"
            << endl;
    }
}


bool Foam::linearSolvers::petscSolver::shiftZeroPivots()
{
    if
    (
        !shiftZeroPivots_ || shifted_ || nModes_ <= 0 || pcName_ != "gamg"
     || matrix_.nComponents() != 3
    )
    {
        return false;
    }
    shifted_ = true;
    // [S16] GAMG's aggregation leaves some cells alone (aggregates of one
    // cell, whose neighbours a maximal independent set gave to other
    // roots): 3 unknowns cannot carry the 6 modes, so the tentative
    // prolongator's 3 rotation columns of such an aggregate are zero and
    // the coarse operator P^T M P has zero rows and columns there (exact
    // zeros: 1 such cell on the first upsetting3D Jacobian at 13 824
    // cells, 9 at 110 592, 8 aggregates of 194 on the two Hertz spheres;
    // interior cells, not contact rows). SOR, block-wise over PETSc's
    // inodes (a cell's unknowns), then met the singular block
    // (SUBPC_ERROR). Those rows and their restricted residuals are exact
    // zeros, so any pivot there gives the correction 0: SOR's diagonal
    // shift replaces the zero pivots, from the first set-up. Relative to
    // the largest diagonal entry, far below every nonzero one. With a
    // shift PETSc's SOR works point by point, not on the cell blocks:
    // more Krylov iterations where nothing fails (doc/performance.md
    // sections 15 and 18.2)
    Vec d = nullptr;
    PetscReal maxDiagonal = 0;
    check(VecDuplicate(A_.x(), &d), "creating a vector");
    check(MatGetDiagonal(A_.mat(), d), "reading the diagonal");
    check(VecNorm(d, NORM_INFINITY, &maxDiagonal), "computing a norm");
    check(VecDestroy(&d), "destroying a vector");
    std::ostringstream shift;
    shift.precision(3);
    shift<< std::scientific << 1e-14*std::max(maxDiagonal, PetscReal(1e-280));
    setDefault("mg_levels_pc_sor_diagonal_shift", shift.str().c_str());
    Info<< "Linear solver petsc: SOR's zero pivots (one-cell aggregates'"
        << " rotations) shifted by " << shift.str().c_str() << endl;
    return true;
}


bool Foam::linearSolvers::petscSolver::aggregationMultigrid() const
{
    // Only the smoothed-aggregation multigrids build on a near-null space
    return pcName_ == "gamg" || pcName_ == "ml";
}


bool Foam::linearSolvers::petscSolver::setUpPreconditioner()
{
    ++nSetUps_;

    // Factorisation and multigrid set-up. A numerical failure is the
    // caller's to handle (reject the step), on every processor alike
    PetscErrorCode ierr = KSPSetUp(ksp_);
    if (!ierr)
    {
        ierr = KSPSetUpOnBlocks(ksp_);
    }
    setUpFailure_.clear();
    if (ierr && numerical(ierr))
    {
        setUpFailure_ = petscSession::message(ierr);
    }
    else
    {
        check(ierr, "setting up the preconditioner");
    }
    if (setUpFailure_.empty())
    {
        PC pc = nullptr;
        PCFailedReason reason = PC_NOERROR;
        check(KSPGetPC(ksp_, &pc), "getting the preconditioner");
        check(PCGetFailedReason(pc, &reason), "querying the set-up");
        if (reason != PC_NOERROR)
        {
            setUpFailure_ = explain(reason);
        }
    }

    setUp_ = !returnReduce(!setUpFailure_.empty(), orOp<bool>());
    if (!setUp_)
    {
        // Every processor reports the first failing one's reason
        List<string> reasons(Pstream::nProcs());
        reasons[Pstream::myProcNo()] = setUpFailure_;
        Pstream::gatherList(reasons);
        Pstream::scatterList(reasons);
        forAll(reasons, proci)
        {
            if (!reasons[proci].empty())
            {
                setUpFailure_ = reasons[proci];
                if (Pstream::parRun())
                {
                    setUpFailure_ += " on processor " + Foam::name(proci);
                }
                break;
            }
        }
        if (!checkedOptions_)
        {
            // The unused-option check waits for the first solve, which a
            // failed set-up never reaches: a misspelt entry may be why it
            // failed, so the reason names what PETSc has not read yet (not
            // fatal: a numerical failure is the caller's to retry)
            std::string fromDict, fromElsewhere;
            check
            (
                options_.unused(fromDict, fromElsewhere),
                "listing the options"
            );
            if (fromDict.size() || fromElsewhere.size())
            {
                setUpFailure_ +=
                    "; PETSc has not read the options" + fromDict
                  + fromElsewhere + " so far (misspelt? 'options' in "
                  + dict_.name() + ")";
            }
        }
        Info<< "Linear solver petsc: preconditioner set-up failed ("
            << setUpFailure_.c_str() << ")" << endl;

        // PETSc keeps a failed set-up's state (in the preconditioner and
        // its sub-solvers): start afresh at the next update (the caller
        // re-assembles after rejecting the step)
        check(KSPDestroy(&ksp_), "destroying the solver");
        createKsp();
        lastConverged_ = false;
    }
    return setUp_;
}


Foam::linearSolver::performance Foam::linearSolvers::petscSolver::solve
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    const scalar relTol
)
{
    performance p;
    if (!setUp_)
    {
        p.reason = "the preconditioner set-up failed: " + setUpFailure_;
        return p;
    }

    petscSession::fpeGuard guard;

    if (b.size() != matrix_.nLocalUnknowns() || x.size() != b.size())
    {
        FatalErrorInFunction
            << "Vector sizes " << label(b.size()) << ", " << label(x.size())
            << " differ from the matrix's " << matrix_.nLocalUnknowns()
            << " local unknowns" << abort(FatalError);
    }

    Vec bp = A_.b(), xp = A_.x();
    check(A_.toPetsc(b, bp), "copying the right-hand side");
    check(A_.toPetsc(x, xp), "copying the initial guess");

    PetscReal normB = 0;
    check(VecNorm(bp, NORM_2, &normB), "computing a norm");
    if (normB == 0)
    {
        x.setZero();
        p.converged = true;
        return p;
    }

    const Eigen::VectorXd x0(x);
    p = krylovSolve(bp, xp, relTol);
    lastIterations_ = p.iterations;

    // A kept preconditioner that no longer does: build it for this matrix
    // and solve again from the caller's initial guess
    label itsBefore = 0;
    while (!p.converged && reused_)
    {
        if (debug && reused_)
        {
            Info<< "Linear solver petsc: " << p.reason.c_str() << " with the"
                << " reused preconditioner (" << p.iterations
                << " iterations): set up again" << endl;
        }
        itsBefore += p.iterations;
        reused_ = false;
        if (pcFailed())
        {
            // PETSc keeps a failed preconditioner's state
            check(KSPDestroy(&ksp_), "destroying the solver");
            createKsp();
        }
        check
        (
            KSPSetReusePreconditioner(ksp_, PETSC_FALSE),
            "setting the preconditioner reuse"
        );
        check
        (
            KSPSetOperators(ksp_, A_.mat(), A_.mat()),
            "setting the operator"
        );
        if (!setUpPreconditioner())
        {
            p = performance();
            p.reason = "the preconditioner set-up failed: " + setUpFailure_;
            return p;
        }
        check(A_.toPetsc(x0, xp), "copying the initial guess");
        p = krylovSolve(bp, xp, relTol);
        lastIterations_ = p.iterations;
    }
    p.iterations += itsBefore;
    lastConverged_ = p.converged;
    if (!p.converged && pcFailed())
    {
        // A preconditioner that failed in its application (a zero pivot
        // met in a solve): PETSc keeps its state, so the next update()
        // starts afresh; the failure is the caller's (no other
        // preconditioner or near-null space behind the user's back)
        setUpFailure_ = p.reason;
        setUp_ = false;
        check(KSPDestroy(&ksp_), "destroying the solver");
        createKsp();
        return p;
    }
    check(A_.fromPetsc(xp, x), "copying the solution");

    if (view_ && !checkedOptions_)
    {
        check(KSPView(ksp_, PETSC_VIEWER_STDOUT_WORLD), "viewing the solver");
    }
    if (!checkedOptions_)
    {
        // Every option has been read by now (some only at set-up or at
        // the end of the first solve)
        checkUnusedOptions();
        checkedOptions_ = true;
    }

    return p;
}


bool Foam::linearSolvers::petscSolver::pcFailed() const
{
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    check(KSPGetConvergedReason(ksp_, &reason), "querying the solve");
    return returnReduce(reason == KSP_DIVERGED_PC_FAILED, orOp<bool>());
}


Foam::linearSolver::performance
Foam::linearSolvers::petscSolver::krylovSolve
(
    Vec bp,
    Vec xp,
    const scalar relTol
)
{
    performance p;
    PetscReal normB = 0;
    check(VecNorm(bp, NORM_2, &normB), "computing a norm");
    check
    (
        KSPSetTolerances
        (
            ksp_, relTol, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT
        ),
        "setting the tolerance"
    );

    const PetscErrorCode ierr = KSPSolve(ksp_, bp, xp);
    if (!numerical(ierr))
    {
        check(ierr, "solving");
    }
    const std::string solveError = petscSession::message(ierr);

    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    PetscInt its = 0;
    check(KSPGetConvergedReason(ksp_, &reason), "querying the solve");
    check(KSPGetIterationNumber(ksp_, &its), "querying the solve");

    // The true residual, whatever norm the method monitored
    PetscReal normR = 0;
    check(MatMult(A_.mat(), xp, r_), "multiplying");
    check(VecAYPX(r_, -1, bp), "computing the residual");
    check(VecNorm(r_, NORM_2, &normR), "computing a norm");

    p.iterations = its;
    p.relativeResidual = normR/normB;
    p.converged =
        !returnReduce(ierr != 0, orOp<bool>())
     && reason > 0
     && std::isfinite(p.relativeResidual);

    if (!p.converged)
    {
        if (ierr)
        {
            p.reason = "PETSc error in KSPSolve: " + solveError;
        }
        else
        {
            p.reason = word(KSPConvergedReasons[reason]);
        }
        if (reason == KSP_DIVERGED_ITS)
        {
            p.reason += " (maxIterations " + Foam::name(maxIterations_)
                + " in " + dict_.name() + ")";
        }
        else if (reason == KSP_DIVERGED_PC_FAILED)
        {
            PC pc = nullptr;
            PCFailedReason pcReason = PC_NOERROR;
            KSPGetPC(ksp_, &pc);
            PCGetFailedReason(pc, &pcReason);
            p.reason += ": " + explain(pcReason);
        }
    }
    return p;
}


// ************************************************************************* //

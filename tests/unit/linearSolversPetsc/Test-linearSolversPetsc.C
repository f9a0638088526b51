/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The 'petsc' linear solver (src/linearSolversPetsc) on elastic block
    operators built without a mesh (tests/unit/include/elasticBlockOperator.H:
    Q1 elasticity on the grid of cell centres, E = 200 GPa, h = 1 cm),
    selected through linearSolver::New as the solver application does (the
    library is loaded on demand: this program does not link it).

    Without arguments (unit test, serial, with OpenFOAM's floating-point
    traps on):
      - 2-D 24 x 24 and 3-D 10^3 symmetric positive definite operators, and
        a non-symmetric 3-D one (upwind term 0.5): GMRES + BoomerAMG,
        CG + GAMG (3-D: the translations as its near-null space), GMRES +
        GAMG (the default), BiCGStab + ILU, MUMPS (and GAMG with the
        rigid-body modes on two bodies in contact, twoBodies()): converged,
        true relative residual |b - M x|/|b| below relTol (1e-10, the
        contract of solve()), the solution against the known one and
        against eigenLU (sparse LU) to the tolerances below;
      - values re-assembled with the pattern kept (M doubled): update()
        and solve() give half the known solution;
      - errors: unknown keyword, unknown keyword value, a bad raw option
        value (FatalIOError at construction); a combination PETSc cannot
        set up (GAMG on a BAIJ matrix: FatalIOError at update(), not a
        failed step; BAIJ with MUMPS solves); a misspelt raw option and an
        unused PETSC_OPTIONS entry under the prefix (error after the first
        solve); PETSC_OPTIONS overriding the dictionary; a zero row with
        MUMPS and with ILU (update() false or solve() not converged with
        the reason, then a good matrix is solved again; with a misspelt
        raw option the failed set-up's reason names it); maxIterations
        reached (not converged, reason names maxIterations); GMRES without
        a preconditioner on a matrix with a decoupled cell and b on that
        cell: DIVERGED_BREAKDOWN reported (not converged, the reason, the
        true relative residual 1).
      - a 'fallback' (fallback()): GMRES stopped at 3 iterations, eigenLU
        behind it: the failed system solved to round-off, its iterations
        counted, the rest of the step by eigenLU alone, the next step by
        GMRES first; a fallback without a type or with an unknown keyword
        is a FatalIOError; the default from krylovCells with the user's
        preconditioner (mumps) solves, without GAMG's entries (unread
        options are an error).

    With -report <file> (argList; serial, or -parallel under mpirun): the
    3-D (or -dimension 2) operator of -cells n per direction solved with
    each preconditioner of -solvers; writes per solver the Krylov
    iterations, relative residual, max error against the known solution,
    set-up and solve times (wall, and CPU of the slowest processor) and the
    peak resident memory (sum over processors). Used by the case test
    parallelLinearSolvers and by tests/benchmarks/linearSolvers.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "linearSolver.H"
#include "elasticBlockOperator.H"
#include "unitTest.H"
#include "sigFpe.H"
#include "solverRuns.H"
#include "reportMode.H"
#include <cstdlib>

using namespace Foam;

// * * * * * * * * * * * * * * * * Helpers  * * * * * * * * * * * * * * * * //

namespace
{

// Tolerances on the max error against the known solution, at relTol 1e-10:
// 10x the largest measured, 2.3e-8 (2-D, BoomerAMG) for the Krylov solvers
// (about the condition number times relTol) and 2.8e-14 (2-D, MUMPS) for
// the direct ones
const scalar tolKrylov = 3e-7;
const scalar tolDirect = 3e-13;

//- Converged to relTol, and within tol of the known solution
void checkSolved
(
    const std::string& name,
    const outcome& o,
    const scalar tol,
    const scalar relTol = 1e-10
)
{
    unitTest::checkTrue
    (
        name + ": set up and converged", o.updated && o.p.converged
    );
    // 1 % over relTol: the residual PETSc monitors is the recursive one
    unitTest::checkBelow
    (
        name + ": |b - M x|/|b|", o.p.relativeResidual, 1.01*relTol
    );
    unitTest::checkBelow(name + ": max error vs x*", o.error, tol);
}


//- FatalIOError / FatalError expected from f
template<class Fn>
bool throwsError(Fn f)
{
    try
    {
        f();
    }
    catch (const Foam::error& e)
    {
        Info<< "    (expected error: " << e.message().c_str() << ")" << endl;
        return true;
    }
    return false;
}


// * * * * * * * * * * * * * * * * Unit tests  * * * * * * * * * * * * * * //

//- Every solver of 'solvers' (ksp and preconditioner) on M: converged to
//  relTol, against the known solution and against eigenLU (sparse LU);
//  the outcomes in the order of 'solvers'
List<outcome> checkSolvers
(
    const std::string& name,
    const blockSparseMatrix& M,
    const std::vector<std::pair<std::string, std::string>>& solvers
)
{
    const outcome lu = solveWith("type eigenLU;", M);
    unitTest::checkBelow
    (
        name + " eigenLU: max error vs x*", lu.error, tolDirect
    );

    List<outcome> outcomes;
    for (const auto& s : solvers)
    {
        const std::string entries = s.first.empty() && s.second.empty()
          ? "" : "type petsc; ksp " + s.first + "; preconditioner "
            + s.second + ";";
        const std::string label = name + " "
          + (entries.empty() ? "default" : s.first + " + " + s.second);
        const scalar tol = s.second == "mumps" ? tolDirect : tolKrylov;
        outcomes.append(solveWith(entries, M));
        checkSolved(label, outcomes.last(), tol);
        unitTest::checkBelow
        (
            label + " vs eigenLU", maxError(outcomes.last().x, lu.x), tol
        );
    }
    return outcomes;
}


void symmetric()
{
    Info<< "2-D, 24 x 24 cells, nu = 0.3" << endl;
    const eo::grid g2{24, 24, 1, 0.01};
    autoPtr<blockSparseMatrix> M2 = eo::build(g2, 2e11, 0.3);
    const List<outcome> o2 = checkSolvers
    (
        "2-D", M2(),
        {{"gmres", "boomerAMG"}, {"cg", "gamg"}, {"gmres", "mumps"}}
    );
    unitTest::checkBelow
    (
        "2-D mumps: Krylov iterations", o2[2].p.iterations, 1
    );

    Info<< "3-D, 10^3 cells, nu = 0.3" << endl;
    const eo::grid g3{10, 10, 10, 0.01};
    autoPtr<blockSparseMatrix> M3 = eo::build(g3, 2e11, 0.3);
    const List<outcome> o3 = checkSolvers
    (
        "3-D", M3(),
        {
            {"", ""}, {"gmres", "boomerAMG"}, {"cg", "gamg"}, {"gmres", "ml"},
            {"gmres", "mumps"}
        }
    );
    unitTest::checkTrue
    (
        "3-D default: petsc with gamg",
        o3[0].description.find("gamg") != std::string::npos
    );

    // Iterative or direct (newtonSolver's chord step [S16b] only for the
    // former): gamg and ILU iterative, MUMPS and eigenLU direct
    for
    (
        const auto& c : std::vector<std::pair<std::string, bool>>
        {
            {"type petsc; preconditioner gamg;", true},
            {"type petsc; ksp bcgs; preconditioner ilu;", true},
            {"type petsc; preconditioner mumps;", false},
            {"type petsc; ksp preonly; preconditioner mumps;", false},
            {"type eigenLU;", false}
        }
    )
    {
        solverDict d(c.first);
        autoPtr<linearSolver> s = linearSolver::New(d(), M3());
        unitTest::checkTrue
        (
            c.first + (c.second ? " iterative" : " direct"),
            s->inexact() == c.second
        );
    }
    const outcome& gamg = o3[2];

    // The 3-D gamg default smooths each level with one Richardson + SOR
    // sweep (mg_levels_ksp_max_it 1; doc/performance.md section 12): the
    // default takes the iterations of that setting spelt out, not those
    // of two sweeps (PETSc's default), which differ on this operator
    {
        const std::string base = "type petsc; ksp gmres; preconditioner gamg;";
        const outcome one = solveWith
        (
            base + " options { mg_levels_ksp_max_it 1; }", M3()
        );
        const outcome two = solveWith
        (
            base + " options { mg_levels_ksp_max_it 2; }", M3()
        );
        checkSolved("3-D gmres + gamg, 1 sweep", one, tolKrylov);
        checkSolved("3-D gmres + gamg, 2 sweeps", two, tolKrylov);
        Info<< "    gamg default " << o3[0].p.iterations << ", 1 sweep "
            << one.p.iterations << ", 2 sweeps " << two.p.iterations
            << " iterations" << endl;
        unitTest::checkTrue
        (
            "3-D default gamg: one sweep per level (iterations of"
            " mg_levels_ksp_max_it 1)",
            o3[0].p.iterations == one.p.iterations
        );
        unitTest::checkTrue
        (
            "3-D gamg: 1 and 2 sweeps per level tell apart",
            one.p.iterations != two.p.iterations
        );
    }

    // GAMG's near-null space on an elastic operator: the rigid-body modes
    // of the coordinates (on request in 3-D) against the translations (the
    // 3-D default, for the contact Jacobians' sake, doc/performance.md
    // section 18.2; the matrix without coordinates gets them too)
    {
        const outcome rigid = solveWith
        (
            "type petsc; ksp cg; preconditioner gamg;"
            " nearNullSpace rigidBodyModes;", M3()
        );
        const outcome translations = solveWith
        (
            "type petsc; ksp cg; preconditioner gamg;"
            " nearNullSpace translations;", M3()
        );
        autoPtr<blockSparseMatrix> N = eo::build(g3, 2e11, 0.3);
        N->setCoordinates(vectorField());
        const outcome noCoordinates = solveWith
        (
            "type petsc; ksp cg; preconditioner gamg;"
            " nearNullSpace rigidBodyModes;", N()
        );
        checkSolved("3-D cg + gamg, rigid-body modes", rigid, tolKrylov);
        checkSolved("3-D cg + gamg, translations", translations, tolKrylov);
        unitTest::checkBelow
        (
            "3-D cg + gamg: iterations with the rigid-body modes over those"
            " with the translations only",
            scalar(rigid.p.iterations)/translations.p.iterations, 0.75
        );
        unitTest::checkTrue
        (
            "3-D gamg without coordinates: the translations",
            noCoordinates.p.iterations == translations.p.iterations
        );
        Info<< "    gamg default " << gamg.p.iterations << ", rigid-body "
            << rigid.p.iterations << ", translations "
            << translations.p.iterations << " iterations" << endl;
    }

    // Pattern kept, values re-assembled: M doubled, same b -> x*/2
    Info<< "3-D, values doubled after the first solve" << endl;
    {
        solverDict d("type petsc; ksp cg; preconditioner gamg;");
        autoPtr<linearSolver> s = linearSolver::New(d(), M3());
        const Eigen::VectorXd b = eo::rightHandSide(M3());
        Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
        s->update();
        s->solve(b, x, 1e-10);

        for (label i = 0; i < M3->values().size(); ++i)
        {
            const_cast<scalarList&>(M3->values())[i] *= 2;
        }
        unitTest::checkTrue("doubled: update()", s->update());
        const linearSolver::performance p = s->solve(b, x, 1e-10);
        unitTest::checkTrue("doubled: converged", p.converged);
        unitTest::checkBelow
        (
            "doubled: max error vs x*/2",
            maxError(2*x, eo::exactSolution(M3())), tolKrylov
        );
        unitTest::checkTrue
        (
            "3-D gamg: a new preconditioner per update by default",
            s->description().find("reused") == std::string::npos
        );
        for (label i = 0; i < M3->values().size(); ++i)
        {
            const_cast<scalarList&>(M3->values())[i] /= 2;
        }
    }

    // A reused preconditioner solves the new operator: multigrid built on
    // the diagonal blocks only (solved in one iteration), then kept for
    // the full operator (its fine-level smoother works on the current
    // values, the hierarchy is the old one): converged to 1e-4 on the full
    // operator (measured: 6 iterations; 5 with a new set-up)
    Info<< "3-D, a reused preconditioner" << endl;
    {
        solverDict d
        (
            "type petsc; ksp gmres; preconditioner gamg; maxIterations 40;"
            " reusePreconditioner yes; refreshIterations 40;"
        );
        scalarList& v = const_cast<scalarList&>(M3->values());
        const scalarList full(v);
        const Eigen::VectorXd b = eo::rightHandSide(M3());
        const label nc = M3->nComponents();
        // zero every block but the diagonal ones
        v = Zero;
        for (label r = 0; r < M3->nRows(); ++r)
        {
            const label diag = M3->find(r, M3->globalRow(r));
            const label start = diag*nc*nc;
            for (label k = start; k < start + nc*nc; ++k)
            {
                v[k] = full[k];
            }
        }
        autoPtr<linearSolver> s = linearSolver::New(d(), M3());
        Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
        s->update();
        const linearSolver::performance p0 = s->solve(b, x, 1e-4);
        unitTest::checkTrue("diagonal blocks: converged", p0.converged);

        v = full;
        x.setZero();
        unitTest::checkTrue("full operator: update() (reuse)", s->update());
        const linearSolver::performance p = s->solve(b, x, 1e-4);
        Info<< "    diagonal blocks " << p0.iterations << " iterations, full"
            << " operator " << p.iterations << " (reused)" << endl;
        unitTest::checkTrue
        (
            "full operator: converged with the reused preconditioner",
            p.converged
        );
        unitTest::checkBelow
        (
            "full operator: |b - M x|/|b|", p.relativeResidual, 1e-4
        );
    }
}


//- GAMG with the rigid-body modes on two bodies in frictionless contact:
//  two 3-D blocks of 13 x 13 x 3 cells, one on the other, coupled by
//  normal penalty springs (100 times a cell's stiffness) across the plane
//  between them (eo::build with contactLayer). GAMG's aggregation leaves
//  some cells alone; the rotation columns of such a one-cell aggregate
//  are zero, so are the coarse operator's rows there, and SOR on the
//  levels meets the zero pivots. With the modes SOR's diagonal shift
//  replaces those pivots from the first set-up (shiftZeroPivots, default
//  yes; [S16]); without it the set-up fails and says so (update() false:
//  no silent fall-back to the translations). The 3-D default near-null
//  space is the translations (doc/performance.md section 18.2).
//  Measured: 108 Krylov iterations with the shifted modes, 491 with the
//  translations; errors 3.7e-7 and 2.4e-6 (the penalties' condition
//  number): tolerance 10 times the larger
void twoBodies()
{
    Info<< "3-D, two bodies in contact (13 x 13 x (3 + 3) cells)" << endl;
    const eo::grid g{13, 13, 6, 0.01};
    autoPtr<blockSparseMatrix> M = eo::build(g, 2e11, 0.3, 0, 2);
    const scalar tol = 3e-5;
    const std::string base = "type petsc; ksp gmres; preconditioner gamg;";
    const outcome rigid =
        solveWith(base + " nearNullSpace rigidBodyModes;", M());
    const outcome noShift = solveWith
    (
        base + " nearNullSpace rigidBodyModes; shiftZeroPivots no;", M()
    );
    const outcome byDefault = solveWith(base, M());
    const outcome translations =
        solveWith(base + " nearNullSpace translations;", M());
    checkSolved("two bodies, gamg shifted rigid-body modes", rigid, tol);
    checkSolved("two bodies, gamg default", byDefault, tol);
    checkSolved("two bodies, gamg translations", translations, tol);
    Info<< "    rigid-body modes " << rigid.p.iterations << ", without the"
        << " shift " << noShift.p.iterations << " (" << noShift.p.reason
        << "), translations " << translations.p.iterations << " iterations"
        << endl;
    unitTest::checkTrue
    (
        "two bodies, the modes without SOR's shift: the preconditioner"
        " failed, reported (no fall-back to the translations)",
        !noShift.p.converged && !noShift.p.reason.empty()
    );
    unitTest::checkTrue
    (
        "two bodies, the default: the translations (their iterations), said"
        " in the description",
        byDefault.p.iterations == translations.p.iterations
     && byDefault.description.find("translations") != std::string::npos
    );
    unitTest::checkTrue
    (
        "two bodies, the modes: the shift said in the description",
        rigid.description.find("rigid-body modes") != std::string::npos
     && rigid.description.find("shifted") != std::string::npos
    );
    unitTest::checkBelow
    (
        "two bodies: iterations with the rigid-body modes over those with"
        " the translations",
        scalar(rigid.p.iterations)/translations.p.iterations, 0.5
    );
}


void nonSymmetric()
{
    Info<< "3-D non-symmetric (upwind term 0.5), 10^3 cells" << endl;
    const eo::grid g3{10, 10, 10, 0.01};
    autoPtr<blockSparseMatrix> M = eo::build(g3, 2e11, 0.3, 0.5);
    const Eigen::SparseMatrix<double> A = M->eigenMatrix();
    const Eigen::SparseMatrix<double> At = A.transpose();
    unitTest::checkBelow
    (
        "non-symmetric: |M - M^T|/|M| above 0.01 (so negated)",
        -(A - At).norm()/A.norm(), -0.01
    );

    checkSolvers
    (
        "non-symmetric", M(),
        {
            {"gmres", "boomerAMG"}, {"gmres", "gamg"}, {"bcgs", "ilu"},
            {"gmres", "mumps"}
        }
    );
}


void errors()
{
    const eo::grid g{8, 8, 1, 0.01};
    autoPtr<blockSparseMatrix> M = eo::build(g, 2e11, 0.3);

    FatalIOError.throwExceptions();
    FatalError.throwExceptions();

    Info<< "Input errors" << endl;
    unitTest::checkTrue
    (
        "unknown keyword -> FatalIOError",
        throwsError([&]{ solveWith("type petsc; precondtioner gamg;", M()); })
    );
    unitTest::checkTrue
    (
        "unknown preconditioner -> FatalIOError",
        throwsError([&]{ solveWith("type petsc; preconditioner amg;", M()); })
    );
    unitTest::checkTrue
    (
        "unknown ksp -> FatalIOError",
        throwsError([&]{ solveWith("type petsc; ksp minres2;", M()); })
    );
    unitTest::checkTrue
    (
        "bad raw option value -> FatalIOError",
        throwsError
        ([&]{ solveWith("type petsc; options { pc_type nonsense; }", M()); })
    );
    unitTest::checkTrue
    (
        "misspelt raw option -> FatalIOError after the first solve",
        throwsError
        ([&]{
            solveWith("type petsc; options { ksp_gmres_restrat 40; }", M());
        })
    );
    unitTest::checkTrue
    (
        "raw option of another preconditioner -> FatalIOError",
        throwsError
        ([&]{
            solveWith
            (
                "type petsc; preconditioner gamg;"
                "options { pc_hypre_boomeramg_max_iter 2; }", M()
            );
        })
    );
    unitTest::checkTrue
    (
        "a configuration PETSc cannot set up (gamg on BAIJ) -> FatalIOError",
        throwsError
        ([&]{
            solveWith
            (
                "type petsc; preconditioner gamg; options { mat_type baij; }",
                M()
            );
        })
    );
    checkSolved
    (
        "BAIJ matrix, mumps",
        solveWith
        (
            "type petsc; preconditioner mumps; options { mat_type baij; }",
            M()
        ),
        tolDirect
    );
    unitTest::checkTrue
    (
        "unused PETSC_OPTIONS entry under the prefix -> FatalError",
        throwsError
        ([&]{ solveWith("type petsc; prefix envunused_;", M()); })
    );
    {
        const outcome o = solveWith
        (
            "type petsc; prefix envwins_; ksp gmres;"
            "options { ksp_type bcgs; }", M()
        );
        unitTest::checkTrue
        (
            "PETSC_OPTIONS -envwins_ksp_type cg overrides the dictionary",
            o.description.find("Krylov method cg") != std::string::npos
        );
        checkSolved("env-selected cg", o, tolKrylov);
    }
    {
        const outcome o = solveWith
        (
            "type petsc; preconditioner jacobi; maxIterations 3;", M()
        );
        unitTest::checkTrue
        (
            "maxIterations 3: not converged, reason names maxIterations",
            !o.p.converged && o.p.iterations == 3
         && o.p.reason.find("maxIterations") != std::string::npos
        );
    }

    Info<< "Singular matrix (a zero row)" << endl;
    for (const char* pc : {"mumps", "ilu"})
    {
        solverDict d(std::string("type petsc; preconditioner ") + pc + ";");
        autoPtr<linearSolver> s = linearSolver::New(d(), M());
        scalarList& v = const_cast<scalarList&>(M->values());
        const scalarList good(v);
        const Eigen::VectorXd b = eo::rightHandSide(M());
        const label r = 5, nc = M->nComponents();
        const label first = M->rowStart()[r]*nc*nc;
        for (label i = first; i < M->rowStart()[r + 1]*nc*nc; ++i)
        {
            v[i] = 0;
        }
        const bool updated = s->update();
        Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
        const linearSolver::performance p = s->solve(b, x, 1e-10);
        Info<< "    " << pc << ": update " << updated << ", converged "
            << p.converged << ", reason: " << p.reason.c_str() << endl;
        unitTest::checkTrue
        (
            std::string(pc) + ", zero row: failure reported with a reason",
            (!updated || !p.converged) && !p.converged && p.reason.size()
        );

        v = good;
        unitTest::checkTrue
        (
            std::string(pc) + ": good matrix set up again", s->update()
        );
        x.setZero();
        const linearSolver::performance q = s->solve(b, x, 1e-10);
        Info<< "    " << pc << " again: converged " << q.converged << ", "
            << q.iterations << " iterations, residual " << q.relativeResidual
            << ", reason: " << q.reason.c_str() << endl;
        unitTest::checkTrue
        (
            std::string(pc) + ": good matrix solved again",
            q.converged
         && maxError(x, eo::exactSolution(M())) < tolKrylov
        );
    }

    Info<< "GMRES breakdown (a cell decoupled: zero block row and column)"
        << endl;
    {
        // b only on the decoupled cell lies in the null space of M: the
        // first Krylov vector maps to zero, GMRES's Hessenberg matrix gets
        // a zero diagonal (DIVERGED_BREAKDOWN, not the happy breakdown)
        // and the solution stays the initial guess: not converged, the
        // reason named, the true relative residual 1 (Newton then rejects
        // the correction, doc/theory.md [S16c])
        solverDict d("type petsc; ksp gmres; preconditioner none;");
        autoPtr<linearSolver> s = linearSolver::New(d(), M());
        scalarList& v = const_cast<scalarList&>(M->values());
        const scalarList good(v);
        const label r = 5, nc = M->nComponents();
        for (label i = 0; i < M->nRows(); ++i)
        {
            for (label k = M->rowStart()[i]; k < M->rowStart()[i + 1]; ++k)
            {
                if (i == r || k == M->find(i, M->globalRow(r)))
                {
                    for (label j = k*nc*nc; j < (k + 1)*nc*nc; ++j)
                    {
                        v[j] = 0;
                    }
                }
            }
        }
        Eigen::VectorXd b = Eigen::VectorXd::Zero(M->nLocalUnknowns());
        b.segment(r*nc, nc).setOnes();
        const bool updated = s->update();
        Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
        const linearSolver::performance p = s->solve(b, x, 1e-10);
        Info<< "    update " << updated << ", converged " << p.converged
            << ", " << p.iterations << " iterations, residual "
            << p.relativeResidual << ", reason: " << p.reason.c_str() << endl;
        unitTest::checkTrue
        (
            "breakdown: not converged, reason DIVERGED_BREAKDOWN",
            updated && !p.converged
         && p.reason.find("DIVERGED_BREAKDOWN") != std::string::npos
        );
        unitTest::checkAbs
        (
            "breakdown: true relative residual 1 (x the initial guess)",
            p.relativeResidual, 1, 1e-12
        );
        v = good;
    }

    {
        // A set-up that fails before the first solve (the unused-option
        // check's moment) names the entries PETSc has not read
        solverDict d
        (
            "type petsc; preconditioner mumps;"
            "options { pc_factor_mat_ordering_typ nd; }"
        );
        autoPtr<linearSolver> s = linearSolver::New(d(), M());
        scalarList& v = const_cast<scalarList&>(M->values());
        const scalarList good(v);
        const label r = 5, nc = M->nComponents();
        const label first = M->rowStart()[r]*nc*nc;
        for (label i = first; i < M->rowStart()[r + 1]*nc*nc; ++i)
        {
            v[i] = 0;
        }
        const bool updated = s->update();
        const Eigen::VectorXd b = eo::rightHandSide(M());
        Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
        const linearSolver::performance p = s->solve(b, x, 1e-10);
        Info<< "    mumps, zero row, misspelt option: update " << updated
            << ", reason: " << p.reason.c_str() << endl;
        unitTest::checkTrue
        (
            "failed set-up before the first solve: the reason names the"
            " unread option",
            !updated && !p.converged
         && p.reason.find("pc_factor_mat_ordering_typ") != std::string::npos
        );
        v = good;
    }

    FatalIOError.dontThrowExceptions();
    FatalError.dontThrowExceptions();
}


//- A solver with a 'fallback' behind it [S16d]: GMRES without a
//  preconditioner stopped at 3 iterations fails on the 2-D operator; the
//  system is solved by eigenLU to round-off, its Krylov iterations
//  counted; the rest of the load step goes to eigenLU alone; the next
//  step (forgetHistory) starts with GMRES again. A fallback without a
//  type, or with an unknown keyword: FatalIOError
void fallback()
{
    autoPtr<blockSparseMatrix> M =
        eo::build(eo::grid{24, 24, 1, 0.01}, 2e11, 0.3);
    const Eigen::VectorXd b = eo::rightHandSide(M());
    const Eigen::VectorXd xStar = eo::exactSolution(M());

    solverDict d
    (
        "type petsc; preconditioner none; maxIterations 3;"
        "fallback { type eigenLU; }"
    );
    autoPtr<linearSolver> s = linearSolver::New(d(), M());
    Info<< "    " << s->description().c_str() << endl;
    unitTest::checkTrue
    (
        "fallback: the description names both",
        s->description().find("Krylov") != std::string::npos
     || s->description().find("GMRES") != std::string::npos
    );
    unitTest::checkTrue
    (
        "fallback: the description names eigenLU behind",
        s->description().find("Eigen") != std::string::npos
    );

    auto solveOnce = [&](const std::string& name, const label iterations)
    {
        const bool updated = s->update();
        Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
        const linearSolver::performance p = s->solve(b, x, 1e-10);
        unitTest::checkTrue(name + ": set up and converged",
                            updated && p.converged);
        unitTest::checkBelow
        (
            name + ": |b - M x|/|b|", p.relativeResidual, 1e-12
        );
        unitTest::checkBelow
        (
            name + ": max error vs x*", maxError(x, xStar), tolDirect
        );
        // (eigenLU reuses its factors: 1 GMRES iteration on them)
        unitTest::checkTrue
        (
            name + ": Krylov iterations " + std::to_string(p.iterations)
          + (iterations ? " (GMRES's counted)" : " (eigenLU's only)"),
            iterations ? p.iterations == iterations : p.iterations <= 1
        );
        unitTest::checkTrue(name + ": exact solves after it", !s->inexact());
    };
    solveOnce("fallback, first solve of a step", 3);
    solveOnce("fallback, second solve of the step", 0);
    s->forgetHistory();
    unitTest::checkTrue("fallback: next step GMRES first", s->inexact());
    solveOnce("fallback, next step", 3);

    // The default from krylovCells with a preconditioner of the user's:
    // GAMG's own entries are not added (PETSc would not read them: an
    // error after the first solve), the LU is behind it
    {
        const outcome o =
            solveWith("krylovCells 100; preconditioner mumps;", M());
        Info<< "    " << o.description.c_str() << endl;
        checkSolved
        (
            "default from krylovCells, preconditioner mumps", o, tolDirect
        );
        unitTest::checkTrue
        (
            "default from krylovCells, preconditioner mumps: eigenLU behind",
            o.description.find("mumps") != std::string::npos
         && o.description.find("where it fails") != std::string::npos
        );
    }

    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    for
    (
        const char* entries :
        {
            "type petsc; fallback { reuse no; }",
            "type petsc; fallback { type eigenLU; reus no; }"
        }
    )
    {
        unitTest::checkTrue
        (
            std::string(entries) + ": FatalIOError",
            throwsError
            (
                [&]()
                {
                    solverDict e(entries);
                    linearSolver::New(e(), M());
                }
            )
        );
    }
    FatalIOError.dontThrowExceptions();
    FatalError.dontThrowExceptions();
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * Main * * * * * * * * * * * * * * * * //

int main(int argc, char* argv[])
{
    if (argc > 1)
    {
        return report(argc, argv);
    }

    // As in a solver: OpenFOAM's floating-point traps on
    sigFpe::set(false);
    unitTest::checkTrue("floating-point traps active", sigFpe::active());

    // Read by PetscInitialize, when the first petsc solver is built
    setenv
    (
        "PETSC_OPTIONS",
        "-envwins_ksp_type cg -envunused_pc_gamg_threshhold 0.1", 1
    );

    symmetric();
    twoBodies();
    nonSymmetric();
    errors();
    fallback();

    return unitTest::exitCode();
}


// ************************************************************************* //

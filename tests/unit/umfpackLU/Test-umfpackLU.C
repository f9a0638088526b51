/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The 'umfpack' linear solver (sparse LU by UMFPACK, the pattern analysed
    once) selected through linearSolver::New as in the solver application:
      - 2-D 24 x 24 symmetric and 3-D 8^3 non-symmetric (upwind term 0.5)
        elastic block operators (tests/unit/include/elasticBlockOperator.H),
        every strategy (symmetric, unsymmetric, auto) with every ordering
        (amd, metis, cholmod, best): the solution against the known one
        and against eigenLU to 3e-13 (10x the largest measured error of
        the direct solvers), the relative residual below 1e-12;
      - values re-assembled with the pattern kept, as at the next Newton
        iteration (the matrix times 1.001, then times 1/1.001 plus a
        non-symmetric change of 10 % of each off-diagonal block, b = M x*
        again): 'reuse no' factorises again, to the same tolerances;
        'reuse yes' solves by GMRES on the earlier factors to the requested
        relative residual 1e-10 (its true residual checked), the error below
        1e-8 (the residual times the operators' condition number, about
        1e2 here);
      - singular matrices: a 2 x 2 block of rank 1 and a zero matrix:
        update() false and the reason names the singular matrix, for
        'reuse yes' and 'no'; then a regular matrix of the same pattern
        factorises and solves again to 1e-13;
      - a bad strategy, ordering or maxReuseIterations: FatalIOError;
      - the default without a 'type' (linearSolver::New), krylovCells
        20000: eigenLU for a 2-D operator of 9 999 cells, umfpack for
        10 000 (the default nestedDissectionCells), eigenLU again for
        10 000 cells with nestedDissectionCells 20000; with the default
        krylovCells (5 000): eigenLU alone for 4 970 cells, GMRES + GAMG
        with eigenLU behind it for 5 000 and with umfpack for 10 000.

\*---------------------------------------------------------------------------*/

#include "linearSolver.H"
#include "elasticBlockOperator.H"
#include "unitTest.H"
#include "sigFpe.H"
#include "solverRuns.H"

using namespace Foam;

namespace
{

const scalar tolDirect = 3e-13;


//- Update s, solve M x = b, compare with the known x* to tol
void checkSolve
(
    const std::string& name,
    linearSolver& s,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& xRef,
    const scalar relTol,
    const scalar tol
)
{
    unitTest::checkTrue(name + ": updated", s.update());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    const linearSolver::performance p = s.solve(b, x, relTol);
    unitTest::checkTrue(name + ": converged", p.converged);
    unitTest::checkBelow
    (
        name + ": |b - M x|/|b|", p.relativeResidual, max(relTol, 1e-12)
    );
    unitTest::checkBelow(name + ": max error", maxError(x, xRef), tol);
}


//- An elastic operator: every strategy and ordering against x* and
//  eigenLU, then two Newton-like re-assemblies with the pattern kept
void elasticOperator(const std::string& name, blockSparseMatrix& M)
{
    const outcome lu = solveWith("type eigenLU; reuse no;", M);
    for (const char* strategy : {"symmetric", "unsymmetric", "auto"})
    {
        for (const char* ordering : {"amd", "metis", "cholmod", "best"})
        {
            const std::string entries =
                std::string("type umfpack; strategy ") + strategy
              + "; ordering " + ordering + ";";
            const outcome u = solveWith(entries, M);
            const std::string tag = name + " " + strategy + " " + ordering;
            unitTest::checkTrue(tag + ": converged", u.p.converged);
            unitTest::checkBelow(tag + ": max error vs x*", u.error, tolDirect);
            unitTest::checkBelow
            (
                tag + " vs eigenLU", maxError(u.x, lu.x), tolDirect
            );
        }
    }

    for (const bool reuse : {false, true})
    {
        const std::string tag = name + (reuse ? " reuse" : " no reuse");
        solverDict d(std::string("type umfpack; reuse ") + (reuse ? "yes;" : "no;"));
        autoPtr<linearSolver> s = linearSolver::New(d(), M);
        s->forgetHistory();
        const Eigen::VectorXd b = eo::rightHandSide(M);
        const Eigen::VectorXd xStar = eo::exactSolution(M);
        // a reused factorisation solves to relTol only
        const scalar relTol = reuse ? 1e-10 : 1e-12;
        const scalar tol = reuse ? 1e-8 : tolDirect;
        checkSolve(tag + " first", s(), b, xStar, relTol, tolDirect);

        scalarList& v = const_cast<scalarList&>(M.values());
        const scalarList v0(v);
        for (scalar& vi : v) { vi *= 1.001; }
        checkSolve(tag + " x 1.001", s(), b, xStar/1.001, relTol, tol);

        // 10 % more in every off-diagonal block's (0, 1) entry: b = M x*
        v = v0;
        const label nc = M.nComponents();
        for (label r = 0; r < M.nRows(); ++r)
        {
            for (label q = M.rowStart()[r]; q < M.rowStart()[r + 1]; ++q)
            {
                if (M.colCells()[q] != M.globalRow(r))
                {
                    M(q, 0, nc - 1) *= 1.1;
                }
            }
        }
        checkSolve
        (
            tag + " changed", s(), eo::rightHandSide(M), xStar, relTol, tol
        );
        v = v0;

        // a new load step: factorised afresh, exact again
        s->forgetHistory();
        checkSolve(tag + " new step", s(), b, xStar, 1e-12, tolDirect);
    }
}


//- 2 x 2: one cell, two components; singular values, then regular ones
void singular()
{
    labelListList columns(1, labelList(1, label(0)));
    blockSparseMatrix M(columns, labelList({0, 1}), globalIndex(1));
    const Eigen::VectorXd b = Eigen::Vector2d(1, 3);

    for (const bool reuse : {false, true})
    {
        const std::string tag = reuse ? " (reuse)" : " (no reuse)";
        solverDict d(std::string("type umfpack; reuse ") + (reuse ? "yes;" : "no;"));
        autoPtr<linearSolver> s = linearSolver::New(d(), M);

        for (const scalar a : {1.0, 0.0})
        {
            // [[a a] [a a]]: rank 1, then zero
            M(0, 0, 0) = a; M(0, 0, 1) = a; M(0, 1, 0) = a; M(0, 1, 1) = a;
            s->forgetHistory();
            const bool ok = s->update();
            const std::string name =
                "[[" + std::string(Foam::name(a)) + " ..]]" + tag;
            unitTest::checkTrue(name + ": update() false", !ok);
            Info<< "    (reason: " << s->updateFailure().c_str() << ")" << endl;
            unitTest::checkTrue
            (
                name + ": the reason names the singular matrix",
                s->updateFailure().find("singular matrix")
             != std::string::npos
            );
            Eigen::VectorXd x = Eigen::VectorXd::Zero(2);
            const linearSolver::performance p = s->solve(b, x, 1e-10);
            unitTest::checkTrue
            (
                name + ": solve not converged, a reason",
                !p.converged && !p.reason.empty()
            );
        }

        // [[2 1] [1 2]] x = (1 3): x = (-1/3, 5/3)
        M(0, 0, 0) = 2; M(0, 0, 1) = 1; M(0, 1, 0) = 1; M(0, 1, 1) = 2;
        s->forgetHistory();
        checkSolve
        (
            "regular after singular" + tag, s(), b,
            Eigen::Vector2d(-1.0/3, 5.0/3), 1e-12, 1e-13
        );
    }
}


//- The description of the default solver for a 2-D operator of nx x ny
//  cells
std::string defaultFor(const label nx, const label ny, const std::string& e)
{
    autoPtr<blockSparseMatrix> M =
        eo::build(eo::grid{nx, ny, 1, 0.01}, 2e11, 0.3);
    solverDict d(e);
    return linearSolver::New(d(), M())->description();
}


bool throwsError(const std::string& entries, const blockSparseMatrix& M)
{
    try
    {
        solverDict d(entries);
        linearSolver::New(d(), M);
    }
    catch (const Foam::error& e)
    {
        Info<< "    (expected error: " << e.message().c_str() << ")" << endl;
        return true;
    }
    return false;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char* argv[])
{
    sigFpe::set(false);

    Info<< "2-D, 24 x 24 cells, nu = 0.3" << endl;
    autoPtr<blockSparseMatrix> M2 =
        eo::build(eo::grid{24, 24, 1, 0.01}, 2e11, 0.3);
    elasticOperator("2-D", M2());

    Info<< "3-D non-symmetric (upwind term 0.5), 8^3 cells" << endl;
    autoPtr<blockSparseMatrix> M3 =
        eo::build(eo::grid{8, 8, 8, 0.01}, 2e11, 0.3, 0.5);
    elasticOperator("3-D non-symmetric", M3());

    Info<< "2 x 2 singular, then regular" << endl;
    singular();

    Info<< "Default solver by the cell count" << endl;
    const std::string direct = "krylovCells 20000;";
    const std::string below = defaultFor(99, 101, direct);
    const std::string at = defaultFor(100, 100, direct);
    const std::string raised =
        defaultFor(100, 100, direct + " nestedDissectionCells 20000;");
    const auto has = [](const std::string& d, const char* what)
    {
        return d.find(what) != std::string::npos;
    };
    unitTest::checkTrue
    (
        "9 999 cells, krylovCells 20000: eigenLU (" + below + ")",
        has(below, "Eigen") && !has(below, "Krylov method")
    );
    unitTest::checkTrue
    (
        "10 000 cells, krylovCells 20000: umfpack (" + at + ")",
        has(at, "UMFPACK") && !has(at, "Krylov method")
    );
    unitTest::checkTrue
    (
        "10 000 cells, krylovCells and nestedDissectionCells 20000: eigenLU ("
      + raised + ")",
        has(raised, "Eigen") && !has(raised, "Krylov method")
    );

    // [S16d] from krylovCells (5 000) on: GMRES + GAMG, the direct solver
    // of the cell count behind it
    const std::string few = defaultFor(70, 71, "");
    const std::string some = defaultFor(50, 100, "");
    const std::string many = defaultFor(100, 100, "");
    unitTest::checkTrue
    (
        "4 970 cells: eigenLU alone (" + few + ")",
        has(few, "Eigen") && !has(few, "Krylov method")
    );
    unitTest::checkTrue
    (
        "5 000 cells: GMRES + GAMG, eigenLU behind it (" + some + ")",
        has(some, "Krylov method gmres, preconditioner gamg")
     && has(some, "where it fails") && has(some, "Eigen")
    );
    unitTest::checkTrue
    (
        "10 000 cells: GMRES + GAMG, umfpack behind it (" + many + ")",
        has(many, "Krylov method gmres, preconditioner gamg")
     && has(many, "where it fails") && has(many, "UMFPACK")
    );

    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    for
    (
        const char* entries :
        {
            "strategy symmetrical;", "ordering nd;", "maxReuseIterations 0;"
        }
    )
    {
        unitTest::checkTrue
        (
            std::string(entries) + ": FatalIOError",
            throwsError(std::string("type umfpack; ") + entries, M2())
        );
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The 'klu' linear solver (sparse LU by KLU, pivots reused within a load
    step) selected through linearSolver::New as in the solver application:
      - 2-D 24 x 24 symmetric and 3-D 8^3 non-symmetric (upwind term 0.5)
        elastic block operators (tests/unit/include/elasticBlockOperator.H):
        the solution against the known one and against eigenLU to 3e-13
        (10x the largest measured error of the direct solvers), the relative
        residual below 1e-12;
      - values re-assembled with the pattern kept, as at the next Newton
        iteration (the matrix times 1.001, then times 1/1.001 plus a
        non-symmetric change of 10 % of each off-diagonal block, b = M x*
        again): solved with the reused pivots to the same tolerances;
      - a 2 x 2 matrix whose first factorisation pivots on the diagonal,
        then values for which that pivot is 1e-14 and 0 of its column: the
        reused pivots lose accuracy (1e-14) or fail (zero pivot): the solver pivots
        again: the solution to 1e-13; forgetHistory() before each update
        gives the same solutions;
      - refactorTolerance outside (0, 1): FatalIOError.

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


//- Solve M x = b with s (updated), compare with the known x*
void checkSolve
(
    const std::string& name,
    linearSolver& s,
    const blockSparseMatrix& M,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& xRef
)
{
    unitTest::checkTrue(name + ": factorised", s.update());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    const linearSolver::performance p = s.solve(b, x, 1e-10);
    unitTest::checkTrue(name + ": converged", p.converged);
    unitTest::checkBelow(name + ": |b - M x|/|b|", p.relativeResidual, 1e-12);
    unitTest::checkBelow(name + ": max error", maxError(x, xRef), tolDirect);
}


//- An elastic operator: klu against x* and eigenLU, then two Newton-like
//  re-assemblies with the pattern kept
void elasticOperator(const std::string& name, blockSparseMatrix& M)
{
    const outcome lu = solveWith("type eigenLU;", M);
    const outcome klu = solveWith("type klu;", M);
    unitTest::checkTrue(name + " klu: converged", klu.p.converged);
    unitTest::checkBelow(name + " klu: max error vs x*", klu.error, tolDirect);
    unitTest::checkBelow
    (
        name + " klu vs eigenLU", maxError(klu.x, lu.x), tolDirect
    );

    solverDict d("type klu;");
    autoPtr<linearSolver> s = linearSolver::New(d(), M);
    s->forgetHistory();
    const Eigen::VectorXd b = eo::rightHandSide(M);
    const Eigen::VectorXd xStar = eo::exactSolution(M);
    checkSolve(name + " first", s(), M, b, xStar);

    scalarList& v = const_cast<scalarList&>(M.values());
    const scalarList v0(v);
    for (scalar& vi : v) { vi *= 1.001; }
    checkSolve(name + " x 1.001, pivots reused", s(), M, b, xStar/1.001);

    // 10 % more in every off-diagonal block's (0, 1) entry: b = M x* again
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
        name + " changed, pivots reused", s(), M, eo::rightHandSide(M), xStar
    );
    v = v0;
}


//- 2 x 2: one cell, two components
void pivotChange()
{
    Info<< "2 x 2, pivot 1 then 1e-14 then 0" << endl;
    labelListList columns(1, labelList(1, label(0)));
    blockSparseMatrix M(columns, labelList({0, 1}), globalIndex(1));
    const Eigen::VectorXd b = Eigen::Vector2d(1, 3);

    for (const bool forget : {false, true})
    {
        const std::string tag = forget ? " (history forgotten)" : "";
        solverDict d("type klu;");
        autoPtr<linearSolver> s = linearSolver::New(d(), M);
        for (const scalar a : {1.0, 1e-14, 0.0})
        {
            // [[a 1] [1 2]] x = (1 3): x = (1, 1 - 3 a)/(1 - 2 a)
            M(0, 0, 0) = a; M(0, 0, 1) = 1; M(0, 1, 0) = 1; M(0, 1, 1) = 2;
            const Eigen::VectorXd x = Eigen::Vector2d(1, 1 - 3*a)/(1 - 2*a);
            if (forget)
            {
                s->forgetHistory();
            }
            checkSolve("a = " + std::string(Foam::name(a)) + tag, s(), M, b, x);
        }
    }
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
    autoPtr<blockSparseMatrix> M2 = eo::build(eo::grid{24, 24, 1, 0.01}, 2e11, 0.3);
    elasticOperator("2-D", M2());

    Info<< "3-D non-symmetric (upwind term 0.5), 8^3 cells" << endl;
    autoPtr<blockSparseMatrix> M3 =
        eo::build(eo::grid{8, 8, 8, 0.01}, 2e11, 0.3, 0.5);
    elasticOperator("3-D non-symmetric", M3());

    pivotChange();

    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    for (const char* t : {"0", "1", "-1e-10"})
    {
        unitTest::checkTrue
        (
            std::string("refactorTolerance ") + t + ": FatalIOError",
            throwsError
            (
                std::string("type klu; refactorTolerance ") + t + ";", M2()
            )
        );
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Newton's method on small nonlinear systems without a mesh
    (doc/theory.md [S14]-[S16]):
      - a stiffening spring chain R = b - K x - c x^3 (exact Jacobian):
        converges to the solution, quadratically (|R_k+1| <= C |R_k|^2);
      - the same, Jacobian-free: converges, with Krylov iterations;
      - R = -atan(x) from x0 = 3, where the full Newton step diverges: the
        line search brings it to 0;
      - a singular Jacobian: the solve fails with the system's reason;
      - a residual with a noise floor of 1e-6: converges only with
        acceptableForceTolerance, and says so;
      - a residual without a root (|R| 0.1-0.3): by default the solve runs
        to maxNewtonIterations; with stallStopIterations 12 and 2 it fails
        early, reason "stalled", the best iterate returned; with the noise
        floor at 1e-6 (below 1e-4 |F|) it runs on [S14f];
      - a 1-D penalty contact R = 1 - x - K max(x - g, 0) from a predictor
        just short of contact (no fraction of the first step lowers |R|):
        with rejectPredictor the solve restarts from xStart (the second
        Jacobian is taken there) and converges; without, it does not
        (the default; the second Jacobian is taken elsewhere) [S16b];
      - initialForcingTerm sets the first linear solve's relative
        tolerance (default 1e-4);
      - the displacement test by the error estimate stops earlier than by
        the last correction, and the returned iterate's true error is
        within the tolerance [S16b];
      - finalChordStep (default yes): once the force test is met, the
        iteration left for the displacement test takes no new Jacobian
        (one Jacobian fewer per chord step), with the same iterations and
        a solution within the tolerance as without, if the linear solves
        are iterative; with a direct solver no chord step [S16b];
      - a linear solve that stops short (mock of a GMRES breakdown) with a
        true relative residual >= 1: the solve fails at once, naming the
        reason, x untouched; below 1 the correction is taken and Newton
        converges; a chord step's failed solve is redone with a new
        Jacobian [S16c];
      - augmented Lagrangian contact ([C5b]): a spring pressed onto an
        obstacle with a soft penalty Ka and a multiplier lambda,
        R = 1 - x - max(lambda + Ka (x - g), 0): the multipliers updated
        between the Newton iterations converge to the exact contact
        (x = g, lambda = 1 - g) within the multiplier tolerance, in one
        solve that reports them converged, each update absorbed by a
        chord step (fewer Jacobians than iterations); with
        augmentBetweenIterations no, the solve is the penalty's alone.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "newtonSolver.H"
#include "IStringStream.H"
#include "eigenVector.H"
#include <fenv.h>
#include <limits>

using namespace Foam;
using namespace unitTest;

//- A small system with a dense Jacobian; which one by 'kind'
class testSystem
:
    public nonlinearSystem
{
public:

    enum kindType
    {
        SPRINGS, ATAN, SINGULAR, NOISY, PENALTY, AUGMENTED, STALLED
    };

    //- PENALTY: spring 1, obstacle at g with stiffness Kp
    static constexpr scalar g = 1e-3;
    static constexpr scalar Kp = 1e4;

    kindType kind;
    //- Pretend the linear solves are iterative (inexactJacobianSolve)
    bool inexact = false;
    Eigen::MatrixXd K;
    Eigen::VectorXd b;
    Eigen::MatrixXd M;
    List<scalar> jacobianResiduals;
    //- The relative tolerance asked of every linear solve
    List<scalar> relTols;
    //- Mock of a Krylov solve that stops short (a GMRES breakdown): if
    //  > 0, solves (all of them, or with chordOnly only those with the
    //  Jacobian of the solve before: chord steps) return not converged,
    //  reason DIVERGED_BREAKDOWN, with dx = (1 - r) M^-1 b, whose true
    //  relative residual |b - M dx|/|b| is r
    scalar breakdownResidual = 0;
    bool chordOnly = false;
    //- NOISY: the amplitude of its noise floor
    scalar noise = 1e-6;
    label nSolvesSinceJacobian = 0;

    //- AUGMENTED: soft penalty, multiplier, its tolerance [m], updates
    static constexpr scalar Ka = 10;
    scalar lambda = 0;
    scalar multiplierTolerance = 1e-9;
    label nUpdates = 0;

    explicit testSystem(const kindType k)
    :
        kind(k)
    {
        const label n = (k == SPRINGS) ? 3 : 1;
        K.setZero(n, n);
        b.setZero(n);
        if (k == SPRINGS)
        {
            // a chain fixed at one end: SPD
            K << 2, -1, 0,   -1, 2, -1,   0, -1, 1;
            b << 0, 0, 5;
        }
    }

    virtual label nDofs() const { return b.size(); }

    virtual void residual(const Eigen::VectorXd& x, Eigen::VectorXd& R)
    {
        switch (kind)
        {
            case SPRINGS:
                R = b - K*x - 0.5*x.array().cube().matrix();
                break;
            case ATAN:
                R.resize(1);
                R(0) = -std::atan(x(0));
                break;
            case SINGULAR:
                R.resize(1);
                R(0) = 1 - sqr(x(0));
                break;
            case NOISY:
                R.resize(1);
                R(0) = -(x(0) - 1) + noise*std::sin(1e9*x(0));
                break;
            case PENALTY:
                R.resize(1);
                R(0) = 1 - x(0) - Kp*max(x(0) - g, 0);
                break;
            case AUGMENTED:
                R.resize(1);
                R(0) = 1 - x(0) - max(lambda + Ka*(x(0) - g), 0);
                break;
            case STALLED:
                // no root: |R| between 0.1 and 0.3 of |F| wherever x is
                R.resize(1);
                R(0) = 0.1*(2 + std::sin(1e9*x(0)));
                break;
        }
    }

    virtual scalar forceScale() const { return 1; }

    virtual scalar typicalDisplacement() const { return 1; }

    virtual bool updateJacobian(const Eigen::VectorXd& x)
    {
        Eigen::VectorXd R;
        residual(x, R);
        jacobianResiduals.append(R.norm());
        nSolvesSinceJacobian = 0;
        switch (kind)
        {
            case SPRINGS:
                M = K;
                M.diagonal() += 1.5*x.array().square().matrix();
                return true;
            case ATAN:
                M.setConstant(1, 1, 1/(1 + sqr(x(0))));
                return true;
            case SINGULAR:
                // 2 x: singular at the start x = 0
                return x(0) != 0;
            case NOISY:
            case STALLED:
                M.setConstant(1, 1, 1);
                return true;
            case PENALTY:
                M.setConstant(1, 1, 1 + (x(0) > g ? Kp : 0));
                return true;
            case AUGMENTED:
                M.setConstant(1, 1, 1 + (lambda + Ka*(x(0) - g) > 0 ? Ka : 0));
                return true;
        }
        return false;
    }

    virtual string failure() const
    {
        return "test: singular";
    }

    virtual bool inexactJacobianSolve() const
    {
        return inexact;
    }

    virtual bool augmentable() const
    {
        return kind == AUGMENTED;
    }

    //- Uzawa: lambda <- tN until it moves by less than the tolerance
    //  times Ka
    virtual bool augment(const Eigen::VectorXd& x)
    {
        const scalar tN = max(lambda + Ka*(x(0) - g), 0);
        if (mag(tN - lambda)/Ka <= multiplierTolerance)
        {
            return false;
        }
        lambda = tN;
        ++nUpdates;
        return true;
    }

    virtual linearSolver::performance solveJacobian
    (
        const Eigen::VectorXd& r,
        Eigen::VectorXd& dx,
        const scalar relTol
    )
    {
        relTols.append(relTol);
        dx = M.lu().solve(r);
        linearSolver::performance p;
        p.converged = true;
        if
        (
            breakdownResidual > 0
         && (!chordOnly || nSolvesSinceJacobian > 0)
        )
        {
            dx *= 1 - breakdownResidual;
            p.converged = false;
            p.iterations = 30;
            p.relativeResidual = breakdownResidual;
            p.reason = "DIVERGED_BREAKDOWN";
        }
        ++nSolvesSinceJacobian;
        return p;
    }
};


int main()
{
    Info<< "Finiteness tests under trapped floating-point exceptions" << endl;
    {
        // As OpenFOAM's FOAM_SIGFPE traps them: an infinite correction
        // from a failed linear solve must make gFinite false (the step is
        // cut back), not raise SIGFPE (Eigen's allFinite() computes
        // inf - inf)
        feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
        Eigen::VectorXd v(Eigen::VectorXd::Ones(4));
        checkTrue("finite vector", gFinite(v));
        v(2) = std::numeric_limits<double>::infinity();
        checkTrue("an infinite entry is caught", !gFinite(v));
        v(2) = -std::numeric_limits<double>::infinity();
        checkTrue("a negative infinite entry is caught", !gFinite(v));
        v(2) = std::numeric_limits<double>::quiet_NaN();
        checkTrue("a NaN entry is caught", !gFinite(v));
        fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    }

    Info<< "Stiffening springs, exact Newton" << endl;
    {
        testSystem sys(testSystem::SPRINGS);
        newtonSolver newton
        (
            controls("forceTolerance 1e-12; displacementTolerance 1e-10;")
        );
        Eigen::VectorXd x(Eigen::VectorXd::Zero(3)), x0(x);
        const newtonSolver::result res = newton.solve(sys, x, x0);
        Eigen::VectorXd R;
        sys.residual(x, R);
        checkTrue("converged", res.converged);
        checkBelow("|R| at the solution", R.norm(), 1e-12);
        checkBelow("Newton iterations", res.newtonIterations, 12);
        checkAbs("no Krylov iterations (direct)", res.krylovIterations, 0, 0);

        // quadratic: |R_k+1|/|R_k|^2 bounded over the last iterations
        const List<scalar>& r = sys.jacobianResiduals;
        scalar worst = 0;
        for (label k = r.size() - 3; k + 1 < r.size(); ++k)
        {
            if (k >= 0 && r[k] < 1e-1 && r[k + 1] > 1e-14)
            {
                worst = max(worst, r[k + 1]/sqr(r[k]));
            }
        }
        Info<< "    residuals at the Jacobians: " << r << endl;
        checkBelow("quadratic rate |R_k+1|/|R_k|^2", worst, 10);
    }

    Info<< "Stiffening springs, Jacobian-free" << endl;
    {
        testSystem sys(testSystem::SPRINGS);
        newtonSolver newton
        (
            controls
            (
                "newtonMethod jacobianFree; forceTolerance 1e-10;"
                " displacementTolerance 1e-8; krylovRefresh 100;"
            )
        );
        Eigen::VectorXd x(Eigen::VectorXd::Zero(3)), x0(x);
        const newtonSolver::result res = newton.solve(sys, x, x0);
        Eigen::VectorXd R;
        sys.residual(x, R);
        checkTrue("converged", res.converged);
        checkBelow("|R| at the solution", R.norm(), 1e-10);
        checkTrue("Krylov iterations counted", res.krylovIterations > 0);
        checkAbs
        (
            "one Jacobian (refreshed only at the start)",
            sys.jacobianResiduals.size(), 1, 0
        );
    }

    Info<< "atan from x0 = 3: the line search" << endl;
    {
        testSystem sys(testSystem::ATAN);
        newtonSolver newton(controls("forceTolerance 1e-12;"));
        Eigen::VectorXd x(Eigen::VectorXd::Constant(1, 3)), x0(x);
        const newtonSolver::result res = newton.solve(sys, x, x0);
        checkTrue("converged", res.converged);
        checkAbs("root 0", x(0), 0, 1e-12);
    }

    Info<< "Singular Jacobian" << endl;
    {
        testSystem sys(testSystem::SINGULAR);
        newtonSolver newton(controls(""));
        Eigen::VectorXd x(Eigen::VectorXd::Zero(1)), x0(x);
        const newtonSolver::result res = newton.solve(sys, x, x0);
        checkTrue("not converged", !res.converged);
        checkTrue("the system's reason", res.reason == "test: singular");
    }

    Info<< "Noise floor 1e-6" << endl;
    {
        testSystem sys(testSystem::NOISY);
        newtonSolver strict
        (
            controls("forceTolerance 1e-9; maxNewtonIterations 15;")
        );
        Eigen::VectorXd x(Eigen::VectorXd::Zero(1)), x0(x);
        const newtonSolver::result a = strict.solve(sys, x, x0);
        checkTrue("fails without acceptableForceTolerance", !a.converged);

        newtonSolver lenient
        (
            controls
            (
                "forceTolerance 1e-9; maxNewtonIterations 15;"
                " acceptableForceTolerance 1e-5; stallIterations 3;"
            )
        );
        x.setZero();
        const newtonSolver::result b = lenient.solve(sys, x, x0);
        checkTrue("accepted below 1e-5", b.converged && b.accepted);
        checkBelow("accepted residual", b.forceResidual, 1e-5);
        checkAbs("near the root", x(0), 1, 1e-5);
    }

    Info<< "Stalled solves: stallStopIterations [S14f]" << endl;
    {
        // |R| between 0.1 and 0.3 |F| everywhere: stalled far from an answer
        testSystem sys(testSystem::STALLED);
        Eigen::VectorXd x(Eigen::VectorXd::Zero(1)), x0(x);
        newtonSolver runsOn(controls("forceTolerance 1e-9;"));
        const newtonSolver::result a = runsOn.solve(sys, x, x0);
        checkAbs("default (off): to maxNewtonIterations", a.newtonIterations, 25, 0);

        newtonSolver twelve
        (
            controls("forceTolerance 1e-9; stallStopIterations 12;")
        );
        x.setZero();
        const newtonSolver::result d = twelve.solve(sys, x, x0);
        Info<< "    12: stopped after " << d.newtonIterations
            << " iterations: " << d.reason.c_str() << endl;
        checkTrue
        (
            "stallStopIterations 12: fails before maxNewtonIterations, reason"
            " stalled",
            !d.converged && d.newtonIterations < 25
         && d.reason.find("stalled") != std::string::npos
        );

        newtonSolver stops
        (
            controls("forceTolerance 1e-9; stallStopIterations 2;")
        );
        x.setZero();
        const newtonSolver::result b = stops.solve(sys, x, x0);
        Info<< "    stopped after " << b.newtonIterations << " iterations: "
            << b.reason.c_str() << endl;
        checkTrue
        (
            "stallStopIterations 2: fails, reason stalled",
            !b.converged && b.reason.find("stalled") != std::string::npos
        );
        checkBelow("stallStopIterations 2: early", b.newtonIterations, 10);

        // the iterate returned is the one whose residual is reported, at
        // most the start's (0.2)
        Eigen::VectorXd Rb;
        sys.residual(x, Rb);
        checkAbs("the returned iterate's |R|", Rb.norm(), b.forceResidual, 1e-14);
        checkBelow("the best iterate, below the start's", b.forceResidual, 0.2);

        // the floor at 1e-6 |F|, below 1e-4: near the answer, it runs on
        testSystem near(testSystem::NOISY);
        x.setZero();
        const newtonSolver::result c = stops.solve(near, x, x0);
        checkTrue
        (
            "stalled below 1e-4 |F|: runs on (" + c.reason + ")",
            c.newtonIterations == 25 && c.reason.find("stalled") == string::npos
        );
    }

    Info<< "Penalty contact from a predictor short of contact" << endl;
    {
        // xStart in contact (the last converged state), the predictor
        // x0 = 0 just outside: its Jacobian lacks the obstacle, the full
        // step penetrates deep and |R| grows linearly along it
        const Eigen::VectorXd xStart(Eigen::VectorXd::Constant(1, 5e-3));
        Eigen::VectorXd RStart;
        testSystem probe(testSystem::PENALTY);
        probe.residual(xStart, RStart);
        const scalar xStar = (1 + testSystem::Kp*testSystem::g)
           /(1 + testSystem::Kp);

        testSystem sys(testSystem::PENALTY);
        newtonSolver newton
        (
            controls("maxNewtonIterations 4; rejectPredictor yes;")
        );
        Eigen::VectorXd x(Eigen::VectorXd::Zero(1));
        const newtonSolver::result res = newton.solve(sys, x, xStart);
        Info<< "    residuals at the Jacobians: " << sys.jacobianResiduals
            << endl;
        checkTrue("predictor rejected", res.predictorRejected);
        checkTrue
        (
            "second Jacobian at xStart",
            sys.jacobianResiduals.size() >= 2
         && sys.jacobianResiduals[1] == RStart.norm()
        );
        checkTrue("converged", res.converged);
        checkAbs("root", x(0), xStar, 1e-12);

        testSystem sys2(testSystem::PENALTY);
        // the default: off
        newtonSolver keep(controls("maxNewtonIterations 4;"));
        x.setZero();
        const newtonSolver::result res2 = keep.solve(sys2, x, xStart);
        checkTrue("without: not rejected", !res2.predictorRejected);
        checkTrue
        (
            "without: second Jacobian elsewhere",
            sys2.jacobianResiduals.size() >= 2
         && sys2.jacobianResiduals[1] != RStart.norm()
        );
    }

    Info<< "initialForcingTerm" << endl;
    {
        testSystem a(testSystem::SPRINGS), b(testSystem::SPRINGS);
        newtonSolver byDefault(controls(""));
        newtonSolver tight(controls("initialForcingTerm 1e-2;"));
        Eigen::VectorXd x(Eigen::VectorXd::Zero(3)), x0(x);
        byDefault.solve(a, x, x0);
        x.setZero();
        tight.solve(b, x, x0);
        checkAbs("default first tolerance", a.relTols[0], 1e-4, 1e-15);
        checkAbs("set first tolerance", b.relTols[0], 1e-2, 1e-15);
    }

    Info<< "Displacement test: error estimate against last correction"
        << endl;
    {
        // the solution to round-off first
        testSystem ref(testSystem::SPRINGS);
        newtonSolver tight
        (
            controls("forceTolerance 1e-14; displacementTolerance 1e-14;")
        );
        Eigen::VectorXd xStar(Eigen::VectorXd::Zero(3)), x0(xStar);
        tight.solve(ref, xStar, x0);

        // (the corrections are 1.1e-1, 1.7e-2, 3.4e-4, 1.3e-7 of the
        // increment: 1e-5 lies between the 3rd correction and the
        // estimate of the error after it, 6.9e-6)
        // (Newton steps only: a chord step is not estimated from)
        const char* common =
            "forceTolerance 1; displacementTolerance 1e-5;"
            " finalChordStep no;";
        label iterations[2];
        for (label k = 0; k < 2; ++k)
        {
            testSystem sys(testSystem::SPRINGS);
            newtonSolver newton
            (
                controls
                (
                    (
                        std::string(common) + " displacementTest "
                      + (k == 0 ? "estimate;" : "correction;")
                    ).c_str()
                )
            );
            Eigen::VectorXd x(Eigen::VectorXd::Zero(3));
            const newtonSolver::result res = newton.solve(sys, x, x0);
            checkTrue("converged", res.converged);
            iterations[k] = res.newtonIterations;
            const scalar err = (x - xStar).cwiseAbs().maxCoeff()
               /(x - x0).cwiseAbs().maxCoeff();
            Info<< "    " << (k == 0 ? "estimate" : "correction") << ": "
                << res.newtonIterations << " iterations, true relative"
                << " error " << err << endl;
            checkBelow("true error within the tolerance", err, 1e-5);
        }
        checkBelow
        (
            "estimate: fewer iterations", iterations[0], iterations[1] - 0.5
        );
    }

    Info<< "finalChordStep: the displacement test's step without a new"
        << " Jacobian" << endl;
    {
        // the force test is met first (forceTolerance 1e-6 of |F| = 1),
        // the displacement test (1e-10) needs one more step: by default a
        // chord step with the Jacobian of the iteration before, if the
        // linear solves are iterative (k = 0, 1); a direct solver's steps
        // stay Newton steps (k = 2)
        testSystem ref(testSystem::SPRINGS);
        newtonSolver tight
        (
            controls("forceTolerance 1e-14; displacementTolerance 1e-14;")
        );
        Eigen::VectorXd xStar(Eigen::VectorXd::Zero(3)), x0(xStar);
        tight.solve(ref, xStar, x0);

        // (the displacement test by the correction: a chord step is never
        // estimated from, so with the estimate the run without chord steps
        // may stop an iteration earlier)
        const char* common =
            "forceTolerance 1e-6; displacementTolerance 1e-10;"
            " displacementTest correction;";
        newtonSolver::result res[3];
        label nJacobians[3];
        for (label k = 0; k < 3; ++k)
        {
            testSystem sys(testSystem::SPRINGS);
            sys.inexact = k < 2;
            newtonSolver newton
            (
                controls
                (
                    (
                        std::string(common)
                      + (k == 1 ? " finalChordStep no;" : "")
                    ).c_str()
                )
            );
            Eigen::VectorXd x(Eigen::VectorXd::Zero(3));
            res[k] = newton.solve(sys, x, x0);
            nJacobians[k] = sys.jacobianResiduals.size();
            const scalar err = (x - xStar).cwiseAbs().maxCoeff()
               /(x - x0).cwiseAbs().maxCoeff();
            Info<< "    "
                << (k == 0 ? "chord (default)" : k == 1 ? "no chord" : "direct")
                << ": "
                << res[k].newtonIterations << " iterations, "
                << nJacobians[k] << " Jacobians, " << res[k].chordSteps
                << " chord steps, true relative error " << err << endl;
            checkTrue("converged", res[k].converged);
            checkBelow("true error within the tolerance", err, 1e-10);
            checkAbs
            (
                "Jacobians = Newton iterations - chord steps",
                nJacobians[k],
                res[k].newtonIterations - res[k].chordSteps, 0
            );
        }
        checkAbs("default: one chord step", res[0].chordSteps, 1, 0);
        checkAbs("finalChordStep no: none", res[1].chordSteps, 0, 0);
        checkAbs("a direct solver: none", res[2].chordSteps, 0, 0);
        checkAbs
        (
            "the same Newton iterations", res[0].newtonIterations,
            res[1].newtonIterations, 0
        );
    }

    Info<< "A linear solve that breaks down [S16c]" << endl;
    {
        // true relative residual 3 (GMRES's breakdown on the 3-D
        // two-sphere contact Jacobian: 1.1-18): no descent direction; the
        // Newton solve fails at once with the reason, x untouched (the
        // caller retries the step). Before, the correction was taken and
        // the solve crept on line-search fractions to maxNewtonIterations
        testSystem sys(testSystem::SPRINGS);
        sys.breakdownResidual = 3;
        newtonSolver newton(controls("forceTolerance 1e-10;"));
        Eigen::VectorXd x(Eigen::VectorXd::Zero(3)), x0(x);
        const newtonSolver::result res = newton.solve(sys, x, x0);
        Info<< "    residual 3: converged " << res.converged << ", "
            << res.newtonIterations << " iterations, reason: "
            << res.reason.c_str() << endl;
        checkTrue("residual 3: not converged", !res.converged);
        checkTrue
        (
            "residual 3: the reason names the breakdown and the residual",
            res.reason.find("DIVERGED_BREAKDOWN") != std::string::npos
         && res.reason.find("no descent direction") != std::string::npos
        );
        checkAbs("residual 3: no Newton step taken", res.newtonIterations, 0, 0);
        checkAbs("residual 3: x untouched", x.norm(), 0, 0);

        // exactly 1: not below 1, rejected (GMRES that breaks down in its
        // first cycle returns the initial guess, dx = 0)
        testSystem sys1(testSystem::SPRINGS);
        sys1.breakdownResidual = 1;
        Eigen::VectorXd x1(Eigen::VectorXd::Zero(3));
        const newtonSolver::result res1 = newton.solve(sys1, x1, x0);
        checkTrue
        (
            "residual 1 (dx = 0): fails with the reason",
            !res1.converged && res1.newtonIterations == 0
         && res1.reason.find("DIVERGED_BREAKDOWN") != std::string::npos
        );

        // 0.5: a descent direction, taken (inexact Newton, linear rate)
        testSystem sys2(testSystem::SPRINGS);
        sys2.breakdownResidual = 0.5;
        Eigen::VectorXd x2(Eigen::VectorXd::Zero(3));
        const newtonSolver::result res2 =
            newtonSolver
            (
                controls("forceTolerance 1e-10; maxNewtonIterations 60;")
            ).solve(sys2, x2, x0);
        Eigen::VectorXd R;
        sys2.residual(x2, R);
        Info<< "    residual 0.5: converged " << res2.converged << " in "
            << res2.newtonIterations << " iterations" << endl;
        checkTrue("residual 0.5: converged", res2.converged);
        checkBelow("residual 0.5: |R| at the solution", R.norm(), 1e-9);

        // a chord step whose solve breaks down takes a new Jacobian
        // instead: converged, no chord step counted, one Jacobian per
        // Newton iteration
        testSystem sys3(testSystem::SPRINGS);
        sys3.inexact = true;
        sys3.breakdownResidual = 3;
        sys3.chordOnly = true;
        Eigen::VectorXd x3(Eigen::VectorXd::Zero(3));
        const newtonSolver::result res3 =
            newtonSolver
            (
                controls("forceTolerance 1e-6; displacementTolerance 1e-10;")
            ).solve(sys3, x3, x0);
        Info<< "    chord step broken down: converged " << res3.converged
            << ", " << res3.newtonIterations << " iterations, "
            << sys3.jacobianResiduals.size() << " Jacobians, "
            << res3.chordSteps << " chord steps" << endl;
        checkTrue("chord breakdown: converged", res3.converged);
        checkAbs("chord breakdown: no chord step", res3.chordSteps, 0, 0);
        checkAbs
        (
            "chord breakdown: a Jacobian per Newton iteration",
            sys3.jacobianResiduals.size(), res3.newtonIterations, 0
        );
    }

    Info<< "Augmented Lagrangian: multipliers between the iterations" << endl;
    {
        // the penalty alone stops at x - g = (1 - g)/(1 + Ka) = 0.09; each
        // update contracts the penetration by 1/(1 + Ka)
        const char* tol =
            "forceTolerance 1e-12; displacementTolerance 1e-10;"
            " maxNewtonIterations 10;";
        testSystem sys(testSystem::AUGMENTED);
        Eigen::VectorXd x(Eigen::VectorXd::Zero(1)), x0(x);
        const newtonSolver::result res =
            newtonSolver(controls(tol)).solve(sys, x, x0);
        Info<< "    converged " << res.converged << ", x - g "
            << x(0) - testSystem::g << ", lambda " << sys.lambda << ", "
            << res.newtonIterations << " iterations, " << res.augmentations
            << " updates, " << sys.jacobianResiduals.size() << " Jacobians"
            << endl;
        checkTrue("augmented: converged", res.converged);
        checkTrue
        (
            "augmented: multipliers reported converged",
            res.multipliersConverged
        );
        // the last update's change was below 1e-9 m; the iterate follows
        // it to the Newton tolerances
        checkBelow
        (
            "augmented: |x - g| below the multiplier tolerance",
            mag(x(0) - testSystem::g), sys.multiplierTolerance
        );
        checkAbs
        (
            "augmented: lambda = 1 - g",
            sys.lambda, 1 - testSystem::g, 10*sys.multiplierTolerance
        );
        // 0.09 -> 1e-9 at 1/11 per update: 8 updates (the first at the
        // penalty's answer); more iterations than maxNewtonIterations,
        // since every update gives the solve as many more
        checkAbs("augmented: updates", res.augmentations, 8, 1);
        checkAbs
        (
            "augmented: updates counted alike",
            res.augmentations, sys.nUpdates, 0
        );
        checkAbs
        (
            "augmented: a chord step absorbs each update",
            sys.jacobianResiduals.size(),
            res.newtonIterations - res.augmentations, 0
        );

        testSystem off(testSystem::AUGMENTED);
        Eigen::VectorXd y(Eigen::VectorXd::Zero(1));
        const newtonSolver::result resOff =
            newtonSolver
            (
                controls
                (
                    "forceTolerance 1e-12; displacementTolerance 1e-10;"
                    " augmentBetweenIterations no;"
                )
            ).solve(off, y, x0);
        checkTrue("not augmented: converged", resOff.converged);
        checkAbs("not augmented: no update", resOff.augmentations, 0, 0);
        checkTrue
        (
            "not augmented: multipliers not reported converged",
            !resOff.multipliersConverged
        );
        checkAbs
        (
            "not augmented: the penalty's answer (1 - g)/(1 + Ka)",
            y(0) - testSystem::g, (1 - testSystem::g)/(1 + testSystem::Ka),
            1e-10
        );
    }

    return exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "newtonKrylov.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::newtonKrylov::newtonKrylov(const dictionary& dict)
:
    forceTol_(dict.lookupOrDefault<scalar>("forceTolerance", 1e-7)),
    acceptableForceTol_
    (
        dict.lookupOrDefault<scalar>("acceptableForceTolerance", 0)
    ),
    stallIterations_(dict.lookupOrDefault<label>("stallIterations", 8)),
    displacementTol_
    (
        dict.lookupOrDefault<scalar>("displacementTolerance", 1e-7)
    ),
    maxNewton_(dict.lookupOrDefault<label>("maxNewtonIterations", 25)),
    restart_(dict.lookupOrDefault<label>("krylovRestart", 40)),
    maxKrylov_(dict.lookupOrDefault<label>("maxKrylovIterations", 200)),
    verbose_(dict.lookupOrDefault<bool>("verbose", false)),
    fullStepFallback_
    (
        dict.lookupOrDefault<bool>("fullStepFallback", false)
    ),
    holdLinearisation_
    (
        dict.lookupOrDefault<bool>("holdContactLinearisation", true)
    ),
    nResidualEvaluations_(0)
{
    if (forceTol_ <= 0 || displacementTol_ <= 0 || maxNewton_ < 1
     || restart_ < 1 || maxKrylov_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": expected forceTolerance > 0,"
            << " displacementTolerance > 0, maxNewtonIterations >= 1,"
            << " krylovRestart >= 1 and maxKrylovIterations >= 1" << nl
            << exit(FatalIOError);
    }
    if (acceptableForceTol_ < 0 || stallIterations_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": expected"
            << " acceptableForceTolerance >= 0 (got " << acceptableForceTol_
            << ") and stallIterations >= 1 (got " << stallIterations_ << ")"
            << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::newtonKrylov::evaluate
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    Eigen::VectorXd& R
)
{
    ++nResidualEvaluations_;
    sys.residual(x, R);
}


Foam::label Foam::newtonKrylov::gmres
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& R,
    const scalar tolerance,
    Eigen::VectorXd& dx
)
{
    // Solves A dx = b with A v = -J v and b = R: the preconditioner
    // approximates -J, which is symmetric positive definite for a stable
    // solid ([S15]).
    const label n = x.size();
    const label m = restart_;

    dx.setZero(n);
    Eigen::VectorXd r(R);
    scalar beta = gNorm(r);

    Eigen::VectorXd xPert(n), Rpert(n), w(n);
    List<Eigen::VectorXd> V(m + 1), Z(m);
    Eigen::MatrixXd H(Eigen::MatrixXd::Zero(m + 1, m));
    Eigen::VectorXd cs(m), sn(m), g(m + 1);

    const scalar typical = sys.typicalDisplacement();
    label iter = 0;

    while (beta > tolerance && iter < maxKrylov_)
    {
        V[0] = r/beta;
        g.setZero();
        g(0) = beta;
        label k = 0;

        for (; k < m && iter < maxKrylov_; ++k, ++iter)
        {
            sys.precondition(V[k], Z[k]);

            // [S15] directional derivative by a forward difference sized so
            // the largest perturbation is 1e-7 of a typical displacement
            const scalar zMax = gMaxNorm(Z[k]);
            const scalar eps =
                1e-7*max(gMaxNorm(x), typical)/max(zMax, VSMALL);
            xPert = x + eps*Z[k];
            evaluate(sys, xPert, Rpert);
            w = -(Rpert - R)/eps;

            // Modified Gram-Schmidt
            for (label i = 0; i <= k; ++i)
            {
                H(i, k) = gDot(w, V[i]);
                w -= H(i, k)*V[i];
            }
            H(k + 1, k) = gNorm(w);
            if (H(k + 1, k) > 0)
            {
                V[k + 1] = w/H(k + 1, k);
            }
            else
            {
                V[k + 1].setZero(n);
            }

            // Givens rotations keep H upper triangular
            for (label i = 0; i < k; ++i)
            {
                const scalar t = cs(i)*H(i, k) + sn(i)*H(i + 1, k);
                H(i + 1, k) = -sn(i)*H(i, k) + cs(i)*H(i + 1, k);
                H(i, k) = t;
            }
            const scalar rho = Foam::sqrt(sqr(H(k, k)) + sqr(H(k + 1, k)));
            cs(k) = rho > 0 ? H(k, k)/rho : 1;
            sn(k) = rho > 0 ? H(k + 1, k)/rho : 0;
            H(k, k) = rho;
            H(k + 1, k) = 0;
            g(k + 1) = -sn(k)*g(k);
            g(k) = cs(k)*g(k);

            if (mag(g(k + 1)) <= tolerance || H(k, k) == 0)
            {
                ++k;
                ++iter;
                break;
            }
        }

        // Back substitution and update with the preconditioned directions
        Eigen::VectorXd y(k);
        for (label i = k - 1; i >= 0; --i)
        {
            scalar s = g(i);
            for (label j = i + 1; j < k; ++j)
            {
                s -= H(i, j)*y(j);
            }
            y(i) = H(i, i) != 0 ? s/H(i, i) : 0;
        }
        for (label i = 0; i < k; ++i)
        {
            dx += y(i)*Z[i];
        }

        if (mag(g(k)) <= tolerance || iter >= maxKrylov_)
        {
            break;
        }

        // Restart from the true linearised residual
        const scalar dxMax = gMaxNorm(dx);
        const scalar eps = 1e-7*max(gMaxNorm(x), typical)/max(dxMax, VSMALL);
        xPert = x + eps*dx;
        evaluate(sys, xPert, Rpert);
        r = R + (Rpert - R)/eps;
        beta = gNorm(r);
    }

    return iter;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::newtonKrylov::result Foam::newtonKrylov::solve
(
    nonlinearSystem& sys,
    Eigen::VectorXd& x,
    const Eigen::VectorXd& xStart
)
{
    result res;
    nResidualEvaluations_ = 0;

    Eigen::VectorXd R(x.size()), Rtrial(x.size()), dx(x.size());
    Eigen::VectorXd xTrial(x.size()), xFull(x.size()), Rfull(x.size());
    scalar normFull = GREAT;

    evaluate(sys, x, R);
    scalar normR = gNorm(R);
    scalar normRprev = normR;

    // The best iterate: a step that stalls returns it rather than the last
    // one (which the non-monotone line search may have made worse)
    Eigen::VectorXd xBest(x);
    scalar normBest = normR;
    label itBest = 0;
    scalar eta = 1e-2;
    label lastKrylov = -1;

    for (label it = 0; it <= maxNewton_; ++it)
    {
        if (!gFinite(R))
        {
            res.reason = "residual is not finite";
            break;
        }

        const scalar Fscale = sys.forceScale();
        res.forceResidual = Fscale > 0 ? normR/Fscale : (normR > 0 ? 1 : 0);

        const scalar increment =
            max(gMaxNorm(x - xStart), 1e-6*sys.typicalDisplacement());
        if (it > 0)
        {
            res.displacementResidual = gMaxNorm(dx)/increment;
        }
        else
        {
            res.displacementResidual = 0;
        }

        if (verbose_)
        {
            Info<< "    Newton " << it << ": force residual "
                << res.forceResidual << ", displacement correction "
                << res.displacementResidual << endl;
        }

        if
        (
            res.forceResidual <= forceTol_
         && res.displacementResidual <= displacementTol_
        )
        {
            res.converged = true;
            break;
        }
        const scalar bestResidual = Fscale > 0 ? normBest/Fscale : 1;
        const bool accept =
            bestResidual <= acceptableForceTol_
         && (it == maxNewton_ || it - itBest >= stallIterations_);
        if (accept || it == maxNewton_)
        {
            if (normBest < normR)
            {
                x = xBest;
                evaluate(sys, x, R);
                res.forceResidual = bestResidual;
            }
            res.converged = accept;
            res.accepted = accept;
            if (!accept)
            {
                res.reason = "no convergence in maxNewtonIterations";
            }
            break;
        }

        // Eisenstat-Walker forcing term (choice 2), no tighter than needed
        // to reach the force tolerance
        if (it > 0)
        {
            const scalar ratio = normR/max(normRprev, VSMALL);
            eta = min(0.1, max(0.9*sqr(ratio), 1e-4));
        }
        const scalar linTol = max(eta*normR, 0.1*forceTol_*Fscale);

        // [S15b] one Jacobian for the preconditioner and the Krylov
        // solve: the contact faces keep their active set meanwhile
        if (holdLinearisation_)
        {
            sys.holdLinearisation(true);
        }
        sys.updatePreconditioner(x, it, lastKrylov);
        lastKrylov = gmres(sys, x, R, linTol, dx);
        if (holdLinearisation_)
        {
            sys.holdLinearisation(false);
        }
        res.krylovIterations += lastKrylov;
        ++res.newtonIterations;

        // Backtracking line search on |R| (Armijo). When no fraction of
        // the step lowers |R| (an active-set change: faces closing into
        // stiff contact make the residual jump before it falls), the full
        // Newton step is taken: it is the linearisation's answer, and the
        // next iteration linearises with the new active set [S14]
        scalar lambda = 1;
        scalar normTrial = GREAT;
        bool decreased = false;
        for (label ls = 0; ls < 6; ++ls)
        {
            xTrial = x + lambda*dx;
            evaluate(sys, xTrial, Rtrial);
            normTrial = gFinite(Rtrial) ? gNorm(Rtrial) : GREAT;
            if (ls == 0)
            {
                xFull = xTrial;
                Rfull = Rtrial;
                normFull = normTrial;
            }
            if (normTrial <= (1 - 1e-4*lambda)*normR)
            {
                decreased = true;
                break;
            }
            lambda *= 0.5;
        }
        if (!decreased && normFull < GREAT && fullStepFallback_)
        {
            lambda = 1;
            xTrial = xFull;
            Rtrial = Rfull;
            normTrial = normFull;
            // the system's fields must hold the accepted iterate
            evaluate(sys, xTrial, Rtrial);
        }
        if (normTrial >= GREAT)
        {
            res.reason = "residual is not finite after the line search";
            break;
        }

        if (verbose_)
        {
            Info<< "        " << lastKrylov << " Krylov iterations, step "
                << lambda << (decreased ? "" : " (no decrease)") << endl;
        }

        dx *= lambda;
        x = xTrial;
        R = Rtrial;
        normRprev = normR;
        normR = normTrial;
        if (normR < normBest)
        {
            if (normR < 0.9*normBest)
            {
                itBest = it + 1;
            }
            normBest = normR;
            xBest = x;
        }
    }

    res.residualEvaluations = nResidualEvaluations_;
    return res;
}


// ************************************************************************* //

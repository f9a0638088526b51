/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "jacobianFreeGMRES.H"
#include "List.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::jacobianFreeGMRES::jacobianFreeGMRES(const dictionary& dict)
:
    restart_(dict.lookupOrDefault<label>("krylovRestart", 40)),
    maxIterations_(dict.lookupOrDefault<label>("maxKrylovIterations", 200))
{
    if (restart_ < 1 || maxIterations_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << ": expected krylovRestart >= 1"
            << " (got " << restart_ << ") and maxKrylovIterations >= 1 (got "
            << maxIterations_ << ")" << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::jacobianFreeGMRES::solve
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& R,
    const scalar tolerance,
    Eigen::VectorXd& dx,
    label& nEvaluations
) const
{
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
    const scalar scale = 1e-7*max(gMaxNorm(x), typical);

    // M v by a forward difference of the residual [S15]
    auto applyM = [&](const Eigen::VectorXd& v, Eigen::VectorXd& Mv)
    {
        const scalar eps = scale/max(gMaxNorm(v), VSMALL);
        xPert = x + eps*v;
        sys.residual(xPert, Rpert);
        ++nEvaluations;
        Mv = -(Rpert - R)/eps;
    };

    label iter = 0;

    while (beta > tolerance && iter < maxIterations_)
    {
        V[0] = r/beta;
        g.setZero();
        g(0) = beta;
        label k = 0;

        for (; k < m && iter < maxIterations_; ++k, ++iter)
        {
            Z[k].setZero(n);
            sys.solveJacobian(V[k], Z[k], 1e-2);
            applyM(Z[k], w);

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

        if (mag(g(k)) <= tolerance || iter >= maxIterations_)
        {
            break;
        }

        // Restart from the true linearised residual
        applyM(dx, w);
        r = R - w;
        beta = gNorm(r);
    }

    return iter;
}


// ************************************************************************* //

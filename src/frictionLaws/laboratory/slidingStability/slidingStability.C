/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "slidingStability.H"
#include "error.H"
#include <Eigen/Dense>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Central-difference step of a state variable (relative, [F31])
static inline scalar stateStep(const scalar x)
{
    return x != 0 ? 1e-6*mag(x) : 1e-9;
}

}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::slidingStability::slidingStability
(
    const frictionLaw& law,
    const scalar tN
)
:
    law_(law),
    tN_(tN)
{
    if (law.nRateStates() < 0)
    {
        FatalErrorInFunction
            << "friction law " << law.type() << " is rate independent: it"
            << " has no rate form, and steady sliding on a spring is"
            << " neutrally stable (no stick-slip from the law)"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const char* Foam::slidingStability::kindName(const criticalKind k)
{
    switch (k)
    {
        case HOPF: return "hopf";
        case STABLE: return "stable";
        default: return "unstable";
    }
}


Foam::slidingStability::linearisation Foam::slidingStability::linearise
(
    const scalar V
) const
{
    typedef frictionLaw::rateStates vec;
    const label m = law_.nRateStates();

    linearisation lin;
    lin.V = V;
    lin.Fx.setSize(m);
    lin.Gv.setSize(m);
    lin.Gx = SquareMatrix<scalar>(m, Zero);

    vec x(scalar(0));
    law_.steadyRateStates(V, tN_, x);
    lin.Fss = law_.slidingTraction(V, x, tN_);

    // Direct effect and dG/dv: central differences in ln v (steps 1e-4)
    const scalar h = 1e-4;
    const scalar Vp = V*std::exp(h), Vm = V*std::exp(-h);
    lin.Fv = law_.rateSensitivity(V, x, tN_)/V;
    vec gp(scalar(0)), gm(scalar(0));
    law_.stateRates(Vp, x, tN_, gp);
    law_.stateRates(Vm, x, tN_, gm);
    for (label i = 0; i < m; ++i)
    {
        lin.Gv[i] = (gp[i] - gm[i])/(Vp - Vm);
    }

    // dF/dx, dG/dx: central differences, relative steps 1e-6
    for (label j = 0; j < m; ++j)
    {
        const scalar hj = stateStep(x[j]);
        vec xp(x), xm(x);
        xp[j] += hj;
        xm[j] -= hj;
        lin.Fx[j] =
            (
                law_.slidingTraction(V, xp, tN_)
              - law_.slidingTraction(V, xm, tN_)
            )/(2*hj);
        law_.stateRates(V, xp, tN_, gp);
        law_.stateRates(V, xm, tN_, gm);
        for (label i = 0; i < m; ++i)
        {
            lin.Gx(i, j) = (gp[i] - gm[i])/(2*hj);
        }
    }

    // Steady slope F_ss' = F_v + F_x . dx_ss/dv
    vec xp(scalar(0)), xm(scalar(0));
    law_.steadyRateStates(Vp, tN_, xp);
    law_.steadyRateStates(Vm, tN_, xm);
    lin.dFssdV = lin.Fv;
    for (label j = 0; j < m; ++j)
    {
        lin.dFssdV += lin.Fx[j]*(xp[j] - xm[j])/(Vp - Vm);
    }
    return lin;
}


Foam::scalar Foam::slidingStability::growthRate
(
    const linearisation& lin,
    const scalar M,
    const scalar k,
    scalar& omega
) const
{
    // Perturbations [F31]: du/dt = w, M dw/dt = -k u - F_v w - F_x . xi,
    // dxi/dt = G_v w + G_x xi; for M = 0, w = -(k u + F_x . xi)/F_v
    const label m = lin.Fx.size();
    Eigen::MatrixXd A;
    if (M > 0)
    {
        A = Eigen::MatrixXd::Zero(m + 2, m + 2);
        A(0, 1) = 1;
        A(1, 0) = -k/M;
        A(1, 1) = -lin.Fv/M;
        for (label j = 0; j < m; ++j)
        {
            A(1, 2 + j) = -lin.Fx[j]/M;
            A(2 + j, 1) = lin.Gv[j];
            for (label i = 0; i < m; ++i)
            {
                A(2 + i, 2 + j) = lin.Gx(i, j);
            }
        }
    }
    else
    {
        A = Eigen::MatrixXd::Zero(m + 1, m + 1);
        A(0, 0) = -k/lin.Fv;
        for (label j = 0; j < m; ++j)
        {
            A(0, 1 + j) = -lin.Fx[j]/lin.Fv;
            A(1 + j, 0) = -lin.Gv[j]*k/lin.Fv;
            for (label i = 0; i < m; ++i)
            {
                A(1 + i, 1 + j) = lin.Gx(i, j) - lin.Gv[i]*lin.Fx[j]/lin.Fv;
            }
        }
    }

    const Eigen::VectorXcd lambda =
        Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
    label iMax = 0;
    for (label i = 1; i < lambda.size(); ++i)
    {
        if (lambda[i].real() > lambda[iMax].real())
        {
            iMax = i;
        }
    }
    omega = mag(lambda[iMax].imag());
    return lambda[iMax].real();
}


Foam::slidingStability::critical Foam::slidingStability::criticalStiffness
(
    const scalar V,
    const scalar M
) const
{
    critical c;
    c.lin = linearise(V);
    const linearisation& lin = c.lin;
    const label m = lin.Fx.size();

    if (!(lin.Fv > 0))
    {
        // a non-positive direct effect: ill posed [F21], unstable for
        // every spring (negative damping of the block)
        c.kind = UNSTABLE;
        c.kc = GREAT;
        return c;
    }

    // At a crossing s = i omega of the characteristic equation
    // M s^2 + F_v s + k + s H(s) = 0, H(s) = F_x (s I - G_x)^-1 G_v:
    // F_v + Re H(i omega) = 0 and k = M omega^2 + omega Im H(i omega)
    // [F31]. Complex arithmetic on the m-square G_x only: no large entries
    Eigen::MatrixXcd Gx(m, m);
    Eigen::VectorXcd Gv(m), Fx(m);
    scalar gMin = GREAT, gMax = 0;
    for (label i = 0; i < m; ++i)
    {
        Gv[i] = lin.Gv[i];
        Fx[i] = lin.Fx[i];
        for (label j = 0; j < m; ++j)
        {
            Gx(i, j) = lin.Gx(i, j);
        }
        gMin = min(gMin, mag(lin.Gx(i, i)));
        gMax = max(gMax, mag(lin.Gx(i, i)));
    }
    auto H = [&](const scalar omega)
    {
        const Eigen::MatrixXcd A =
            std::complex<scalar>(0, omega)*Eigen::MatrixXcd::Identity(m, m)
          - Gx;
        return std::complex<scalar>(Fx.dot(A.partialPivLu().solve(Gv)));
    };
    // (Eigen's dot conjugates its first argument; Fx is real)
    auto phi = [&](const scalar omega) { return lin.Fv + H(omega).real(); };

    // Roots of phi on a log grid of 16 decades around the state rates,
    // refined by bisection in ln omega; the largest k among them is k_c
    c.kind = STABLE;
    c.kc = 0;
    if (m > 0 && gMax > 0)
    {
        const label nScan = 3200;
        const scalar w0 = 1e-8*max(gMin, SMALL*gMax), w1 = 1e8*gMax;
        scalar wPrev = w0, fPrev = phi(w0);
        for (label j = 1; j <= nScan; ++j)
        {
            const scalar w = w0*std::pow(w1/w0, scalar(j)/nScan);
            const scalar f = phi(w);
            if ((f < 0) != (fPrev < 0))
            {
                scalar lo = wPrev, hi = w, flo = fPrev;
                for (label it = 0; it < 200 && hi/lo - 1 > 1e-14; ++it)
                {
                    const scalar mid = std::sqrt(lo*hi);
                    const scalar fm = phi(mid);
                    if ((fm < 0) == (flo < 0))
                    {
                        lo = mid;
                        flo = fm;
                    }
                    else
                    {
                        hi = mid;
                    }
                }
                const scalar wc = std::sqrt(lo*hi);
                const scalar k = M*wc*wc + wc*H(wc).imag();
                if (k > c.kc)
                {
                    c.kc = k;
                    c.omegac = wc;
                    c.kind = HOPF;
                }
            }
            wPrev = w;
            fPrev = f;
        }
    }
    return c;
}


// ************************************************************************* //

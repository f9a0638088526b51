/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "lowRankUpdate.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::lowRankUpdate::update
(
    const List<Eigen::VectorXd>& U,
    const List<Eigen::VectorXd>& V,
    linearSolver& solver
)
{
    U_ = U;
    V_ = V;
    const label r = U_.size();
    Z_.setSize(r);
    Eigen::MatrixXd S(Eigen::MatrixXd::Identity(r, r));
    for (label a = 0; a < r; ++a)
    {
        // the columns of M^-1 U to round-off: they enter every solve
        Z_[a].setZero(U_[a].size());
        solver.solve(U_[a], Z_[a], 1e-12);
    }
    for (label a = 0; a < r; ++a)
    {
        for (label b = 0; b < r; ++b)
        {
            S(a, b) += gDot(V_[a], Z_[b]);
        }
    }
    if (r)
    {
        capacitance_.compute(S);
        return std::isfinite(capacitance_.determinant())
            && capacitance_.determinant() != 0;
    }
    return true;
}


Foam::linearSolver::performance Foam::lowRankUpdate::solve
(
    linearSolver& solver,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    const scalar relTol
) const
{
    linearSolver::performance p = solver.solve(b, x, relTol);
    const label r = U_.size();
    if (r)
    {
        Eigen::VectorXd Vx(r);
        for (label a = 0; a < r; ++a)
        {
            Vx(a) = gDot(V_[a], x);
        }
        const Eigen::VectorXd c(capacitance_.solve(Vx));
        for (label a = 0; a < r; ++a)
        {
            x -= c(a)*Z_[a];
        }
    }
    return p;
}


// ************************************************************************* //

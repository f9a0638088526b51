/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

\*---------------------------------------------------------------------------*/

#include <boost/math/distributions/students_t.hpp>
#include "leastSquaresIntervals.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::leastSquaresIntervals::leastSquaresIntervals
(
    const Eigen::VectorXd& r,
    const Eigen::MatrixXd& J,
    const scalar confidence
)
:
    confidence(confidence),
    dof(r.size() - J.cols())
{
    const label nP = J.cols();
    const scalar ssr = r.squaredNorm();
    rms = std::sqrt(ssr/r.size());
    const scalar s2 = ssr/dof;
    const Eigen::MatrixXd cov =
        s2*(J.transpose()*J).ldlt().solve(Eigen::MatrixXd::Identity(nP, nP));
    const scalar t = studentT(confidence, dof);
    stdError.setSize(nP);
    halfWidth.setSize(nP);
    for (label j = 0; j < nP; ++j)
    {
        stdError[j] = std::sqrt(std::max(cov(j, j), 0.0));
        halfWidth[j] = t*stdError[j];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::leastSquaresIntervals::studentT
(
    const scalar confidence,
    const label dof
)
{
    return boost::math::quantile
    (
        boost::math::students_t(dof), 0.5 + 0.5*confidence
    );
}


// ************************************************************************* //

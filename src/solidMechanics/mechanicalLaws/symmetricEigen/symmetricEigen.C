/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "symmetricEigen.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::symmetricEigen::planeProblem
(
    const scalar a,
    const scalar b,
    const scalar c,
    const vector& u,
    const vector& w
)
{
    // [[a b] [b c]] = m I + [[h b] [b -h]]: eigenvalues m +- r; the vector
    // of m + r is (h + r, b) or (b, r - h), whichever has no cancellation
    const scalar m = 0.5*(a + c);
    const scalar h = 0.5*(a - c);
    const scalar r = Foam::sqrt(h*h + b*b);

    values[1] = m + r;
    values[2] = m - r;

    if (r == 0)
    {
        vectors[1] = u;
        vectors[2] = w;
        return;
    }

    scalar x = b;
    scalar y = r - h;
    if (h >= 0)
    {
        x = h + r;
        y = b;
    }
    const scalar l = 1/Foam::sqrt(x*x + y*y);
    x *= l;
    y *= l;
    vectors[1] = x*u + y*w;
    vectors[2] = x*w - y*u;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::symmetricEigen::symmetricEigen()
:
    values(Zero)
{
    vectors[0] = vector(1, 0, 0);
    vectors[1] = vector(0, 1, 0);
    vectors[2] = vector(0, 0, 1);
}


Foam::symmetricEigen::symmetricEigen(const symmTensor& S)
{
    // Work on the deviator: its entries are the spread of the eigenvalues,
    // so round-off is relative to the spread, not to the mean
    const scalar mean = tr(S)/3;

    // Plane strain: z is an eigenvector, zz its eigenvalue. The 2-D
    // solver's tensors carry xz, yz of round-off size (1e-20 of the trace
    // measured: cell centres differ in z by round-off); dropping entries
    // below 1e-15 of the diagonal changes ln S by their size, no more
    const scalar offPlane = mag(S.xz()) + mag(S.yz());
    if (offPlane <= 1e-15*(mag(S.xx()) + mag(S.yy()) + mag(S.zz())))
    {
        vectors[0] = vector(0, 0, 1);
        planeProblem
        (
            S.xx() - mean, S.xy(), S.yy() - mean,
            vector(1, 0, 0), vector(0, 1, 0)
        );
        values += mean*vector::one;
        values[0] = S.zz();
        return;
    }

    const symmTensor D(dev(S));

    // [S7c] 1. The eigenvalue of B = D/p farthest from the others:
    // 2 cos(phi) (the largest) when det(B)/2 >= 0, else
    // 2 cos(phi + 2 pi/3) (the smallest), phi = acos(det(B)/2)/3
    const scalar p = Foam::sqrt(magSqr(D)/6);
    if (!(p > VSMALL))
    {
        // Off-diagonal entries below the floating-point range
        *this = symmetricEigen();
        values = vector(S.xx(), S.yy(), S.zz());
        return;
    }
    const symmTensor B(D*(1/p));
    const scalar r = min(max(det(B)/2, scalar(-1)), scalar(1));
    const scalar phi = Foam::acos(r)/3;
    const scalar lambda =
        2*Foam::cos(r >= 0 ? phi : phi + constant::mathematical::twoPi/3);

    // Its eigenvector: B - lambda I has rank 2 (the other eigenvalues of B
    // are at least sqrt(3) away), its rows are normal to the vector, and the
    // largest cross product of two rows is the best conditioned
    const vector r0(B.xx() - lambda, B.xy(), B.xz());
    const vector r1(B.xy(), B.yy() - lambda, B.yz());
    const vector r2(B.xz(), B.yz(), B.zz() - lambda);
    vector c(r0 ^ r1);
    const vector c02(r0 ^ r2);
    const vector c12(r1 ^ r2);
    if (magSqr(c02) > magSqr(c))
    {
        c = c02;
    }
    if (magSqr(c12) > magSqr(c))
    {
        c = c12;
    }
    const vector v(c*(1/mag(c)));
    vectors[0] = v;
    values[0] = v & (D & v);

    // 2. The other two in the plane normal to v
    const vector u
    (
        mag(v.x()) > mag(v.y())
      ? vector(-v.z(), 0, v.x())*(1/Foam::sqrt(sqr(v.x()) + sqr(v.z())))
      : vector(0, v.z(), -v.y())*(1/Foam::sqrt(sqr(v.y()) + sqr(v.z())))
    );
    const vector w(v ^ u);
    const vector Du(D & u);
    planeProblem(u & Du, w & Du, w & (D & w), u, w);
    values += mean*vector::one;
}


// ************************************************************************* //

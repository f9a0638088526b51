/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Closed-form spectral decomposition of symmetric tensors
    (src/solidMechanics/mechanicalLaws/symmetricEigen, doc/theory.md
    [S7c]): for random tensors, plane-strain tensors (no xz, yz) and
    tensors with eigenvalues 1e-4 ... 1e-16 apart or all equal, the
    eigenvectors are orthonormal to 1e-14, S is reproduced to 4e-15 of |S|,
    the eigenvalues agree with Eigen's iterative solver in long double to
    4e-15 of |S|, and so does ln S composed from them (4e-15 absolute;
    measured 6e-16, where Eigen's solver in double precision gives up to
    1.3e-15). The divided difference of ln agrees with
    (ln a - ln b)/(a - b) where that has no cancellation, with 1/a at
    a = b, and is continuous where its series takes over.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "symmetricEigen.H"
#include "mechanicalLawTestTools.H"
#include <random>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <Eigen/Eigenvalues>
#pragma GCC diagnostic pop

using namespace Foam;

// Errors of one decomposition: orthonormality, reproduction (relative to
// |S|), eigenvalues (relative to |S|) and ln S (absolute: eigenvalues near
// 1) against Eigen's iterative solver in long double
struct errors
{
    scalar ortho = 0, repro = 0, values = 0, logS = 0;

    void add(const symmTensor& S)
    {
        const symmetricEigen e(S);
        for (direction a = 0; a < 3; ++a)
        {
            for (direction b = 0; b < 3; ++b)
            {
                ortho = max(ortho,
                    mag((e.vectors[a] & e.vectors[b]) - (a == b ? 1 : 0)));
            }
        }
        repro = max(repro,
            cmptMax(cmptMag(e.compose(e.values) - S))/cmptMax(cmptMag(S)));

        typedef Eigen::Matrix<long double, 3, 3> matrix;
        matrix A;
        A << S.xx(), S.xy(), S.xz(), S.xy(), S.yy(), S.yz(), S.xz(), S.yz(), S.zz();
        Eigen::SelfAdjointEigenSolver<matrix> es(A);
        vector sorted(e.values);
        std::sort(sorted.begin(), sorted.end());
        for (direction a = 0; a < 3; ++a)
        {
            values = max(values,
                scalar(std::abs(sorted[a] - es.eigenvalues()(a)))/cmptMax(cmptMag(S)));
        }

        const symmTensor L(e.compose(vector
            (Foam::log(e.values.x()), Foam::log(e.values.y()), Foam::log(e.values.z()))));
        const matrix Lref =
            es.eigenvectors()*es.eigenvalues().array().log().matrix().asDiagonal()
           *es.eigenvectors().transpose();
        const symmTensor d
        (
            L.xx() - Lref(0, 0), L.xy() - Lref(0, 1), L.xz() - Lref(0, 2),
            L.yy() - Lref(1, 1), L.yz() - Lref(1, 2), L.zz() - Lref(2, 2)
        );
        logS = max(logS, cmptMax(cmptMag(d)));
    }
};


static symmTensor spd(const tensor& Q, const vector& v)
{
    return symm(mechanicalLawTest::principal(Q, v));
}


int main()
{
    std::mt19937 gen(4711);
    std::uniform_real_distribution<double> u(-1, 1);

    Info<< "Random symmetric positive definite tensors" << endl;
    {
        errors e;
        for (label i = 0; i < 10000; ++i)
        {
            const tensor Q(mechanicalLawTest::rotation
                (vector(u(gen), u(gen), u(gen)), 3*u(gen)));
            e.add(spd(Q, vector(1 + 0.5*u(gen), 1 + 0.5*u(gen), 1 + 0.5*u(gen))));
        }
        unitTest::checkBelow("random: orthonormal eigenvectors", e.ortho, 1e-14);
        unitTest::checkBelow("random: S reproduced (/ |S|)", e.repro, 4e-15);
        unitTest::checkBelow("random: eigenvalues vs Eigen (/ |S|)", e.values, 4e-15);
        unitTest::checkBelow("random: ln S vs Eigen", e.logS, 4e-15);
    }

    Info<< "Plane-strain tensors (z an eigenvector)" << endl;
    {
        errors e;
        bool zExact = true;
        for (label i = 0; i < 1000; ++i)
        {
            const tensor Q(mechanicalLawTest::rotation(vector(0, 0, 1), 3*u(gen)));
            const symmTensor S(spd(Q, vector(1 + 0.5*u(gen), 1 + 0.5*u(gen), 1 + 0.5*u(gen))));
            // exactly plane, or with the round-off off-plane entries of
            // the 2-D solver (1e-20)
            const scalar off = (i % 2)*1e-20*S.xx();
            const symmTensor S2(S.xx(), S.xy(), off, S.yy(), -off, S.zz());
            e.add(S2);
            const symmetricEigen d(S2);
            zExact = zExact && d.vectors[0] == vector(0, 0, 1) && d.values[0] == S2.zz();
        }
        unitTest::checkTrue("plane strain: z axis and zz exactly", zExact);
        unitTest::checkBelow("plane strain: orthonormal eigenvectors", e.ortho, 1e-14);
        unitTest::checkBelow("plane strain: S reproduced (/ |S|)", e.repro, 4e-15);
        unitTest::checkBelow("plane strain: eigenvalues vs Eigen (/ |S|)", e.values, 4e-15);
        unitTest::checkBelow("plane strain: ln S vs Eigen", e.logS, 4e-15);
    }

    Info<< "Near-repeated, repeated and triple eigenvalues" << endl;
    {
        for (const scalar gap : {1e-4, 1e-8, 1e-12, 1e-16, 0.0})
        {
            errors e;
            for (label i = 0; i < 1000; ++i)
            {
                const tensor Q(mechanicalLawTest::rotation
                    (vector(u(gen), u(gen), u(gen)), 3*u(gen)));
                const scalar a = 1 + 0.01*u(gen);
                // a pair, and all three, 'gap' apart
                e.add(spd(Q, vector(a, a*(1 + gap), 1.3)));
                e.add(spd(Q, vector(0.8, a, a*(1 - gap))));
                e.add(spd(Q, vector(a, a*(1 + gap), a*(1 - gap))));
            }
            const std::string g = "gap " + std::string(Foam::name(gap)) + ": ";
            unitTest::checkBelow(g + "orthonormal eigenvectors", e.ortho, 1e-14);
            unitTest::checkBelow(g + "eigenvalues vs Eigen (/ |S|)", e.values, 4e-15);
            unitTest::checkBelow(g + "ln S vs Eigen", e.logS, 4e-15);
        }
        const symmetricEigen iso(symmTensor(2, 0, 0, 2, 0, 2));
        unitTest::checkAbs("2 I: eigenvalues", cmptMax(cmptMag(iso.values - 2*vector::one)), 0, 0);
        const symmetricEigen tiny(symmTensor(1, 0, 1e-300, 1, 0, 1));
        unitTest::checkAbs("I with an xz of 1e-300: eigenvalues",
            cmptMax(cmptMag(tiny.values - vector::one)), 0, 1e-16);
    }

    Info<< "Divided difference of ln" << endl;
    {
        scalar err = 0;
        for (const scalar d : {1e-2, 0.1, 0.5, 2.0, 10.0})
        {
            const scalar a = 1.3;
            const scalar b = a*(1 + d);
            err = max(err, mag(symmetricEigen::logDifference(a, b)
                /((Foam::log(a) - Foam::log(b))/(a - b)) - 1));
        }
        unitTest::checkBelow("(ln a - ln b)/(a - b), separated", err, 1e-14);
        unitTest::checkRel("a = b: 1/a",
            symmetricEigen::logDifference(1.7, 1.7), 1/1.7, 1e-16);
        // Series below z^2 = 1e-4, z = (a - b)/(a + b): both sides agree
        // (a, b = m (1 +- z): the value is atanh(z)/(m z))
        const scalar m = 1.1;
        const scalar zs = 1e-2;
        const scalar zb = zs*(1 - 1e-13);
        const scalar za = zs*(1 + 1e-13);
        unitTest::checkRel("continuous where the series takes over",
            symmetricEigen::logDifference(m*(1 + zb), m*(1 - zb)),
            symmetricEigen::logDifference(m*(1 + za), m*(1 - za)), 1e-14);
        const scalar a = m;
        // Against a long series of atanh(z)/z at z = 9e-3
        const scalar z = 9e-3;
        const scalar b = a*(1 - z)/(1 + z);
        scalar series = 0;
        for (label k = 20; k >= 0; --k)
        {
            series = 1.0/(2*k + 1) + z*z*series;
        }
        unitTest::checkRel("small gap: 2 atanh(z)/(z (a + b))",
            symmetricEigen::logDifference(a, b), 2*series/(a + b), 1e-15);
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

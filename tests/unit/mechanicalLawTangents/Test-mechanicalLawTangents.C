/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Consistent tangents of the mechanical laws (doc/theory.md [S3], [S4],
    [S7b]): stressAndTangent() against central differences of stress()
    (step 1e-6 max(|F|, 1), old state held) to 1e-6 relative (largest entry of the
    difference over the largest entry of the tangent; the differences are
    the base class's default stressAndTangent()): Hooke; neo-Hookean
    at stretch 2 and at a rotated, sheared F; finite-strain J2 elastic from
    a virgin state, plastic loading and elastic unloading after a 3-D
    non-proportional pre-strain (Swift, tabulated and perfectly plastic
    hardening), plane strain, near-repeated, repeated and triple
    eigenvalues. Also: stressAndTangent() returns the stress and the state
    of stress(), and the acoustic tensor is the tangent's contraction.

    The central differences are accurate to about 1e-9 here (truncation
    h^2 P''' with P''' ~ G/|e|^2 for the flow direction N = e/|e|, |e| the
    trial elastic strain ~ 5e-3; round-off 1e-16 |P|/h), so 1e-6 leaves a
    margin of 1000 over them while any wrong term (a hardening slope off by
    1 %, a sign, a missing geometric or rotation term) is 1e-3 or more.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "mechanicalLawTestTools.H"

using namespace Foam;
using namespace mechanicalLawTest;

// Pear-tube steel
static const std::string steel = "rho 7900; E 193e9; nu 0.29; ";

// Plane strain: in-plane stretches only
static tensor path2D(const scalar t)
{
    const tensor Q(rotation(vector(0, 0, 1), 0.4));
    return
        rotation(vector(0, 0, 1), 0.7*t)
      & principal(Q, vector(Foam::exp(t), Foam::exp(-0.9*t), 1));
}

// Uniaxial path with lateral stretches exp(-t/2) and exp(-t/2)(1 + delta)
static tensor uniaxial(const scalar t, const scalar delta)
{
    const tensor Q(rotation(vector(2, -1, 1), 0.6));
    return principal
    (
        Q,
        vector(Foam::exp(t), Foam::exp(-t/2), Foam::exp(-t/2)*(1 + delta))
    );
}

// Tangent against differences, the path taken, and stressAndTangent() =
// stress()
static void checkPoint
(
    const std::string& name,
    const mechanicalLaw& law,
    const tensor& F,
    const materialState& old,
    const int expectPlastic       // 1 plastic, 0 elastic, -1 no check
)
{
    materialState s1, s2;
    stressTangent A;
    const tensor P1(law.stress(F, old, s1));
    const tensor P2(law.stressAndTangent(F, old, s2, A));
    unitTest::checkBelow(name + ": tangent vs central differences",
        relativeDifference(A, differenceTangent(law, F, old)), 1e-6);
    unitTest::checkAbs(name + ": same stress as stress()",
        cmptMax(cmptMag(P2 - P1))/cmptMax(cmptMag(P1)), 0, 1e-15);
    unitTest::checkAbs(name + ": same state as stress()",
        cmptMax(cmptMag(s2.CpInv - s1.CpInv)) + mag(s2.epsilonP - s1.epsilonP),
        0, 1e-15);
    if (expectPlastic >= 0)
    {
        unitTest::checkTrue
        (
            name + (expectPlastic ? ": plastic step" : ": elastic step"),
            (s1.epsilonP > old.epsilonP) == bool(expectPlastic)
        );
    }
}


int main()
{
    Info<< "Hooke [S3]" << endl;
    {
        autoPtr<mechanicalLaw> law = mechanicalLawTest::law
        (
            "type linearElastic; " + steel
        );
        checkPoint("linearElastic, general F", *law, path3D(0.01),
            materialState(), -1);
    }

    Info<< "Neo-Hookean [S4]" << endl;
    {
        autoPtr<mechanicalLaw> law = mechanicalLawTest::law
        (
            "type neoHookean; rho 1100; E 10e6; nu 0.3;"
        );
        checkPoint("neoHookean, stretch 2",
            *law, tensor(2, 0, 0, 0, 0.8, 0, 0, 0, 0.8), materialState(), -1);
        const tensor shear(1, 0.4, 0, 0, 1, -0.2, 0.1, 0, 1);
        checkPoint("neoHookean, rotated and sheared",
            *law, path3D(0.6) & shear, materialState(), -1);
    }

    Info<< "Finite-strain J2, Swift hardening [S7b]" << endl;
    {
        autoPtr<mechanicalLaw> law = mechanicalLawTest::law
        (
            "type vonMisesPlastic; " + steel
          + "yieldStress { type swift; K 1270e6; eps0 0.03; n 0.45; }"
        );
        const mechanicalLaw& m = *law;

        checkPoint("swift, elastic from the virgin state",
            m, path3D(0.001), materialState(), 0);

        const materialState pre(preStrain(m, path3D, 0.25, 25));
        checkPoint("swift, plastic loading (3-D)", m, path3D(0.26), pre, 1);
        checkPoint("swift, plastic loading with a shear",
            m, path3D(0.26) & tensor(1, 0.01, 0, 0, 1, 0, 0, -0.005, 1), pre, 1);
        checkPoint("swift, elastic unloading from a plastic state",
            m, path3D(0.2495), pre, 0);

        const materialState pre2D(preStrain(m, path2D, 0.25, 25));
        checkPoint("swift, plastic loading (plane strain)",
            m, path2D(0.26), pre2D, 1);
        checkPoint("swift, elastic unloading (plane strain)",
            m, path2D(0.2497), pre2D, 0);

        // be trial with two eigenvalues 1e-9 apart, the same (up to
        // round-off in the axes Q), and all three equal
        const materialState preU
        (
            preStrain(m, [](scalar t){ return uniaxial(t, 0); }, 0.2, 20)
        );
        checkPoint("swift, near-repeated eigenvalues (1e-9), plastic",
            m, uniaxial(0.21, 1e-9), preU, 1);
        checkPoint("swift, repeated eigenvalues, plastic",
            m, uniaxial(0.21, 0), preU, 1);
        checkPoint("swift, near-repeated eigenvalues, elastic unloading",
            m, uniaxial(0.1995, 1e-9), preU, 0);
        checkPoint("swift, triple eigenvalue (F = 1.001 I)",
            m, 1.001*tensor::I, materialState(), 0);
        checkPoint("swift, triple eigenvalue after plastic flow",
            m, uniaxial(0.2, 0) & rotation(vector(1, 1, 0), 0.3), preU, -1);

        // Acoustic tensor = n.(dP/dF).n, elastic mu I + (lambda + mu) n n
        // at F = I
        const vector n(vector(1, 2, 2)/3);
        const tensor A0(m.acousticTensor(tensor::I, materialState(), n));
        const tensor A0exact(m.mu()*tensor::I + (m.lambda() + m.mu())*sqr(n));
        unitTest::checkAbs("acoustic tensor at F = I",
            cmptMax(cmptMag(A0 - A0exact))/m.mu(), 0, 1e-12);
        // A u = (dP/dF : (u n)) . n, the force per displacement jump u
        stressTangent D;
        materialState s;
        const tensor F(path3D(0.26));
        m.stressAndTangent(F, pre, s, D);
        const tensor A(m.acousticTensor(F, pre, n));
        scalar err = 0;
        for (direction k = 0; k < 3; ++k)
        {
            vector u(Zero);
            u[k] = 1;
            err = max(err, mag((A & u) - (applyTangent(D, u*n) & n)));
        }
        unitTest::checkAbs("acoustic tensor, plastic: (dP/dF : (u n)) . n",
            err/m.mu(), 0, 1e-12);
        unitTest::checkBelow("acoustic tensor, plastic: softer than elastic",
            (n & A & n)/(n & A0exact & n), 1);
    }

    Info<< "Finite-strain J2, tabulated and perfectly plastic" << endl;
    {
        autoPtr<mechanicalLaw> table = mechanicalLawTest::law
        (
            "type vonMisesPlastic; " + steel
          + "yieldStress table ((0 262e6) (0.05 430e6) (0.1 510e6)"
            " (0.2 620e6) (0.4 760e6) (0.8 940e6) (2 1300e6));"
        );
        const materialState pre(preStrain(*table, path3D, 0.25, 25));
        checkPoint("table, plastic loading", *table, path3D(0.26), pre, 1);
        checkPoint("table, elastic unloading", *table, path3D(0.2495), pre, 0);

        // A step across the point (0.4, 760e6): the slope of the segment
        // where the return mapping ends
        const materialState pre2(preStrain(*table, path3D, 0.38, 38));
        materialState s;
        table->stress(path3D(0.40), pre2, s);
        unitTest::checkTrue("table: the step crosses epsilonP = 0.4",
            pre2.epsilonP < 0.4 && s.epsilonP > 0.4);
        checkPoint("table, step across a table point",
            *table, path3D(0.40), pre2, 1);

        autoPtr<mechanicalLaw> perfect = mechanicalLawTest::law
        (
            "type vonMisesPlastic; " + steel + "yieldStress constant 250e6;"
        );
        const materialState preP(preStrain(*perfect, path3D, 0.25, 25));
        checkPoint("perfectly plastic, plastic loading",
            *perfect, path3D(0.26), preP, 1);
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Stresses of the mechanical laws against closed forms (doc/theory.md
    [S3]-[S8], [V3], [V8]):
    - Hooke: P = lambda tr(eps) I + 2 mu eps with eps = sym(F - I);
    - neo-Hookean: uniaxial stretch (P11, P22 of [V3]) and hydrostatic
      stretch, P = (mu (s - 1/s) + 3 lambda ln(s)/s) I;
    - finite-strain J2: Hencky elasticity at finite elastic stretch,
      hydrostatic stretch without plastic flow, uniaxial stress to a
      logarithmic strain of 0.8 with Swift hardening: Kirchhoff stress
      tau = sigma_y(epsP), epsP = ln(l) - tau/E, lateral
      ln(l2) = -nu tau/E - epsP/2 ([V8]; one step gives the same answer);
      objectivity P(QF) = Q P(F) with the same updated state; plastic
      incompressibility det(Cp^-1) = 1 along a non-proportional 3-D path;
      the committed state lies on the yield surface.
    Tolerances: round-off (1e-11 to 1e-14 relative, larger where terms
    cancel); the uniaxial driver zeroes the lateral stress to 1e-11 of the
    yield stress.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "mechanicalLawTestTools.H"

using namespace Foam;
using namespace mechanicalLawTest;

static scalar relDiff(const tensor& a, const tensor& b)
{
    return cmptMax(cmptMag(a - b))/cmptMax(cmptMag(b));
}

static scalar relDiff(const symmTensor& a, const symmTensor& b)
{
    return cmptMax(cmptMag(a - b))/cmptMax(cmptMag(b));
}

// Uniaxial stress at axial stretch l from state s: the lateral stretch l2
// (F22 = F33) with P22 = 0, by Newton with the law's tangent; commits s
static scalar uniaxialStep
(
    const mechanicalLaw& law,
    const scalar l,
    scalar& l2,
    materialState& s,
    const scalar stressScale
)
{
    for (label iter = 0; iter < 50; ++iter)
    {
        const tensor F(l, 0, 0, 0, l2, 0, 0, 0, l2);
        materialState u;
        stressTangent D;
        const tensor P(law.stressAndTangent(F, s, u, D));
        if (mag(P.yy()) < 1e-11*stressScale)
        {
            s = u;
            return P.xx();
        }
        l2 -= P.yy()/(D(4, 4) + D(4, 8));
    }
    FatalErrorInFunction << "no lateral equilibrium" << exit(FatalError);
    return 0;
}


int main()
{
    const std::string steel = "rho 7900; E 193e9; nu 0.29; ";
    const scalar E = 193e9;
    const scalar nu = 0.29;

    Info<< "Hooke [S3]" << endl;
    {
        autoPtr<mechanicalLaw> law(mechanicalLawTest::law("type linearElastic; " + steel));
        const tensor H(1e-3, 2e-4, -3e-4, 5e-4, -7e-4, 1e-4, 0, 3e-4, 2e-4);
        const symmTensor eps(symm(H));
        const scalar lambda = nu*E/((1 + nu)*(1 - 2*nu));
        const scalar mu = E/(2*(1 + nu));
        // The law sees F = I + H: F - I carries round-off of 1e-16/|H|
        materialState s;
        unitTest::checkAbs("Hooke: P = lambda tr(eps) I + 2 mu eps",
            relDiff(law->stress(tensor::I + H, materialState(), s),
                tensor(lambda*tr(eps)*symmTensor::I + 2*mu*eps)), 0, 1e-11);
    }

    Info<< "Neo-Hookean [S4], [V3]" << endl;
    {
        autoPtr<mechanicalLaw> law
        (
            mechanicalLawTest::law("type neoHookean; rho 1100; E 10e6; nu 0.3;")
        );
        const scalar mu = law->mu();
        const scalar lambda = law->lambda();
        const scalar l = 2;
        const scalar l2 = 0.8;
        const scalar lnJ = Foam::log(l*l2*l2);
        materialState s;
        const tensor P(law->stress(tensor(l, 0, 0, 0, l2, 0, 0, 0, l2), s, s));
        unitTest::checkRel("neo-Hookean uniaxial: P11",
            P.xx(), mu*(l - 1/l) + lambda*lnJ/l, 1e-14);
        // P22 is 2 % of its terms: cancellation
        unitTest::checkRel("neo-Hookean uniaxial: P22",
            P.yy(), mu*(l2 - 1/l2) + lambda*lnJ/l2, 1e-12);
        unitTest::checkAbs("neo-Hookean uniaxial: no shear",
            mag(P.xy()) + mag(P.yz()) + mag(P.zx()), 0, 0);
        const scalar st = 0.7;
        unitTest::checkAbs("neo-Hookean hydrostatic",
            relDiff(law->stress(st*tensor::I, s, s),
                (mu*(st - 1/st) + 3*lambda*Foam::log(st)/st)*tensor::I),
            0, 1e-14);
    }

    Info<< "Finite-strain J2: elasticity [S5]" << endl;
    {
        autoPtr<mechanicalLaw> law
        (
            mechanicalLawTest::law
            (
                "type vonMisesPlastic; " + steel + "yieldStress constant 1e15;"
            )
        );
        const scalar K = law->bulkModulus();
        const scalar G = law->mu();
        const vector stretch(1.2, 0.9, 1.1);
        const vector e
        (
            Foam::log(stretch.x()), Foam::log(stretch.y()), Foam::log(stretch.z())
        );
        const scalar v = e.x() + e.y() + e.z();
        const tensor Q(rotation(vector(1, -2, 0.5), 0.8));
        const tensor R(rotation(vector(0.3, 1, 1), -1.1));
        const tensor F(R & principal(Q, stretch));
        const tensor RQ(R & Q);
        const tensor tau(principal(RQ, K*v*vector::one + 2*G*(e - v/3*vector::one)));
        materialState s;
        unitTest::checkAbs("Hencky at finite elastic stretch: P = tau F^-T",
            relDiff(law->stress(F, materialState(), s), tau & inv(F).T()),
            0, 1e-13);
        const scalar st = 1.05;
        unitTest::checkAbs("hydrostatic stretch: P = 3 K ln(s)/s I",
            relDiff(law->stress(st*tensor::I, materialState(), s),
                3*K*Foam::log(st)/st*tensor::I), 0, 1e-14);
    }

    Info<< "Finite-strain J2: uniaxial stress with Swift hardening [V8]"
        << endl;
    {
        autoPtr<mechanicalLaw> law
        (
            mechanicalLawTest::law
            (
                "type vonMisesPlastic; " + steel
              + "yieldStress { type swift; K 1270e6; eps0 0.03; n 0.45; }"
            )
        );
        auto swift = [](scalar e){ return 1270e6*Foam::pow(0.03 + e, 0.45); };
        const scalar epsEnd = 0.8;
        const label nSteps = 40;

        materialState s;
        scalar l2 = 1;
        scalar P11 = 0;
        for (label i = 1; i <= nSteps; ++i)
        {
            P11 = uniaxialStep(*law, Foam::exp(epsEnd*i/nSteps), l2, s, swift(0));
        }
        const scalar l = Foam::exp(epsEnd);
        const scalar tau = P11*l;                  // Kirchhoff tau11 = P11 F11
        unitTest::checkRel("uniaxial: Kirchhoff stress = sigma_y(epsP)",
            tau, swift(s.epsilonP), 1e-12);
        unitTest::checkRel("uniaxial: epsP = ln(l) - tau/E",
            s.epsilonP, epsEnd - tau/E, 1e-12);
        unitTest::checkAbs("uniaxial: ln(l2) = -nu tau/E - epsP/2",
            Foam::log(l2), -nu*tau/E - s.epsilonP/2, 1e-12);
        unitTest::checkAbs("uniaxial: plastic incompressibility det(Cp^-1) = 1",
            det(s.CpInv) - 1, 0, 1e-13);

        materialState one;
        scalar l2one = 1;
        const scalar P11one = uniaxialStep(*law, l, l2one, one, swift(0));
        unitTest::checkRel("uniaxial: one step of strain 0.8 = 40 steps",
            P11one, P11, 1e-11);
        unitTest::checkRel("uniaxial: one step, same epsP",
            one.epsilonP, s.epsilonP, 1e-11);
    }

    Info<< "Finite-strain J2: objectivity, incompressibility, consistency"
        << endl;
    {
        autoPtr<mechanicalLaw> law
        (
            mechanicalLawTest::law
            (
                "type vonMisesPlastic; " + steel
              + "yieldStress { type swift; K 1270e6; eps0 0.03; n 0.45; }"
            )
        );
        const mechanicalLaw& m = *law;

        scalar detErr = 0;
        for (label n = 1; n <= 50; ++n)
        {
            detErr = max(detErr, mag(det(preStrain(m, path3D, 0.012*n, n).CpInv) - 1));
        }
        const materialState s(preStrain(m, path3D, 0.6, 50));
        unitTest::checkTrue("3-D path is plastic", s.epsilonP > 0.5);
        unitTest::checkAbs("plastic incompressibility along the 3-D path:"
            " max |det(Cp^-1) - 1|", detErr, 0, 1e-13);

        // Plastic step from s, then the same F with a superposed rotation
        const tensor F(path3D(0.62) & tensor(1, 0.02, 0, 0, 1, 0, 0, 0, 1));
        const tensor Q(rotation(vector(2, -1, 3), 2.1));
        materialState u1, u2;
        const tensor P1(m.stress(F, s, u1));
        const tensor P2(m.stress(Q & F, s, u2));
        unitTest::checkTrue("objectivity: the step is plastic", u1.epsilonP > s.epsilonP);
        // be = I + 2 eps_e: the elastic strain (3e-3) carries round-off of
        // 1e-16/3e-3, and so does the deviatoric stress
        unitTest::checkAbs("objectivity: P(QF) = Q P(F)", relDiff(P2, Q & P1), 0, 1e-12);
        unitTest::checkAbs("objectivity: same Cp^-1",
            relDiff(u2.CpInv, u1.CpInv), 0, 1e-13);
        unitTest::checkRel("objectivity: same epsP", u2.epsilonP, u1.epsilonP, 1e-14);

        autoPtr<mechanicalLaw> nh
        (
            mechanicalLawTest::law("type neoHookean; rho 1100; E 10e6; nu 0.3;")
        );
        const tensor Fnh(path3D(0.5) & tensor(1, 0.3, 0, 0, 1, 0.1, 0, 0, 1));
        materialState dummy;
        unitTest::checkAbs("neo-Hookean objectivity: P(QF) = Q P(F)",
            relDiff(nh->stress(Q & Fnh, dummy, dummy),
                Q & nh->stress(Fnh, dummy, dummy)), 0, 1e-14);

        // The committed state is on the yield surface: the same F again
        // gives the same stress and no further flow
        materialState u3;
        const tensor P3(m.stress(F, u1, u3));
        unitTest::checkAbs("consistency: same stress from the committed state",
            relDiff(P3, P1), 0, 1e-12);
        unitTest::checkAbs("consistency: no further plastic strain",
            u3.epsilonP - u1.epsilonP, 0, 1e-14);
        const symmTensor tau(symm(P1 & F.T()));
        unitTest::checkRel("consistency: von Mises stress = sigma_y(epsP)",
            Foam::sqrt(1.5)*mag(dev(tau)),
            1270e6*Foam::pow(0.03 + u1.epsilonP, 0.45), 1e-12);
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

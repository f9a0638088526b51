/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "vonMisesPlastic.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(vonMisesPlastic, 0);
    addToRunTimeSelectionTable(mechanicalLaw, vonMisesPlastic, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mechanicalLaws::vonMisesPlastic::checkHardening
(
    const dictionary& dict
) const
{
    const label nSamples = 2000;
    const scalar epsMax = 10;

    scalar previous = yieldStress(0);
    if (!(previous > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'yieldStress' in dictionary " << dict.name()
            << ": initial yield stress is " << previous
            << "; expected a positive value" << nl << exit(FatalIOError);
    }

    for (label i = 1; i <= nSamples; ++i)
    {
        const scalar epsP = epsMax*i/nSamples;
        const scalar sy = yieldStress(epsP);
        if (!(sy >= previous*(1 - 1e-12)))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'yieldStress' in dictionary " << dict.name()
                << ": the hardening curve decreases from " << previous
                << " to " << sy << " at epsilonP = " << epsP
                << "; expected a non-decreasing curve (softening is not"
                << " supported)" << nl << exit(FatalIOError);
        }
        previous = sy;
    }
}


Foam::scalar Foam::mechanicalLaws::vonMisesPlastic::plasticMultiplier
(
    const scalar qTrial,
    const scalar epsP,
    scalar sigmaY,
    scalar& H,
    const bool slopeAtRoot
) const
{
    // [S7]: g(dg) = qTrial - 3 G dg - sigmaY(epsP + dg) is strictly
    // decreasing, g(0) > 0 and g(qTrial/3G) < 0, so Newton's iteration with
    // the exact slope, kept inside the shrinking bracket by bisection,
    // always converges (for a concave curve, such as Swift's, from below
    // without overshoot; for a table, exactly once in the final segment).
    // On entry sigmaY and H are the curve at dg = 0
    const scalar threeG = 3*mu();
    scalar lo = 0;
    scalar hi = qTrial/threeG;
    scalar dg = 0;

    const scalar tol = 1e-14*qTrial;

    for (label iter = 0; iter < 200; ++iter)
    {
        if (iter)
        {
            sigmaY = yieldStress_.value(epsP + dg, H);
        }
        const scalar g = qTrial - threeG*dg - sigmaY;

        if (mag(g) <= tol)
        {
            return dg;
        }
        if (g > 0) { lo = dg; } else { hi = dg; }

        const scalar step = g/(threeG + H);
        scalar next = dg + step;

        if (!(next > lo && next < hi))
        {
            next = 0.5*(lo + hi);
        }
        else if (mag(step) <= 1e-8*next)
        {
            // A Newton step this small leaves an error of
            // step^2 |sigmaY''|/(2 (3G + H)), below 1e-16 dg for any curve
            // with |sigmaY''| dg < 3G: accepted without evaluating the
            // curve again (one pow less per plastic update for Swift)
            dg = next;
            break;
        }
        if (mag(next - dg) <= 1e-16*max(dg, SMALL))
        {
            dg = next;
            break;
        }
        dg = next;
    }

    if (slopeAtRoot)
    {
        yieldStress_.value(epsP + dg, H);
    }
    return dg;
}


bool Foam::mechanicalLaws::vonMisesPlastic::returnMap
(
    const tensor& F,
    const materialState& old,
    returnMapping& r,
    const bool withTangent
) const
{
    if (!admissible(F))
    {
        return false;
    }

    // [S6] elastic predictor: trial left Cauchy-Green be = F Cp^-1 F^T
    const tensor A(F & old.CpInv);
    const symmTensor beTrial
    (
        A.x() & F.x(), A.x() & F.y(), A.x() & F.z(),
                       A.y() & F.y(), A.y() & F.z(),
                                      A.z() & F.z()
    );
    r.trial = symmetricEigen(beTrial);
    const vector& lambda = r.trial.values;
    if (!(cmptMin(lambda) > 0))
    {
        return false;
    }

    // Principal logarithmic elastic strains
    const vector eps
    (
        0.5*symmetricEigen::log(lambda.x()),
        0.5*symmetricEigen::log(lambda.y()),
        0.5*symmetricEigen::log(lambda.z())
    );
    r.volStrain = eps.x() + eps.y() + eps.z();
    r.devEps = eps - r.volStrain/3*vector::one;

    // [S5] Hencky: trial von Mises stress
    const scalar G = mu();
    const scalar qTrial = Foam::sqrt(1.5)*2*G*mag(r.devEps);

    r.theta = 1;
    r.thetaBar = 0;
    r.dGamma = 0;

    // The curve does not decrease: below the initial yield stress no pow
    // or table lookup is needed
    scalar H = 0;
    const scalar sigmaY =
        qTrial > initialYield_
      ? yieldStress_.value(old.epsilonP, H)
      : initialYield_;

    if (qTrial > sigmaY)
    {
        // [S7] radial return
        r.dGamma =
            plasticMultiplier(qTrial, old.epsilonP, sigmaY, H, withTangent);
        r.theta = 1 - 3*G*r.dGamma/qTrial;
        if (withTangent)
        {
            r.thetaBar = 1/(1 + H/(3*G)) - (1 - r.theta);
        }
    }

    r.tau = 2*G*r.theta*r.devEps + bulkModulus()*r.volStrain*vector::one;

    return true;
}


void Foam::mechanicalLaws::vonMisesPlastic::commit
(
    const tensor& Finv,
    const materialState& old,
    const returnMapping& r,
    materialState& updated
) const
{
    updated.epsilonP = old.epsilonP + r.dGamma;

    if (r.dGamma > 0)
    {
        // [S6] corrected be = exp(2 eps), eps = theta dev(eps_trial) + ln Je/3
        // (same axes), back to the plastic history: Cp^-1 = F^-1 be F^-T
        const vector eps(r.theta*r.devEps + r.volStrain/3*vector::one);
        const symmTensor be
        (
            r.trial.compose
            (
                vector
                (
                    Foam::exp(2*eps.x()),
                    Foam::exp(2*eps.y()),
                    Foam::exp(2*eps.z())
                )
            )
        );
        updated.CpInv = symm(Finv & be & Finv.T());
    }
    else
    {
        updated.CpInv = old.CpInv;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaws::vonMisesPlastic::vonMisesPlastic(const dictionary& dict)
:
    mechanicalLaw(dict),
    yieldStress_("yieldStress", dict),
    initialYield_(yieldStress_.value(0))
{
    checkHardening(dict);
    checkKeywords(dict, wordList({"yieldStress", "yieldStressCoeffs"}));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::mechanicalLaws::vonMisesPlastic::stress
(
    const tensor& F,
    const materialState& old,
    materialState& updated
) const
{
    returnMapping r;
    if (!returnMap(F, old, r))
    {
        updated = old;
        return rejectedStress();
    }

    const tensor Finv(inv(F));
    commit(Finv, old, r, updated);

    // P = tau F^-T   [S2]
    return r.trial.compose(r.tau) & Finv.T();
}


Foam::tensor Foam::mechanicalLaws::vonMisesPlastic::stressAndTangent
(
    const tensor& F,
    const materialState& old,
    materialState& updated,
    stressTangent& dPdF
) const
{
    returnMapping r;
    if (!returnMap(F, old, r, true))
    {
        // Not evaluated: the elastic tangent keeps a matrix invertible
        updated = old;
        hookeTangent(dPdF);
        return rejectedStress();
    }

    const tensor Finv(inv(F));
    commit(Finv, old, r, updated);
    const tensor P(r.trial.compose(r.tau) & Finv.T());
    tangent(F, Finv, old, r, P, dPdF);
    return P;
}


Foam::tensor Foam::mechanicalLaws::vonMisesPlastic::acousticTensor
(
    const tensor& F,
    const materialState& old,
    const vector& n
) const
{
    // A_ik = n_j dP_ij/dF_kl n_l: the force a face takes per displacement
    // jump across it (elastic mu I + (lambda + mu) n n at F = I)
    stressTangent dPdF;
    materialState updated;
    stressAndTangent(F, old, updated, dPdF);

    tensor A(Zero);
    for (direction i = 0; i < 3; ++i)
    {
        for (direction k = 0; k < 3; ++k)
        {
            scalar s = 0;
            for (direction j = 0; j < 3; ++j)
            {
                for (direction l = 0; l < 3; ++l)
                {
                    s += n[j]*dPdF(3*i + j, 3*k + l)*n[l];
                }
            }
            A[3*i + k] = s;
        }
    }
    return A;
}


// ************************************************************************* //

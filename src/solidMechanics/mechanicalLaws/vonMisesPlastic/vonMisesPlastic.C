/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "vonMisesPlastic.H"
#include "symmetricEigen.H"
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
    const scalar epsP
) const
{
    // [S7]: g(dg) = qTrial - 3 G dg - sigmaY(epsP + dg) is strictly
    // decreasing, g(0) > 0 and g(qTrial/3G) < 0, so a Newton iteration kept
    // inside the shrinking bracket by bisection always converges.
    const scalar threeG = 3*mu();
    scalar lo = 0;
    scalar hi = qTrial/threeG;
    scalar dg = 0;

    const scalar tol = 1e-14*qTrial;

    for (label iter = 0; iter < 200; ++iter)
    {
        const scalar sy = yieldStress(epsP + dg);
        const scalar g = qTrial - threeG*dg - sy;

        if (mag(g) <= tol)
        {
            return dg;
        }
        if (g > 0) { lo = dg; } else { hi = dg; }

        const scalar h = 1e-7*(epsP + dg) + 1e-10;
        const scalar H = (yieldStress(epsP + dg + h) - sy)/h;
        scalar next = dg + g/(threeG + max(H, scalar(0)));

        if (!(next > lo && next < hi))
        {
            next = 0.5*(lo + hi);
        }
        if (mag(next - dg) <= 1e-16*max(dg, SMALL))
        {
            return next;
        }
        dg = next;
    }

    return dg;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaws::vonMisesPlastic::vonMisesPlastic(const dictionary& dict)
:
    mechanicalLaw(dict),
    yieldStress_(Function1<scalar>::New("yieldStress", dict))
{
    checkHardening(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::mechanicalLaws::vonMisesPlastic::stress
(
    const tensor& F,
    const materialState& old,
    materialState& updated
) const
{
    if (!admissible(F))
    {
        updated = old;
        return rejectedStress();
    }

    // [S6] elastic predictor: trial left Cauchy-Green be = F Cp^-1 F^T
    const symmTensor beTrial(symm(F & old.CpInv & F.T()));
    const symmetricEigen eig(beTrial);
    if (!(cmptMin(eig.values) > 0))
    {
        updated = old;
        return rejectedStress();
    }

    // Principal logarithmic elastic strains
    vector eps
    (
        0.5*Foam::log(eig.values.x()),
        0.5*Foam::log(eig.values.y()),
        0.5*Foam::log(eig.values.z())
    );
    const scalar volStrain = eps.x() + eps.y() + eps.z();
    const vector devEps(eps - volStrain/3*vector::one);

    // [S5] Hencky: Kirchhoff stress in principal axes
    const scalar G = mu();
    vector devTau(2*G*devEps);
    const scalar qTrial = Foam::sqrt(1.5)*mag(devTau);

    updated.epsilonP = old.epsilonP;

    if (qTrial > yieldStress(old.epsilonP))
    {
        // [S7] radial return
        const scalar dg = plasticMultiplier(qTrial, old.epsilonP);
        const scalar scale = 1 - 3*G*dg/qTrial;
        devTau *= scale;
        eps = scale*devEps + volStrain/3*vector::one;
        updated.epsilonP = old.epsilonP + dg;

        // [S6] back to the plastic history: Cp^-1 = F^-1 be F^-T
        const symmTensor be
        (
            eig.compose
            (
                vector
                (
                    Foam::exp(2*eps.x()),
                    Foam::exp(2*eps.y()),
                    Foam::exp(2*eps.z())
                )
            )
        );
        const tensor Finv(inv(F));
        updated.CpInv = symm(Finv & be & Finv.T());
    }
    else
    {
        updated.CpInv = old.CpInv;
    }

    const symmTensor tau
    (
        eig.compose(devTau + bulkModulus()*volStrain*vector::one)
    );

    // P = tau F^-T   [S2]
    return tau & inv(F).T();
}


Foam::tensor Foam::mechanicalLaws::vonMisesPlastic::acousticTensor
(
    const tensor& F,
    const materialState& old,
    const vector& n
) const
{
    const tensor elastic(mechanicalLaw::acousticTensor(F, old, n));

    if (!admissible(F))
    {
        return elastic;
    }

    const symmTensor beTrial(symm(F & old.CpInv & F.T()));
    const symmetricEigen eig(beTrial);
    if (!(cmptMin(eig.values) > 0))
    {
        return elastic;
    }
    const vector eps
    (
        0.5*Foam::log(eig.values.x()),
        0.5*Foam::log(eig.values.y()),
        0.5*Foam::log(eig.values.z())
    );
    const vector devEps(eps - (eps.x() + eps.y() + eps.z())/3*vector::one);
    const scalar G = mu();
    const scalar qTrial = Foam::sqrt(1.5)*2*G*mag(devEps);

    if (qTrial <= yieldStress(old.epsilonP))
    {
        return elastic;
    }

    // [S16] consistent J2 tangent C = K 1x1 + 2 G theta Idev
    // - 2 G thetaBar N x N, contracted with n on both sides
    const scalar dg = plasticMultiplier(qTrial, old.epsilonP);
    const scalar epsP = old.epsilonP + dg;
    const scalar h = 1e-7*epsP + 1e-10;
    const scalar H =
        max((yieldStress(epsP + h) - yieldStress(epsP))/h, scalar(0));
    const scalar theta = 1 - 3*G*dg/qTrial;
    const scalar thetaBar = 1/(1 + H/(3*G)) - (1 - theta);

    const symmTensor N(eig.compose(devEps/mag(devEps)));
    const vector m(N & n);

    const scalar Gt = G*theta;
    return
        Gt*tensor::I + (bulkModulus() + Gt/3)*sqr(n)
      - 2*G*max(thetaBar, scalar(0))*sqr(m);
}


// ************************************************************************* //

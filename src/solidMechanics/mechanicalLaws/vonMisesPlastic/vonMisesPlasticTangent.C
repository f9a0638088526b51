/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.

Description
    Consistent tangent dP/dF of the finite-strain J2 return mapping
    ([S7b] in doc/theory.md), column by column (dF = e_k e_l^T):

    1. trial left Cauchy-Green tensor: dbe = dF A + (dF A)^T, A = Cp^-1 F^T;
    2. its logarithm in the principal axes v_a of be (Daleckii-Krein):
       (v_a . deps . v_b) = 1/2 L(lambda_a, lambda_b) (v_a . dbe . v_b),
       L the divided difference of ln (1/lambda_a on the diagonal);
    3. Kirchhoff stress by the algorithmic J2 tangent in logarithmic
       strains, coaxial with be: K 1x1 + 2 G theta Idev - 2 G thetaBar N x N;
    4. P = tau F^-T: dP = dtau F^-T - P dF^T F^-T.

\*---------------------------------------------------------------------------*/

#include "vonMisesPlastic.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mechanicalLaws::vonMisesPlastic::tangent
(
    const tensor& F,
    const tensor& Finv,
    const materialState& old,
    const returnMapping& r,
    const tensor& P,
    stressTangent& dPdF
) const
{
    const vector* v = r.trial.vectors;
    const vector& lambda = r.trial.values;

    // v_a . dbe . v_b = v_a,k w_b,l + v_b,k w_a,l with w_a = A v_a; the
    // image of v_b under F^-1 carries dtau into dtau F^-T
    const tensor A(old.CpInv & F.T());
    vector w[3];
    vector z[3];
    for (direction a = 0; a < 3; ++a)
    {
        w[a] = A & v[a];
        z[a] = Finv & v[a];
    }

    scalar L[3][3];
    for (direction a = 0; a < 3; ++a)
    {
        for (direction b = a; b < 3; ++b)
        {
            L[a][b] = 0.5*symmetricEigen::logDifference(lambda[a], lambda[b]);
            L[b][a] = L[a][b];
        }
    }

    const scalar G = mu();
    const scalar K = bulkModulus();
    const scalar twoGtheta = 2*G*r.theta;
    const scalar magDev = mag(r.devEps);
    const vector N(r.dGamma > 0 ? r.devEps/magDev : vector::zero);
    const scalar twoGthetaBar = 2*G*r.thetaBar;

    for (direction k = 0; k < 3; ++k)
    {
        for (direction l = 0; l < 3; ++l)
        {
            // 2. principal components of deps
            scalar de[3][3];
            for (direction a = 0; a < 3; ++a)
            {
                for (direction b = a; b < 3; ++b)
                {
                    de[a][b] =
                        L[a][b]*(v[a][k]*w[b][l] + v[b][k]*w[a][l]);
                    de[b][a] = de[a][b];
                }
            }

            // 3. principal components of dtau
            const scalar trDe = de[0][0] + de[1][1] + de[2][2];
            const scalar NDe =
                N[0]*de[0][0] + N[1]*de[1][1] + N[2]*de[2][2];
            scalar dtau[3][3];
            for (direction a = 0; a < 3; ++a)
            {
                for (direction b = 0; b < 3; ++b)
                {
                    dtau[a][b] = twoGtheta*de[a][b];
                }
                dtau[a][a] +=
                    (K - twoGtheta/3)*trDe - twoGthetaBar*N[a]*NDe;
            }

            // 4. dP = sum_ab dtau_ab v_a (F^-1 v_b) - P dF^T F^-T
            tensor dP(Zero);
            for (direction a = 0; a < 3; ++a)
            {
                const vector T
                (
                    dtau[a][0]*z[0] + dtau[a][1]*z[1] + dtau[a][2]*z[2]
                );
                dP += v[a]*T;
            }
            for (direction i = 0; i < 3; ++i)
            {
                for (direction j = 0; j < 3; ++j)
                {
                    dPdF(3*i + j, 3*k + l) =
                        dP[3*i + j] - P[3*i + l]*Finv[3*j + k];
                }
            }
        }
    }
}


// ************************************************************************* //

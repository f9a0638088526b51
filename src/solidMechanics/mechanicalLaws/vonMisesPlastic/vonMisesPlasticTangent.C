/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Consistent tangent dP/dF of the finite-strain J2 return mapping
    ([S7b] in doc/theory.md). For dF = e_k e_l^T:

    1. trial left Cauchy-Green tensor: dbe = dF A + (dF A)^T, A = Cp^-1 F^T,
       so in the principal axes v_a of be
       v_a.dbe.v_b = Y_ab + Y_ba with Y_ab(kl) = v_a,k w_b,l, w_b = A v_b;
    2. its logarithm (Daleckii-Krein): v_a.deps.v_b = L_ab v_a.dbe.v_b,
       L_ab = 1/2 (ln l_a - ln l_b)/(l_a - l_b) (1/(2 l_a) for a = b);
    3. the algorithmic J2 tangent, coaxial with be: principal components
       dtau_aa = sum_c C_ac deps_cc, C_ac = K - 2 G theta/3
       + 2 G theta d_ac - 2 G thetaBar N_a N_c; shears
       dtau_ab = 2 G theta deps_ab;
    4. P = tau F^-T: dP = dtau F^-T - P dF^T F^-T, where
       v_a.dtau.v_b contributes dtau_ab X_ab, X_ab(ij) = v_a,i z_b,j,
       z_b = F^-1 v_b.
    So dP/dF = sum_(a<b) 2 G theta L_ab (X_ab + X_ba)(Y_ab + Y_ba)^T
             + sum_a X_aa (sum_c 2 C_ac L_cc Y_cc)^T - P_il Finv_jk:
    six rank-one 9 x 9 updates and the geometric term.

\*---------------------------------------------------------------------------*/

#include "vonMisesPlastic.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

typedef Eigen::Matrix<double, 9, 1> vector9;

//- a b^T as a 9-vector in tensor component order
inline vector9 dyad9(const Foam::vector& a, const Foam::vector& b)
{
    vector9 r;
    r << a.x()*b.x(), a.x()*b.y(), a.x()*b.z(),
         a.y()*b.x(), a.y()*b.y(), a.y()*b.z(),
         a.z()*b.x(), a.z()*b.y(), a.z()*b.z();
    return r;
}

} // End anonymous namespace


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

    const tensor A(old.CpInv & F.T());
    vector w[3];
    vector z[3];
    for (direction a = 0; a < 3; ++a)
    {
        w[a] = A & v[a];
        z[a] = Finv & v[a];
    }

    const scalar G = mu();
    const scalar twoGtheta = 2*G*r.theta;
    const vector N(r.dGamma > 0 ? r.devEps/mag(r.devEps) : vector::zero);
    const scalar twoGthetaBar = 2*G*r.thetaBar;
    const scalar C0 = bulkModulus() - twoGtheta/3;

    // Geometric term -P_il Finv_jk
    for (direction i = 0; i < 3; ++i)
    {
        for (direction j = 0; j < 3; ++j)
        {
            for (direction k = 0; k < 3; ++k)
            {
                for (direction l = 0; l < 3; ++l)
                {
                    dPdF(3*i + j, 3*k + l) = -P[3*i + l]*Finv[3*j + k];
                }
            }
        }
    }

    // Shears in the principal axes
    for (direction a = 0; a < 3; ++a)
    {
        for (direction b = a + 1; b < 3; ++b)
        {
            const scalar c =
                twoGtheta*0.5*symmetricEigen::logDifference(lambda[a], lambda[b]);
            dPdF.noalias() +=
                (c*(dyad9(v[a], z[b]) + dyad9(v[b], z[a])))
               *(dyad9(v[a], w[b]) + dyad9(v[b], w[a])).transpose();
        }
    }

    // Principal components: d(eps_cc)/dF = 2 L_cc Y_cc = Y_cc/l_c
    vector9 dEps[3];
    for (direction c = 0; c < 3; ++c)
    {
        dEps[c] = dyad9(v[c], w[c])/lambda[c];
    }
    for (direction a = 0; a < 3; ++a)
    {
        vector9 dTau(vector9::Zero());
        for (direction c = 0; c < 3; ++c)
        {
            const scalar Cac =
                C0 + (a == c ? twoGtheta : 0) - twoGthetaBar*N[a]*N[c];
            dTau += Cac*dEps[c];
        }
        dPdF.noalias() += dyad9(v[a], z[a])*dTau.transpose();
    }
}


// ************************************************************************* //

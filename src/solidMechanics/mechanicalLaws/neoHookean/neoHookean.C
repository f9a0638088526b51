/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "neoHookean.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(neoHookean, 0);
    addToRunTimeSelectionTable(mechanicalLaw, neoHookean, dictionary);
}
}


Foam::mechanicalLaws::neoHookean::neoHookean(const dictionary& dict)
:
    mechanicalLaw(dict)
{
    checkKeywords(dict, wordList());
}


Foam::tensor Foam::mechanicalLaws::neoHookean::stress
(
    const tensor& F,
    const materialState& old,
    materialState& updated
) const
{
    updated = old;

    if (!admissible(F))
    {
        return rejectedStress();
    }
    const scalar J = det(F);

    // [S4]
    const tensor FinvT(inv(F).T());
    return mu()*(F - FinvT) + lambda()*Foam::log(J)*FinvT;
}


Foam::tensor Foam::mechanicalLaws::neoHookean::stressAndTangent
(
    const tensor& F,
    const materialState& old,
    materialState& updated,
    stressTangent& dPdF
) const
{
    updated = old;

    if (!admissible(F))
    {
        // Not evaluated: the elastic tangent keeps a matrix invertible
        hookeTangent(dPdF);
        return rejectedStress();
    }

    // [S4] with d(F^-T)_ij/dF_kl = -Finv_jk Finv_li and
    // d(ln J)/dF_kl = Finv_lk:
    // dP_ij/dF_kl = mu d_ik d_jl + (mu - lambda ln J) Finv_jk Finv_li
    //             + lambda Finv_ji Finv_lk
    const tensor Finv(inv(F));
    const scalar lnJ = Foam::log(det(F));
    const scalar m = mu();
    const scalar l = lambda();
    const scalar c = m - l*lnJ;
    for (direction i = 0; i < 3; ++i)
    {
        for (direction j = 0; j < 3; ++j)
        {
            for (direction k = 0; k < 3; ++k)
            {
                for (direction q = 0; q < 3; ++q)
                {
                    dPdF(3*i + j, 3*k + q) =
                        (i == k && j == q ? m : 0)
                      + c*Finv[3*j + k]*Finv[3*q + i]
                      + l*Finv[3*j + i]*Finv[3*q + k];
                }
            }
        }
    }

    const tensor FinvT(Finv.T());
    return m*(F - FinvT) + l*lnJ*FinvT;
}


// ************************************************************************* //

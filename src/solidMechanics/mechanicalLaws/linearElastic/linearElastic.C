/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "linearElastic.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(linearElastic, 0);
    addToRunTimeSelectionTable(mechanicalLaw, linearElastic, dictionary);
}
}


Foam::mechanicalLaws::linearElastic::linearElastic(const dictionary& dict)
:
    mechanicalLaw(dict)
{
    checkKeywords(dict, wordList());
}


Foam::tensor Foam::mechanicalLaws::linearElastic::stress
(
    const tensor& F,
    const materialState& old,
    materialState& updated
) const
{
    // [S3]: small strain from the displacement gradient F - I
    const symmTensor eps(symm(F - tensor::I));
    updated = old;
    return tensor(lambda()*tr(eps)*symmTensor::I + 2*mu()*eps);
}


Foam::tensor Foam::mechanicalLaws::linearElastic::stressAndTangent
(
    const tensor& F,
    const materialState& old,
    materialState& updated,
    stressTangent& dPdF
) const
{
    hookeTangent(dPdF);
    return stress(F, old, updated);
}


// ************************************************************************* //

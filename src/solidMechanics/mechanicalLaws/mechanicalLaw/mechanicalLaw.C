/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "mechanicalLaw.H"
#include "boundedEntry.H"
#include "OStringStream.H"
#include "strictDictionary.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(mechanicalLaw, 0);
    defineRunTimeSelectionTable(mechanicalLaw, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::mechanicalLaw::readBounded
(
    const dictionary& dict,
    const word& key,
    const scalar lower,
    const scalar upper,
    const bool open
)
{
    OStringStream expected;
    expected
        << "a value in " << (open ? "(" : "[") << lower << ", " << upper
        << (open ? ")" : "]");
    return strictDictionary::readBounded<scalar>
    (
        dict, key,
        [&](const scalar& value)
        {
            return
                open
              ? (value > lower && value < upper)
              : (value >= lower && value <= upper);
        },
        expected.str()
    );
}


void Foam::mechanicalLaw::checkKeywords
(
    const dictionary& dict,
    const wordList& own
)
{
    wordList known({"type", "rho", "E", "nu"});
    known.append(own);
    strictDictionary::check
    (
        dict, known, "mechanical law " + dict.getOrDefault<word>("type", "")
    );
}


void Foam::mechanicalLaw::hookeTangent(stressTangent& dPdF) const
{
    const scalar l = lambda();
    const scalar m = mu();
    dPdF.setZero();
    for (direction i = 0; i < 3; ++i)
    {
        for (direction j = 0; j < 3; ++j)
        {
            dPdF(4*i, 4*j) += l;
            dPdF(3*i + j, 3*i + j) += m;
            dPdF(3*i + j, 3*j + i) += m;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaw::mechanicalLaw(const dictionary& dict)
:
    dict_(dict),
    rho_(readBounded(dict, "rho", 0, GREAT, false)),
    E_(readBounded(dict, "E", 0, GREAT)),
    nu_(readBounded(dict, "nu", -1, 0.5))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::mechanicalLaw::stressAndTangent
(
    const tensor& F,
    const materialState& old,
    materialState& updated,
    stressTangent& dPdF
) const
{
    // Central differences, step 1e-6 of |F|: truncation and round-off
    // errors both near 1e-10 relative for smooth laws
    const scalar h = 1e-6*max(mag(F), scalar(1));
    materialState scratch;
    for (direction b = 0; b < 9; ++b)
    {
        tensor Fp(F);
        tensor Fm(F);
        Fp[b] += h;
        Fm[b] -= h;
        const tensor dP((stress(Fp, old, scratch) - stress(Fm, old, scratch))/(2*h));
        for (direction a = 0; a < 9; ++a)
        {
            dPdF(a, b) = dP[a];
        }
    }
    return stress(F, old, updated);
}


// ************************************************************************* //

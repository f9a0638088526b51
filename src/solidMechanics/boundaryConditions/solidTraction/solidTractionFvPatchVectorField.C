/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "solidTractionFvPatchVectorField.H"
#include "checkedFunction1.H"
#include "addToRunTimeSelectionTable.H"
#include "strictDictionary.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(p, iF),
    traction_(),
    pressure_(),
    followerPressure_(true),
    foundationStiffness_(0),
    foundationDirection_(Zero)
{}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    calculatedFvPatchVectorField(p, iF, dict, false),
    traction_(),
    pressure_(),
    followerPressure_(dict.lookupOrDefault<bool>("followerPressure", true)),
    foundationStiffness_
    (
        dict.lookupOrDefault<scalar>("foundationStiffness", 0)
    ),
    foundationDirection_(Zero)
{
    if (foundationStiffness_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'foundationStiffness' in dictionary " << dict.name()
            << " must be >= 0, got " << foundationStiffness_ << nl
            << exit(FatalIOError);
    }
    if (foundationStiffness_ > 0)
    {
        foundationDirection_ = dict.get<vector>("foundationDirection");
        if (mag(foundationDirection_) < SMALL)
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'foundationDirection' in dictionary "
                << dict.name() << " must be a non-zero vector" << nl
                << exit(FatalIOError);
        }
        foundationDirection_ /= mag(foundationDirection_);
    }
    if (dict.found("traction"))
    {
        traction_ = checkedFunction1<vector>("traction", dict);
    }
    if (dict.found("pressure"))
    {
        pressure_ = checkedFunction1<scalar>("pressure", dict);
    }
    if (!traction_.valid() && !pressure_.valid())
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << p.name() << " of field "
            << iF.name() << " (dictionary " << dict.name() << "): "
            << "type solidTraction expects keyword 'traction' (a "
            << "Function1 of time) and/or 'pressure'" << nl
            << exit(FatalIOError);
    }

    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=(patchInternalField());
    }

    strictDictionary::check
    (
        dict,
        {
            "type", "value", "patchType", "traction", "tractionCoeffs",
            "pressure", "pressureCoeffs", "followerPressure",
            "foundationStiffness", "foundationDirection"
        },
        "solidTraction patch " + p.name()
    );
}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const solidTractionFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    calculatedFvPatchVectorField(ptf, p, iF, mapper),
    traction_(ptf.traction_.clone()),
    pressure_(ptf.pressure_.clone()),
    followerPressure_(ptf.followerPressure_),
    foundationStiffness_(ptf.foundationStiffness_),
    foundationDirection_(ptf.foundationDirection_)
{}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const solidTractionFvPatchVectorField& ptf
)
:
    calculatedFvPatchVectorField(ptf),
    solidForceBoundary(),
    traction_(ptf.traction_.clone()),
    pressure_(ptf.pressure_.clone()),
    followerPressure_(ptf.followerPressure_),
    foundationStiffness_(ptf.foundationStiffness_),
    foundationDirection_(ptf.foundationDirection_)
{}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const solidTractionFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(ptf, iF),
    traction_(ptf.traction_.clone()),
    pressure_(ptf.pressure_.clone()),
    followerPressure_(ptf.followerPressure_),
    foundationStiffness_(ptf.foundationStiffness_),
    foundationDirection_(ptf.foundationDirection_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidTractionFvPatchVectorField::force
(
    const solidPatchKinematics& k,
    vectorField& f
) const
{
    f = Zero;

    if (traction_.valid())
    {
        f += traction_->value(k.time)*mag(k.Sf0);
    }

    if (pressure_.valid())
    {
        const scalar p = pressure_->value(k.time);

        if (followerPressure_)
        {
            // [S12] Nanson: n da = J F^-T . N dA
            forAll(f, facei)
            {
                const tensor& F = k.F[facei];
                f[facei] -= p*det(F)*(inv(F).T() & k.Sf0[facei]);
            }
        }
        else
        {
            f -= p*k.Sf0;
        }
    }

    if (foundationStiffness_ > 0)
    {
        f -= mag(k.Sf0)*foundationTraction(k);
    }
}


Foam::vector Foam::solidTractionFvPatchVectorField::foundationTraction
(
    const solidPatchKinematics& k
) const
{
    // [S12] only the patch's mean displacement (its rigid translation) is
    // resisted, so the foundation does not stiffen the wall's deformation
    const scalarField magS(mag(k.Sf0));
    const vector meanD(gSum(magS*k.D)/max(gSum(magS), VSMALL));
    return foundationStiffness_*(sqr(foundationDirection_) & meanD);
}


void Foam::solidTractionFvPatchVectorField::tangent
(
    const solidPatchKinematics& k,
    List<faceForceTangent>& df
) const
{
    df.setSize(k.F.size());
    df = faceForceTangent();

    if (!pressure_.valid() || !followerPressure_)
    {
        return;
    }

    // [S21] the follower force -p a, a = J F^-T . S0 (Nanson):
    // da_i/dF_kl = a_i F^-T_kl - a_k F^-T_il
    const scalar p = pressure_->value(k.time);
    forAll(df, facei)
    {
        const tensor& F = k.F[facei];
        const tensor FinvT(inv(F).T());
        const vector a(det(F)*(FinvT & k.Sf0[facei]));
        for (direction i = 0; i < 3; ++i)
        {
            df[facei].dfdF[i] = -p*(a[i]*FinvT - a*FinvT.row(i));
        }
    }
}


void Foam::solidTractionFvPatchVectorField::meanDisplacementTangent
(
    const solidPatchKinematics& k,
    tensorField& dfdMean
) const
{
    // [S12b] f_i = -|S0_i| k (e e) . <D>
    dfdMean = (-foundationStiffness_*mag(k.Sf0))
       *tensor(sqr(foundationDirection_));
}


void Foam::solidTractionFvPatchVectorField::report
(
    const solidPatchKinematics& k
) const
{
    if (foundationStiffness_ > 0)
    {
        const vector F(-gSum(mag(k.Sf0))*foundationTraction(k));
        Info<< "    foundation force on " << patch().name() << ": " << F
            << " N" << endl;
    }
}


void Foam::solidTractionFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    if (traction_.valid())
    {
        traction_->writeData(os);
    }
    if (pressure_.valid())
    {
        pressure_->writeData(os);
    }
    os.writeEntry("followerPressure", followerPressure_);
    if (foundationStiffness_ > 0)
    {
        os.writeEntry("foundationStiffness", foundationStiffness_);
        os.writeEntry("foundationDirection", foundationDirection_);
    }
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        solidTractionFvPatchVectorField
    );
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "solidTractionFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

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
    followerPressure_(true)
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
    followerPressure_(dict.lookupOrDefault<bool>("followerPressure", true))
{
    if (dict.found("traction"))
    {
        traction_ = Function1<vector>::New("traction", dict);
    }
    if (dict.found("pressure"))
    {
        pressure_ = Function1<scalar>::New("pressure", dict);
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
    followerPressure_(ptf.followerPressure_)
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
    followerPressure_(ptf.followerPressure_)
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
    followerPressure_(ptf.followerPressure_)
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

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionalContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "wallFvPatch.H"
#include "volFields.H"
#include "strictDictionary.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::frictionalContactFvPatchVectorField::copyFrom
(
    const frictionalContactFvPatchVectorField& ptf
)
{
    copyContactFaces(ptf);
    surface_.reset(new rigidContactSurface(ptf.surface_(), patch()));
}


void Foam::frictionalContactFvPatchVectorField::mapFaces
(
    const frictionalContactFvPatchVectorField& ptf,
    const fvPatchFieldMapper& mapper
)
{
    contactFaces::mapFaces(ptf, mapper);
    surface_->resetSearches(mapper.size());
}


void Foam::frictionalContactFvPatchVectorField::evaluate
(
    const solidPatchKinematics& k,
    List<slaveFace>& faces
) const
{
    // [C4] current areas; [C1]-[C3] each face against the obstacle
    scalarField area(k.F.size());
    forAll(area, i)
    {
        area[i] = currentArea(k.F[i], k.Sf0[i]);
    }
    evaluateSlaveFaces
    (
        surface_->bind(k), k.D - k.Dold, area, k.deltaT, faces
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(p, iF)
{}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    calculatedFvPatchVectorField(p, iF, dict, false)
{
    if (!isA<wallFvPatch>(p))
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << p.name() << " (dictionary " << dict.name()
            << "): type frictionalContact needs a patch of type 'wall' in"
            << " constant/polyMesh/boundary; it is of type '" << p.type()
            << "'" << nl << exit(FatalIOError);
    }

    surface_.reset(new rigidContactSurface(p, dict));

    readContactFaces(dict);
    Info<< "    obstacle " << surface_->obstacleDict().get<word>("type")
        << ", search distance " << surface_->searchDistance() << " m"
        << endl;

    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=(patchInternalField());
    }

    surface_->checkInitialGap(*this, iF.time().value(), dict);

    wordList known({"type", "value", "patchType"});
    known.append(rigidContactSurface::keywords());
    known.append(contactFacesKeywords());
    strictDictionary::check
    (
        dict, known, "frictionalContact patch " + p.name()
    );
}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    calculatedFvPatchVectorField(ptf, p, iF, mapper)
{
    // iF may be a null field (reconstructPar): the time comes from the mesh
    copyContactFaces(ptf);
    surface_.reset(new rigidContactSurface(ptf.surface_(), p));
    mapFaces(ptf, mapper);
}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf
)
:
    calculatedFvPatchVectorField(ptf),
    contactForceBoundary(),
    contactFaces()
{
    copyFrom(ptf);
}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(ptf, iF),
    contactForceBoundary(),
    contactFaces()
{
    copyFrom(ptf);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionalContactFvPatchVectorField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    calculatedFvPatchVectorField::autoMap(m);
    const frictionalContactFvPatchVectorField old(*this);
    mapFaces(old, m);
}


void Foam::frictionalContactFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    calculatedFvPatchVectorField::rmap(ptf, addr);

    const frictionalContactFvPatchVectorField& fcptf =
        refCast<const frictionalContactFvPatchVectorField>(ptf);
    forAll(addr, i)
    {
        copyFace(fcptf, i, addr[i]);
    }
}


// ************************************************************************* //

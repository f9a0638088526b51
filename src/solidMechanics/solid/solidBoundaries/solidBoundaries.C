/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "solidBoundaries.H"
#include "emptyFvPatch.H"
#include "symmetryPlaneFvPatch.H"
#include "symmetryFvPatch.H"
#include "wedgeFvPatch.H"
#include "wedgePolyPatch.H"
#include "processorFvPatch.H"
#include "cyclicFvPatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::solidBoundaries::patchKind Foam::solidBoundaries::classify
(
    const label patchi,
    volVectorField& D
)
{
    const fvPatch& p = mesh_.boundary()[patchi];
    fvPatchVectorField& pf = D.boundaryFieldRef()[patchi];

    if (isA<emptyFvPatch>(p))
    {
        return EMPTY;
    }
    if (isA<wedgeFvPatch>(p))
    {
        return WEDGE;
    }
    if (isA<processorFvPatch>(p))
    {
        return COUPLED;
    }
    if
    (
        isA<cyclicFvPatch>(p)
     && refCast<const cyclicFvPatch>(p).parallel()
    )
    {
        // translational periodicity: the neighbour cell's values as they
        // are (a rotational one would have to rotate them)
        return COUPLED;
    }
    if (p.coupled())
    {
        FatalErrorInFunction
            << "Patch " << p.name() << " of field D (file " << D.objectPath()
            << ") is a coupled patch of type '" << p.type() << "', which"
            << " largeStrainSolidFoam does not support." << nl
            << "Coupled patches may be processor patches (decomposePar) or"
            << " translational cyclics; model a rotationally periodic body"
            << " in full" << nl << exit(FatalError);
    }
    if (isA<symmetryPlaneFvPatch>(p) || isA<symmetryFvPatch>(p))
    {
        return SYMMETRY;
    }
    if (isA<solidForceBoundary>(pf))
    {
        forcePatches_[patchi] = dynamic_cast<solidForceBoundary*>(&pf);
        contactPatches_[patchi] = dynamic_cast<contactForceBoundary*>(&pf);
        return FORCE;
    }
    if (pf.fixesValue())
    {
        return FIXED;
    }

    FatalErrorInFunction
        << "Patch " << p.name() << " of field D (file " << D.objectPath()
        << ") has boundary condition type '" << pf.type() << "', which"
        << " largeStrainSolidFoam does not support." << nl
        << "Expected a fixed-value type (fixedValue, uniformFixedValue, ...),"
        << " solidTraction, frictionalContact, or a symmetryPlane/symmetry,"
        << " wedge, empty or processor patch" << nl
        << exit(FatalError);
    return EMPTY;
}


void Foam::solidBoundaries::checkEmptyPatches(const volVectorField& D) const
{
    // A 2-D mesh has its empty faces in two parallel planes; faces whose
    // normals turn belong to a wedge, which empty patches would make a
    // plane-strain slab of the wrong shape
    vector n0(Zero);
    bool found = false;
    label bad = -1;
    forAll(mesh_.boundary(), patchi)
    {
        if (kinds_[patchi] != EMPTY)
        {
            continue;
        }
        // the polyPatch: an empty fvPatch has no faces
        const vectorField nf(mesh_.boundaryMesh()[patchi].faceNormals());
        forAll(nf, i)
        {
            if (!found)
            {
                n0 = nf[i];
                found = true;
            }
            else if (mag(nf[i] ^ n0) > 1e-6)
            {
                bad = patchi;
            }
        }
    }
    if (returnReduce(bad >= 0, orOp<bool>()))
    {
        FatalErrorInFunction
            << "The empty patches of the mesh (constant/polyMesh/boundary,"
            << " used by field D, file " << D.objectPath() << ") are not"
            << " parallel" << (bad >= 0 ? ": patch " : "")
            << (bad >= 0 ? mesh_.boundary()[bad].name() : word::null)
            << (bad >= 0 ? " is not parallel to the first one." : ".") << nl
            << "A wedge-shaped (axisymmetric) mesh needs patches of type"
            << " wedge for its front and back, a plane-strain mesh parallel"
            << " empty patches" << nl << exit(FatalError);
    }
}


void Foam::solidBoundaries::setWedgeGeometry(const volVectorField& D)
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const scalar size = mag(mesh_.bounds().span());

    forAll(pbm, patchi)
    {
        if (!isA<wedgePolyPatch>(pbm[patchi]))
        {
            continue;
        }
        const wedgePolyPatch& wp = refCast<const wedgePolyPatch>(pbm[patchi]);
        wedgeRotation_[patchi] = wp.faceT();

        if (!axisymmetric_)
        {
            axisymmetric_ = true;
            axis_ = wp.axis();
            hoopDirection_ = wp.centreNormal();
        }
        else if (mag(axis_ ^ wp.axis()) > 1e-6)
        {
            FatalErrorInFunction
                << "Wedge patches of field D (file " << D.objectPath()
                << ") have different axes: " << axis_ << " and "
                << wp.axis() << " (patch " << wp.name() << ")." << nl
                << "An axisymmetric mesh is one wedge about one axis"
                << nl << exit(FatalError);
        }

        // OpenFOAM's wedge transformations are rotations about an axis
        // through the origin: the face planes must hold it
        const vectorField Cf(wp.faceCentres());
        const vectorField nf(wp.faceNormals());
        forAll(Cf, i)
        {
            if (mag(nf[i] & Cf[i]) > 1e-6*size)
            {
                FatalErrorInFunction
                    << "Wedge patch " << wp.name() << " of field D (file "
                    << D.objectPath() << "): the face at " << Cf[i]
                    << " lies " << (nf[i] & Cf[i]) << " m off a plane"
                    << " through the origin." << nl
                    << "The wedge's axis must pass through the origin"
                    << " (axis " << wp.axis() << "); translate the mesh"
                    << nl << exit(FatalError);
            }
        }
    }

    if (!axisymmetric_)
    {
        return;
    }

    // The hoop direction must be the mesh's unsolved direction: two
    // unknowns per cell, as in plane strain
    direction hoop = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mag(hoopDirection_[d]) > mag(hoopDirection_[hoop]))
        {
            hoop = d;
        }
    }
    if (mesh_.nGeometricD() != 2 || mesh_.geometricD()[hoop] == 1)
    {
        FatalErrorInFunction
            << "Field D (file " << D.objectPath() << "): the wedge's centre"
            << " plane normal " << hoopDirection_ << " is not the mesh's"
            << " one direction without cells (geometricD " << mesh_.geometricD()
            << ")." << nl << "An axisymmetric mesh is one cell thick"
            << " around the axis, with a wedge patch on each side"
            << nl << exit(FatalError);
    }

    const vectorField& C = mesh_.C().primitiveField();
    forAll(C, celli)
    {
        const vector r(C[celli] - (C[celli] & axis_)*axis_);
        if (mag(r) < 1e-9*size)
        {
            FatalErrorInFunction
                << "Cell " << celli << " at " << C[celli] << " lies on the"
                << " axis of the wedge (field D, file " << D.objectPath()
                << "): its hoop strain u_r/r is undefined" << nl
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidBoundaries::solidBoundaries(volVectorField& D)
:
    mesh_(D.mesh()),
    kinds_(mesh_.boundary().size()),
    forcePatches_(mesh_.boundary().size(), nullptr),
    contactPatches_(mesh_.boundary().size(), nullptr),
    axisymmetric_(false),
    axis_(Zero),
    hoopDirection_(Zero),
    wedgeRotation_(mesh_.boundary().size(), tensor::I)
{
    forAll(kinds_, patchi)
    {
        kinds_[patchi] = classify(patchi, D);
    }
    DynamicList<label> contacts;
    forAll(contactPatches_, patchi)
    {
        if (contactPatches_[patchi])
        {
            contacts.append(patchi);
        }
    }
    contactPatchIDs_.transfer(contacts);
    checkEmptyPatches(D);
    setWedgeGeometry(D);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::solidBoundaries::hoopGradient(const point& X) const
{
    const vector r(X - (X & axis_)*axis_);
    return r/magSqr(r);
}


// ************************************************************************* //

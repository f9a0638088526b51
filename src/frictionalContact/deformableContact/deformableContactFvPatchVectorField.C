/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "deformableContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "strictDictionary.H"
#include "wallFvPatch.H"
#include "wedgePolyPatch.H"
#include "volFields.H"
#include "regionSplit.H"
#include "HashOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::deformableContactFvPatchVectorField::copyPair
(
    const deformableContactFvPatchVectorField& ptf
)
{
    dict_ = ptf.dict_;
    partnerName_ = ptf.partnerName_;
    slave_ = ptf.slave_;
    searchDistance_ = ptf.searchDistance_;
    checked_ = false;
    if (slave_)
    {
        copyContactFaces(ptf);
    }
}


void Foam::deformableContactFvPatchVectorField::setSegments()
{
    // [C11] a plane-strain face is a segment in the solved plane: its end
    // points are the extreme face points along the in-plane tangent
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const polyPatch& pp = patch().patch();
    const pointField& pts = mesh.points();
    if (mesh.nGeometricD() == 3)
    {
        // [C11b] the face's polygon; its segment is not used
        Xv_.setSize(pp.size());
        forAll(pp, i)
        {
            Xv_[i] = pp[i].points(pts);
        }
        Xa_ = pp.faceCentres();
        Xb_ = Xa_;
        return;
    }
    vector ez(Zero);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh.geometricD()[d] != 1)
        {
            ez[d] = 1;
        }
    }
    Xa_.setSize(pp.size());
    Xb_.setSize(pp.size());
    forAll(pp, i)
    {
        const point& C = pp.faceCentres()[i];
        vector tau(ez ^ pp.faceNormals()[i]);
        tau /= max(mag(tau), VSMALL);
        scalar lo = GREAT;
        scalar hi = -GREAT;
        for (const label pi : pp[i])
        {
            const scalar xi = (pts[pi] - C) & tau;
            lo = min(lo, xi);
            hi = max(hi, xi);
        }
        Xa_[i] = C + lo*tau;
        Xb_[i] = C + hi*tau;
    }
}


const Foam::deformableContactFvPatchVectorField&
Foam::deformableContactFvPatchVectorField::partner() const
{
    const volVectorField& D =
        db().lookupObject<volVectorField>(internalField().name());
    const label pi = patch().boundaryMesh().findPatchID(partnerName_);
    return refCast<const deformableContactFvPatchVectorField>
    (
        D.boundaryField()[pi]
    );
}


const Foam::fvPatch*
Foam::deformableContactFvPatchVectorField::partnerBodyPatch() const
{
    // The mesh's patch, not its condition: the penalties are set while D's
    // boundary conditions are still being constructed
    return &patch().boundaryMesh()
    [
        patch().boundaryMesh().findPatchID(partnerName_)
    ];
}


const Foam::deformableContactFvPatchVectorField&
Foam::deformableContactFvPatchVectorField::slaveSide() const
{
    return slave_ ? *this : partner();
}


void Foam::deformableContactFvPatchVectorField::checkPair() const
{
    if (checked_)
    {
        return;
    }
    checked_ = true;

    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const volVectorField& D =
        db().lookupObject<volVectorField>(internalField().name());
    const label pi = patch().boundaryMesh().findPatchID(partnerName_);
    const fvPatchVectorField& pf = D.boundaryField()[pi];
    if (!isA<deformableContactFvPatchVectorField>(pf))
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword 'partnerPatch' in dictionary " << dict_.name()
            << " names patch " << partnerName_ << ", whose condition is '"
            << pf.type() << "'; expected deformableContact naming "
            << patch().name() << " as its partnerPatch" << nl
            << exit(FatalIOError);
    }
    const deformableContactFvPatchVectorField& p = partner();
    if (p.partnerName_ != patch().name())
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword 'partnerPatch' in dictionary " << dict_.name()
            << ": patch " << partnerName_ << " names " << p.partnerName_
            << " as its partnerPatch, not " << patch().name()
            << "; the two patches of a pair name each other" << nl
            << exit(FatalIOError);
    }
    if (p.slave_ == slave_)
    {
        FatalIOErrorInFunction(dict_)
            << "Patches " << patch().name() << " and " << partnerName_
            << " (dictionary " << dict_.name() << ") "
            << (slave_ ? "both have" : "neither has")
            << " a 'frictionLaw': exactly one side of a deformableContact"
            << " pair (the slave) carries the law" << nl
            << exit(FatalIOError);
    }

    // [C9] the two patches must bound different bodies (connected regions)
    const regionSplit regions(mesh);
    labelHashSet own;
    for (const label c : patch().faceCells())
    {
        own.insert(regions[c]);
    }
    // [C14] the regions are numbered globally; the faces of this patch may
    // lie on other processors
    Pstream::combineGather(own, HashSetOps::plusEqOp<label, Foam::Hash<label>>());
    Pstream::combineScatter(own);
    for (const label c : mesh.boundary()[pi].faceCells())
    {
        if (own.found(regions[c]))
        {
            FatalIOErrorInFunction(dict_)
                << "Keyword 'partnerPatch' in dictionary " << dict_.name()
                << ": patches " << patch().name() << " and " << partnerName_
                << " bound the same body (connected cells, e.g. cell " << c
                << " at " << mesh.C()[c] << "); contact pairs two bodies"
                << nl << exit(FatalIOError);
        }
    }

    // Bodies that overlap at the start (a mesh or an initial displacement
    // in which a slave face lies behind the master surface by more than 1 %
    // of its cell depth: no penalty pushes them apart gently). Not at a
    // restart: its displacement is a converged solution, whose faces
    // penetrate by the penalty's tN/KN ([C5], [C5d]), several per cent of
    // a cell depth where a stiff body's corner presses into a soft one
    const Time& runTime = mesh.time();
    const bool restart = isFile
    (
        runTime.path()/runTime.timeName(runTime.startTime().value())
       /"uniform"/"solidState",
        false
    );
    if (!restart && runTime.timeIndex() <= runTime.startTimeIndex() + 1)
    {
        const deformableContactFvPatchVectorField& s = slaveSide();
        side sl;
        side ms;
        s.committedKinematics(sl);
        s.partnerKinematics(ms, true);
        List<slaveFace> faces;
        s.evaluatePair(sl, ms, mesh.time().deltaTValue(), faces);
        const scalarField& V = mesh.V();
        const labelUList& fc = s.patch().faceCells();
        forAll(faces, i)
        {
            const scalar depth = V[fc[i]]/mag(sl.S0[i]);
            if (faces[i].inReach && faces[i].gap < -0.01*depth)
            {
                FatalIOErrorInFunction(s.dict_)
                    << "Patches " << s.patch().name() << " and "
                    << s.partnerName_ << " (keyword 'partnerPatch' in "
                    << "dictionary " << s.dict_.name() << ") overlap at the"
                    << " start: face " << i << " of " << s.patch().name()
                    << " at " << sl.X[i] + sl.D[i] << " lies "
                    << -faces[i].gap << " m behind the other body's surface"
                    << " (its cell depth is " << depth << " m); move the"
                    << " bodies apart in the mesh" << nl
                    << exit(FatalIOError);
            }
        }
    }
}


void Foam::deformableContactFvPatchVectorField::committedKinematics
(
    side& s
) const
{
    s.X = patch().Cf();
    s.S0 = patch().Sf();
    s.Dold = *this;
    s.D = s.Dold;
    s.F = tensorField(s.X.size(), tensor::I);
    s.Xa = Xa_;
    s.Xb = Xb_;
    s.a = Xa_ + s.D;
    s.b = Xb_ + s.D;
    s.Xv = Xv_;
    s.v = Xv_;
    forAll(s.v, i)
    {
        s.v[i] += s.D[i];
    }
    s.area = mag(s.S0);
    s.n = s.S0/s.area;
}


void Foam::deformableContactFvPatchVectorField::kinematics(side& s) const
{
    // The solver's iterate: the solid's face kinematics of this force
    // patch [C2], the same the solver hands the patch
    s.X = patch().Cf();
    s.S0 = patch().Sf();
    s.Dold = *this;
    body().forcePatchKinematics(patch().index(), s.D, s.F);
    const label n = s.D.size();
    s.a.setSize(n);
    s.b.setSize(n);
    s.area.setSize(n);
    s.n.setSize(n);
    s.Xa = Xa_;
    s.Xb = Xb_;
    s.Xv = Xv_;
    s.v = Xv_;
    for (label i = 0; i < n; ++i)
    {
        faceGeometry(s, i);
    }
}


void Foam::deformableContactFvPatchVectorField::faceGeometry
(
    side& s,
    const label i
)
{
    const point x(s.X[i] + s.D[i]);
    s.a[i] = x + (s.F[i] & (s.Xa[i] - s.X[i]));
    s.b[i] = x + (s.F[i] & (s.Xb[i] - s.X[i]));
    if (s.Xv.size())
    {
        // [C11b] the deformed polygon: linear within the face as D and F
        const pointField& Xv = s.Xv[i];
        pointField& v = s.v[i];
        forAll(Xv, k)
        {
            v[k] = x + (s.F[i] & (Xv[k] - s.X[i]));
        }
    }
    const vector A(currentAreaVector(s.F[i], s.S0[i]));
    s.area[i] = mag(A);
    s.n[i] = A/max(s.area[i], VSMALL);
}


Foam::scalar Foam::deformableContactFvPatchVectorField::faceLength
(
    const side& s,
    const label i
)
{
    return s.Xv.size() ? Foam::sqrt(s.area[i]) : mag(s.b[i] - s.a[i]);
}


void Foam::deformableContactFvPatchVectorField::evaluate
(
    side& sl,
    side& ms,
    List<slaveFace>& faces,
    const scalar deltaT
) const
{
    const deformableContactFvPatchVectorField& s = slaveSide();
    s.kinematics(sl);
    s.partnerKinematics(ms, false);
    s.evaluatePair(sl, ms, deltaT, faces);
}


void Foam::deformableContactFvPatchVectorField::pairForces
(
    const List<slaveFace>& faces,
    const label nMaster,
    vectorField& fSlave,
    vectorField& fMaster
)
{
    // [C1], [C10]: f_s = c da (tN n - tT); f_m = -sum_s w_sm f_s
    fSlave.setSize(faces.size());
    fSlave = Zero;
    fMaster.setSize(nMaster);
    fMaster = Zero;
    forAll(faces, i)
    {
        const slaveFace& sf = faces[i];
        if (!sf.inReach)
        {
            continue;
        }
        fSlave[i] = slaveForce(sf);
        forAll(sf.masters, j)
        {
            fMaster[sf.masters[j]] -= sf.weights[j]*fSlave[i];
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformableContactFvPatchVectorField::deformableContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(p, iF),
    slave_(false),
    searchDistance_(GREAT),
    checked_(false),
    committedTime_(-GREAT)
{
    setSegments();
}


Foam::deformableContactFvPatchVectorField::deformableContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    calculatedFvPatchVectorField(p, iF, dict, false),
    dict_(dict),
    partnerName_(dict.get<word>("partnerPatch")),
    slave_(dict.found("frictionLaw")),
    searchDistance_(-1),
    checked_(false),
    committedTime_(-GREAT)
{
    const fvMesh& mesh = p.boundaryMesh().mesh();
    if (!isA<wallFvPatch>(p))
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << p.name() << " (dictionary " << dict.name()
            << "): type deformableContact needs a patch of type 'wall' in"
            << " constant/polyMesh/boundary; it is of type '" << p.type()
            << "'" << nl << exit(FatalIOError);
    }
    const label partneri = p.boundaryMesh().findPatchID(partnerName_);
    if (partneri < 0 || partneri == p.index())
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'partnerPatch' in dictionary " << dict.name()
            << " names '" << partnerName_ << "', "
            << (partneri < 0 ? "which is no patch of the mesh" : "the patch itself")
            << "; expected the facing patch of the other body, one of "
            << p.boundaryMesh().mesh().boundaryMesh().names() << nl
            << exit(FatalIOError);
    }
    if (mesh.nGeometricD() < 2)
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << p.name() << " (dictionary " << dict.name()
            << "): deformableContact needs a plane-strain (2-D) or 3-D"
            << " mesh (doc/theory.md [C11]); this mesh is "
            << mesh.nGeometricD() << "-D" << nl << exit(FatalIOError);
    }
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wedgePolyPatch>(pp))
        {
            FatalIOErrorInFunction(dict)
                << "Patch " << p.name() << " (dictionary " << dict.name()
                << "): deformableContact is built for plane strain only;"
                << " the mesh is axisymmetric (wedge patch " << pp.name()
                << ")" << nl << exit(FatalIOError);
        }
    }
    // [C14] the same on every processor, whether it holds faces of the
    // patch or not
    searchDistance_ = contactSurface::readSearchDistance(dict, p);

    setSegments();
    if (slave_)
    {
        readContactFaces(dict);
    }

    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=(patchInternalField());
    }

    // The law, penalties and face state only on the side with a law
    wordList known({"type", "value", "patchType", "partnerPatch"});
    known.append("searchDistance");
    if (slave_)
    {
        known.append(contactFacesKeywords());
    }
    strictDictionary::check
    (
        dict, known,
        "deformableContact patch " + p.name()
      + (
            slave_
          ? " (with the friction law)"
          : " (without 'frictionLaw': the law, penalties and smoothing go"
            " with 'frictionLaw' on one side of the pair)"
        )
    );
}


Foam::deformableContactFvPatchVectorField::deformableContactFvPatchVectorField
(
    const deformableContactFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    calculatedFvPatchVectorField(ptf, p, iF, mapper),
    dict_(ptf.dict_),
    partnerName_(ptf.partnerName_),
    slave_(ptf.slave_),
    searchDistance_(ptf.searchDistance_),
    checked_(false),
    committedTime_(-GREAT)
{
    setSegments();
    if (slave_)
    {
        copyContactFaces(ptf);
        mapFaces(ptf, mapper);
    }
}


Foam::deformableContactFvPatchVectorField::deformableContactFvPatchVectorField
(
    const deformableContactFvPatchVectorField& ptf
)
:
    calculatedFvPatchVectorField(ptf),
    contactForceBoundary(),
    contactFaces(),
    Xa_(ptf.Xa_),
    Xb_(ptf.Xb_),
    Xv_(ptf.Xv_),
    committedTime_(-GREAT)
{
    copyPair(ptf);
}


Foam::deformableContactFvPatchVectorField::deformableContactFvPatchVectorField
(
    const deformableContactFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(ptf, iF),
    contactForceBoundary(),
    contactFaces(),
    Xa_(ptf.Xa_),
    Xb_(ptf.Xb_),
    Xv_(ptf.Xv_),
    committedTime_(-GREAT)
{
    copyPair(ptf);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformableContactFvPatchVectorField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    calculatedFvPatchVectorField::autoMap(m);
    setSegments();
    if (slave_)
    {
        const deformableContactFvPatchVectorField old(*this);
        mapFaces(old, m);
    }
}


void Foam::deformableContactFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    calculatedFvPatchVectorField::rmap(ptf, addr);
    if (slave_)
    {
        const deformableContactFvPatchVectorField& dptf =
            refCast<const deformableContactFvPatchVectorField>(ptf);
        forAll(addr, i)
        {
            copyFace(dptf, i, addr[i]);
        }
    }
}


void Foam::deformableContactFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    os.writeEntry("partnerPatch", partnerName_);
    os.writeEntry("searchDistance", searchDistance_);
    if (slave_)
    {
        writeFaces(os);
    }
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        deformableContactFvPatchVectorField
    );
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    contactFaces: the commit of a converged step, reports, the fields
    written for ParaView and the face state written for restart.

\*---------------------------------------------------------------------------*/

#include "contactFaces.H"
#include "volFields.H"
#include "reportFiles.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Diagnostic field of the mesh: found, or created (zero, written)
template<class Type>
static GeometricField<Type, fvPatchField, volMesh>& contactField
(
    const objectRegistry& db,
    const fvMesh& mesh,
    const word& name,
    const dimensionSet& dims
)
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;
    if (!db.foundObject<fieldType>(name))
    {
        fieldType* fldPtr = new fieldType
        (
            IOobject
            (
                name,
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::AUTO_WRITE
            ),
            mesh,
            dimensioned<Type>(dims, Zero)
        );
        fldPtr->store();
    }
    return const_cast<fieldType&>(db.lookupObject<fieldType>(name));
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactFaces::updateFields() const
{
    const fvMesh& mesh = contactPatch().boundaryMesh().mesh();
    const label pi = contactPatch().index();

    auto scalarOut = [&](const word& name, const dimensionSet& dims)
        -> scalarField&
    {
        return contactField<scalar>(mesh, mesh, name, dims)
            .boundaryFieldRef()[pi];
    };
    auto vectorOut = [&](const word& name, const dimensionSet& dims)
        -> vectorField&
    {
        return contactField<vector>(mesh, mesh, name, dims)
            .boundaryFieldRef()[pi];
    };

    // The law's state variables it marks shown
    for (const frictionStateEntry& e : layout_.entries())
    {
        if (!e.show)
        {
            continue;
        }
        if (e.kind == frictionStateEntry::VECTOR)
        {
            vectorOut(e.name, dimensionSet(e.dimensions)) = layout_.vectorValues(state_, e);
        }
        else
        {
            scalarOut(e.name, dimensionSet(e.dimensions)) = layout_.scalarValues(state_, e);
        }
    }
    scalarOut("contactPressure", dimPressure) = contactPressure_;
    scalarOut("nominalContactPressure", dimPressure) =
        nominalContactPressure_;
    vectorOut("frictionTraction", dimPressure) = frictionTraction_;
    scalarOut("penetration", dimLength) = penetration_;
}


void Foam::contactFaces::writeIntegrals() const
{
    if (!Pstream::master())
    {
        return;
    }
    const Time& runTime = contactPatch().boundaryMesh().mesh().time();
    const fileName dir(runTime.globalPath()/"postProcessing"/"contact");
    mkDir(dir);
    const fileName file(dir/(contactPatch().name() + ".dat"));
    const bool fresh = !isFile(file);
    OFstream os
    (
        file, IOstream::ASCII, IOstream::currentVersion,
        IOstream::UNCOMPRESSED, true
    );
    if (fresh)
    {
        os  << "# time normalForce(x y z) [N] frictionForce(x y z) [N]"
            << " dissipatedEnergy [J] maxPenetration [m]"
            << " at(x y z) contactFaces slipFaces" << nl;
    }
    os  << runTime.value() << ' '
        << normalForce_.x() << ' ' << normalForce_.y() << ' '
        << normalForce_.z() << ' '
        << frictionForce_.x() << ' ' << frictionForce_.y() << ' '
        << frictionForce_.z() << ' '
        << totalDissipation_ << ' ' << maxPenetration_ << ' '
        << maxPenetrationAt_.x() << ' ' << maxPenetrationAt_.y() << ' '
        << maxPenetrationAt_.z() << ' ' << nContact_ << ' ' << nSlip_ << nl;
    reportFiles::checkWritten(os);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactFaces::beginCommit()
{
    normalForce_ = Zero;
    frictionForce_ = Zero;
    maxPenetration_ = 0;
    maxPenetrationAt_ = Zero;
    nContact_ = 0;
    nSlip_ = 0;
    sensitivity_ = frictionLaw::sensitivitySummary();
}


void Foam::contactFaces::commitFace
(
    const label i,
    const frictionResult& res,
    const vector& n,
    const scalar area,
    const scalar gap,
    const scalar magS0,
    const point& x
)
{
    // [C7] dissipation: friction traction times plastic slip
    dissipation_[i] +=
        area*(res.tT & (res.state.plasticSlip - state_[i].plasticSlip));
    state_[i] = res.state;
    contactPressure_[i] = res.tN;
    nominalContactPressure_[i] = res.tN*area/magS0;
    frictionTraction_[i] = -res.tT;
    penetration_[i] = max(-gap, scalar(0));
    multipliers_.commit(i, res.tN);
    committedInReach_[i] = true;

    normalForce_ += area*res.tN*n;
    frictionForce_ -= area*res.tT;
    if (res.tN > 0)
    {
        ++nContact_;
        if (res.state.status == 2)
        {
            ++nSlip_;
            sampleSensitivity(res);
        }
        const scalar pen = max(-gap, scalar(0));
        if (pen > maxPenetration_)
        {
            maxPenetration_ = pen;
            maxPenetrationAt_ = x;
        }
    }
}


void Foam::contactFaces::commitOpenFace(const label i)
{
    frictionState s(law().initialState());
    s.cumulatedSlip = state_[i].cumulatedSlip;
    state_[i] = s;
    contactPressure_[i] = 0;
    nominalContactPressure_[i] = 0;
    frictionTraction_[i] = Zero;
    penetration_[i] = 0;
    multipliers_.commitOpen(i);
    committedInReach_[i] = false;
}


void Foam::contactFaces::endCommit()
{
    // the next step's k from the plastic strain just committed
    refreshShearYield();
    totalDissipation_ = gSum(dissipation_);
    reduce(normalForce_, sumOp<vector>());
    reduce(frictionForce_, sumOp<vector>());
    reduce(nContact_, sumOp<label>());
    reduce(nSlip_, sumOp<label>());
    {
        frictionLaw::sensitivitySummary& s = sensitivity_;
        const scalar localMin = s.minimum;
        reduce(s.minimum, minOp<scalar>());
        if (localMin != s.minimum)
        {
            s.vAtMin = -GREAT;
            s.pAtMin = -GREAT;
        }
        reduce(s.vAtMin, maxOp<scalar>());
        reduce(s.pAtMin, maxOp<scalar>());
        reduce(s.nSampled, sumOp<label>());
        reduce(s.nNegative, sumOp<label>());
        reduce(s.vNegMin, minOp<scalar>());
        reduce(s.vNegMax, maxOp<scalar>());
        reduce(s.pNegMin, minOp<scalar>());
        reduce(s.pNegMax, maxOp<scalar>());
    }
    {
        // location of the largest penetration over all processors
        scalarList pens(Pstream::nProcs(), scalar(0));
        List<point> where(Pstream::nProcs(), point::zero);
        pens[Pstream::myProcNo()] = maxPenetration_;
        where[Pstream::myProcNo()] = maxPenetrationAt_;
        Pstream::gatherList(pens);
        Pstream::gatherList(where);
        Pstream::scatterList(pens);
        Pstream::scatterList(where);
        const label iMax = findMax(pens);
        maxPenetration_ = pens[iMax];
        maxPenetrationAt_ = where[iMax];
    }

    // [C5b] the next step starts from this step's normal tractions (and
    // [C5f] from their extrapolation, once the step's size is known)
    multipliers_.predict(0);

    updateFields();
    writeIntegrals();
}


void Foam::contactFaces::commitReaction
(
    const vectorField& f,
    const vectorField& n,
    const scalarField& area,
    const scalarField& magS0
)
{
    beginCommit();
    resizeFaces(f.size());
    forAll(f, i)
    {
        // traction on this surface: the pressure pushes against its normal
        const vector t(f[i]/max(area[i], VSMALL));
        const scalar p = -(t & n[i]);
        contactPressure_[i] = p;
        nominalContactPressure_[i] = -(f[i] & n[i])/magS0[i];
        frictionTraction_[i] = t + p*n[i];
        penetration_[i] = 0;
        normalForce_ += (f[i] & n[i])*n[i];
        frictionForce_ += f[i] - (f[i] & n[i])*n[i];
        if (p > 0)
        {
            ++nContact_;
        }
    }
    endCommit();
}


void Foam::contactFaces::reportFaces(const scalar time) const
{
    const word& name = contactPatch().name();
    Info<< "    contact " << name << ": " << nContact_
        << " faces in contact (" << nSlip_ << " slipping), normal force "
        << normalForce_ << " N, friction force " << frictionForce_
        << " N, dissipated " << totalDissipation_ << " J, largest"
        << " penetration " << maxPenetration_ << " m at "
        << maxPenetrationAt_ << endl;

    // [F21] sliding faces with a negative instantaneous rate sensitivity
    const frictionLaw::sensitivitySummary& s = sensitivity_;
    if (s.nNegative)
    {
        if (!illPosedWarned_)
        {
            law().warnIllPosed
            (
                s,
                "sliding faces of patch " + name + " at t = "
              + Foam::name(time)
            );
            illPosedWarned_ = true;
        }
        Info<< "    contact " << name << ": ill-posed sliding on "
            << s.nNegative << " of " << s.nSampled << " sliding faces"
            << " (d tT/d ln v < 0 at tN " << s.pNegMin << " to "
            << s.pNegMax << " Pa, v " << s.vNegMin << " to " << s.vNegMax
            << " m/s; min " << s.minimum << " Pa)" << endl;
    }
}


void Foam::contactFaces::writeFaces(Ostream& os) const
{
    os.writeKeyword("frictionLaw") << lawDict_;
    os.writeEntry("penaltyScale", penaltyScale_);
    os.writeEntry("tangentialPenaltyScale", tangentialPenaltyScale_);
    os.writeEntry("contactSmoothing", contactSmoothing_);

    // Face state for restart, as the law declares it
    layout_.write(os, state_);
    dissipation_.writeEntry("dissipatedEnergy", os);
    multipliers_.write(os);
}


// ************************************************************************* //

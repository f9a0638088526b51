/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.

Description
    frictionalContact: forces and their tangent handed to the solver, the commit
    of a converged step, reports and the fields written for ParaView.

\*---------------------------------------------------------------------------*/

#include "frictionalContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "OFstream.H"

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

void Foam::frictionalContactFvPatchVectorField::updateFields() const
{
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const label pi = patch().index();

    auto scalarOut = [&](const word& name, const dimensionSet& dims)
        -> scalarField&
    {
        return contactField<scalar>(db(), mesh, name, dims)
            .boundaryFieldRef()[pi];
    };
    auto vectorOut = [&](const word& name, const dimensionSet& dims)
        -> vectorField&
    {
        return contactField<vector>(db(), mesh, name, dims)
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


void Foam::frictionalContactFvPatchVectorField::sampleSensitivity
(
    const frictionResult& res
)
{
    // [F21] at the face's own pressure, sliding rate and state
    const frictionLaw& l = law();
    if (l.nRateStates() >= 0 && res.state.status == frictionState::SLIP)
    {
        frictionLaw::rateStates x(scalar(0));
        l.rateStatesOf(res.state, x);
        sensitivity_.add
        (
            l.rateSensitivity(res.state.slipRate, x, res.tN),
            res.state.slipRate, res.tN
        );
    }
}


void Foam::frictionalContactFvPatchVectorField::writeIntegrals() const
{
    if (!Pstream::master())
    {
        return;
    }
    const Time& runTime = db().time();
    const fileName dir(runTime.globalPath()/"postProcessing"/"contact");
    mkDir(dir);
    const fileName file(dir/(patch().name() + ".dat"));
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
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionalContactFvPatchVectorField::force
(
    const solidPatchKinematics& k,
    vectorField& f
) const
{
    frictionResult res;
    vector n;
    scalar area;
    scalar gap;
    forAll(f, i)
    {
        if (evaluateFace(i, k, res, n, area, gap))
        {
            // [C1] traction on the body: tN n - tT
            f[i] = area*(res.tN*n - res.tT);
        }
        else
        {
            f[i] = Zero;
        }
    }
}


void Foam::frictionalContactFvPatchVectorField::tangent
(
    const solidPatchKinematics& k,
    List<faceForceTangent>& df
) const
{
    // [C6] the exact derivative of f = da (tN n - tT) with respect to the
    // face displacement and deformation gradient, the face state held
    df.setSize(k.F.size());
    df = faceForceTangent();

    const scalarField& V = patch().boundaryMesh().mesh().V();
    const labelUList& faceCells = patch().faceCells();
    const scalar e = contactSmoothing_;

    forAll(df, facei)
    {
        const frictionState& old = state_[facei];

        const point x(k.Cf0[facei] + k.D[facei]);
        obstaclePoint cp;
        if
        (
            !obstacle_->nearest
            (
                x, k.time, searchDistance_,
                searchRefreshFraction_*V[faceCells[facei]]/mag(k.Sf0[facei]),
                cp, search_[facei]
            )
        )
        {
            continue;
        }

        const vector& n = cp.n;
        const tensor& N = cp.dndx;
        const tensor P(tensor::I - sqr(n));
        const vector v
        (
            old.totalSlip + (k.D[facei] - k.Dold[facei])
          - obstacle_->materialDisplacement(cp.p, k.time - k.deltaT, k.time)
        );

        frictionInput in;
        in.gN = smoothedPenetration(-cp.gap);
        in.gT = P & v;
        in.n = n;
        in.dt = k.deltaT;
        frictionResult res;
        law().update(old, in, res);

        // gN = smoothed(-gap) [C2b]; gT = (I - n n).v [C3]
        const scalar g = -cp.gap;
        const scalar dSmooth =
            g >= e ? 1 : (g <= -e ? 0 : (g + e)/(2*e));
        const vector dgNdx(-dSmooth*cp.dgapdx);
        const tensor dvdx
        (
            tensor::I
          - (
                obstacle_->materialDisplacementGradient
                (
                    k.time - k.deltaT, k.time
                ) & cp.dpdx
            )
        );
        const tensor dgTdx
        (
            (P & dvdx) - (n & v)*N - n*(N.T() & v)
        );

        // the law's tangent [F7]; on a curved obstacle also the turn of
        // the tangent plane inside the law, by central differences in n
        tensor dtTdx((res.dtTdgT & dgTdx) + res.dtTdgN*dgNdx);
        if (magSqr(N) > 0)
        {
            const scalar h = 1e-6;
            vector t1(P & vector(1, 0, 0));
            if (magSqr(t1) < 0.1)
            {
                t1 = P & vector(0, 1, 0);
            }
            t1 /= mag(t1);
            const vector t2(n ^ t1);
            for (const vector& tj : {t1, t2})
            {
                frictionInput inp(in);
                frictionInput inm(in);
                inp.n = (n + h*tj)/mag(n + h*tj);
                inm.n = (n - h*tj)/mag(n - h*tj);
                frictionResult rp;
                frictionResult rm;
                law().update(old, inp, rp);
                law().update(old, inm, rm);
                dtTdx += ((rp.tT - rm.tT)/(2*h))*(N.T() & tj);
            }
        }

        // [C4] area da = |a|, a = J F^-T . S0
        const tensor& F = k.F[facei];
        const tensor FinvT(inv(F).T());
        const vector a(det(F)*(FinvT & k.Sf0[facei]));
        const scalar area = mag(a);
        const tensor dAreadF(area*FinvT - a*(inv(F) & (a/area)));

        const vector t(res.tN*n - res.tT);
        df[facei].dfdD =
            area*(n*(res.dtNdgN*dgNdx) + res.tN*N - dtTdx);
        for (direction i = 0; i < 3; ++i)
        {
            df[facei].dfdF[i] = t[i]*dAreadF;
        }
    }
}


void Foam::frictionalContactFvPatchVectorField::linearise
(
    const solidPatchKinematics& k
)
{
    linearised_ = false;
    const label n = state_.size();
    heldInput_.setSize(n);
    heldResult_.setSize(n);
    heldInReach_.setSize(n);
    vector normal;
    scalar area;
    scalar gap;
    forAll(state_, i)
    {
        heldInReach_[i] = evaluateFace
        (
            i, k, heldResult_[i], normal, area, gap, &heldInput_[i]
        );
    }
    linearised_ = true;
}


void Foam::frictionalContactFvPatchVectorField::release()
{
    linearised_ = false;
}


void Foam::frictionalContactFvPatchVectorField::commit
(
    const solidPatchKinematics& k
)
{
    normalForce_ = Zero;
    frictionForce_ = Zero;
    maxPenetration_ = 0;
    maxPenetrationAt_ = Zero;
    nContact_ = 0;
    nSlip_ = 0;
    sensitivity_ = frictionLaw::sensitivitySummary();

    frictionResult res;
    vector n;
    scalar area;
    scalar gap;

    forAll(state_, i)
    {
        if (evaluateFace(i, k, res, n, area, gap))
        {
            // [C7] dissipation: friction traction times plastic slip
            dissipation_[i] +=
                area*(res.tT & (res.state.plasticSlip - state_[i].plasticSlip));
            state_[i] = res.state;
            contactPressure_[i] = res.tN;
            nominalContactPressure_[i] = res.tN*area/mag(k.Sf0[i]);
            frictionTraction_[i] = -res.tT;
            penetration_[i] = max(-gap, scalar(0));

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
                    maxPenetrationAt_ = k.Cf0[i] + k.D[i];
                }
            }
        }
        else
        {
            // out of reach: an open face, fresh if it comes back
            frictionState s(law().initialState());
            s.cumulatedSlip = state_[i].cumulatedSlip;
            state_[i] = s;
            contactPressure_[i] = 0;
            nominalContactPressure_[i] = 0;
            frictionTraction_[i] = Zero;
            penetration_[i] = 0;
        }
    }

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

    updateFields();
    writeIntegrals();
}


void Foam::frictionalContactFvPatchVectorField::report
(
    const solidPatchKinematics& k
) const
{
    Info<< "    contact " << patch().name() << ": " << nContact_
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
                "sliding faces of patch " + patch().name() + " at t = "
              + name(k.time)
            );
            illPosedWarned_ = true;
        }
        Info<< "    contact " << patch().name() << ": ill-posed sliding on "
            << s.nNegative << " of " << s.nSampled << " sliding faces"
            << " (d tT/d ln v < 0 at tN " << s.pNegMin << " to "
            << s.pNegMax << " Pa, v " << s.vNegMin << " to " << s.vNegMax
            << " m/s; min " << s.minimum << " Pa)" << endl;
    }

    // [C2c] obstacle searches since the last report (this step and any
    // cut-back attempts before it)
    const labelPair n
    (
        returnReduce(obstacle_->searchCounts().first(), sumOp<label>()),
        returnReduce(obstacle_->searchCounts().second(), sumOp<label>())
    );
    if (n.first() + n.second() > 0)
    {
        Info<< "    contact " << patch().name() << ": obstacle searches "
            << n.first() << ", re-projections " << n.second() << endl;
    }
    obstacle_->resetSearchCounts();
}


void Foam::frictionalContactFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    os.writeKeyword("obstacle") << obstacleDict_;
    os.writeKeyword("frictionLaw") << lawDict_;
    os.writeEntry("penaltyScale", penaltyScale_);
    os.writeEntry("tangentialPenaltyScale", tangentialPenaltyScale_);
    os.writeEntry("searchDistance", searchDistance_);
    os.writeEntry("contactSmoothing", contactSmoothing_);
    os.writeEntry("searchRefreshFraction", searchRefreshFraction_);

    // Face state for restart, as the law declares it
    layout_.write(os, state_);
    dissipation_.writeEntry("dissipatedEnergy", os);

    // [C2c] search records (triangulated obstacles): -1 not searched, -2
    // nothing in reach, else the triangle followed
    if (obstacle_->cachesSearches())
    {
        labelField tri(search_.size());
        vectorField x0(search_.size());
        forAll(search_, i)
        {
            tri[i] =
                !search_[i].searched ? -1
              : !search_[i].hit ? -2
              : search_[i].hint;
            x0[i] = search_[i].x0;
        }
        tri.writeEntry("searchTriangle", os);
        x0.writeEntry("searchPoint", os);
    }
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        frictionalContactFvPatchVectorField
    );
}


// ************************************************************************* //

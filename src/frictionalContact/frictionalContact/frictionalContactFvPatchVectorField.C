/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "frictionalContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "wallFvPatch.H"
#include "volFields.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::frictionalContactFvPatchVectorField::automaticPenalty
(
    const scalar scale
) const
{
    // [C5] a face penalty as stiff as penaltyScale cells of the solid
    const dictionary& lawDict =
        db().lookupObject<IOdictionary>("mechanicalProperties")
       .subDict("mechanicalLaw");
    const scalar E = lawDict.get<scalar>("E");
    const scalar nu = lawDict.get<scalar>("nu");

    const scalarField& V = patch().boundaryMesh().mesh().V();
    const labelUList& fc = patch().faceCells();
    const scalarField& magSf = patch().magSf();
    scalar sumDepth = 0;
    forAll(fc, i)
    {
        sumDepth += V[fc[i]]/magSf[i];
    }
    const scalar h =
        returnReduce(sumDepth, sumOp<scalar>())
       /max(returnReduce(fc.size(), sumOp<label>()), 1);

    return scale*E/(1 - sqr(nu))/max(h, VSMALL);
}


void Foam::frictionalContactFvPatchVectorField::createLaw() const
{
    dictionary dict(lawDict_);
    const bool automatic = !dict.found("KN") || !dict.found("KT");
    if (automatic)
    {
        if (!dict.found("KN"))
        {
            dict.add("KN", automaticPenalty(penaltyScale_));
        }
        if (!dict.found("KT"))
        {
            dict.add("KT", automaticPenalty(tangentialPenaltyScale_));
        }
    }
    law_ = frictionLaw::New(dict);
    effectiveLawDict_ = dict;
    layout_ = law_->stateLayout();

    Info<< "frictionalContact on patch " << patch().name() << ": law "
        << lawDict_.get<word>("type") << ", obstacle "
        << obstacleDict_.get<word>("type") << ", KN " << law_->KN()
        << " Pa/m, KT " << law_->KT() << " Pa/m"
        << (automatic ? " (automatic)" : "") << ", search distance "
        << searchDistance_ << " m" << endl;
}


void Foam::frictionalContactFvPatchVectorField::copyFrom
(
    const frictionalContactFvPatchVectorField& ptf
)
{
    obstacleDict_ = ptf.obstacleDict_;
    lawDict_ = ptf.lawDict_;
    effectiveLawDict_ = ptf.effectiveLawDict_;
    obstacle_ = rigidObstacle::New(obstacleDict_, db().time().globalPath());
    if (ptf.law_.valid())
    {
        law_ = frictionLaw::New(effectiveLawDict_);
    }
    penaltyScale_ = ptf.penaltyScale_;
    tangentialPenaltyScale_ = ptf.tangentialPenaltyScale_;
    searchDistance_ = ptf.searchDistance_;
    contactSmoothing_ = ptf.contactSmoothing_;
    searchRefreshFraction_ = ptf.searchRefreshFraction_;
    layout_ = ptf.layout_;
    state_ = ptf.state_;
    search_ = ptf.search_;
    contactPressure_ = ptf.contactPressure_;
    nominalContactPressure_ = ptf.nominalContactPressure_;
    frictionTraction_ = ptf.frictionTraction_;
    penetration_ = ptf.penetration_;
    normalForce_ = ptf.normalForce_;
    frictionForce_ = ptf.frictionForce_;
    totalDissipation_ = ptf.totalDissipation_;
    dissipation_ = ptf.dissipation_;
    maxPenetration_ = ptf.maxPenetration_;
    maxPenetrationAt_ = ptf.maxPenetrationAt_;
    nContact_ = ptf.nContact_;
    nSlip_ = ptf.nSlip_;
    sensitivity_ = ptf.sensitivity_;
    illPosedWarned_ = ptf.illPosedWarned_;
    linearised_ = false;
}


const Foam::frictionLaw& Foam::frictionalContactFvPatchVectorField::law() const
{
    if (!law_.valid())
    {
        createLaw();
    }
    return law_();
}


void Foam::frictionalContactFvPatchVectorField::copyFace
(
    const frictionalContactFvPatchVectorField& ptf,
    const label from,
    const label to
)
{
    if (from < 0 || from >= ptf.state_.size())
    {
        return;
    }
    state_[to] = ptf.state_[from];
    search_[to] = obstacleSearch();
    contactPressure_[to] = ptf.contactPressure_[from];
    nominalContactPressure_[to] = ptf.nominalContactPressure_[from];
    frictionTraction_[to] = ptf.frictionTraction_[from];
    penetration_[to] = ptf.penetration_[from];
    dissipation_[to] = ptf.dissipation_[from];
}


void Foam::frictionalContactFvPatchVectorField::readState
(
    const dictionary& dict,
    const frictionLaw& l
)
{
    const label n = patch().size();
    state_.setSize(n, l.initialState());
    search_.setSize(n, obstacleSearch());
    contactPressure_.setSize(n, 0);
    nominalContactPressure_.setSize(n, 0);
    frictionTraction_.setSize(n, Zero);
    penetration_.setSize(n, 0);
    dissipation_.setSize(n, 0);

    // Restart: the state written by write(), as the law declares it
    if (layout_.foundIn(dict))
    {
        const wordList missing = layout_.read(dict, state_);
        if (missing.size())
        {
            WarningInFunction
                << "patch " << patch().name() << ": the restart state in "
                << dict.name() << " has no " << missing << " (written by"
                << " another law?); law " << lawDict_.get<word>("type")
                << " starts those as in a fresh contact" << endl;
        }
    }
    if (dict.found("dissipatedEnergy"))
    {
        dissipation_ = scalarField("dissipatedEnergy", dict, n);
    }

    // [C2c] the search records as written: a restart then re-projects
    // where the uninterrupted run would (the same triangles, bit for bit)
    if (dict.found("searchTriangle"))
    {
        const labelField tri("searchTriangle", dict, n);
        const vectorField x0("searchPoint", dict, n);
        forAll(search_, i)
        {
            search_[i].searched = tri[i] != -1;
            search_[i].hit = tri[i] >= 0;
            search_[i].hint = max(tri[i], label(-1));
            search_[i].x0 = x0[i];
        }
    }
}


bool Foam::frictionalContactFvPatchVectorField::evaluateFace
(
    const label facei,
    const solidPatchKinematics& k,
    frictionResult& res,
    vector& gapNormal,
    scalar& area,
    scalar& gap,
    frictionInput* input
) const
{
    if (linearised_ && !heldInReach_[facei])
    {
        return false;
    }

    const frictionState& old = state_[facei];

    // [C2] geometry: deformed face centre against the obstacle, the search
    // reused while the face moves less than a fraction of its cell [C2c]
    const point x(k.Cf0[facei] + k.D[facei]);
    const scalar cellDepth =
        patch().boundaryMesh().mesh().V()[patch().faceCells()[facei]]
       /mag(k.Sf0[facei]);
    obstaclePoint cp;
    if
    (
        !obstacle_->nearest
        (
            x, k.time, searchDistance_, searchRefreshFraction_*cellDepth,
            cp, search_[facei]
        )
    )
    {
        return false;
    }
    gapNormal = cp.n;
    gap = cp.gap;

    // [C3] slip relative to the obstacle in the current tangent plane
    // (objective rate, [F29]): the face's motion over the step less that of
    // the obstacle's material point under it
    const vector ds
    (
        (k.D[facei] - k.Dold[facei])
      - obstacle_->materialDisplacement(cp.p, k.time - k.deltaT, k.time)
    );
    const tensor P(tensor::I - sqr(cp.n));

    frictionInput in;
    in.gN = smoothedPenetration(-cp.gap);
    in.gT = P & (old.totalSlip + ds);
    in.n = cp.n;
    in.dt = k.deltaT;

    if (linearised_)
    {
        // [S15b] the held face's tangent, not the law
        const frictionInput& in0 = heldInput_[facei];
        res = heldResult_[facei];
        const scalar dgN = in.gN - in0.gN;
        const vector dgT(in.gT - in0.gT);
        res.tN += res.dtNdgN*dgN;
        res.tT += (res.dtTdgT & dgT) + res.dtTdgN*dgN;
    }
    else
    {
        law().update(old, in, res);
    }
    if (input)
    {
        *input = in;
    }

    // [C4] current area, Nanson
    const tensor& F = k.F[facei];
    area = mag(det(F)*(inv(F).T() & k.Sf0[facei]));

    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(p, iF),
    penaltyScale_(100),
    tangentialPenaltyScale_(0.1),
    searchDistance_(GREAT),
    contactSmoothing_(0),
    searchRefreshFraction_(0.2),
    normalForce_(Zero),
    frictionForce_(Zero),
    totalDissipation_(0),
    maxPenetration_(0),
    maxPenetrationAt_(Zero),
    nContact_(0),
    nSlip_(0),
    illPosedWarned_(false),
    linearised_(false)
{}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    calculatedFvPatchVectorField(p, iF, dict, false),
    obstacleDict_(dict.subDict("obstacle")),
    lawDict_(dict.subDict("frictionLaw")),
    penaltyScale_(dict.lookupOrDefault<scalar>("penaltyScale", 100)),
    tangentialPenaltyScale_
    (
        dict.lookupOrDefault<scalar>("tangentialPenaltyScale", 0.1)
    ),
    searchDistance_(-1),
    contactSmoothing_(0),
    searchRefreshFraction_
    (
        dict.lookupOrDefault<scalar>("searchRefreshFraction", 0.2)
    ),
    normalForce_(Zero),
    frictionForce_(Zero),
    totalDissipation_(0),
    maxPenetration_(0),
    maxPenetrationAt_(Zero),
    nContact_(0),
    nSlip_(0),
    illPosedWarned_(false),
    linearised_(false)
{
    if (!isA<wallFvPatch>(p))
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << p.name() << " (dictionary " << dict.name()
            << "): type frictionalContact needs a patch of type 'wall' in"
            << " constant/polyMesh/boundary; it is of type '" << p.type()
            << "'" << nl << exit(FatalIOError);
    }
    if (!(penaltyScale_ > 0) || !(tangentialPenaltyScale_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keywords 'penaltyScale' and 'tangentialPenaltyScale' in"
            << " dictionary " << dict.name() << " must be > 0, got "
            << penaltyScale_ << " and " << tangentialPenaltyScale_ << nl
            << exit(FatalIOError);
    }

    // Default search distance: two cell depths
    const scalarField& V = p.boundaryMesh().mesh().V();
    scalar hMax = 0;
    forAll(p.faceCells(), i)
    {
        hMax = max(hMax, V[p.faceCells()[i]]/p.magSf()[i]);
    }
    reduce(hMax, maxOp<scalar>());
    searchDistance_ =
        dict.lookupOrDefault<scalar>("searchDistance", 2*max(hMax, SMALL));

    // [C2b] width of the smoothed onset of contact: 1e-3 of a cell depth
    contactSmoothing_ =
        dict.lookupOrDefault<scalar>("contactSmoothing", 1e-3*hMax);
    if (contactSmoothing_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'contactSmoothing' in dictionary " << dict.name()
            << " must be >= 0, got " << contactSmoothing_ << nl
            << exit(FatalIOError);
    }
    if (searchRefreshFraction_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'searchRefreshFraction' in dictionary " << dict.name()
            << " must be >= 0 (0: a full search at every evaluation), got "
            << searchRefreshFraction_ << nl << exit(FatalIOError);
    }
    if (!(searchDistance_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'searchDistance' in dictionary " << dict.name()
            << " must be > 0, got " << searchDistance_ << nl
            << exit(FatalIOError);
    }

    obstacle_ = rigidObstacle::New(obstacleDict_, db().time().globalPath());

    // The law needs the solid's moduli for automatic penalties; utilities
    // such as decomposePar read D without them and only copy the entries,
    // for which the law's state layout is enough (penalties do not change
    // it)
    if (db().foundObject<IOdictionary>("mechanicalProperties"))
    {
        createLaw();
        readState(dict, law_());
    }
    else
    {
        dictionary d(lawDict_);
        d.set("KN", 1.0);
        d.set("KT", 1.0);
        const autoPtr<frictionLaw> layoutLaw(frictionLaw::New(d));
        layout_ = layoutLaw->stateLayout();
        readState(dict, layoutLaw());
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


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    calculatedFvPatchVectorField(ptf, p, iF, mapper),
    penaltyScale_(ptf.penaltyScale_),
    tangentialPenaltyScale_(ptf.tangentialPenaltyScale_),
    searchDistance_(ptf.searchDistance_),
    contactSmoothing_(ptf.contactSmoothing_),
    searchRefreshFraction_(ptf.searchRefreshFraction_),
    normalForce_(Zero),
    frictionForce_(Zero),
    totalDissipation_(0),
    maxPenetration_(0),
    maxPenetrationAt_(Zero),
    nContact_(0),
    nSlip_(0),
    illPosedWarned_(false),
    linearised_(false)
{
    // iF may be a null field (reconstructPar): the time comes from the mesh
    obstacleDict_ = ptf.obstacleDict_;
    lawDict_ = ptf.lawDict_;
    effectiveLawDict_ = ptf.effectiveLawDict_;
    layout_ = ptf.layout_;
    obstacle_ = rigidObstacle::New
    (
        obstacleDict_, p.boundaryMesh().mesh().time().globalPath()
    );

    const label n = mapper.size();
    state_.setSize(n);
    search_.setSize(n, obstacleSearch());
    contactPressure_.setSize(n, 0);
    nominalContactPressure_.setSize(n, 0);
    frictionTraction_.setSize(n, Zero);
    penetration_.setSize(n, 0);
    dissipation_.setSize(n, 0);

    if
    (
        mapper.direct()
     && notNull(mapper.directAddressing())
     && mapper.directAddressing().size()
    )
    {
        const labelUList& addr = mapper.directAddressing();
        forAll(addr, i)
        {
            copyFace(ptf, addr[i], i);
        }
    }
}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf
)
:
    calculatedFvPatchVectorField(ptf),
    solidForceBoundary()
{
    copyFrom(ptf);
}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(ptf, iF)
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
    const label n = m.size();
    state_.setSize(n);
    search_.setSize(n, obstacleSearch());
    contactPressure_.setSize(n, 0);
    nominalContactPressure_.setSize(n, 0);
    frictionTraction_.setSize(n, Zero);
    penetration_.setSize(n, 0);
    dissipation_.setSize(n, 0);
    if (m.direct() && notNull(m.directAddressing()))
    {
        const labelUList& addr = m.directAddressing();
        forAll(addr, i)
        {
            copyFace(old, addr[i], i);
        }
    }
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

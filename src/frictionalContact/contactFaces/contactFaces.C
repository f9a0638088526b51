/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "contactFaces.H"
#include "solidRestartState.H"
#include "volFields.H"
#include "IOdictionary.H"
#include "vonMisesPlastic.H"
#include "surfaceFields.H"
#include "strictDictionary.H"
#include "frictionParameters.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::contactFaces::cellStiffness(const fvPatch& p) const
{
    // [C5] E'/h of the body that holds the patch's cells [C9], h the mean
    // depth V/|S| of those cells
    const fvMesh& mesh = p.boundaryMesh().mesh();
    const labelUList& fc = p.faceCells();
    const scalar Eprime = body().planeStrainModulus(fc);

    const scalarField& V = mesh.V();
    const scalarField& magSf = p.magSf();
    scalar sumDepth = 0;
    forAll(fc, i)
    {
        sumDepth += V[fc[i]]/magSf[i];
    }
    const scalar h =
        returnReduce(sumDepth, sumOp<scalar>())
       /max(returnReduce(fc.size(), sumOp<label>()), 1);

    return Eprime/max(h, VSMALL);
}


Foam::scalar Foam::contactFaces::automaticPenalty(const scalar scale) const
{
    // [C5] a face penalty as stiff as penaltyScale cells of the solid; for
    // two deformable bodies, cells of the softer side [C5d], so that a
    // stiff slave does not make the penalty stiff against the body that
    // deforms (and a rigid partner's limit is the obstacle's penalty)
    scalar k = cellStiffness(contactPatch());
    const fvPatch* other = partnerBodyPatch();
    if (other)
    {
        k = min(k, cellStiffness(*other));
    }
    return scale*k;
}


void Foam::contactFaces::createLaw() const
{
    dictionary dict(lawDict_);
    const bool automatic = !dict.found("KN") || !dict.found("KT");
    if (!dict.found("KN"))
    {
        dict.add("KN", automaticPenalty(penaltyScale_));
    }
    if (!dict.found("KT"))
    {
        dict.add("KT", automaticPenalty(tangentialPenaltyScale_));
    }
    law_ = frictionLaw::New(dict);
    effectiveLawDict_ = dict;
    layout_ = law_->stateLayout();

    Info<< contactType() << " on patch " << contactPatch().name() << ": law "
        << lawDict_.get<word>("type") << ", KN " << law_->KN()
        << " Pa/m, KT " << law_->KT() << " Pa/m"
        << (automatic ? " (automatic)" : "") << endl;
}


void Foam::contactFaces::findFlowLaw()
{
    flowLaw_ = nullptr;
    if (!law().needsShearYield())
    {
        return;
    }

    // [F35] k comes from the mechanical law of the body that holds the
    // patch's cells: only a plastic one has a flow stress
    const fvPatch& p = contactPatch();
    const labelUList& fc = p.faceCells();
    word lawType("none");
    if (fc.size())
    {
        const mechanicalLaw& cellLaw = body_->cellLaw(fc[0]);
        lawType = cellLaw.type();
        flowLaw_ = isA<mechanicalLaws::vonMisesPlastic>(cellLaw)
          ? &refCast<const mechanicalLaws::vonMisesPlastic>(cellLaw)
          : nullptr;
    }
    if (returnReduce(fc.size() && !flowLaw_, orOp<bool>()))
    {
        const IOdictionary& mp =
            p.boundaryMesh().mesh().lookupObject<IOdictionary>
            (
                "mechanicalProperties"
            );
        FatalIOErrorInFunction(mp)
            << "patch " << p.name() << ": friction law "
            << lawDict_.get<word>("type") << " needs the shear flow stress"
            << " k = sigma_y/sqrt(3) of the body in contact, but the"
            << " mechanical law of the patch's body in " << mp.name()
            << " is " << lawType << ", which has no flow stress; give the"
            << " body a plastic law (vonMisesPlastic) or choose a friction"
            << " law without k (coulomb, tabulated with quantity mu, ...)"
            << nl << exit(FatalIOError);
    }
}


void Foam::contactFaces::refreshShearYield() const
{
    // [F35] k_n from the committed plastic strain of the face's cell:
    // constant over a step; taken at the first use (after the solid is
    // attached, and in a copy of the condition) and at each commit (the
    // solid commits its plastic history before its force boundaries)
    if (!flowLaw_)
    {
        shearYield_.clear();
        return;
    }
    const fvPatch& p = contactPatch();
    const scalarField epsP(body().cellPlasticStrain(p.faceCells()));
    shearYield_.setSize(p.size());
    forAll(epsP, facei)
    {
        shearYield_[facei] = flowLaw_->yieldStress(epsP[facei])/std::sqrt(3.0);
    }
}


Foam::scalar Foam::contactFaces::shearYield(const label i) const
{
    if (!flowLaw_)
    {
        return -1;
    }
    if (shearYield_.size() != contactPatch().size())
    {
        refreshShearYield();
    }
    return shearYield_[i];
}


void Foam::contactFaces::readState
(
    const dictionary& dict,
    const frictionLaw& l
)
{
    const label n = contactPatch().size();
    state_.setSize(n, l.initialState());
    resizeFaces(n);

    // Restart: the state written by write(), as the law declares it
    if (layout_.foundIn(dict))
    {
        const wordList missing = layout_.read(dict, state_);
        if (missing.size())
        {
            WarningInFunction
                << "patch " << contactPatch().name() << ": the restart state"
                << " in " << dict.name() << " has no " << missing
                << " (written by another law?); law "
                << lawDict_.get<word>("type")
                << " starts those as in a fresh contact" << endl;
        }
    }
    if (dict.found("dissipatedEnergy"))
    {
        dissipation_ = scalarField("dissipatedEnergy", dict, n);
    }
    multipliers_.readState(dict, n);
}


Foam::wordList Foam::contactFaces::missingState
(
    const dictionary& dict
) const
{
    // [S19b] at a restart every entry of the face state written with the
    // time: the law's state, the face displacement, the dissipated
    // energy, the multipliers
    DynamicList<word> missing;
    for (const frictionStateEntry& e : layout_.entries())
    {
        if
        (
            e.write && !dict.found(e.name)
         && (e.oldName.empty() || !dict.found(e.oldName))
        )
        {
            missing.append(e.name);
        }
    }
    for (const word& key : faceStateKeywords())
    {
        const bool written =
            !normalMultipliers::stateKeywords().found(key)
         || multipliers_.written(key);
        if (written && !dict.found(key))
        {
            missing.append(key);
        }
    }
    return wordList(missing);
}


void Foam::contactFaces::checkRestartState() const
{
    if (missingState_.empty())
    {
        return;
    }
    const Time& runTime = contactPatch().boundaryMesh().mesh().time();
    FatalIOErrorInFunction(settings_)
        << "Restart from time " << runTime.timeName() << ": patch "
        << contactPatch().name() << " in " << settings_.name() << " has no "
        << (missingState_.size() > 1 ? "keywords" : "keyword");
    for (const word& key : missingState_)
    {
        FatalIOError<< " '" << key.c_str() << "'";
    }
    FatalIOError
        << ", the face state of the contact (law "
        << lawDict_.get<word>("type") << ") written with every time"
        << " directory, which the next step starts from. The time"
        << " directory " << runTime.timePath() << " was edited or"
        << " written by another law; restore it, or restart from another"
        << " complete time" << nl << exit(FatalIOError);
}


void Foam::contactFaces::checkPenaltyScales() const
{
    // [C5] an automatic penalty (scale x the cells' stiffness) that a
    // friction law can hold [F2b]: a scale beyond it refused where it was
    // written (the product would overflow)
    const scalar k = automaticPenalty(1);
    const scalar kMax = frictionParameters::representable.second();
    const Pair<word> keys("penaltyScale", "tangentialPenaltyScale");
    const Pair<word> lawKeys("KN", "KT");
    const Pair<scalar> scales(penaltyScale_, tangentialPenaltyScale_);
    for (label s = 0; s < 2; ++s)
    {
        if
        (
            !lawDict_.found(lawKeys[s]) && k > 1e-270
         && !(scales[s] <= kMax/k)
        )
        {
            FatalIOErrorInFunction(settings_)
                << "Keyword '" << keys[s] << "' in dictionary "
                << settings_.name() << " is " << scales[s] << ": the"
                << " automatic penalty " << lawKeys[s] << " = "
                << keys[s] << " x " << k << " Pa/m (the cells'"
                << " stiffness) would exceed " << kMax << " Pa/m, the"
                << " largest a friction law keeps finite" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::contactFaces::sampleSensitivity(const frictionResult& res)
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


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::contactFaces::readContactFaces(const dictionary& dict)
{
    // Named after the file its entries came from (an #include'd law
    // dictionary) for the law's messages
    lawDict_ = dict.subDict("frictionLaw");
    strictDictionary::nameAfterSource(lawDict_);
    multipliers_.readSettings
    (
        dict, contactSurface::maxCellDepth(contactPatch())
    );
    // [C5], [C5c], [C5f] stiff for the plain penalty and a given
    // augmentation (its tolerance chosen for it), soft for
    // 'augmentedLagrangian yes' and softer for the predicted pressure
    const bool defaultAugmentation =
        augmented() && !dict.isDict("augmentedLagrangian");
    penaltyScale_ =
        dict.lookupOrDefault<scalar>
        (
            "penaltyScale",
            defaultAugmentation ? 10 : multipliers_.predicted() ? 3 : 100
        );
    tangentialPenaltyScale_ =
        dict.lookupOrDefault<scalar>("tangentialPenaltyScale", 0.1);
    if (!(penaltyScale_ > 0) || !(tangentialPenaltyScale_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keywords 'penaltyScale' and 'tangentialPenaltyScale' in"
            << " dictionary " << dict.name() << " must be > 0, got "
            << penaltyScale_ << " and " << tangentialPenaltyScale_ << nl
            << exit(FatalIOError);
    }

    // [C2b] width of the smoothed onset of contact: 'contactSmoothing' in
    // metres, or 'contactSmoothingCells' in cell depths (default 1e-3); a
    // written time directory holds the width in metres
    const fvPatch& p = contactPatch();
    if (dict.found("contactSmoothing") && dict.found("contactSmoothingCells"))
    {
        FatalIOErrorInFunction(dict)
            << "Keywords 'contactSmoothing' (metres) and"
            << " 'contactSmoothingCells' (cell depths) in dictionary "
            << dict.name() << " both given; expected one of them" << nl
            << exit(FatalIOError);
    }
    const word key
    (
        dict.found("contactSmoothing")
      ? "contactSmoothing"
      : "contactSmoothingCells"
    );
    const scalar width = dict.lookupOrDefault<scalar>(key, 1e-3);
    if (!(width >= 0) || !std::isfinite(width))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' in dictionary " << dict.name()
            << " must be a finite number >= 0, got " << width << nl
            << exit(FatalIOError);
    }
    contactSmoothing_ =
        key == "contactSmoothing"
      ? width
      : width*contactSurface::maxCellDepth(p);

    // [C2b] the smoothed onset starts at a gap of its width: a face that
    // far is searched (a wider onset would make the force jump where the
    // search ends, and sqr(gN + e) of a huge width overflows)
    const scalar search = contactSurface::readSearchDistance(dict, p);
    if (!(contactSmoothing_ < search))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' in dictionary " << dict.name()
            << " gives the smoothed contact onset a width of "
            << contactSmoothing_ << " m, not below the search distance "
            << search << " m ('searchDistance'): the contact force would"
            << " start beyond the faces searched; expected a width below it"
            << nl << exit(FatalIOError);
    }

    // The law's state layout and the face state (a restart's) need no
    // penalties; the law with its penalties is made when the solid is
    // attached (attachBody: its moduli). Utilities such as decomposePar
    // read D without a solid and only copy the entries
    {
        dictionary d(lawDict_);
        d.set("KN", 1.0);
        d.set("KT", 1.0);
        const autoPtr<frictionLaw> layoutLaw(frictionLaw::New(d));
        layout_ = layoutLaw->stateLayout();
        readState(dict, layoutLaw());
    }
    missingState_ =
        solidRestartState::expected(p.boundaryMesh().mesh().time())
      ? missingState(dict)
      : wordList();

    // what the checks at attachBody name: the settings as written, without
    // the face state
    settings_ = dict;
    for (const word& key : layout_.keywords())
    {
        settings_.remove(key);
    }
    for (const word& key : faceStateKeywords())
    {
        settings_.remove(key);
    }
}


void Foam::contactFaces::attachBody(const solidBody& body)
{
    body_ = &body;
    // (the master of a deformable pair carries no law)
    if (lawDict_.empty())
    {
        return;
    }
    checkPenaltyScales();
    checkRestartState();
    createLaw();
    findFlowLaw();
    shearYield_.clear();
}


const Foam::solidBody& Foam::contactFaces::body() const
{
    if (!body_)
    {
        FatalErrorInFunction
            << "patch " << contactPatch().name() << ": the contact is used"
            << " outside the solid solver (no solid attached)"
            << exit(FatalError);
    }
    return *body_;
}


Foam::wordList Foam::contactFaces::contactFacesKeywords() const
{
    wordList w
    ({
        "frictionLaw", "penaltyScale", "tangentialPenaltyScale",
        "contactSmoothing", "contactSmoothingCells"
    });
    w.append(normalMultipliers::settingKeywords());
    w.append(faceStateKeywords());
    w.append(layout_.keywords());
    return w;
}


const Foam::wordList& Foam::contactFaces::faceStateKeywords()
{
    static const wordList keys = []
    {
        wordList w({"value", "dissipatedEnergy"});
        w.append(normalMultipliers::stateKeywords());
        return w;
    }();
    return keys;
}


void Foam::contactFaces::copyContactFaces(const contactFaces& ptf)
{
    lawDict_ = ptf.lawDict_;
    effectiveLawDict_ = ptf.effectiveLawDict_;
    if (ptf.law_.valid())
    {
        law_ = frictionLaw::New(effectiveLawDict_);
    }
    body_ = ptf.body_;
    flowLaw_ = ptf.flowLaw_;
    settings_ = ptf.settings_;
    missingState_ = ptf.missingState_;
    penaltyScale_ = ptf.penaltyScale_;
    tangentialPenaltyScale_ = ptf.tangentialPenaltyScale_;
    contactSmoothing_ = ptf.contactSmoothing_;
    // (a retry's widening is not part of the condition)
    onsetWidening_ = 1;
    layout_ = ptf.layout_;
    state_ = ptf.state_;
    contactPressure_ = ptf.contactPressure_;
    nominalContactPressure_ = ptf.nominalContactPressure_;
    frictionTraction_ = ptf.frictionTraction_;
    penetration_ = ptf.penetration_;
    dissipation_ = ptf.dissipation_;
    normalForce_ = ptf.normalForce_;
    frictionForce_ = ptf.frictionForce_;
    totalDissipation_ = ptf.totalDissipation_;
    maxPenetration_ = ptf.maxPenetration_;
    maxPenetrationAt_ = ptf.maxPenetrationAt_;
    nContact_ = ptf.nContact_;
    nSlip_ = ptf.nSlip_;
    sensitivity_ = ptf.sensitivity_;
    illPosedWarned_ = ptf.illPosedWarned_;
    multipliers_ = ptf.multipliers_;
    committedInReach_ = ptf.committedInReach_;
    linearised_ = false;
}


void Foam::contactFaces::resizeFaces(const label n)
{
    state_.setSize(n);
    contactPressure_.setSize(n, 0);
    nominalContactPressure_.setSize(n, 0);
    frictionTraction_.setSize(n, Zero);
    penetration_.setSize(n, 0);
    dissipation_.setSize(n, 0);
    multipliers_.resize(n);
    committedInReach_.setSize(n);
    committedInReach_ = true;
}


void Foam::contactFaces::copyFace
(
    const contactFaces& ptf,
    const label from,
    const label to
)
{
    if (from < 0 || from >= ptf.state_.size())
    {
        return;
    }
    state_[to] = ptf.state_[from];
    contactPressure_[to] = ptf.contactPressure_[from];
    nominalContactPressure_[to] = ptf.nominalContactPressure_[from];
    frictionTraction_[to] = ptf.frictionTraction_[from];
    penetration_[to] = ptf.penetration_[from];
    dissipation_[to] = ptf.dissipation_[from];
    multipliers_.copyFace(ptf.multipliers_, from, to);
    committedInReach_[to] = ptf.committedInReach_[from];
}


void Foam::contactFaces::mapFaces
(
    const contactFaces& ptf,
    const fvPatchFieldMapper& m
)
{
    resizeFaces(m.size());
    if (m.direct() && notNull(m.directAddressing()))
    {
        const labelUList& addr = m.directAddressing();
        forAll(addr, i)
        {
            copyFace(ptf, addr[i], i);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactFaces::contactFaces()
:
    penaltyScale_(100),
    tangentialPenaltyScale_(0.1),
    contactSmoothing_(0),
    onsetWidening_(1),
    normalForce_(Zero),
    frictionForce_(Zero),
    totalDissipation_(0),
    maxPenetration_(0),
    maxPenetrationAt_(Zero),
    nContact_(0),
    nSlip_(0),
    illPosedWarned_(false),
    body_(nullptr),
    flowLaw_(nullptr),
    linearised_(false)
{
    onsetFace_ = -1;
    onsetFaceFraction_ = 1;
    onsetP0_ = 0;
    onsetP1_ = 0;
    onsetClosing_ = 0;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::frictionLaw& Foam::contactFaces::law() const
{
    if (!law_.valid())
    {
        createLaw();
    }
    return law_();
}


void Foam::contactFaces::beginHold()
{
    linearised_ = false;
    const label n = state_.size();
    heldInput_.setSize(n);
    heldResult_.setSize(n);
    heldInReach_.setSize(n);
    heldInReach_ = false;
}


void Foam::contactFaces::holdFace
(
    const label i,
    const bool inReach,
    const frictionInput& in,
    const frictionResult& res
)
{
    heldInReach_[i] = inReach;
    heldInput_[i] = in;
    heldResult_[i] = res;
}


void Foam::contactFaces::faceUpdate
(
    const label i,
    const frictionInput& in,
    frictionResult& res
) const
{
    if (linearised_)
    {
        // [S15b] the held face's tangent, not the law
        linearAbout(heldInput_[i], heldResult_[i], in, res);
    }
    else
    {
        law().update(state_[i], in, res);
    }
}


bool Foam::contactFaces::setOnsetWidening(const scalar factor)
{
    if (factor != onsetWidening_)
    {
        onsetWidening_ = factor;
        multipliers_.reset();
    }
    return contactSmoothing_ > 0;
}


bool Foam::contactFaces::augmentSlaveFaces(const List<slaveFace>& faces)
{
    if (!augmented())
    {
        return false;
    }
    // [C5b] lambda <- tN; the faces out of reach carry none
    scalar penetration = 0;
    scalarField next(faces.size(), 0);
    forAll(faces, i)
    {
        const slaveFace& sf = faces[i];
        if (sf.inReach)
        {
            next[i] = sf.result.tN;
            if (sf.result.tN > 0)
            {
                penetration = max(penetration, -sf.gap);
            }
        }
    }
    reduce(penetration, maxOp<scalar>());
    return multipliers_.update
    (
        next, law().KN(), penetration, contactPatch().name()
    );
}


void Foam::contactFaces::linearAbout
(
    const frictionInput& in0,
    const frictionResult& res0,
    const frictionInput& in,
    frictionResult& res
)
{
    res = res0;
    const scalar dgN = in.gN - in0.gN;
    const vector dgT(in.gT - in0.gT);
    res.tN += res.dtNdgN*dgN;
    res.tT += (res.dtTdgT & dgT) + res.dtTdgN*dgN;
}


// ************************************************************************* //

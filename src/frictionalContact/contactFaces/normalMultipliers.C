/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

\*---------------------------------------------------------------------------*/

#include "normalMultipliers.H"
#include "strictDictionary.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::normalMultipliers::normalMultipliers()
:
    augmented_(false),
    tolerance_(0),
    maxIterations_(0),
    acceleration_(false),
    predicted_(false),
    nUpdates_(0),
    lastChange_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::normalMultipliers::extrapolation
(
    const scalar change
) const
{
    // [C5e] Uzawa's updates contract the constraint's violation by a
    // nearly constant factor rho (k/(k + KN), [C5b]): the multipliers'
    // limit lies 1/(1 - rho) times the update away (Aitken). rho is the
    // ratio of this update's change to the last one's; an update after
    // an extrapolation that overshot or one that hardly contracted (rho
    // outside (0, rhoMax)) is the plain one
    const scalar rhoMax = 0.75;
    if (!acceleration_ || lastChange_ <= 0)
    {
        return 1;
    }
    const scalar rho = change/lastChange_;
    if (!(rho > 0) || rho > rhoMax)
    {
        return 1;
    }
    return 1/(1 - rho);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::normalMultipliers::readSettings
(
    const dictionary& dict,
    const scalar cellDepth
)
{
    // [C5b]; 'yes' with the automatic soft penalty and tolerance [C5c]
    const entry* e = dict.findEntry("augmentedLagrangian", keyType::LITERAL);
    augmented_ =
        e && (e->isDict() || dict.get<bool>("augmentedLagrangian"));
    // [C5f] the default where the multipliers are not solved for; a time
    // directory written before the keyword existed (a face state without
    // it) continues with the plain penalty it was run with
    const bool writtenBefore =
        dict.found("dissipatedEnergy") && !dict.found("pressurePrediction");
    predicted_ =
        dict.lookupOrDefault<bool>
        (
            "pressurePrediction", !augmented_ && !writtenBefore
        );
    if (augmented_ && predicted_)
    {
        FatalIOErrorInFunction(dict)
            << "Keywords 'augmentedLagrangian' and 'pressurePrediction yes'"
            << " in dictionary " << dict.name() << " both given; expected"
            << " one of them (the augmented Lagrangian solves for the"
            << " pressures that the prediction guesses)" << nl
            << exit(FatalIOError);
    }
    if (!augmented_)
    {
        return;
    }
    // a dictionary names its tolerance; 'yes' takes 1e-4 of the largest
    // cell depth [C5c]
    const dictionary empty(dict, dictionary());
    const bool given = e && e->isDict();
    const dictionary& a = given ? e->dict() : empty;
    tolerance_ = given ? a.get<scalar>("tolerance") : 1e-4*cellDepth;
    maxIterations_ = a.lookupOrDefault<label>("maxIterations", 10);
    acceleration_ = a.lookupOrDefault<bool>("acceleration", true);
    strictDictionary::check
    (
        a, {"tolerance", "maxIterations", "acceleration"},
        "augmented Lagrangian contact"
    );
    if (!(tolerance_ > 0) || maxIterations_ < 1)
    {
        FatalIOErrorInFunction(a)
            << "Keywords 'tolerance' (a penetration [m]) and 'maxIterations'"
            << " in dictionary " << a.name() << " must be > 0 and >= 1, got "
            << tolerance_ << " and " << maxIterations_ << nl
            << exit(FatalIOError);
    }
}


const Foam::wordList& Foam::normalMultipliers::settingKeywords()
{
    static const wordList keys({"augmentedLagrangian", "pressurePrediction"});
    return keys;
}


const Foam::wordList& Foam::normalMultipliers::stateKeywords()
{
    static const wordList keys
    ({
        "normalMultiplier", "previousNormalMultiplier"
    });
    return keys;
}


bool Foam::normalMultipliers::written(const word& key) const
{
    // the multipliers only where the penalty is shifted by them, the step
    // before's only with the predicted pressure
    return
        key == "previousNormalMultiplier" ? predicted_
      : key == "normalMultiplier" ? shifted()
      : false;
}


void Foam::normalMultipliers::resize(const label n)
{
    committed_.setSize(n, 0);
    previous_.setSize(n, 0);
    start_.setSize(n, 0);
    current_.setSize(n, 0);
}


void Foam::normalMultipliers::copyFace
(
    const normalMultipliers& m,
    const label from,
    const label to
)
{
    committed_[to] = m.committed_[from];
    previous_[to] = m.previous_[from];
    start_[to] = m.start_[from];
    current_[to] = m.current_[from];
}


void Foam::normalMultipliers::readState
(
    const dictionary& dict,
    const label n
)
{
    // [C5b], [C5f] the multipliers the next step starts from, and the
    // ones of the step before (to extrapolate from)
    if (dict.found("normalMultiplier"))
    {
        committed_ = scalarField("normalMultiplier", dict, n);
    }
    previous_ = committed_;
    if (dict.found("previousNormalMultiplier"))
    {
        previous_ = scalarField("previousNormalMultiplier", dict, n);
    }
    predict(0);
}


void Foam::normalMultipliers::write(Ostream& os) const
{
    if (augmented_)
    {
        os.beginBlock("augmentedLagrangian");
        os.writeEntry("tolerance", tolerance_);
        os.writeEntry("maxIterations", maxIterations_);
        os.endBlock();
    }
    else
    {
        os.writeEntry("pressurePrediction", word(predicted_ ? "yes" : "no"));
    }
    if (shifted())
    {
        committed_.writeEntry("normalMultiplier", os);
    }
    if (predicted_)
    {
        previous_.writeEntry("previousNormalMultiplier", os);
    }
}


void Foam::normalMultipliers::predict(const scalar extrapolation)
{
    // [C5f] linear in time from the last two converged steps, as the
    // displacements are [S18]; a pressure is never negative
    start_ = committed_;
    if (predicted_ && extrapolation > 0)
    {
        forAll(start_, i)
        {
            start_[i] = max
            (
                committed_[i] + extrapolation*(committed_[i] - previous_[i]),
                scalar(0)
            );
        }
    }
    reset();
}


void Foam::normalMultipliers::reset()
{
    current_ = start_;
    nUpdates_ = 0;
    lastChange_ = 0;
}


bool Foam::normalMultipliers::update
(
    const scalarField& next,
    const scalar KN,
    const scalar penetration,
    const word& patchName
)
{
    // [C5b] the update lambda <- tN moves each multiplier by KN times the
    // face's constraint violation (its penetration, or the opening of a
    // face that still carries its multiplier): converged when that is
    // below the tolerance everywhere
    scalar change = 0;
    forAll(next, i)
    {
        change = max(change, mag(next[i] - current_[i])/KN);
    }
    reduce(change, maxOp<scalar>());

    const bool done = change <= tolerance_ || nUpdates_ >= maxIterations_;
    Info<< "    contact " << patchName << ": augmentation "
        << nUpdates_ << ", largest penetration " << penetration
        << " m, multiplier change " << change << " m (tolerance "
        << tolerance_ << " m)"
        << (
               change <= tolerance_ ? ": converged"
             : done ? ": maxIterations reached, not converged"
             : ": update"
           )
        << endl;
    if (done)
    {
        return false;
    }
    const scalar omega = extrapolation(change);
    forAll(next, i)
    {
        current_[i] = max(current_[i] + omega*(next[i] - current_[i]), 0);
    }
    lastChange_ = change;
    ++nUpdates_;
    return true;
}


// ************************************************************************* //

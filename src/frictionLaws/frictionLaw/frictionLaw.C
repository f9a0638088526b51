/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionLaw.H"
#include "frictionParameters.H"
#include "error.H"
#include "strictDictionary.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(frictionLaw, 0);
    defineRunTimeSelectionTable(frictionLaw, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionLaw::frictionLaw(const dictionary& dict)
:
    KN_(frictionParameters::positive(dict, "KN")),
    KT_(frictionParameters::positive(dict, "KT")),
    layout_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::frictionState Foam::frictionLaw::initialState() const
{
    return frictionState();
}


void Foam::frictionLaw::openContact
(
    const frictionState& old,
    const frictionInput& in,
    frictionResult& out
) const
{
    out.tT = Zero;
    out.dtTdgT = Zero;
    out.dtTdgN = Zero;
    out.state = initialState();
    out.state.totalSlip = in.gT;
    out.state.plasticSlip = in.gT;
    out.state.cumulatedSlip = old.cumulatedSlip;
    out.state.status = frictionState::OPEN;
}


void Foam::frictionLaw::setFromReturn
(
    const frictionState& old,
    const frictionInput& in,
    const radialReturn::output& rr,
    frictionResult& out
)
{
    out.tT = rr.F;
    out.dtTdgT = rr.dFdgT;
    out.dtTdgN = rr.dFdgN;
    out.state.totalSlip = in.gT;
    out.state.plasticSlip = old.plasticSlip + rr.dg*rr.m;
    out.state.cumulatedSlip = old.cumulatedSlip + rr.dg;
    out.state.status = rr.slip ? frictionState::SLIP : frictionState::STICK;
}


void Foam::frictionLaw::checkKeywords
(
    const dictionary& dict,
    const wordList& own
)
{
    wordList known({"type", "KN", "KT"});
    known.append(own);
    strictDictionary::check
    (
        dict, known, "friction law " + dict.getOrDefault<word>("type", "")
    );
}


long Foam::frictionLaw::nIterationLimitHits()
{
    return safeguardedNewton::nLimitHits();
}


long Foam::frictionLaw::reportIterationLimitHits()
{
    const long n = safeguardedNewton::nLimitHits();
    if (n > 0)
    {
        WarningInFunction
            << n << " of " << safeguardedNewton::nSolves()
            << " return-mapping solves hit the iteration limit"
            << " (result kept at the last bracketed iterate)" << endl;
    }
    return n;
}

// ************************************************************************* //

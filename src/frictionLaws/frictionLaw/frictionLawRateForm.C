/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    frictionLaw: the rate form [F31] (defaults for laws without one) and
    the well-posedness check on the instantaneous rate sensitivity [F21].

\*---------------------------------------------------------------------------*/

#include "frictionLaw.H"
#include "error.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

static void noRateForm(const word& law, const char* what)
{
    FatalErrorInFunction
        << "friction law " << law << " is rate independent: it has no rate"
        << " form (" << what << ")" << exit(FatalError);
}

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionLaw::sensitivitySummary::add
(
    const scalar s,
    const scalar v,
    const scalar p
)
{
    ++nSampled;
    if (s < minimum)
    {
        minimum = s;
        vAtMin = v;
        pAtMin = p;
    }
    if (s < 0)
    {
        ++nNegative;
        vNegMin = min(vNegMin, v);
        vNegMax = max(vNegMax, v);
        pNegMin = min(pNegMin, p);
        pNegMax = max(pNegMax, p);
    }
}


void Foam::frictionLaw::steadyRateStates
(
    const scalar,
    const scalar,
    rateStates&
) const
{
    noRateForm(type(), "steady state");
}


Foam::scalar Foam::frictionLaw::slidingTraction
(
    const scalar,
    const rateStates&,
    const scalar
) const
{
    noRateForm(type(), "sliding traction");
    return 0;
}


void Foam::frictionLaw::stateRates
(
    const scalar,
    const rateStates&,
    const scalar,
    rateStates&
) const
{
    noRateForm(type(), "state rates");
}


void Foam::frictionLaw::rateStatesOf(const frictionState&, rateStates&) const
{
    noRateForm(type(), "state");
}


Foam::scalar Foam::frictionLaw::steadyTraction
(
    const scalar v,
    const scalar tN
) const
{
    rateStates x(scalar(0));
    steadyRateStates(v, tN, x);
    return slidingTraction(v, x, tN);
}


Foam::scalar Foam::frictionLaw::rateSensitivity
(
    const scalar v,
    const rateStates& x,
    const scalar tN
) const
{
    // Central differences in ln v: truncation h^2/6 F''' ~ 1e-9 relative
    const scalar h = 1e-4;
    return
        (
            slidingTraction(v*std::exp(h), x, tN)
          - slidingTraction(v*std::exp(-h), x, tN)
        )/(2*h);
}


Foam::frictionLaw::sensitivitySummary Foam::frictionLaw::steadySensitivity
(
    const scalar vMin,
    const scalar vMax,
    const scalar pMin,
    const scalar pMax
) const
{
    // 400 rates (as [F21]) by 21 pressures, log spaced
    const label nV = 400, nP = pMax > pMin ? 20 : 0;
    sensitivitySummary s;
    rateStates x(scalar(0));
    for (label j = 0; j <= nP; ++j)
    {
        const scalar p = nP ? pMin*std::pow(pMax/pMin, scalar(j)/nP) : pMin;
        for (label i = 0; i <= nV; ++i)
        {
            const scalar v = vMin*std::pow(vMax/vMin, scalar(i)/nV);
            steadyRateStates(v, p, x);
            s.add(rateSensitivity(v, x, p), v, p);
        }
    }
    return s;
}


void Foam::frictionLaw::warnIllPosed
(
    const sensitivitySummary& s,
    const string& where
) const
{
    WarningInFunction
        << "friction law " << type() << ": sliding is ill posed (strain"
        << " localisation, mesh-dependent results) where the instantaneous"
        << " rate sensitivity d tT/d ln v is negative: " << s.nNegative
        << " of " << s.nSampled << " " << where.c_str() << ", at contact"
        << " pressures " << s.pNegMin << " to " << s.pNegMax
        << " Pa and slip rates " << s.vNegMin << " to " << s.vNegMax
        << " m/s; smallest " << s.minimum << " Pa at tN = " << s.pAtMin
        << " Pa, v = " << s.vAtMin << " m/s (doc/theory.md [F21])" << endl;
}


bool Foam::frictionLaw::checkWellPosedness
(
    const scalar vMin,
    const scalar vMax,
    const scalar pMin,
    const scalar pMax
) const
{
    if (nRateStates() < 0)
    {
        return false;
    }
    const sensitivitySummary s = steadySensitivity(vMin, vMax, pMin, pMax);
    if (s.nNegative)
    {
        warnIllPosed
        (
            s,
            "steady states checked on slip rates " + name(vMin) + " to "
          + name(vMax) + " m/s and pressures " + name(pMin) + " to "
          + name(pMax) + " Pa"
        );
        return true;
    }
    return false;
}


// ************************************************************************* //

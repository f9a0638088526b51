/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "coulomb.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(coulomb, 0);
    addToRunTimeSelectionTable(frictionLaw, coulomb, dictionary);
}
}


Foam::frictionLaws::coulomb::coulomb(const dictionary& dict)
:
    frictionLaw(dict),
    mu_(frictionParameters::nonNegative(dict, "mu")),
    muStatic_(dict.getOrDefault<scalar>("muStatic", mu_))
{
    frictionParameters::check
    (
        dict, "muStatic", muStatic_, mu_, frictionParameters::closed
    );
    checkKeywords(dict, {"mu", "muStatic"});
}


void Foam::frictionLaws::coulomb::update
(
    const frictionState& old,
    const frictionInput& in,
    frictionResult& out
) const
{
    if (!normalContact(in, out))
    {
        openContact(old, in, out);
        return;
    }

    out.state = old;
    out.state.slipRate = 0;

    const scalar tN = out.tN;
    const tensor P = projector(in.n);
    const vector xiTrial = KT_*(P & (in.gT - old.plasticSlip));      // [F3]

    // Static check for a point at rest; dynamic threshold in the corrector
    const scalar muCheck =
        old.status == frictionState::SLIP ? mu_ : muStatic_;
    const scalar muSlide = mu_;
    const scalar KN = KN_;

    // [F8]: Y(0) = muCheck tN decides stick; the return uses mu tN
    auto threshold = [=](scalar dg, slipThreshold& thr)
    {
        const scalar m = dg > 0 ? muSlide : muCheck;
        thr.Y = m*tN;
        thr.dYdDg = 0;
        thr.dYdgN = m*KN;
        thr.dYdgT = Zero;
    };

    radialReturn::output rr;
    radialReturn::solve(xiTrial, Zero, KT_, KT_, P, threshold, rr);
    setFromReturn(old, in, rr, out);
    if (rr.slip && in.dt > 0)
    {
        out.state.slipRate = rr.dg/in.dt;
    }
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "flowStressFriction.H"
#include "dimensionSets.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionLaws::flowStressFriction::flowStressFriction
(
    const dictionary& dict
)
:
    frictionLaw(dict),
    dictName_(dict.name())
{
    // [F35] the k the point saw, for ParaView; it follows from the plastic
    // strain on restart, so it is not written
    layout_.add
    (
        "shearYield", frictionStateEntry::SCALAR, shearYieldSlot,
        dimPressure, false, true
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionLaws::flowStressFriction::update
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
    if (needsShearYield() && !(in.shearYield >= 0))
    {
        FatalErrorInFunction
            << "friction law " << type() << " (dictionary " << dictName_
            << ") needs the shear flow stress k of the body at the contact"
            << " point, got " << in.shearYield << " ([F35]: the contact"
            << " condition sets it from a plastic body's law)"
            << exit(FatalError);
    }

    out.state = old;
    out.state.slipRate = 0;
    out.state.scalars[shearYieldSlot] = in.shearYield;

    const scalar tN = out.tN;
    const scalar k = in.shearYield;
    const scalar dt = in.dt;
    const bool rate = rateDependent() && dt > 0;
    const tensor P = projector(in.n);
    const vector xiTrial = KT_*(P & (in.gT - old.plasticSlip));      // [F3]
    const scalar KN = KN_;

    // [F35] Y(dg) = tau_f(tN, k, dg/dt): k fixed over the step
    auto threshold = [&](scalar dg, slipThreshold& thr)
    {
        scalar dtN = 0, dv = 0;
        const scalar v = rate ? dg/dt : 0;
        thr.Y = max(shearStrength(tN, k, v, dg > 0, dtN, dv), scalar(0));
        thr.dYdDg = rate ? dv/dt : 0;
        thr.dYdgN = dtN*KN;
        thr.dYdgT = Zero;
    };

    radialReturn::output rr;
    radialReturn::solve
    (
        xiTrial, Zero, KT_, KT_, P, threshold, rr, nullptr,
        rate ? old.slipRate*dt : -1
    );
    setFromReturn(old, in, rr, out);
    if (rr.slip && dt > 0)
    {
        out.state.slipRate = rr.dg/dt;
    }
}

// ************************************************************************* //

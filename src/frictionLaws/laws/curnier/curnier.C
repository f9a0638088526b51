/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "curnier.H"
#include "frictionParameters.H"
#include "addToRunTimeSelectionTable.H"
#include "dimensionSets.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(curnier, 0);
    addToRunTimeSelectionTable(frictionLaw, curnier, dictionary);
}
}


Foam::frictionLaws::curnier::curnier(const dictionary& dict)
:
    frictionLaw(dict),
    criterion_(COULOMB),
    f_(0),
    C_(frictionParameters::nonNegative(dict, "C", 0)),
    QT_(frictionParameters::nonNegative(dict, "QT", 0)),
    Q_(frictionParameters::nonNegative(dict, "Q", 0)),
    n_(1),
    pRef_(frictionParameters::positive(dict, "referencePressure", 1)),
    a_(1),
    b_(1),
    direction1_(1, 0, 0)
{
    // [F25]: DS_T since the contact formed (tear force), DS_N while open
    layout_.add
    (
        "tearSlip", frictionStateEntry::VECTOR, tearSlot, dimLength, true,
        false
    );
    layout_.add
    (
        "normalSlip", frictionStateEntry::SCALAR, normalSlipSlot, dimLength,
        true, false
    );

    const word crit(dict.get<word>("criterion"));
    if (crit == "coulomb")
    {
        criterion_ = COULOMB;
        f_ = frictionParameters::nonNegative(dict, "f");
    }
    else if (crit == "anisotropicCoulomb")
    {
        criterion_ = ANISOTROPIC;
        f_ = frictionParameters::nonNegative(dict, "f");
        a_ = frictionParameters::positive(dict, "a");
        b_ = frictionParameters::positive(dict, "b");
        direction1_ = dict.get<vector>("direction1");
        if (mag(direction1_) <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'direction1' must be a non-zero vector, got "
                << direction1_ << exit(FatalIOError);
        }
    }
    else if (crit == "paraboloid")
    {
        criterion_ = PARABOLOID;
        f_ = frictionParameters::nonNegative(dict, "f", 1);
        n_ = 2;
    }
    else if (crit == "power")
    {
        criterion_ = POWER;
        f_ = frictionParameters::nonNegative(dict, "f");
        n_ = frictionParameters::positive(dict, "n");
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'criterion': unknown criterion '" << crit
            << "' (valid: coulomb anisotropicCoulomb paraboloid power)"
            << " in dictionary " << dict.name() << exit(FatalIOError);
    }
    checkKeywords
    (
        dict,
        {
            "criterion", "f", "a", "b", "n", "direction1", "C", "QT", "Q",
            "referencePressure"
        }
    );
}


void Foam::frictionLaws::curnier::threshold
(
    const scalar s,
    scalar& Y,
    scalar& dYds
) const
{
    // [F9]
    if (s <= 0)
    {
        Y = 0;
        dYds = 0;
        return;
    }
    if (n_ == 1)
    {
        Y = s;
        dYds = 1;
        return;
    }
    const scalar x = s/pRef_;
    Y = pRef_*std::pow(x, 1/n_);
    dYds = Y/(n_*s);
}


void Foam::frictionLaws::curnier::update
(
    const frictionState& old,
    const frictionInput& in,
    frictionResult& out
) const
{
    if (!normalContact(in, out))
    {
        openContact(old, in, out);
        out.state.vectors[tearSlot] = Zero;
        out.state.scalars[normalSlipSlot] = -in.gN;     // separation, [F26]
        return;
    }

    out.state = old;
    out.state.scalars[normalSlipSlot] = 0;  // no lift-off in compression

    const scalar tN = out.tN;
    const tensor P = projector(in.n);
    const vector X = QT_*(P & old.vectors[tearSlot]);          // [F10]
    const vector xiTrial = KT_*(P & (in.gT - old.plasticSlip)) - X;  // [F3]
    const scalar Dc = old.cumulatedSlip;
    const scalar fKN = f_*KN_;
    const scalar Q = Q_;

    auto thr = [&](scalar dg, slipThreshold& t)
    {
        // s = C + f tN - Q (Dc + dg)   [F9], [F10]
        scalar Y, dYds;
        threshold(C_ + f_*tN - Q*(Dc + dg), Y, dYds);
        t.Y = Y;
        t.dYdDg = -Q*dYds;
        t.dYdgN = fKN*dYds;
        t.dYdgT = Zero;
    };

    radialReturn::output rr;
    if (criterion_ == ANISOTROPIC)
    {
        ellipticNorm A;
        A.e1 = P & direction1_;
        A.e1 /= mag(A.e1) + VSMALL;
        A.e2 = in.n ^ A.e1;
        A.a = a_;
        A.b = b_;
        radialReturn::solve(xiTrial, X, KT_, KT_ + QT_, P, thr, rr, &A);
    }
    else
    {
        radialReturn::solve(xiTrial, X, KT_, KT_ + QT_, P, thr, rr);
    }

    setFromReturn(old, in, rr, out);
    out.state.vectors[tearSlot] = old.vectors[tearSlot] + rr.dg*rr.m;
    out.state.slipRate = in.dt > 0 ? rr.dg/in.dt : 0;
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "generalFriction.H"
#include "frictionParameters.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(generalFriction, 0);
    addToRunTimeSelectionTable(frictionLaw, generalFriction, dictionary);
}
}


Foam::scalar Foam::frictionLaws::generalFriction::asperityPressureRatio
(
    const scalar f
)
{
    // [F38] slip-line field of a flat asperity with friction f on its top
    return
        1 + constant::mathematical::piByTwo + std::acos(f)
      + std::sqrt(max(1 - f*f, scalar(0)));
}


Foam::frictionLaws::generalFriction::generalFriction(const dictionary& dict)
:
    flowStressFriction(dict),
    f_(frictionParameters::unitInterval(dict, "f")),
    alphaT_(dict.getOrDefault<scalar>("transitionRealArea", 0.5)),
    h_(asperityPressureRatio(f_))
{
    frictionParameters::check
    (
        dict, "transitionRealArea", alphaT_,
        0, frictionParameters::open, 1, frictionParameters::open
    );
    checkKeywords(dict, {"f", "transitionRealArea"});
}


Foam::scalar Foam::frictionLaws::generalFriction::realAreaRatio
(
    const scalar pk,
    scalar& dAlpha
) const
{
    // [F38] alpha = (p/k)/h up to alphaT, then the exponential approach to
    // 1 with the same value and slope at (p/k)T = alphaT h
    const scalar pkT = alphaT_*h_;
    if (pk <= pkT)
    {
        dAlpha = 1/h_;
        return pk/h_;
    }
    const scalar e = std::exp(-(pk - pkT)/((1 - alphaT_)*h_));
    dAlpha = e/h_;
    return 1 - (1 - alphaT_)*e;
}


Foam::scalar Foam::frictionLaws::generalFriction::shearStrength
(
    const scalar tN,
    const scalar k,
    const scalar v,
    const bool sliding,
    scalar& dtN,
    scalar& dv
) const
{
    dv = 0;
    if (k <= 0)
    {
        // no strength left in the body: alpha -> 1, tau = f k = 0
        dtN = 0;
        return 0;
    }
    scalar dAlpha;
    const scalar alpha = realAreaRatio(tN/k, dAlpha);
    dtN = f_*dAlpha;
    return f_*alpha*k;
}

// ************************************************************************* //

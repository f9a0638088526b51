/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "cylinderObstacle.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace rigidObstacles
{
    defineTypeNameAndDebug(cylinderObstacle, 0);
    addToRunTimeSelectionTable(rigidObstacle, cylinderObstacle, dictionary);
}
}


Foam::rigidObstacles::cylinderObstacle::cylinderObstacle
(
    const dictionary& dict,
    const fileName&
)
:
    rigidObstacle(dict),
    axisPoint_(dict.get<point>("axisPoint")),
    axis_(readDirection(dict, "axis")),
    radius_(readPositive(dict, "radius")),
    inside_(true)
{
    const word side(dict.get<word>("side"));

    if (side == "inside")
    {
        inside_ = true;
    }
    else if (side == "outside")
    {
        inside_ = false;
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'side': expected inside or outside, got '" << side
            << "' in dictionary " << dict.name()
            << exit(FatalIOError);
    }
    checkKeywords(dict, wordList({"axisPoint", "axis", "radius", "side"}));
}


bool Foam::rigidObstacles::cylinderObstacle::nearestInitial
(
    const point& x0,
    const scalar maxDistance,
    obstaclePoint& cp,
    const label
) const
{
    const vector d = x0 - axisPoint_;
    const scalar axial = d & axis_;
    vector radial = d - axial*axis_;
    const scalar rho = mag(radial);

    const scalar gap = inside_ ? radius_ - rho : rho - radius_;

    if (mag(gap) > maxDistance)
    {
        return false;
    }

    if (rho > SMALL*radius_)
    {
        radial /= rho;
    }
    else
    {
        // On the axis: any radial direction; take the one closest to the
        // coordinate axis least aligned with the cylinder axis
        const vector& a = axis_;
        const vector e =
            mag(a.x()) <= mag(a.y()) && mag(a.x()) <= mag(a.z())
          ? vector(1, 0, 0)
          : mag(a.y()) <= mag(a.z()) ? vector(0, 1, 0) : vector(0, 0, 1);
        radial = e - (e & a)*a;
        radial /= mag(radial);
    }

    cp.p = axisPoint_ + axial*axis_ + radius_*radial;
    cp.n = inside_ ? -radial : radial;
    cp.gap = gap;
    cp.hint = -1;

    // [C6] the radial direction turns with x: d(radial)/dx =
    // (I - a a - r r)/rho, the curvature seen from x
    if (rho > SMALL*radius_)
    {
        const tensor Pt(tensor::I - sqr(axis_) - sqr(radial));
        cp.dndx = (inside_ ? -1 : 1)*Pt/rho;
        cp.dpdx = sqr(axis_) + (radius_/rho)*Pt;
    }
    else
    {
        cp.dndx = Zero;
        cp.dpdx = sqr(axis_);
    }

    return true;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "planeObstacle.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace rigidObstacles
{
    defineTypeNameAndDebug(planeObstacle, 0);
    addToRunTimeSelectionTable(rigidObstacle, planeObstacle, dictionary);
}
}


Foam::rigidObstacles::planeObstacle::planeObstacle
(
    const dictionary& dict,
    const fileName&
)
:
    rigidObstacle(dict),
    origin_(dict.get<point>("point")),
    normal_(readDirection(dict, "normal"))
{
    checkKeywords(dict, wordList({"point", "normal"}));
}


bool Foam::rigidObstacles::planeObstacle::nearestInitial
(
    const point& x0,
    const scalar maxDistance,
    obstaclePoint& cp,
    const label
) const
{
    const scalar gap = (x0 - origin_) & normal_;

    if (mag(gap) > maxDistance)
    {
        return false;
    }

    cp.p = x0 - gap*normal_;
    cp.n = normal_;
    cp.gap = gap;
    cp.hint = -1;
    cp.dndx = Zero;
    cp.dpdx = tensor::I - sqr(normal_);

    return true;
}


// ************************************************************************* //

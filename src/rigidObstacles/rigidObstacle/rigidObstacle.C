/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "rigidObstacle.H"
#include "checkedFunction1.H"
#include "strictDictionary.H"
#include "error.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(rigidObstacle, 0);
    defineRunTimeSelectionTable(rigidObstacle, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::vector Foam::rigidObstacle::readDirection
(
    const dictionary& dict,
    const word& key
)
{
    const vector v(dict.get<vector>(key));
    const scalar m = mag(v);

    if (!(m > VSMALL))
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': zero vector " << v
            << " in dictionary " << dict.name() << nl
            << "    a direction is required"
            << exit(FatalIOError);
    }

    return v/m;
}


Foam::scalar Foam::rigidObstacle::readPositive
(
    const dictionary& dict,
    const word& key
)
{
    const scalar s(dict.get<scalar>(key));

    if (!(s > 0))
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': must be > 0, got " << s
            << " in dictionary " << dict.name()
            << exit(FatalIOError);
    }

    return s;
}


void Foam::rigidObstacle::checkKeywords
(
    const dictionary& dict,
    const wordList& own
)
{
    wordList known
    ({
        "type", "translation", "translationCoeffs", "rotationAxis",
        "rotationOrigin", "rotationAngle", "rotationAngleCoeffs"
    });
    known.append(own);
    strictDictionary::check
    (
        dict, known, "obstacle " + dict.getOrDefault<word>("type", "")
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidObstacle::rigidObstacle(const dictionary& dict)
:
    translation_(),
    rotationAxis_(0, 0, 1),
    rotationOrigin_(dict.getOrDefault<point>("rotationOrigin", Zero)),
    rotationAngle_(),
    nFullSearches_(0),
    nReprojections_(0)
{
    if (dict.found("translation"))
    {
        translation_ = checkedFunction1<vector>("translation", dict);
        // Build any demand-driven look-up data now: later queries only read
        translation_->value(0);
    }

    if (dict.found("rotationAxis"))
    {
        rotationAxis_ = readDirection(dict, "rotationAxis");
    }

    if (dict.found("rotationAngle"))
    {
        rotationAngle_ = checkedFunction1<scalar>("rotationAngle", dict);
        rotationAngle_->value(0);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::rigidObstacle::moving() const
{
    return translation_.valid() || rotationAngle_.valid();
}


Foam::vector Foam::rigidObstacle::translation(const scalar t) const
{
    return translation_.valid() ? translation_->value(t) : vector(Zero);
}


Foam::tensor Foam::rigidObstacle::rotation(const scalar t) const
{
    if (!rotationAngle_.valid())
    {
        return tensor::I;
    }

    // Rodrigues: R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k
    const scalar a = rotationAngle_->value(t);
    const vector& k = rotationAxis_;
    const scalar c = Foam::cos(a);
    const scalar s = Foam::sin(a);

    return
        c*tensor::I
      + s*tensor
        (
            0,    -k.z(),  k.y(),
            k.z(),  0,    -k.x(),
           -k.y(),  k.x(),  0
        )
      + (1 - c)*sqr(k);
}


Foam::point Foam::rigidObstacle::toCurrent
(
    const point& x0,
    const scalar t
) const
{
    if (!moving())
    {
        return x0;
    }
    return
        (rotation(t) & (x0 - rotationOrigin_))
      + rotationOrigin_ + translation(t);
}


Foam::point Foam::rigidObstacle::toInitial
(
    const point& x,
    const scalar t
) const
{
    if (!moving())
    {
        return x;
    }
    // R is orthogonal: R^-1 = R^T, and (v & R) = R^T v
    return
        ((x - rotationOrigin_ - translation(t)) & rotation(t))
      + rotationOrigin_;
}


bool Foam::rigidObstacle::nearest
(
    const point& x,
    const scalar t,
    const scalar maxDistance,
    obstaclePoint& cp,
    const label hint
) const
{
    const point x0 = toInitial(x, t);
    obstaclePoint cp0;
    if (!nearestInitial(x0, maxDistance, cp0, hint))
    {
        return false;
    }
    currentFrame(x0, cp0, t, cp);
    return true;
}


bool Foam::rigidObstacle::nearest
(
    const point& x,
    const scalar t,
    const scalar maxDistance,
    const scalar refreshDistance,
    obstaclePoint& cp,
    obstacleSearch& search
) const
{
    if (!reusesSearches())
    {
        return nearest(x, t, maxDistance, cp);
    }

    const point x0 = toInitial(x, t);
    obstaclePoint cp0;

    if
    (
        search.searched
     && magSqr(x0 - search.x0) < sqr(refreshDistance)
    )
    {
        // [C2c] moved less than refreshDistance since the full search: a
        // miss then (nothing within maxDistance + refreshDistance) is a
        // miss now; a hit is re-projected from the triangle followed
        ++nReprojections_;
        if (!search.hit)
        {
            return false;
        }
        if (!nearestLocal(x0, maxDistance, cp0, search.hint))
        {
            return false;
        }
    }
    else
    {
        ++nFullSearches_;
        search.searched = true;
        search.x0 = x0;
        search.hit =
            nearestInitial(x0, maxDistance + refreshDistance, cp0, -1);
        search.hint = search.hit ? cp0.hint : -1;
        // the type's own reach criterion, from the triangle just found
        if (!search.hit || !nearestLocal(x0, maxDistance, cp0, cp0.hint))
        {
            return false;
        }
    }
    search.hint = cp0.hint;

    currentFrame(x0, cp0, t, cp);
    return true;
}


void Foam::rigidObstacle::currentFrame
(
    const point& x0,
    const obstaclePoint& cp0,
    const scalar t,
    obstaclePoint& cp
) const
{
    // [C6] gap derivative from those of p and n: gap = (x - p) . n
    const vector dgapdx0
    (
        ((tensor::I - cp0.dpdx).T() & cp0.n) + (cp0.dndx.T() & (x0 - cp0.p))
    );

    if (!moving())
    {
        cp = cp0;
        cp.dgapdx = dgapdx0;
        return;
    }

    // Distances and hence the gap are invariant under the rigid motion;
    // points, normals and their derivatives rotate
    const tensor R(rotation(t));
    cp.p = (R & (cp0.p - rotationOrigin_)) + rotationOrigin_ + translation(t);
    cp.n = R & cp0.n;
    cp.gap = cp0.gap;
    cp.hint = cp0.hint;
    cp.dndx = R & cp0.dndx & R.T();
    cp.dpdx = R & cp0.dpdx & R.T();
    cp.dgapdx = R & dgapdx0;
}


Foam::tensor Foam::rigidObstacle::materialDisplacementGradient
(
    const scalar t0,
    const scalar t1
) const
{
    if (!moving())
    {
        return Zero;
    }
    // p - (R0 R1^T (p - o - T1) + o + T0)
    return tensor::I - (rotation(t0) & rotation(t1).T());
}


Foam::vector Foam::rigidObstacle::materialDisplacement
(
    const point& p,
    const scalar t0,
    const scalar t1
) const
{
    if (!moving())
    {
        return Zero;
    }
    return p - toCurrent(toInitial(p, t1), t0);
}


// ************************************************************************* //

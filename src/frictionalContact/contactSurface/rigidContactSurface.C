/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "rigidContactSurface.H"
#include "fvMesh.H"
#include "volMesh.H"
#include "Time.H"
#include "IOdictionary.H"
#include "solidRestartState.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::rigidContactSurface::cellDepth
(
    const label i,
    const vector& S0
) const
{
    return patch_.boundaryMesh().mesh().V()[patch_.faceCells()[i]]/mag(S0);
}


bool Foam::rigidContactSurface::nearest
(
    const label i,
    const point& x,
    const scalar t,
    const vector& S0,
    obstaclePoint& cp,
    obstacleSearch& record
) const
{
    return obstacle_->nearest
    (
        x, t, searchDistance_, searchRefreshFraction_*cellDepth(i, S0), cp,
        record
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidContactSurface::rigidContactSurface
(
    const fvPatch& p,
    const dictionary& dict
)
:
    patch_(p),
    obstacleDict_(dict.subDict("obstacle")),
    searchDistance_(-1),
    searchRefreshFraction_
    (
        dict.lookupOrDefault<scalar>("searchRefreshFraction", 0.2)
    ),
    search_(p.size(), obstacleSearch()),
    k_(nullptr)
{
    if (searchRefreshFraction_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'searchRefreshFraction' in dictionary " << dict.name()
            << " must be >= 0 (0: a full search at every evaluation), got "
            << searchRefreshFraction_ << nl << exit(FatalIOError);
    }
    searchDistance_ = readSearchDistance(dict, p);

    obstacle_ = rigidObstacle::New
    (
        obstacleDict_, p.boundaryMesh().mesh().time().globalPath()
    );

    // [C2c] the search records as written: a restart then re-projects
    // where the uninterrupted run would (the same triangles, bit for bit)
    if (dict.found("searchTriangle"))
    {
        const label n = p.size();
        const labelField tri("searchTriangle", dict, n);
        const vectorField x0("searchPoint", dict, n);
        forAll(search_, i)
        {
            search_[i].searched = tri[i] != -1;
            search_[i].hit = tri[i] >= 0;
            search_[i].hint = max(tri[i], label(-1));
            search_[i].x0 = x0[i];
        }
    }
    else if
    (
        obstacle_->cachesSearches()
     && p.boundaryMesh().mesh().foundObject<IOdictionary>
        (
            "mechanicalProperties"
        )
     && solidRestartState::expected(p.boundaryMesh().mesh().time())
    )
    {
        // [S19b] without them the restart's gaps differ in the last bit
        FatalIOErrorInFunction(dict)
            << "Restart from time "
            << p.boundaryMesh().mesh().time().timeName() << ": patch "
            << p.name() << " in " << dict.name() << " has no keywords"
            << " 'searchTriangle' and 'searchPoint', the obstacle search"
            << " records ([C2c]) written with every time directory. Restore"
            << " them, or restart from another complete time" << nl
            << exit(FatalIOError);
    }
}


Foam::rigidContactSurface::rigidContactSurface
(
    const rigidContactSurface& s,
    const fvPatch& p
)
:
    contactSurface(),
    patch_(p),
    obstacleDict_(s.obstacleDict_),
    obstacle_
    (
        rigidObstacle::New
        (
            obstacleDict_, p.boundaryMesh().mesh().time().globalPath()
        )
    ),
    searchDistance_(s.searchDistance_),
    searchRefreshFraction_(s.searchRefreshFraction_),
    search_(s.search_),
    k_(nullptr)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rigidContactSurface::checkInitialGap
(
    const vectorField& D,
    const scalar t,
    const dictionary& dict
) const
{
    // [C2d] a face that starts deep inside the obstacle is out of its
    // search reach and would never come into contact; an obstacle whose
    // normals point into the body sees the body on its far side
    const bool allow =
        dict.getOrDefault<bool>("allowInitialPenetration", false);
    const scalar fraction = 0.25;
    const vectorField& Cf = patch_.Cf();
    const vectorField& Sf = patch_.Sf();

    label nDeep = 0, nNear = 0, nAway = 0;
    scalar ratio = -1, deepest = 0, deepestCellDepth = 0;
    point deepestAt(Zero);
    forAll(Cf, i)
    {
        const point x(Cf[i] + D[i]);
        obstaclePoint cp;
        if (!obstacle_->nearest(x, t, GREAT, cp))
        {
            continue;
        }
        const scalar h = cellDepth(i, Sf[i]);
        if (mag(cp.gap) <= searchDistance_)
        {
            ++nNear;
            // the body's outward normal and the obstacle's on one side
            if ((Sf[i] & cp.n) > 0)
            {
                ++nAway;
            }
        }
        if (-cp.gap > fraction*h)
        {
            ++nDeep;
            if (-cp.gap/h > ratio)
            {
                ratio = -cp.gap/h;
                deepest = -cp.gap;
                deepestCellDepth = h;
                deepestAt = x;
            }
        }
    }

    reduce(nNear, sumOp<label>());
    reduce(nAway, sumOp<label>());
    reduce(nDeep, sumOp<label>());
    const word type(obstacleDict_.getOrDefault<word>("type", "?"));

    if (nNear > 0 && nAway > 0.9*nNear)
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << patch_.name() << " (dictionary " << dict.name()
            << "): the normals of the obstacle (type " << type << ") point"
            << " away from the body: " << nAway << " of the " << nNear
            << " faces within searchDistance " << searchDistance_ << " m"
            << " see the obstacle's normal on their own side (the body"
            << " behind the surface). The obstacle's normals must point"
            << " towards the body: reverse the surface's triangles, set"
            << " 'flipNormals yes;' (triSurface) or reverse 'normal'"
            << " (plane) in dictionary obstacle" << nl << exit(FatalIOError);
    }

    // The deepest face over the processors
    const scalar maxRatio = returnReduce(ratio, maxOp<scalar>());
    if (ratio != maxRatio)
    {
        deepest = 0;
        deepestCellDepth = 0;
        deepestAt = Zero;
    }
    reduce(deepest, maxOp<scalar>());
    reduce(deepestCellDepth, maxOp<scalar>());
    reduce(deepestAt, maxMagSqrOp<vector>());
    const label nFaces = returnReduce(Cf.size(), sumOp<label>());

    if (nDeep && !allow)
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << patch_.name() << " (dictionary " << dict.name()
            << "): " << nDeep << " of " << nFaces << " faces start inside"
            << " the obstacle (type " << type << ") deeper than "
            << fraction << " of their cell's depth at time " << t
            << ": the deepest by " << deepest << " m (" << maxRatio
            << " times its cell's depth " << deepestCellDepth << " m) at "
            << deepestAt << nl
            << "Move the obstacle (or the body) so that the bodies start"
            << " apart or touching, or set 'allowInitialPenetration yes;'"
            << " in the patch dictionary to start from this overlap"
            << exit(FatalIOError);
    }
}


bool Foam::rigidContactSurface::masterPointOf
(
    const label i,
    masterPoint& mp,
    const bool derivatives
) const
{
    // [C2] the deformed face centre against the obstacle, the search
    // reused while the face moves less than a fraction of its cell [C2c]
    const solidPatchKinematics& k = *k_;
    mp = masterPoint();
    obstaclePoint cp;
    if (!nearest(i, k.Cf0[i] + k.D[i], k.time, k.Sf0[i], cp, search_[i]))
    {
        return false;
    }
    mp.inReach = true;
    mp.gap = cp.gap;
    mp.n = cp.n;

    // [C3] the obstacle's material point under the face: its rigid motion
    // (a Function1 translation and rotation) over the step
    mp.motion = obstacle_->materialDisplacement(cp.p, k.time - k.deltaT, k.time);

    if (derivatives)
    {
        // [C6] curvature seen from x, dgap/dx; a rotating obstacle's
        // material point moves with the nearest point
        mp.dgapdx = cp.dgapdx;
        mp.dndx = cp.dndx;
        mp.dmotiondx =
            obstacle_->materialDisplacementGradient(k.time - k.deltaT, k.time)
          & cp.dpdx;
    }
    return true;
}


bool Foam::rigidContactSurface::nearestQuery
(
    const label i,
    const point& x,
    const scalar t,
    const vector& S0,
    obstaclePoint& cp
) const
{
    obstacleSearch record(search_[i]);
    return nearest(i, x, t, S0, cp, record);
}


void Foam::rigidContactSurface::resetSearches(const label n)
{
    search_.setSize(n);
    search_ = obstacleSearch();
}


void Foam::rigidContactSurface::report(const word& patchName) const
{
    // [C2c] obstacle searches since the last report (this step and any
    // cut-back attempts before it)
    const labelPair n
    (
        returnReduce(obstacle_->searchCounts().first(), sumOp<label>()),
        returnReduce(obstacle_->searchCounts().second(), sumOp<label>())
    );
    if (n.first() + n.second() > 0)
    {
        Info<< "    contact " << patchName << ": obstacle searches "
            << n.first() << ", re-projections " << n.second() << endl;
    }
    obstacle_->resetSearchCounts();
}


void Foam::rigidContactSurface::write(Ostream& os) const
{
    os.writeKeyword("obstacle") << obstacleDict_;
    os.writeEntry("searchDistance", searchDistance_);
    os.writeEntry("searchRefreshFraction", searchRefreshFraction_);
}


void Foam::rigidContactSurface::writeSearches(Ostream& os) const
{
    // [C2c] -1 not searched, -2 nothing in reach, else the triangle
    // followed
    if (obstacle_->cachesSearches())
    {
        labelField tri(search_.size());
        vectorField x0(search_.size());
        forAll(search_, i)
        {
            tri[i] =
                !search_[i].searched ? -1
              : !search_[i].hit ? -2
              : search_[i].hint;
            x0[i] = search_[i].x0;
        }
        tri.writeEntry("searchTriangle", os);
        x0.writeEntry("searchPoint", os);
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "triSurfaceObstacle.H"
#include "addToRunTimeSelectionTable.H"
#include "OSspecific.H"
#include "unitConversion.H"
#include "triPointRef.H"

namespace Foam
{
namespace rigidObstacles
{
    defineTypeNameAndDebug(triSurfaceObstacle, 0);
    addToRunTimeSelectionTable(rigidObstacle, triSurfaceObstacle, dictionary);
}
}


const Foam::Enum
<
    Foam::rigidObstacles::triSurfaceObstacle::normalModel
>
Foam::rigidObstacles::triSurfaceObstacle::normalModelNames
({
    { normalModel::smooth, "smooth" },
    { normalModel::nearest, "nearest" },
    { normalModel::face, "face" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::rigidObstacles::triSurfaceObstacle::surfaceFile
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    const fileName name(dict.get<fileName>("file"));

    if (name.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'file': empty file name in dictionary "
            << dict.name() << nl
            << "    expected a file in " << caseDir/"constant"/"triSurface"
            << exit(FatalIOError);
    }

    return caseDir/"constant"/"triSurface"/name;
}


Foam::triSurface Foam::rigidObstacles::triSurfaceObstacle::readSurface
(
    const dictionary& dict,
    const fileName& file
)
{
    if (!isFile(file))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'file': surface file not found in dictionary "
            << dict.name() << nl
            << "    expected: " << file
            << exit(FatalIOError);
    }

    const scalar scale = dict.getOrDefault<scalar>("scale", 1);
    if (!(scale > 0))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'scale': must be > 0, got " << scale
            << " in dictionary " << dict.name()
            << exit(FatalIOError);
    }

    checkSTLFile(dict, file);
    triSurface surf(file, scale);

    if (surf.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'file': surface has no triangles in dictionary "
            << dict.name() << nl
            << "    file: " << file
            << exit(FatalIOError);
    }

    checkSurface(dict, file, surf);
    return surf;
}


bool Foam::rigidObstacles::triSurfaceObstacle::evaluate
(
    const label f,
    const point& x0,
    obstaclePoint& cp
) const
{
    const pointField& pts = surface_.localPoints();
    const labelledTri& tri = surface_.localFaces()[f];
    const triPointRef t(pts[tri[0]], pts[tri[1]], pts[tri[2]]);

    label nearType = triPointRef::NONE;
    label nearLabel = -1;
    const point p = t.nearestPointClassify(x0, nearType, nearLabel).rawPoint();

    const vector d = x0 - p;
    const scalar dist = mag(d);

    // Pseudo-normal of the nearest feature, whether it is sharp and
    // whether it lies on an open boundary (edges from nInternalEdges() on
    // have one triangle)
    vector pseudo = faceNormals_[f];
    bool sharp = false;
    bool openBoundary = false;

    if (nearType == triPointRef::EDGE)
    {
        const edge e(tri[nearLabel], tri[(nearLabel + 1) % 3]);
        for (const label edgei : surface_.faceEdges()[f])
        {
            if (edge::compare(surface_.edges()[edgei], e) != 0)
            {
                pseudo = Zero;
                for (const label g : surface_.edgeFaces()[edgei])
                {
                    pseudo += faceNormals_[g];
                }
                sharp = sharpEdge_[edgei];
                openBoundary = edgei >= surface_.nInternalEdges();
                break;
            }
        }
    }
    else if (nearType == triPointRef::POINT)
    {
        pseudo = pointNormals_[tri[nearLabel]];
        sharp = sharpPoint_[tri[nearLabel]];
        for (const label edgei : surface_.pointEdges()[tri[nearLabel]])
        {
            openBoundary =
                openBoundary || edgei >= surface_.nInternalEdges();
        }
    }

    // Behind an open boundary (beyond the edge of a strip, on its back
    // side) there is no obstacle: out of reach. The sign rule below would
    // make such a point penetrate by its whole distance to the edge, a gap
    // that jumps from +|d| to -|d| as the point crosses the plane of the
    // end triangle, and traps faces sliding off the strip onto its edge
    if (openBoundary && (d & pseudo) < 0)
    {
        const scalar m = mag(pseudo);
        const vector dT(m > VSMALL ? d - (d & pseudo)*pseudo/sqr(m) : d);
        if (mag(dT) > smallDistance_)
        {
            return false;
        }
    }

    vector n = faceNormals_[f];

    // [C6] how the nearest point moves with x0: in the triangle's plane
    // inside it, along the edge on an edge, not at a vertex
    tensor dpdx(Zero);
    if (nearType == triPointRef::NONE)
    {
        dpdx = tensor::I - sqr(faceNormals_[f]);
    }
    else if (nearType == triPointRef::EDGE)
    {
        const vector e
        (
            pts[tri[(nearLabel + 1) % 3]] - pts[tri[nearLabel]]
        );
        dpdx = sqr(e/mag(e));
    }
    tensor dndx(Zero);

    if
    (
        normalModel_ == normalModel::nearest
     || (normalModel_ == normalModel::smooth && sharp)
    )
    {
        if (dist > smallDistance_)
        {
            n = ((d & pseudo) >= 0 ? d : -d)/dist;
            // n = +-(x - p)/|x - p| turns with x unless x moves along it
            dndx = ((d & pseudo) >= 0 ? 1 : -1)
               *((tensor::I - sqr(d/dist)) & (tensor::I - dpdx))/dist;
        }
        else if (mag(pseudo) > VSMALL)
        {
            n = pseudo/mag(pseudo);
        }
    }
    else if (normalModel_ == normalModel::smooth)
    {
        // Phong normal: the corner normals interpolated at p
        const barycentric2D w = t.pointToBarycentric(p);
        const FixedList<vector, 3>& cn = cornerNormals_[f];
        const vector ns = w[0]*cn[0] + w[1]*cn[1] + w[2]*cn[2];
        const scalar m = mag(ns);
        if (m > VSMALL)
        {
            n = ns/m;
            // barycentric gradients (b - c) x nt/(2 A), ... in the plane
            // (nt the triangle's own unit normal, whatever the flip)
            const vector nt(t.areaNormal()/mag(t.areaNormal()));
            const scalar twoA = 2*mag(t.areaNormal());
            tensor dns(Zero);
            for (label k = 0; k < 3; ++k)
            {
                const point& b = pts[tri[(k + 1) % 3]];
                const point& c = pts[tri[(k + 2) % 3]];
                dns += cn[k]*(((b - c) ^ nt)/twoA);
            }
            dndx = ((tensor::I - sqr(n)) & dns & dpdx)/m;
        }
    }

    cp.dndx = dndx;
    cp.dpdx = dpdx;
    cp.p = p;
    cp.n = n;
    cp.gap = d & n;
    cp.hint = f;
    return true;
}


Foam::label Foam::rigidObstacles::triSurfaceObstacle::hintedNearest
(
    const point& x0,
    const scalar maxDistance,
    const label hint
) const
{
    if (hint < 0 || hint >= surface_.size())
    {
        return -1;
    }

    const pointField& pts = surface_.localPoints();
    const List<labelledTri>& faces = surface_.localFaces();

    label best = -1;
    label bestType = -1;
    scalar bestDist = GREAT;

    auto tryFace = [&](const label f)
    {
        const labelledTri& tri = faces[f];
        label nearType = -1;
        label nearLabel = -1;
        const scalar dist =
            triPointRef(pts[tri[0]], pts[tri[1]], pts[tri[2]])
           .nearestPointClassify(x0, nearType, nearLabel).distance();
        if (dist < bestDist)
        {
            best = f;
            bestType = nearType;
            bestDist = dist;
        }
    };

    tryFace(hint);
    for (const label edgei : surface_.faceEdges()[hint])
    {
        for (const label g : surface_.edgeFaces()[edgei])
        {
            if (g != hint)
            {
                tryFace(g);
            }
        }
    }

    if (bestType == triPointRef::NONE && bestDist <= maxDistance)
    {
        return best;
    }
    return -1;
}


Foam::label Foam::rigidObstacles::triSurfaceObstacle::walkNearest
(
    const point& x0,
    const label f,
    const label maxMoves
) const
{
    const pointField& pts = surface_.localPoints();
    const List<labelledTri>& faces = surface_.localFaces();
    const labelListList& pointFaces = surface_.pointFaces();

    auto distance = [&](const label g)
    {
        const labelledTri& tri = faces[g];
        return
            triPointRef(pts[tri[0]], pts[tri[1]], pts[tri[2]])
           .nearestPoint(x0).distance();
    };

    label current = f;
    scalar currentDist = distance(f);

    for (label move = 0; move <= maxMoves; ++move)
    {
        // every triangle touching the current one, so also every triangle
        // holding its nearest point, whether inside, on an edge or a vertex
        label best = current;
        scalar bestDist = currentDist;
        for (const label pointi : faces[current])
        {
            for (const label g : pointFaces[pointi])
            {
                if (g != current)
                {
                    const scalar d = distance(g);
                    if (d < bestDist)
                    {
                        best = g;
                        bestDist = d;
                    }
                }
            }
        }
        if (best == current)
        {
            return current;
        }
        current = best;
        currentDist = bestDist;
    }

    return -1;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidObstacles::triSurfaceObstacle::triSurfaceObstacle
(
    const dictionary& dict,
    const fileName& caseDir
)
:
    rigidObstacle(dict),
    file_(surfaceFile(dict, caseDir)),
    surface_(readSurface(dict, file_)),
    search_(surface_),
    normalModel_
    (
        normalModelNames.getOrDefault("normal", dict, normalModel::smooth)
    ),
    featureCos_
    (
        Foam::cos(degToRad(dict.getOrDefault<scalar>("featureAngle", 30)))
    ),
    smallDistance_(0)
{
    calcNormals(dict.getOrDefault<bool>("flipNormals", false));

    // Build the octree and the addressing now: queries are then read-only
    search_.tree();
    surface_.pointFaces();
    surface_.faceEdges();
    surface_.edgeFaces();

    checkKeywords
    (
        dict,
        wordList
        ({
            "file", "scale", "normal", "featureAngle", "flipNormals",
            "closed"
        })
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::rigidObstacles::triSurfaceObstacle::nearestFullSearch
(
    const point& x0,
    const scalar maxDistance,
    obstaclePoint& cp
) const
{
    const pointIndexHit hit =
        search_.tree().findNearest(x0, sqr(maxDistance));

    if (!hit.hit())
    {
        return false;
    }

    return evaluate(hit.index(), x0, cp);
}


bool Foam::rigidObstacles::triSurfaceObstacle::nearestInitial
(
    const point& x0,
    const scalar maxDistance,
    obstaclePoint& cp,
    const label hint
) const
{
    const label f = hintedNearest(x0, maxDistance, hint);

    if (f >= 0)
    {
        return evaluate(f, x0, cp);
    }

    return nearestFullSearch(x0, maxDistance, cp);
}


bool Foam::rigidObstacles::triSurfaceObstacle::nearestLocal
(
    const point& x0,
    const scalar maxDistance,
    obstaclePoint& cp,
    const label hint
) const
{
    if (hint < 0 || hint >= surface_.size())
    {
        return nearestFullSearch(x0, maxDistance, cp);
    }

    label f = hintedNearest(x0, maxDistance, hint);

    if (f < 0)
    {
        f = walkNearest(x0, hint, 100);
        if (f < 0)
        {
            return nearestFullSearch(x0, maxDistance, cp);
        }
    }

    evaluate(f, x0, cp);
    return mag(x0 - cp.p) <= maxDistance;
}


// ************************************************************************* //

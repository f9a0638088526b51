/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
Description
    Normals and sharp features of triSurfaceObstacle (see its header).

\*---------------------------------------------------------------------------*/

#include "triSurfaceObstacle.H"
#include "boundBox.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rigidObstacles::triSurfaceObstacle::calcNormals(const bool flip)
{
    const pointField& pts = surface_.localPoints();
    const List<labelledTri>& faces = surface_.localFaces();
    const edgeList& edges = surface_.edges();
    const labelListList& edgeFaces = surface_.edgeFaces();
    const labelListList& pointFaces = surface_.pointFaces();
    const labelListList& pointEdges = surface_.pointEdges();

    smallDistance_ = 1e-8*boundBox(pts).mag();

    faceNormals_ = surface_.faceNormals();
    if (flip)
    {
        faceNormals_ = -faceNormals_;
    }

    // Weight of triangle f in the normal at its corner k: the interior
    // angle (independent of how a face is split into triangles), for the
    // smooth corner normals times the area (a long flat facet meeting short facets of an arc at a tangent
    // point keeps its normal there, which is the curve's; with the angle
    // alone, an extruded strip weighs both sides equally and the normal
    // at the tangent point is off by a quarter of the arc's facet angle)
    auto cornerWeight = [&](const label f, const label k, const bool area)
    {
        const labelledTri& tri = faces[f];
        const point& p = pts[tri[k]];
        const vector a = pts[tri[(k + 1) % 3]] - p;
        const vector b = pts[tri[(k + 2) % 3]] - p;
        const scalar ma = mag(a);
        const scalar mb = mag(b);
        if (ma < VSMALL || mb < VSMALL)
        {
            return scalar(0);
        }
        const scalar angle =
            Foam::acos(max(-1.0, min(1.0, (a & b)/(ma*mb))));
        return area ? angle*0.5*mag(a ^ b) : angle;
    };

    // Corner index of point v in triangle f
    auto cornerOf = [&](const label f, const label v)
    {
        const labelledTri& tri = faces[f];
        return tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
    };

    // Angle-weighted pseudo-normals of the points (their sign tells the
    // side of a point nearest to the vertex, Baerentzen and Aanaes 2005)
    pointNormals_.setSize(pts.size());
    forAll(pts, v)
    {
        vector n = Zero;
        for (const label g : pointFaces[v])
        {
            n += cornerWeight(g, cornerOf(g, v), false)*faceNormals_[g];
        }
        const scalar m = mag(n);
        pointNormals_[v] = m > VSMALL ? vector(n/m) : vector(Zero);
    }

    // Corner normals: the same sum restricted to the triangles within the
    // feature angle of the corner's triangle
    cornerNormals_.setSize(faces.size());
    forAll(faces, f)
    {
        for (label k = 0; k < 3; ++k)
        {
            vector n = Zero;
            for (const label g : pointFaces[faces[f][k]])
            {
                if ((faceNormals_[g] & faceNormals_[f]) >= featureCos_)
                {
                    n += cornerWeight(g, cornerOf(g, faces[f][k]), true)
                        *faceNormals_[g];
                }
            }
            const scalar m = mag(n);
            cornerNormals_[f][k] = m > VSMALL ? vector(n/m) : faceNormals_[f];
        }
    }

    // Sharp edges and points
    sharpEdge_.setSize(edges.size());
    forAll(edges, edgei)
    {
        const labelList& ef = edgeFaces[edgei];
        sharpEdge_[edgei] =
            ef.size() != 2
         || (faceNormals_[ef[0]] & faceNormals_[ef[1]]) < featureCos_;
    }

    sharpPoint_.setSize(pts.size());
    forAll(pts, v)
    {
        sharpPoint_[v] = false;
        for (const label edgei : pointEdges[v])
        {
            if (sharpEdge_[edgei])
            {
                sharpPoint_[v] = true;
                break;
            }
        }
    }
}


// ************************************************************************* //

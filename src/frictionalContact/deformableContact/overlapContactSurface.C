/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "overlapContactSurface.H"
#include "polygonOverlap.H"
#include "DynamicList.H"
#include "boundBox.H"
#include "indexedOctree.H"
#include "treeDataPrimitivePatch.H"
#include "primitiveFacePatch.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- One overlap of a slave face with a master face [C11], [C11b]
struct faceOverlap
{
    label master;
    scalar length;      // overlap length (3-D: area) l_sm, master measure
    scalar projected;   // measure of the slave face's projection
    scalar gap;         // (x_s - x_m) . n_m at the overlap's centroid
};

} // End namespace Foam


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::overlapContactSurface::findCandidates
(
    const contactSide& sl,
    const contactSide& ms,
    const scalar searchDistance,
    const scalar margin,
    labelListList& cand
)
{
    // Candidates by a sweep along the direction in which the master
    // surface extends most: the master faces sorted by the lower end of
    // their interval (widened by the search distance); a slave face's
    // candidates start within one interval length before its own
    // [C11]: O(n log n)
    const label nM = ms.X.size();
    cand.setSize(sl.X.size());
    if (nM == 0)
    {
        cand = labelList();
        return;
    }
    if (sl.Xv.size())
    {
        findCandidates3D(sl, ms, searchDistance, margin, cand);
        return;
    }
    boundBox bb(ms.a, false);
    bb.add(ms.b);
    const vector span(bb.span());
    const direction ax =
        span.x() >= span.y() && span.x() >= span.z() ? 0
      : (span.y() >= span.z() ? 1 : 2);
    scalar longest = 0;
    forAll(ms.a, m)
    {
        longest = max(longest, mag(ms.b[m] - ms.a[m]));
    }
    const scalar widen = searchDistance + margin*longest;
    scalarField lo(nM);
    scalarField hi(nM);
    scalar maxLength = 0;
    forAll(lo, m)
    {
        lo[m] = min(ms.a[m][ax], ms.b[m][ax]) - widen;
        hi[m] = max(ms.a[m][ax], ms.b[m][ax]) + widen;
        maxLength = max(maxLength, hi[m] - lo[m]);
    }
    labelList order(identity(nM));
    std::sort
    (
        order.begin(), order.end(),
        [&](const label i, const label j) { return lo[i] < lo[j]; }
    );
    scalarList sortedLo(nM);
    forAll(order, k)
    {
        sortedLo[k] = lo[order[k]];
    }

    DynamicList<label> found(8);
    forAll(cand, i)
    {
        const scalar sLo = min(sl.a[i][ax], sl.b[i][ax]);
        const scalar sHi = max(sl.a[i][ax], sl.b[i][ax]);
        found.clear();
        label k = label
        (
            std::lower_bound
            (
                sortedLo.begin(), sortedLo.end(), sLo - maxLength
            ) - sortedLo.begin()
        );
        for (; k < nM && sortedLo[k] <= sHi; ++k)
        {
            const label m = order[k];
            // facing surfaces only
            if (hi[m] >= sLo && (sl.n[i] & ms.n[m]) < 0)
            {
                found.append(m);
            }
        }
        cand[i] = found;
    }
}


void Foam::overlapContactSurface::findCandidates3D
(
    const contactSide& sl,
    const contactSide& ms,
    const scalar searchDistance,
    const scalar margin,
    labelListList& cand
)
{
    // [C11b] an octree of the master faces' deformed polygons; a slave
    // face's candidates are the master faces that meet its bounding box
    // widened by the search distance (and 'margin' times its diameter):
    // O(n log n) (called by findCandidates(), which sized cand)
    label nPoints = 0;
    forAll(ms.v, m)
    {
        nPoints += ms.v[m].size();
    }
    faceList faces(ms.v.size());
    pointField points(nPoints);
    nPoints = 0;
    forAll(ms.v, m)
    {
        face& f = faces[m];
        f.setSize(ms.v[m].size());
        forAll(f, k)
        {
            f[k] = nPoints;
            points[nPoints++] = ms.v[m][k];
        }
    }
    const primitiveFacePatch surface(faces, points);
    treeBoundBox overall(points);
    overall.inflate(1e-4);
    typedef treeDataPrimitivePatch<primitiveFacePatch> treeType;
    const indexedOctree<treeType> tree
    (
        treeType(true, surface, 1e-6),
        overall,
        8,
        10,
        3.0
    );

    DynamicList<label> found(8);
    forAll(cand, i)
    {
        treeBoundBox bb(sl.v[i]);
        const scalar widen = searchDistance + margin*mag(bb.span());
        bb.min() -= vector::uniform(widen);
        bb.max() += vector::uniform(widen);
        found.clear();
        for (const label m : tree.findBox(bb))
        {
            // facing surfaces only
            if ((sl.n[i] & ms.n[m]) < 0)
            {
                found.append(m);
            }
        }
        Foam::sort(found);
        cand[i] = found;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::overlapContactSurface::masterPointOf
(
    const label i,
    masterPoint& mp,
    const bool derivatives
) const
{
    // The derivatives of a deformable pair involve the master faces'
    // unknowns too: they are central differences of the whole face's
    // evaluation [C13], not asked of the surface ('derivatives' unused)
    mp = masterPoint();
    const contactSide& sl = slave_;
    const contactSide& ms = master_;
    const labelList& cand = candidates_[i];
    const point& as = sl.a[i];
    const point& bs = sl.b[i];

    DynamicList<faceOverlap> overlaps(8);
    if (sl.Xv.size())
    {
        // [C11b] polygons
        const point xs(sl.X[i] + sl.D[i]);
        for (const label m : cand)
        {
            scalar area;
            scalar projected;
            scalar g;
            if
            (
                polygonOverlap::overlap
                (
                    sl.v[i], xs, sl.n[i],
                    ms.v[m], ms.X[m] + ms.D[m], ms.n[m],
                    area, projected, g
                )
             && mag(g) <= searchDistance_
            )
            {
                overlaps.append({m, area, projected, g});
            }
        }
    }
    else
    {
        // [C11] segments
        for (const label m : cand)
        {
            const vector& nm = ms.n[m];
            if ((sl.n[i] & nm) >= 0)
            {
                continue;
            }
            const vector e(ms.b[m] - ms.a[m]);
            const scalar Lm = mag(e);
            if (Lm < VSMALL)
            {
                continue;
            }
            const vector tau(e/Lm);
            const scalar xa = (as - ms.a[m]) & tau;
            const scalar xb = (bs - ms.a[m]) & tau;
            const scalar l0 = max(min(xa, xb), scalar(0));
            const scalar l1 = min(max(xa, xb), Lm);
            if (l1 <= l0)
            {
                continue;
            }
            // the gap is linear over the overlap: its midpoint value is its
            // mean
            const scalar xc = 0.5*(l0 + l1);
            const scalar lambda =
                mag(xb - xa) > VSMALL ? (xc - xa)/(xb - xa) : 0.5;
            const point xs(as + lambda*(bs - as));
            const point xm(ms.a[m] + xc*tau);
            const scalar g = (xs - xm) & nm;
            if (mag(g) > searchDistance_)
            {
                continue;
            }
            overlaps.append({m, l1 - l0, mag(xb - xa), g});
        }
    }

    scalar total = 0;
    for (const faceOverlap& o : overlaps)
    {
        total += o.length;
    }
    if (total <= 0)
    {
        return false;
    }

    // [C10] weighted gap, normal, coverage; [C12] the master's motion
    mp.inReach = true;
    mp.masters.setSize(overlaps.size());
    mp.weights.setSize(overlaps.size());
    mp.gap = 0;
    vector n(Zero);
    scalar projected = 0;
    forAll(overlaps, j)
    {
        const faceOverlap& o = overlaps[j];
        const scalar w = o.length/total;
        mp.masters[j] = o.master;
        mp.weights[j] = w;
        mp.gap += w*o.gap;
        n += w*ms.n[o.master];
        projected += w*o.projected;
        mp.motion += w*(ms.D[o.master] - ms.Dold[o.master]);
    }
    mp.n = n/max(mag(n), VSMALL);
    mp.coverage = min(total/max(projected, VSMALL), scalar(1));
    return true;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "polygonOverlap.H"
#include "vector2D.H"
#include "DynamicList.H"
#include "ListOps.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polygonOverlap::area2D
(
    const UList<vector2D>& p,
    vector2D& centroid
)
{
    // shoelace formula about the first vertex (round-off of far polygons)
    scalar a2 = 0;
    vector2D c(Zero);
    const label n = p.size();
    for (label k = 1; k + 1 < n; ++k)
    {
        const vector2D e1(p[k] - p[0]);
        const vector2D e2(p[k + 1] - p[0]);
        const scalar t = e1.x()*e2.y() - e1.y()*e2.x();
        a2 += t;
        c += t*(e1 + e2)/3;
    }
    centroid = p.size() ? p[0] : vector2D(Zero);
    if (mag(a2) > VSMALL)
    {
        centroid += c/a2;
    }
    return 0.5*a2;
}


void Foam::polygonOverlap::clip
(
    const UList<vector2D>& s,
    const UList<vector2D>& c,
    DynamicList<vector2D>& out
)
{
    DynamicList<vector2D> in(s);
    out = s;
    forAll(c, e)
    {
        const vector2D& p0 = c[e];
        const vector2D& p1 = c[c.fcIndex(e)];
        const vector2D t(p1 - p0);
        // inside: to the left of the clip edge
        auto side = [&](const vector2D& q)
        {
            return t.x()*(q.y() - p0.y()) - t.y()*(q.x() - p0.x());
        };
        in.transfer(out);
        out.clear();
        forAll(in, k)
        {
            const vector2D& a = in[k];
            const vector2D& b = in[in.fcIndex(k)];
            const scalar sa = side(a);
            const scalar sb = side(b);
            if (sa >= 0)
            {
                out.append(a);
            }
            if ((sa >= 0) != (sb >= 0))
            {
                out.append(a + (sa/(sa - sb))*(b - a));
            }
        }
        if (out.size() < 3)
        {
            out.clear();
            return;
        }
    }
}


bool Foam::polygonOverlap::overlap
(
    const UList<point>& s,
    const point& xs,
    const vector& ns,
    const UList<point>& m,
    const point& xm,
    const vector& nm,
    scalar& area,
    scalar& projected,
    scalar& gap
)
{
    area = 0;
    projected = 0;
    gap = GREAT;
    const scalar cosine = ns & nm;
    if (m.size() < 3 || s.size() < 3 || cosine > -SMALL)
    {
        return false;
    }

    // plane coordinates on the master face: t1 along its first edge (a
    // smooth function of the vertices, for the derivatives [C13])
    vector t1(m[1] - m[0]);
    t1 -= (t1 & nm)*nm;
    t1 /= max(mag(t1), VSMALL);
    const vector t2(nm ^ t1);
    auto project = [&](const UList<point>& p, List<vector2D>& q)
    {
        q.setSize(p.size());
        forAll(p, k)
        {
            const vector d(p[k] - xm);
            q[k] = vector2D(d & t1, d & t2);
        }
        vector2D c;
        if (area2D(q, c) < 0)
        {
            // counter-clockwise about nm
            reverse(q);
        }
    };
    List<vector2D> sp;
    List<vector2D> mp;
    project(s, sp);
    project(m, mp);

    DynamicList<vector2D> ov(8);
    clip(sp, mp, ov);
    if (ov.size() < 3)
    {
        return false;
    }
    vector2D c;
    area = area2D(ov, c);
    if (area <= 0)
    {
        area = 0;
        return false;
    }
    vector2D cs;
    projected = mag(area2D(sp, cs));

    // the slave plane's point above the centroid along nm
    const point pc(xm + c.x()*t1 + c.y()*t2);
    gap = ((xs - pc) & ns)/cosine;
    return true;
}


// ************************************************************************* //

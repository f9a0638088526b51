/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The deformable master surface of the slave-face loop
    (overlapContactSurface, doc/theory.md [C10]-[C12]) on hand-made sides,
    against the overlap lengths and areas worked out by hand, with the
    candidates of its search (findCandidates: the 2-D sweep, the 3-D
    octree):
      - 2-D: a slave segment of length 1.5 over two master segments, of
        which it covers 0.5 and 1: weights 1/3 and 2/3, the gap, the
        normal, the master's motion as the weighted mean of the two master
        faces' displacement increments, coverage 1; a slave segment half
        over the end of the master surface: coverage 0.5, one master;
        a gap beyond the search distance and a slave facing the same way
        as the master: out of reach;
      - 3-D: a unit slave square over two master squares, half on each:
        weights 1/2, coverage 1, the gap.
    Tolerance 1e-12 absolute on quantities of order 1 (round-off).

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "overlapContactSurface.H"

using namespace Foam;

namespace
{

//- A 2-D side of straight segments [a_i, b_i] with normal n (undeformed,
//  D = displacement now, Dold = 0)
contactSide segments
(
    const List<point>& a,
    const List<point>& b,
    const vector& n,
    const List<vector>& D
)
{
    contactSide s;
    const label N = a.size();
    s.a = vectorField(a);
    s.b = vectorField(b);
    s.X = 0.5*(s.a + s.b);
    s.D = vectorField(D);
    s.Dold = vectorField(N, Zero);
    s.n = vectorField(N, n);
    s.area = mag(s.b - s.a);
    return s;
}

//- A 3-D side of one polygon per face, normal n
contactSide polygons(const List<pointField>& v, const vector& n)
{
    contactSide s;
    const label N = v.size();
    s.Xv = v;
    s.v = v;
    s.X.setSize(N);
    forAll(v, i)
    {
        s.X[i] = sum(v[i])/v[i].size();
    }
    s.D = vectorField(N, Zero);
    s.Dold = s.D;
    s.a = s.X;
    s.b = s.X;
    s.n = vectorField(N, n);
    s.area = scalarField(N, 1);
    return s;
}

pointField square(const scalar x0, const scalar x1, const scalar z)
{
    pointField p(4);
    p[0] = point(x0, 0, z);
    p[1] = point(x1, 0, z);
    p[2] = point(x1, 1, z);
    p[3] = point(x0, 1, z);
    return p;
}

} // End anonymous namespace


int main()
{
    const scalar tol = 1e-12;
    const scalar g = 2e-3;
    const scalar searchDistance = 0.01;

    Info<< "2-D: a slave segment over two master segments" << endl;
    {
        // master faces [0, 1] and [1, 3] on y = 0, facing +y, moved by
        // 0.1 and 0.4 along x over the step
        const contactSide ms = segments
        (
            {point(0, 0, 0), point(1, 0, 0)},
            {point(1, 0, 0), point(3, 0, 0)},
            vector(0, 1, 0),
            {vector(0.1, 0, 0), vector(0.4, 0, 0)}
        );
        // slave faces facing -y at y = g: [0.5, 2] (over both), [2.5, 3.5]
        // (half past the end), [0.2, 0.8] at y = 2 searchDistance (too far)
        const contactSide sl = segments
        (
            {point(0.5, g, 0), point(2.5, g, 0), point(0.2, 2*searchDistance, 0)},
            {point(2, g, 0), point(3.5, g, 0), point(0.8, 2*searchDistance, 0)},
            vector(0, -1, 0),
            {Zero, Zero, Zero}
        );
        // the candidates by the sweep [C11]: the masters each face's
        // interval meets
        labelListList cand;
        overlapContactSurface::findCandidates(sl, ms, searchDistance, 0, cand);
        unitTest::checkTrue
        (
            "sweep candidates {0 1} {1} {0}",
            cand.size() == 3 && cand[0] == labelList({0, 1})
         && cand[1] == labelList({1}) && cand[2] == labelList({0})
        );
        const overlapContactSurface master(sl, ms, cand, searchDistance);

        masterPoint mp;
        unitTest::checkTrue("face over two masters in reach", master.masterPointOf(0, mp));
        unitTest::checkTrue("two masters", mp.masters.size() == 2);
        unitTest::checkAbs("weight of master 0 (0.5 of 1.5)", mp.weights[0], 1.0/3, tol);
        unitTest::checkAbs("weight of master 1 (1 of 1.5)", mp.weights[1], 2.0/3, tol);
        unitTest::checkAbs("gap", mp.gap, g, tol);
        unitTest::checkAbs("normal y", mp.n.y(), 1, tol);
        unitTest::checkAbs
        (
            "master motion = 1/3 0.1 + 2/3 0.4", mp.motion.x(), 0.3, tol
        );
        unitTest::checkAbs("coverage", mp.coverage, 1, tol);
        unitTest::checkTrue("surface is deformable", master.deformable());

        unitTest::checkTrue("face half past the end in reach", master.masterPointOf(1, mp));
        unitTest::checkAbs("coverage half past the end", mp.coverage, 0.5, tol);
        unitTest::checkTrue("one master", mp.masters.size() == 1 && mp.masters[0] == 1);
        unitTest::checkAbs("its motion", mp.motion.x(), 0.4, tol);

        unitTest::checkTrue("face beyond the search distance out of reach", !master.masterPointOf(2, mp) && !mp.inReach);

        // the same slave faces turned to face +y: no candidate faces them
        contactSide turned(sl);
        turned.n = -turned.n;
        const overlapContactSurface same(turned, ms, cand, searchDistance);
        unitTest::checkTrue("surfaces facing the same way: out of reach", !same.masterPointOf(0, mp));
    }

    Info<< "3-D: a slave square over two master squares" << endl;
    {
        const contactSide ms = polygons
        (
            {square(0, 1, 0), square(1, 2, 0)}, vector(0, 0, 1)
        );
        const contactSide sl = polygons({square(0.5, 1.5, g)}, vector(0, 0, -1));
        // the candidates by the octree of the master polygons [C11b]
        labelListList cand;
        overlapContactSurface::findCandidates(sl, ms, searchDistance, 0, cand);
        unitTest::checkTrue
        (
            "octree candidates {0 1}",
            cand.size() == 1 && cand[0] == labelList({0, 1})
        );
        const overlapContactSurface master(sl, ms, cand, searchDistance);

        masterPoint mp;
        unitTest::checkTrue("square in reach", master.masterPointOf(0, mp));
        unitTest::checkTrue("two masters", mp.masters.size() == 2);
        unitTest::checkAbs("weight 0", mp.weights[0], 0.5, tol);
        unitTest::checkAbs("weight 1", mp.weights[1], 0.5, tol);
        unitTest::checkAbs("gap", mp.gap, g, tol);
        unitTest::checkAbs("coverage", mp.coverage, 1, tol);
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Rigid obstacles (src/rigidObstacles):
      - plane and cylinder (side inside and outside): nearest point, normal
        and gap against the analytic values, 1e-12 absolute (lengths of
        order 0.03 m to 1 m, so about 1e3 ulp of slack);
      - rigid motion: the gap of a fixed point against a translating
        plane and a rotating cylinder, and materialDisplacement, against
        the closed-form motion (1e-12);
      - triSurface: an extruded circle of radius R = 28.6 mm written as an
        ASCII STL of 720 facets in a temporary case. Gaps against R - r
        within the chordal error R(1 - Foam::cos(pi/720)) = 2.72e-7 m plus the
        rounding of STL's single-precision coordinates (2 R FLT_EPSILON =
        6.8e-9 m); normals against the radius within 1e-3 rad (the
        'smooth' normal), within the facet half-angle pi/720 for
        'nearest' and within the facet angle 2 pi/720 for 'face' (where p
        is a vertex the octree may report either facet);
        the hinted search gives bit-identical results to the octree;
        the search record (rigidObstacle::nearest with obstacleSearch,
        doc/theory.md [C2c]) gives bit-identical results to the octree
        along a path of short and long moves, keeps a miss without a
        search and uses the extended reach;
        flipNormals; maxDistance; a quarter circle continued by its
        tangent line in one long facet (the pear die's flank): the normal
        along the line within 1e-3 rad of the line's;
      - input errors (FatalIOError caught as Foam::error): missing file
        (message names the full expected path), unknown type, radius <= 0,
        zero normal, zero axis.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "dictionaryTestTools.H"
#include "rigidObstacle.H"
#include "triSurfaceObstacle.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"
#include <cfloat>
#include <fstream>
#include <iomanip>

using namespace Foam;
using unitTest::dictOf;
using unitTest::fatalMessage;
using namespace Foam::constant::mathematical;

namespace
{

autoPtr<rigidObstacle> obstacle(const std::string& s, const fileName& dir = "")
{
    return rigidObstacle::New(dictOf(s), dir);
}

//- Angle between two vectors [rad]
scalar angle(const vector& a, const vector& b)
{
    return Foam::atan2(mag(a ^ b), a & b);
}


//- ASCII STL of the polyline pts (x-y plane) extruded over [z0, z1];
//  triangle normals to the left of the direction of travel
void writeStripSTL
(
    const fileName& file,
    const List<point>& pts,
    const scalar z0,
    const scalar z1
)
{
    std::ofstream os(file.c_str());
    os << std::setprecision(17) << "solid strip\n";
    auto tri = [&](const point& a, const point& b, const point& c)
    {
        vector n = (b - a) ^ (c - a);
        n /= mag(n);
        os << " facet normal " << n.x() << ' ' << n.y() << ' ' << n.z()
           << "\n  outer loop\n";
        for (const point& p : {a, b, c})
        {
            os << "   vertex " << p.x() << ' ' << p.y() << ' ' << p.z()
               << '\n';
        }
        os << "  endloop\n endfacet\n";
    };
    for (label i = 0; i < pts.size() - 1; ++i)
    {
        const point a(pts[i].x(), pts[i].y(), z0);
        const point b(pts[i + 1].x(), pts[i + 1].y(), z0);
        const point c(pts[i + 1].x(), pts[i + 1].y(), z1);
        const point d(pts[i].x(), pts[i].y(), z1);
        tri(a, c, b);
        tri(a, d, c);
    }
    os << "endsolid strip\n";
}


//- Points of an arc of radius R about the origin, angles t0 to t1, n facets
List<point> arcPoints(const scalar R, const scalar t0, const scalar t1, label n)
{
    List<point> pts(n + 1);
    forAll(pts, i)
    {
        const scalar t = t0 + (t1 - t0)*i/n;
        pts[i] = point(R*Foam::cos(t), R*Foam::sin(t), 0);
    }
    return pts;
}

} // End anonymous namespace


int main()
{
    const scalar tol = 1e-12;

    Info<< "Plane" << endl;
    {
        // Normal (1 2 2)/3 through (1 2 3); x = origin + 0.3 n + tangent
        auto pl = obstacle("type plane; point (1 2 3); normal (2 4 4);");
        const vector n(1.0/3, 2.0/3, 2.0/3);
        const vector tang(2.0/3, -2.0/3, 1.0/3);
        const point x = point(1, 2, 3) + 0.3*n + 0.7*tang;
        obstaclePoint cp;
        unitTest::checkTrue("plane: found", pl->nearest(x, 0, 1, cp));
        unitTest::checkAbs("plane: gap", cp.gap, 0.3, tol);
        unitTest::checkAbs
        (
            "plane: nearest point", mag(cp.p - (point(1, 2, 3) + 0.7*tang)),
            0, tol
        );
        unitTest::checkAbs("plane: normal", mag(cp.n - n), 0, tol);
        unitTest::checkTrue("plane: hint -1", cp.hint == -1);

        const point y = point(1, 2, 3) - 0.2*n;
        pl->nearest(y, 0, 1, cp);
        unitTest::checkAbs("plane: penetration gap", cp.gap, -0.2, tol);

        obstaclePoint untouched;
        untouched.gap = 123;
        unitTest::checkTrue
        (
            "plane: beyond maxDistance returns false",
            !pl->nearest(x, 0, 0.29, untouched)
        );
        unitTest::checkTrue("plane: cp untouched", untouched.gap == 123);
    }

    Info<< "Cylinder" << endl;
    {
        const scalar R = 0.0286;
        const point x(0.01, 0.02, 0.5);
        const scalar rho = Foam::sqrt(sqr(0.01) + sqr(0.02));
        const vector er(0.01/rho, 0.02/rho, 0);
        const point pExact(R*er.x(), R*er.y(), 0.5);

        auto die = obstacle
        (
            "type cylinder; axisPoint (0 0 -1); axis (0 0 3); radius 0.0286;"
            "side inside;"
        );
        obstaclePoint cp;
        unitTest::checkTrue("inside: found", die->nearest(x, 0, 1, cp));
        unitTest::checkAbs("inside: gap R - rho", cp.gap, R - rho, tol);
        unitTest::checkAbs("inside: point", mag(cp.p - pExact), 0, tol);
        unitTest::checkAbs("inside: normal -e_r", mag(cp.n + er), 0, tol);

        auto punch = obstacle
        (
            "type cylinder; axisPoint (0 0 0); axis (0 0 1); radius 0.0286;"
            "side outside;"
        );
        punch->nearest(x, 0, 1, cp);
        unitTest::checkAbs("outside: gap rho - R", cp.gap, rho - R, tol);
        unitTest::checkAbs("outside: point", mag(cp.p - pExact), 0, tol);
        unitTest::checkAbs("outside: normal e_r", mag(cp.n - er), 0, tol);

        // Tilted axis (1 1 0)/sqrt2 through (1 0 0): x = a + 2 e + 0.5 f
        // with f = (0 0 1) normal to the axis
        auto tilted = obstacle
        (
            "type cylinder; axisPoint (1 0 0); axis (1 1 0); radius 0.3;"
            "side outside;"
        );
        const vector e(1/Foam::sqrt(2.0), 1/Foam::sqrt(2.0), 0);
        const point xt = point(1, 0, 0) + 2*e + vector(0, 0, 0.5);
        tilted->nearest(xt, 0, 1, cp);
        unitTest::checkAbs("tilted: gap", cp.gap, 0.2, tol);
        unitTest::checkAbs
        (
            "tilted: point",
            mag(cp.p - (point(1, 0, 0) + 2*e + vector(0, 0, 0.3))), 0, tol
        );
        unitTest::checkAbs
        (
            "tilted: normal", mag(cp.n - vector(0, 0, 1)), 0, tol
        );

        unitTest::checkTrue
        (
            "cylinder: beyond maxDistance returns false",
            !die->nearest(x, 0, 0.5*(R - rho), cp)
        );
    }

    Info<< "Rigid motion" << endl;
    {
        // Plane y = 0 moving up: T(t) = (0 0.1 0) t
        auto pl = obstacle
        (
            "type plane; point (0 0 0); normal (0 1 0);"
            "translation table ((0 (0 0 0)) (1 (0 0.1 0)));"
        );
        const point x(0.3, 0.08, 0.1);
        obstaclePoint cp;
        pl->nearest(x, 0.5, 1, cp);
        unitTest::checkAbs("translation: gap at t = 0.5", cp.gap, 0.03, tol);
        unitTest::checkAbs
        (
            "translation: point at t = 0.5",
            mag(cp.p - point(0.3, 0.05, 0.1)), 0, tol
        );
        pl->nearest(x, 1, 1, cp);
        unitTest::checkAbs("translation: gap at t = 1", cp.gap, -0.02, tol);
        unitTest::checkAbs
        (
            "translation: materialDisplacement",
            mag(pl->materialDisplacement(x, 0.25, 0.75) - vector(0, 0.05, 0)),
            0, tol
        );

        // Roller of radius 0.2 about (1 0 z), rotating about the z axis
        // through the origin: angle(t) = (pi/2) t, so at t = 1 its axis
        // passes through (0 1 0); right-handed: +x turns to +y
        auto roller = obstacle
        (
            "type cylinder; axisPoint (1 0 0); axis (0 0 1); radius 0.2;"
            "side outside; rotationAxis (0 0 2); rotationOrigin (0 0 0);"
            "rotationAngle table ((0 0) (1 1.5707963267948966));"
        );
        const point y(0, 1.5, 0.2);
        roller->nearest(y, 1, 10, cp);
        unitTest::checkAbs("rotation: gap at t = 1", cp.gap, 0.3, tol);
        unitTest::checkAbs
        (
            "rotation: point at t = 1", mag(cp.p - point(0, 1.2, 0.2)), 0, tol
        );
        unitTest::checkAbs
        (
            "rotation: normal at t = 1", mag(cp.n - vector(0, 1, 0)), 0, tol
        );
        roller->nearest(y, 0, 10, cp);
        unitTest::checkAbs
        (
            "rotation: gap at t = 0", cp.gap, Foam::sqrt(1 + 2.25) - 0.2, tol
        );

        // Material point at p = (1 0 0) at t1 = 1 was at angle
        // -(pi/2)(1 - 0.5) = -pi/4 relative to it at t0 = 0.5
        const point p(1, 0, 0);
        const vector dExact =
            p - point(Foam::cos(-0.25*pi), Foam::sin(-0.25*pi), 0);
        unitTest::checkAbs
        (
            "rotation: materialDisplacement",
            mag(roller->materialDisplacement(p, 0.5, 1) - dExact), 0, tol
        );
        unitTest::checkTrue("rotation: moving()", roller->moving());

        // Round trip of the frame maps
        const point q(0.3, -0.2, 0.7);
        unitTest::checkAbs
        (
            "rotation: toCurrent(toInitial(q))",
            mag(roller->toCurrent(roller->toInitial(q, 0.3), 0.3) - q), 0, tol
        );
    }

    // Temporary case with the circle surface
    const fileName caseDir
    (
        "/tmp/Test-rigidObstacles-" + Foam::name(label(pid()))
    );
    mkDir(caseDir/"constant"/"triSurface");

    const scalar R = 0.0286;
    const label nFacets = 720;
    // Counter-clockwise: the inside (the free side) is on the left
    writeStripSTL
    (
        caseDir/"constant"/"triSurface"/"circle.stl",
        arcPoints(R, 0, twoPi, nFacets), -1e-3, 2e-3
    );
    const scalar chordal = R*(1 - Foam::cos(pi/nFacets));
    const scalar gapTol = chordal + 2*R*FLT_EPSILON;

    Info<< "triSurface: extruded circle, " << nFacets << " facets" << endl;
    {
        auto die = obstacle
        (
            "type triSurface; file \"circle.stl\";", caseDir
        );
        auto faceDie = obstacle
        (
            "type triSurface; file \"circle.stl\"; normal face;", caseDir
        );
        auto nearestDie = obstacle
        (
            "type triSurface; file \"circle.stl\"; normal nearest;", caseDir
        );
        const auto& triDie =
            dynamic_cast<const rigidObstacles::triSurfaceObstacle&>(*die);

        scalar maxGapErr = 0, maxNormalErr = 0;
        scalar maxFaceNormalErr = 0, maxNearestNormalErr = 0;
        scalar maxHintDiff = 0;
        bool allFound = true, hintsValid = true;

        // Radii inside and outside (penetration), angles off the facet
        // centres and on facet vertices
        const scalar radii[] = {0.95*R, 0.999*R, R, 1.0001*R, 1.02*R};
        for (const scalar r : radii)
        {
            for (label k = 0; k < 97; ++k)
            {
                const scalar theta = 0.0123 + k*twoPi/97;
                const point x(r*Foam::cos(theta), r*Foam::sin(theta), 5e-4);
                const vector inward(-Foam::cos(theta), -Foam::sin(theta), 0);

                obstaclePoint cp, cpf, cpn;
                allFound = die->nearest(x, 0, 0.01, cp) && allFound;
                faceDie->nearest(x, 0, 0.01, cpf);
                nearestDie->nearest(x, 0, 0.01, cpn);

                maxGapErr = max(maxGapErr, mag(cp.gap - (R - r)));
                maxNormalErr = max(maxNormalErr, angle(cp.n, inward));
                maxFaceNormalErr = max(maxFaceNormalErr, angle(cpf.n, inward));
                maxNearestNormalErr =
                    max(maxNearestNormalErr, angle(cpn.n, inward));

                // Move by a tenth of a facet and search again with the hint
                const scalar theta2 = theta + 0.1*twoPi/nFacets;
                const point x2(r*Foam::cos(theta2), r*Foam::sin(theta2), 5e-4);
                obstaclePoint cpHint, cpFull;
                die->nearest(x2, 0, 0.01, cpHint, cp.hint);
                triDie.nearestFullSearch(x2, 0.01, cpFull);
                hintsValid = hintsValid && cpHint.hint == cpFull.hint;
                maxHintDiff = max
                (
                    maxHintDiff,
                    mag(cpHint.p - cpFull.p) + mag(cpHint.n - cpFull.n)
                  + mag(cpHint.gap - cpFull.gap)
                );
            }
        }

        unitTest::checkTrue("all points found", allFound);
        unitTest::checkBelow("smooth: max |gap - (R - r)|", maxGapErr, gapTol);
        unitTest::checkBelow("smooth: max normal angle", maxNormalErr, 1e-3);
        unitTest::checkBelow
        (
            "face: max normal angle (<= 2 pi/720: at a vertex either facet)",
            maxFaceNormalErr, twoPi/nFacets
        );
        unitTest::checkBelow
        (
            "nearest: max normal angle (<= pi/720)",
            maxNearestNormalErr, pi/nFacets + 1e-6
        );
        unitTest::checkTrue("hinted and octree: same triangle", hintsValid);
        unitTest::checkAbs("hinted vs octree: difference", maxHintDiff, 0, 0);

        // A point of a facet's corner region outside the die: the normal of
        // 'nearest' turns with (x - p) (exact distance to the facets)
        {
            const scalar th = twoPi*10/nFacets;
            const point x(1.01*R*Foam::cos(th), 1.01*R*Foam::sin(th), 5e-4);
            obstaclePoint cp;
            nearestDie->nearest(x, 0, 0.01, cp);
            unitTest::checkAbs
            (
                "nearest at a vertex: gap = -(r - R)", cp.gap, -0.01*R,
                2*R*FLT_EPSILON
            );
        }

        obstaclePoint untouched;
        untouched.gap = 123;
        unitTest::checkTrue
        (
            "beyond maxDistance returns false",
            !die->nearest(point(0.5*R, 0, 5e-4), 0, 0.4*R, untouched)
         && untouched.gap == 123
        );
        unitTest::checkTrue
        (
            "beyond maxDistance with a hint returns false",
            !die->nearest(point(0.5*R, 0, 5e-4), 0, 0.4*R, untouched, 0)
         && untouched.gap == 123
        );

        auto punch = obstacle
        (
            "type triSurface; file \"circle.stl\"; flipNormals yes;", caseDir
        );
        const point x(1.01*R*Foam::cos(0.3), 1.01*R*Foam::sin(0.3), 0);
        obstaclePoint cp;
        punch->nearest(x, 0, 0.01, cp);
        unitTest::checkAbs("flipNormals: gap r - R", cp.gap, 0.01*R, gapTol);
        unitTest::checkBelow
        (
            "flipNormals: normal angle to e_r",
            angle(cp.n, vector(Foam::cos(0.3), Foam::sin(0.3), 0)), 1e-3
        );

        // Moving surface: the circle translated by (0 -1 0) mm
        auto moved = obstacle
        (
            "type triSurface; file \"circle.stl\";"
            "translation constant (0 -0.001 0);", caseDir
        );
        moved->nearest(point(0, -0.5*R, 0), 0, 0.1, cp);
        unitTest::checkAbs
        (
            "translated surface: gap R - |x - c|", cp.gap, 0.5*R + 0.001,
            gapTol
        );

        // Search record [C2c]: a point circling inside the die in steps of
        // 0.01 to 3.3 facets, re-projected while it stays within the
        // refresh distance of its last full search: 0.2 facet widths (most
        // steps are re-projections) and 5 facet widths (the long steps are
        // walks over several facets); every result bit-identical to the
        // octree's
        {
            const scalar facet = twoPi*R/nFacets;
            const scalar refresh = 0.2*facet;
            for (const scalar refreshFacets : {0.2, 5.0})
            {
                obstacleSearch record;
                die->resetSearchCounts();
                scalar maxDiff = 0;
                bool sameFound = true;
                scalar theta = 0.0123;
                for (label k = 0; k < 400; ++k)
                {
                    theta += (k % 7 == 6 ? 3.3 : 0.01)*twoPi/nFacets;
                    const scalar r = (k % 2 ? 0.999 : 1.0002)*R;
                    const point x
                    (
                        r*Foam::cos(theta), r*Foam::sin(theta), 5e-4
                    );
                    obstaclePoint cpRec, cpFull;
                    const bool found = die->nearest
                    (
                        x, 0, 0.01, refreshFacets*facet, cpRec, record
                    );
                    sameFound =
                        sameFound
                     && found == triDie.nearestFullSearch(x, 0.01, cpFull);
                    maxDiff = max
                    (
                        maxDiff,
                        mag(cpRec.p - cpFull.p) + mag(cpRec.n - cpFull.n)
                      + mag(cpRec.gap - cpFull.gap)
                    );
                }
                const labelPair n = die->searchCounts();
                const word tag("record (" + Foam::name(refreshFacets) + "): ");
                Info<< "    " << tag << n.first() << " full searches, "
                    << n.second() << " re-projections" << endl;
                unitTest::checkTrue(tag + "found as the octree", sameFound);
                unitTest::checkAbs
                (
                    tag + "difference to the octree", maxDiff, 0, 0
                );
                unitTest::checkTrue
                (
                    tag + "mostly re-projections",
                    n.second() > 4*n.first() && n.first() > 0
                );
            }

            // Reach: nothing within maxDistance + refresh stays a miss
            // without a search while the point moves less than refresh; a
            // point just beyond maxDistance becomes in reach by moving
            // (extended reach of the recorded search)
            const scalar maxDist = 0.4*R;
            obstacleSearch far;
            die->resetSearchCounts();
            obstaclePoint untouched;
            untouched.gap = 123;
            const bool miss1 = !die->nearest
            (
                point(0.5*R, 0, 5e-4), 0, maxDist, refresh, untouched, far
            );
            const bool miss2 = !die->nearest
            (
                point(0.5*R + 0.5*refresh, 0, 5e-4), 0, maxDist, refresh,
                untouched, far
            );
            unitTest::checkTrue
            (
                "record: a miss stays a miss without a search",
                miss1 && miss2 && untouched.gap == 123
             && die->searchCounts() == labelPair(1, 1)
            );

            obstacleSearch edge;
            const scalar d0 = maxDist + 0.5*refresh;
            obstaclePoint cpEdge;
            const bool beyond = !die->nearest
            (
                point(R - d0, 0, 5e-4), 0, maxDist, refresh, cpEdge, edge
            );
            const bool inReach = die->nearest
            (
                point(R - d0 + 0.6*refresh, 0, 5e-4), 0, maxDist, refresh,
                cpEdge, edge
            );
            unitTest::checkTrue
            (
                "record: beyond maxDistance, then in reach after a short move",
                beyond && inReach
            );
            unitTest::checkAbs
            (
                "record: gap after the short move", cpEdge.gap,
                d0 - 0.6*refresh, gapTol
            );
        }
    }

    Info<< "triSurface: arc and tangent line (smooth normal at the join)"
        << endl;
    {
        // Quarter circle R from -90 to 0 deg in 90 facets, then the tangent
        // line x = R up to y = 0.035 in one facet (the pear die's flank);
        // the inside is on the left
        List<point> pts = arcPoints(R, -0.5*pi, 0, 90);
        pts.append(point(R, 0.035, 0));
        writeStripSTL
        (
            caseDir/"constant"/"triSurface"/"flank.stl", pts, -1e-3, 2e-3
        );
        auto die = obstacle("type triSurface; file \"flank.stl\";", caseDir);

        // Along the flank, at 10 um penetration and separation: normal
        // exactly (-1 0 0) up to the area-weighted vertex normal at the
        // tangent point, (l_arc/L)(h/2) = 1e-4 rad with l_arc = 0.5 mm,
        // h = 1 deg; bound 1e-3 rad. On the arc (0 to -81 deg): the
        // radius, 1e-3 rad.
        scalar maxFlank = 0, maxArc = 0, maxFlankGap = 0;
        for (label k = 0; k < 50; ++k)
        {
            const scalar y = 0.035*(k + 0.5)/50;
            for (const scalar dx : {-1e-5, 1e-5})
            {
                obstaclePoint cp;
                die->nearest(point(R + dx, y, 0), 0, 0.01, cp);
                maxFlank = max(maxFlank, angle(cp.n, vector(-1, 0, 0)));
                maxFlankGap = max(maxFlankGap, mag(cp.gap + dx));
            }
            // Away from the open end at -90 deg, where the vertex normal
            // can only be the end facet's
            const scalar th = -0.45*pi*(k + 0.5)/50;
            obstaclePoint cp;
            die->nearest
            (
                point(1.0003*R*Foam::cos(th), 1.0003*R*Foam::sin(th), 0),
                0, 0.01, cp
            );
            maxArc = max
            (
                maxArc,
                angle(cp.n, -vector(Foam::cos(th), Foam::sin(th), 0))
            );
        }
        unitTest::checkBelow("flank: max normal angle", maxFlank, 1e-3);
        unitTest::checkBelow
        (
            "flank: max |gap - (R - x)| (STL float rounding)",
            maxFlankGap, 2*R*FLT_EPSILON
        );
        unitTest::checkBelow("arc: max normal angle", maxArc, 1e-3);
    }

    Info<< "Input errors" << endl;
    {
        FatalError.throwExceptions();
        FatalIOError.throwExceptions();

        const std::string missing = fatalMessage
        (
            [&]() { obstacle("type triSurface; file \"die.stl\";", caseDir); }
        );
        const std::string expectedPath =
            caseDir/"constant"/"triSurface"/"die.stl";
        unitTest::checkTrue
        (
            "missing file: error naming keyword and full path",
            missing.find(expectedPath) != std::string::npos
         && missing.find("keyword 'file'") != std::string::npos
        );

        std::ofstream(caseDir/"constant"/"triSurface"/"empty.stl")
            << "solid empty\nendsolid empty\n";
        const std::string empty = fatalMessage
        (
            [&]() { obstacle("type triSurface; file \"empty.stl\";", caseDir); }
        );
        unitTest::checkTrue("empty file: error", !empty.empty());

        unitTest::checkTrue
        (
            "unknown type: error",
            fatalMessage([]() { obstacle("type sphere;"); })
           .find("unknown rigid obstacle") != std::string::npos
        );
        unitTest::checkTrue
        (
            "radius <= 0: error",
            fatalMessage
            (
                []()
                {
                    obstacle
                    (
                        "type cylinder; axisPoint (0 0 0); axis (0 0 1);"
                        "radius 0; side inside;"
                    );
                }
            ).find("keyword 'radius'") != std::string::npos
        );
        unitTest::checkTrue
        (
            "zero normal: error",
            fatalMessage
            (
                []() { obstacle("type plane; point (0 0 0); normal (0 0 0);"); }
            ).find("keyword 'normal'") != std::string::npos
        );
        unitTest::checkTrue
        (
            "zero axis: error",
            fatalMessage
            (
                []()
                {
                    obstacle
                    (
                        "type cylinder; axisPoint (0 0 0); axis (0 0 0);"
                        "radius 1; side inside;"
                    );
                }
            ).find("keyword 'axis'") != std::string::npos
        );
        unitTest::checkTrue
        (
            "bad side: error",
            fatalMessage
            (
                []()
                {
                    obstacle
                    (
                        "type cylinder; axisPoint (0 0 0); axis (0 0 1);"
                        "radius 1; side both;"
                    );
                }
            ).find("keyword 'side'") != std::string::npos
        );

        FatalError.dontThrowExceptions();
        FatalIOError.dontThrowExceptions();
    }

    rmDir(caseDir);

    return unitTest::exitCode();
}


// ************************************************************************* //

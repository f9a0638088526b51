/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The exact die profile (profileCurve, rigid obstacle type 'profile',
    doc/theory.md [C8]) on the pear die of tutorials/pearShapedTube: a
    circle of radius R about the origin, the line tangent to it through
    the apex (0, H), a fillet of radius rf at the apex, mirrored about
    x = 0. Against the closed-form geometry (1e-12 m absolute, lengths of
    order 0.03 m):
      - gap, nearest point, normal (towards the free side) and curvature
        on the circle (inside and penetrating), on the flank, on the fillet
        and on the mirrored half; continuity of the normal across the
        circle-flank joint (a G1 joint);
      - a corner (two lines at a right angle): the normal bisects;
      - a clockwise arc (free side outside: a punch);
      - discretise(): the chordal error r (1 - cos(dtheta/2)) and the
        vertices on the circle;
      - the obstacle type 'profile' reading the profile from a file, and
        input errors (segments that do not join, a collinear arc, a bad
        freeSide, a mirror that does not end on x = 0, a missing file)
        as FatalIOErrors naming the keyword.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "dictionaryTestTools.H"
#include "rigidObstacle.H"
#include "profileCurve.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace Foam;
using unitTest::dictOf;
using unitTest::fatalMessage;
using namespace Foam::constant::mathematical;

namespace
{

// The pear die (tutorials/pearShapedTube/base/system/dieProfileDict)
const scalar R = 0.0286;
const scalar H = 0.05;
const scalar rf = 0.004;

vector2D tangentPoint()
{
    return vector2D(R*std::sqrt(H*H - R*R)/H, R*R/H);
}

vector2D filletCentre()
{
    return vector2D(0, H - rf*H/R);
}

vector2D filletFlankPoint()
{
    const vector2D T(tangentPoint());
    return vector2D(rf*T.x()/R, H - rf*(H - T.y())/R);
}

std::string v2(const vector2D& v)
{
    std::ostringstream os;
    os << std::setprecision(17) << '(' << v.x() << ' ' << v.y() << ')';
    return os.str();
}

//- The pear profile's entries
std::string pearEntries()
{
    const vector2D T(tangentPoint());
    const vector2D F(filletFlankPoint());
    const vector2D C(filletCentre());
    // mid points on the bisecting radii
    const scalar aT = std::atan2(T.y(), T.x());
    const scalar am = 0.5*(-0.5*pi + aT);
    const vector2D circleMid(R*std::cos(am), R*std::sin(am));
    const scalar aF = std::atan2(F.y() - C.y(), F.x() - C.x());
    const scalar af = 0.5*(aF + 0.5*pi);
    const vector2D filletMid(C + rf*vector2D(std::cos(af), std::sin(af)));
    const vector2D top(0, C.y() + rf);

    return
        "freeSide left; mirror yes; segments ("
        " arc { start (0 " + std::to_string(-R) + "); mid " + v2(circleMid)
      + "; end " + v2(T) + "; }"
        " line { start " + v2(T) + "; end " + v2(F) + "; }"
        " arc { start " + v2(F) + "; mid " + v2(filletMid) + "; end "
      + v2(top) + "; } );";
}

//- [C8], [C6] the obstacle's dn/dx, dp/dx and dgap/dx at the points ys
//  against central differences of its nearest point (step 1e-8 of the
//  profile's size; dn/dx checked scaled by 1e-2 m, a cell's size)
void checkDerivatives
(
    const std::string& what,
    const rigidObstacle& obstacle,
    std::initializer_list<point> ys
)
{
    const scalar h = 1e-10;
    for (const point& y : ys)
    {
        obstaclePoint c0;
        obstacle.nearest(y, 0, 10, c0);
        scalar errN = 0, errP = 0, errG = 0;
        for (direction j = 0; j < 3; ++j)
        {
            vector e(Zero);
            e[j] = h;
            obstaclePoint cp, cm;
            obstacle.nearest(y + e, 0, 10, cp);
            obstacle.nearest(y - e, 0, 10, cm);
            const vector dn((cp.n - cm.n)/(2*h));
            const vector dp((cp.p - cm.p)/(2*h));
            for (direction i = 0; i < 3; ++i)
            {
                errN = max(errN, 1e-2*mag(dn[i] - c0.dndx(i, j)));
                errP = max(errP, mag(dp[i] - c0.dpdx(i, j)));
            }
            errG = max(errG, mag((cp.gap - cm.gap)/(2*h) - c0.dgapdx[j]));
        }
        const std::string at(what + " derivatives at " + name(y) + ": ");
        unitTest::checkBelow(at + "dn/dx (x 1 cm)", errN, 1e-5);
        unitTest::checkBelow(at + "dp/dx", errP, 1e-5);
        unitTest::checkBelow(at + "dgap/dx", errG, 1e-5);
    }
}

} // End anonymous namespace


int main()
{
    using namespace unitTest;
    const scalar tol = 1e-12;

    const profileCurve pear(dictOf(pearEntries()));

    // Circle: a point at radius r, angle -45 deg
    {
        for (const scalar r : {0.028, 0.0287})
        {
            const scalar a = -0.25*pi;
            const vector2D x(r*std::cos(a), r*std::sin(a));
            const profileCurve::nearestPoint np(pear.nearest(x));
            const std::string tag =
                r < R ? "circle inside: " : "circle penetrating: ";
            checkAbs(tag + "gap R - r", (x - np.p) & np.n, R - r, tol);
            checkAbs(tag + "p on the circle", mag(np.p), R, tol);
            checkAbs
            (
                tag + "normal towards the centre",
                np.n & (-x/mag(x)), 1, tol
            );
            checkAbs(tag + "curvature 1/R", np.curvature, 1/R, 1e-9);
        }
    }

    // Flank: a point 0.2 mm inside, half way along the line
    const vector2D T(tangentPoint());
    const vector2D F(filletFlankPoint());
    {
        const vector2D t((F - T)/mag(F - T));
        const vector2D inward(-t.y(), t.x());
        const vector2D x(0.5*(T + F) + 2e-4*inward);
        const profileCurve::nearestPoint np(pear.nearest(x));
        checkAbs("flank: gap", (x - np.p) & np.n, 2e-4, tol);
        checkAbs("flank: normal", np.n & inward, 1, tol);
        checkAbs("flank: curvature 0", np.curvature, 0, tol);
    }

    // Fillet: a point 1 mm from its centre, 30 deg from +y
    {
        const vector2D C(filletCentre());
        const scalar a = 0.5*pi - pi/6;
        const vector2D x(C + 1e-3*vector2D(std::cos(a), std::sin(a)));
        const profileCurve::nearestPoint np(pear.nearest(x));
        checkAbs("fillet: gap rf - |x - C|", (x - np.p) & np.n, rf - 1e-3, tol);
        checkAbs("fillet: p on the fillet", mag(np.p - C), rf, tol);
        checkAbs("fillet: curvature 1/rf", np.curvature, 1/rf, 1e-9);

        // The mirror image of the point has the mirrored answer
        const vector2D xm(-x.x(), x.y());
        const profileCurve::nearestPoint nm(pear.nearest(xm));
        checkAbs("mirror: gap", (xm - nm.p) & nm.n, rf - 1e-3, tol);
        checkAbs("mirror: normal x", nm.n.x(), -np.n.x(), tol);
        checkAbs("mirror: normal y", nm.n.y(), np.n.y(), tol);
    }

    // The pruned search gives what evaluating every segment gives: the
    // first segment at the least distance, the same point bit for bit,
    // its normal away from the joints; on a 241 x 301 grid over and
    // beyond the die (inside, outside, across both joints and the axis)
    {
        label nDiffer = 0;
        label nPoints = 0;
        const List<profileCurve::segment>& segs = pear.segments();
        for (label i = 0; i <= 240; ++i)
        {
            for (label j = 0; j <= 300; ++j)
            {
                const vector2D x(-0.06 + 0.0005*i, -0.05 + 0.0004*j);
                label first = -1;
                scalar least = GREAT;
                forAll(segs, si)
                {
                    const scalar d2 = magSqr(x - pear.nearestOn(si, x).p);
                    if (d2 < least)
                    {
                        least = d2;
                        first = si;
                    }
                }
                const profileCurve::nearestPoint all(pear.nearestOn(first, x));
                const profileCurve::nearestPoint np(pear.nearest(x));
                const bool atJoint =
                    mag(all.p - segs[first].start) <= 1e-12*pear.length()
                 || mag(all.p - segs[first].end) <= 1e-12*pear.length();
                if
                (
                    np.segmenti != first
                 || np.p != all.p
                 || (!atJoint && np.n != all.n)
                )
                {
                    ++nDiffer;
                }
                ++nPoints;
            }
        }
        checkTrue
        (
            "nearest: the pruned search = every segment, "
          + std::to_string(nPoints) + " points",
            nDiffer == 0
        );
    }

    // The circle-flank joint is G1: the normal does not jump across it
    {
        const vector2D nT(-T/mag(T));
        const vector2D t((F - T)/mag(F - T));
        for (const scalar s : {-1e-7, 1e-7})
        {
            const vector2D x(T + s*t + 1e-4*nT);
            const profileCurve::nearestPoint np(pear.nearest(x));
            checkAbs
            (
                "joint circle/flank: normal continuous (" + std::to_string(s)
              + ")",
                np.n & nT, 1, 1e-9
            );
        }
    }

    // A right-angled corner: the normal bisects
    {
        const profileCurve corner
        (
            dictOf
            (
                "freeSide left; segments ( line { start (0 0); end (1 0); }"
                " line { start (1 0); end (1 1); } );"
            )
        );
        const profileCurve::nearestPoint np(corner.nearest(vector2D(1.5, -0.5)));
        checkAbs("corner: p x", np.p.x(), 1, tol);
        checkAbs("corner: p y", np.p.y(), 0, tol);
        checkAbs("corner: bisector x", np.n.x(), -std::sqrt(0.5), tol);
        checkAbs("corner: bisector y", np.n.y(), std::sqrt(0.5), tol);
    }

    // A clockwise arc with the free side outside (a punch of radius 1)
    {
        const profileCurve punch
        (
            dictOf
            (
                "freeSide left; segments ( arc { start (-1 0);"
                " mid (0 1); end (1 0); } );"
            )
        );
        const profileCurve::nearestPoint np(punch.nearest(vector2D(0, 1.5)));
        checkAbs("punch: gap", (vector2D(0, 1.5) - np.p) & np.n, 0.5, tol);
        checkAbs("punch: normal outwards", np.n.y(), 1, tol);
        checkAbs("punch: curvature -1", np.curvature, -1, 1e-12);
    }

    // Discretisation: vertices on the circle, chordal error
    {
        DynamicList<vector2D> pts;
        const scalar chordal = pear.discretise(degToRad(0.5), pts);
        checkAbs("discretise: first point", mag(pts[0]), R, tol);
        checkAbs("discretise: second point", mag(pts[1]), R, tol);
        const scalar aT = std::atan2(T.y(), T.x());
        const scalar sweep = aT + 0.5*pi;
        const label n = std::ceil(radToDeg(sweep)/0.5 - 1e-9);
        checkAbs
        (
            "discretise: chordal error R(1 - cos(dtheta/2))",
            chordal, R*(1 - std::cos(0.5*sweep/n)), 1e-15
        );
        checkAbs("discretise: closed by the mirror", pts.last().x(), 0, tol);
        checkAbs("discretise: ends at the bottom", pts.last().y(), -R, tol);
    }

    // The obstacle reading its profile from a file
    {
        const fileName dir("profileObstacleTest");
        mkDir(dir/"system");
        {
            std::ofstream os((dir/"system"/"dieProfileDict").c_str());
            os << pearEntries() << '\n';
        }
        autoPtr<rigidObstacle> die
        (
            rigidObstacle::New
            (
                dictOf("type profile; file \"system/dieProfileDict\";"),
                dir
            )
        );
        obstaclePoint cp;
        const point x(0, -0.028, 5e-4);
        checkTrue("obstacle: in reach", die->nearest(x, 0, 1e-3, cp));
        checkAbs("obstacle: gap", cp.gap, R - 0.028, tol);
        checkAbs("obstacle: normal +y", cp.n.y(), 1, tol);
        checkAbs("obstacle: p keeps z", cp.p.z(), 5e-4, tol);
        checkTrue("obstacle: out of reach", !die->nearest(x, 0, 1e-4, cp));

        // [C8], [C6] dn/dx, dp/dx and dgap/dx against central differences:
        // on the circle and the fillet (seen from their concave side), a
        // flank (a line)
        checkDerivatives
        (
            "die", die(),
            {
                point(0.003, -0.0255, 1e-4), point(0.0102, -0.0149, 0),
                point(0.0124, 0.0305, 0), point(0.001, 0.044, 2e-4)
            }
        );
        // an arc seen from its convex side (the punch of radius 1 in the
        // x-y plane) and beyond its end (clamped)
        checkDerivatives
        (
            "punch",
            rigidObstacle::New
            (
                dictOf
                (
                    "type profile; freeSide left; segments ( arc { start"
                    " (-1 0); mid (0 1); end (1 0); } );"
                ),
                dir
            )(),
            {point(0.3, 1.4, 0), point(-0.2, 1.1, 0.5), point(1.5, -0.5, 0)}
        );
        rmDir(dir);
    }

    // Input errors
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    auto expectError = [](const std::string& name, const std::string& d,
        const std::string& words)
    {
        const std::string msg =
            fatalMessage([&]() { profileCurve c(dictOf(d)); });
        checkTrue
        (
            name + " (" + msg.substr(0, 60) + "...)",
            msg.find(words) != std::string::npos
        );
    };
    expectError
    (
        "error: segments that do not join",
        "freeSide left; segments ( line { start (0 0); end (1 0); }"
        " line { start (1.1 0); end (1 1); } );",
        "keyword 'start'"
    );
    expectError
    (
        "error: collinear arc",
        "freeSide left; segments ( arc { start (0 0); mid (1 0);"
        " end (2 0); } );",
        "collinear"
    );
    expectError
    (
        "error: bad freeSide",
        "freeSide up; segments ( line { start (0 0); end (1 0); } );",
        "keyword 'freeSide'"
    );
    expectError
    (
        "error: mirror not ending on x = 0",
        "freeSide left; mirror yes; segments ( line { start (0 0);"
        " end (1 0); } );",
        "keyword 'mirror'"
    );
    {
        const std::string msg = fatalMessage
        (
            []()
            {
                rigidObstacle::New
                (
                    dictOf("type profile; file \"noSuchDict\";"), "."
                );
            }
        );
        checkTrue
        (
            "error: missing profile file names keyword 'file'",
            msg.find("keyword 'file'") != std::string::npos
        );
    }

    return exitCode();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
Application
    dieProfileToSTL

Description
    Writes the surface of a rigid die for a plane-strain case: a 2-D
    profile in the x-y plane made of straight lines and circular arcs,
    extruded across z in [zMin, zMax] (choose it slightly wider than the
    mesh's one-cell thickness) and triangulated, to the ASCII STL file
    constant/triSurface/<name>.stl, read by the rigid obstacle of type
    triSurface (src/rigidObstacles).

    Dictionary (default system/dieProfileDict, option -dict), SI units:
    \verbatim
        name            pearDie;    // output constant/triSurface/pearDie.stl
        zMin            -1e-3;
        zMax            2e-3;
        freeSide        left;       // left | right of the direction of travel
        arcResolution   1;          // largest angle of an arc facet [deg]
        scale           1;          // optional, multiplies all coordinates
        mirror          no;         // optional, see below
        segments
        (
            line { start (0 0); end (1 0); }
            arc  { start (1 0); mid (1.7071 0.2929); end (2 1); }
        );
    \endverbatim
    The segments are walked in order and must join (each start equal to
    the previous end, to 1e-9 of the profile size). An arc is given by
    three of its points: start, a point 'mid' anywhere on the arc strictly
    between start and end, and end; it runs from start through mid to end
    (this fixes both the circle and the sense without a separate flag).
    An optional 'nSegments' in an arc overrides arcResolution.

    The triangle normals point to the free side: the side where the
    deformable body is, to the left or right of the direction of travel
    along the profile.

    mirror yes: the profile is completed by its mirror image about x = 0,
    walked back (the profile must end on x = 0); with a half-profile from
    x = 0 to x = 0 this gives the closed full profile, with the free side
    kept.

    The chordal error of the arcs, r (1 - cos(dtheta/2)), is printed.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "dictionary.H"
#include "vector2D.H"
#include "point.H"
#include "DynamicList.H"
#include "unitConversion.H"

using namespace Foam;

namespace
{

//- Angle in [0, 2 pi)
scalar wrap(scalar a)
{
    a = std::fmod(a, constant::mathematical::twoPi);
    return a < 0 ? a + constant::mathematical::twoPi : a;
}


//- Append the points of an arc through start, mid, end (start excluded);
//  returns the chordal error
scalar discretiseArc
(
    const dictionary& dict,
    const vector2D& s,
    const vector2D& m,
    const vector2D& e,
    const scalar resolution,
    DynamicList<vector2D>& pts
)
{
    // Circumcentre of the three points
    const vector2D b = m - s;
    const vector2D c = e - s;
    const scalar d = 2*(b.x()*c.y() - b.y()*c.x());
    const scalar size = max(mag(b), mag(c));

    if (mag(d) <= 1e-12*sqr(size))
    {
        FatalIOErrorInFunction(dict)
            << "arc: start " << s << ", mid " << m << " and end " << e
            << " are collinear or coincide in dictionary " << dict.name()
            << exit(FatalIOError);
    }

    const vector2D centre
    (
        s.x() + (c.y()*magSqr(b) - b.y()*magSqr(c))/d,
        s.y() + (b.x()*magSqr(c) - c.x()*magSqr(b))/d
    );
    const scalar r = mag(s - centre);

    const scalar a0 = std::atan2(s.y() - centre.y(), s.x() - centre.x());
    const scalar toMid =
        wrap(std::atan2(m.y() - centre.y(), m.x() - centre.x()) - a0);
    const scalar toEnd =
        wrap(std::atan2(e.y() - centre.y(), e.x() - centre.x()) - a0);

    // Counter-clockwise if mid comes before end going counter-clockwise
    const scalar sweep =
        toMid < toEnd ? toEnd : -(constant::mathematical::twoPi - toEnd);

    label n = dict.getOrDefault<label>
    (
        "nSegments", label(std::ceil(mag(sweep)/resolution - 1e-9))
    );
    if (n < 1)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'nSegments': must be >= 1, got " << n
            << " in dictionary " << dict.name()
            << exit(FatalIOError);
    }

    for (label i = 1; i < n; ++i)
    {
        const scalar a = a0 + sweep*i/n;
        pts.append(centre + r*vector2D(std::cos(a), std::sin(a)));
    }
    pts.append(e);

    Info<< "    arc: centre " << centre << ", radius " << r
        << ", sweep " << radToDeg(sweep) << " deg, " << n << " facets"
        << endl;

    return r*(1 - std::cos(0.5*sweep/n));
}


//- Write one ASCII STL facet
void writeFacet(OFstream& os, const point& a, const point& b, const point& c)
{
    vector n = (b - a) ^ (c - a);
    n /= mag(n);
    os  << "  facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << nl
        << "    outer loop" << nl;
    for (const point* p : {&a, &b, &c})
    {
        os  << "      vertex " << p->x() << ' ' << p->y() << ' ' << p->z()
            << nl;
    }
    os  << "    endloop" << nl
        << "  endfacet" << nl;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    argList::addNote
    (
        "Extrude a 2-D die profile of lines and arcs across z and write it"
        " to constant/triSurface/<name>.stl"
    );
    argList::noParallel();
    argList::addOption
    (
        "dict",
        "file",
        "Profile dictionary (default: system/dieProfileDict)"
    );

    #include "setRootCase.H"

    const fileName caseDir(args.path());
    fileName dictFile =
        args.getOrDefault<fileName>("dict", "system/dieProfileDict");
    if (!dictFile.isAbsolute())
    {
        dictFile = caseDir/dictFile;
    }

    IFstream is(dictFile);
    if (!is.good())
    {
        FatalErrorInFunction
            << "cannot open the profile dictionary " << dictFile
            << exit(FatalError);
    }
    const dictionary dict(is);

    const word name(dict.get<word>("name"));
    const scalar zMin(dict.get<scalar>("zMin"));
    const scalar zMax(dict.get<scalar>("zMax"));
    const scalar scale(dict.getOrDefault<scalar>("scale", 1));
    const scalar resolution(degToRad(dict.get<scalar>("arcResolution")));
    const bool mirror(dict.getOrDefault<bool>("mirror", false));
    const word freeSide(dict.get<word>("freeSide"));

    if (!(zMax > zMin))
    {
        FatalIOErrorInFunction(dict)
            << "keywords 'zMin', 'zMax': need zMax > zMin, got " << zMin
            << ", " << zMax << " in dictionary " << dict.name()
            << exit(FatalIOError);
    }
    if (!(resolution > 0) || !(scale > 0))
    {
        FatalIOErrorInFunction(dict)
            << "keywords 'arcResolution', 'scale': must be > 0"
            << " in dictionary " << dict.name()
            << exit(FatalIOError);
    }
    if (freeSide != "left" && freeSide != "right")
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'freeSide': expected left or right, got '"
            << freeSide << "' in dictionary " << dict.name()
            << exit(FatalIOError);
    }

    // Walk the segments
    const PtrList<entry> segments(dict.lookup("segments"));
    if (segments.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'segments': no segments in dictionary " << dict.name()
            << exit(FatalIOError);
    }

    // Joining tolerance: 1e-9 of the extent of the segment end points
    scalar extent = 0;
    for (const entry& seg : segments)
    {
        if (seg.isDict())
        {
            extent = max(extent, mag(seg.dict().get<vector2D>("start")));
            extent = max(extent, mag(seg.dict().get<vector2D>("end")));
        }
    }
    const scalar joinTol = 1e-9*max(extent, SMALL);

    DynamicList<vector2D> pts;
    scalar chordal = 0;
    scalar length = 0;

    for (const entry& seg : segments)
    {
        if (!seg.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'segments': expected 'line { .. }' or"
                << " 'arc { .. }', got " << seg.keyword()
                << " in dictionary " << dict.name()
                << exit(FatalIOError);
        }
        const dictionary& sd = seg.dict();
        const vector2D s(sd.get<vector2D>("start"));
        const vector2D e(sd.get<vector2D>("end"));

        if (pts.empty())
        {
            pts.append(s);
        }
        else if (mag(s - pts.last()) > joinTol)
        {
            FatalIOErrorInFunction(sd)
                << "keyword 'start': " << s << " does not join the previous"
                << " segment's end " << pts.last() << " in dictionary "
                << sd.name()
                << exit(FatalIOError);
        }

        const label n0 = pts.size();
        if (seg.keyword() == "line")
        {
            if (mag(e - s) <= joinTol)
            {
                FatalIOErrorInFunction(sd)
                    << "line of zero length in dictionary " << sd.name()
                    << exit(FatalIOError);
            }
            pts.append(e);
        }
        else if (seg.keyword() == "arc")
        {
            chordal = max
            (
                chordal,
                discretiseArc
                (
                    sd, pts.last(), sd.get<vector2D>("mid"), e, resolution,
                    pts
                )
            );
        }
        else
        {
            FatalIOErrorInFunction(sd)
                << "unknown segment type '" << seg.keyword()
                << "' (line or arc) in dictionary " << sd.name()
                << exit(FatalIOError);
        }
        for (label i = n0 - 1; i < pts.size() - 1; ++i)
        {
            length += mag(pts[i + 1] - pts[i]);
        }
    }

    if (mirror)
    {
        if (mag(pts.last().x()) > joinTol)
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'mirror': the profile must end on x = 0 to be"
                << " mirrored, it ends at " << pts.last()
                << " in dictionary " << dict.name()
                << exit(FatalIOError);
        }
        pts.last().x() = 0;
        for (label i = pts.size() - 2; i >= 0; --i)
        {
            const vector2D m(0 - pts[i].x(), pts[i].y());
            length += mag(m - pts.last());
            pts.append(m);
        }
    }

    // Extrude and write: quad a b c d = (P_i, zMin) (P_i+1, zMin)
    // (P_i+1, zMax) (P_i, zMax); (a b c), (a c d) have their normal to the
    // right of the direction of travel
    const bool left = (freeSide == "left");
    const fileName outDir(caseDir/"constant"/"triSurface");
    mkDir(outDir);
    const fileName outFile(outDir/(name + ".stl"));

    OFstream os(outFile);
    os.precision(12);
    os  << "solid " << name << nl;
    for (label i = 0; i < pts.size() - 1; ++i)
    {
        const vector2D p0 = scale*pts[i];
        const vector2D p1 = scale*pts[i + 1];
        const point a(p0.x(), p0.y(), zMin);
        const point b(p1.x(), p1.y(), zMin);
        const point c(p1.x(), p1.y(), zMax);
        const point d(p0.x(), p0.y(), zMax);
        if (left)
        {
            writeFacet(os, a, c, b);
            writeFacet(os, a, d, c);
        }
        else
        {
            writeFacet(os, a, b, c);
            writeFacet(os, a, c, d);
        }
    }
    os  << "endsolid " << name << nl;

    Info<< nl << "Profile: " << pts.size() << " points, length "
        << scale*length << " m, from " << scale*pts.first() << " to "
        << scale*pts.last() << nl
        << "Largest chordal error of the arcs: " << scale*chordal << " m" << nl
        << "Wrote " << 2*(pts.size() - 1) << " triangles, z in [" << zMin
        << ", " << zMax << "], free side " << freeSide << ", to " << outFile
        << nl << endl;

    Info<< "End" << nl << endl;

    return 0;
}


// ************************************************************************* //

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

    The chordal error of the arcs, r (1 - cos(dtheta/2)), is printed. The
    profile itself (segments, freeSide, scale, mirror) is read by
    profileCurve (src/rigidObstacles), the same code the exact rigid
    obstacle of type 'profile' answers its queries with, so the STL and a
    case's contact geometry come from one definition.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IFstream.H"
#include "strictDictionary.H"
#include "numberRange.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "dictionary.H"
#include "profileCurve.H"
#include "point.H"
#include "unitConversion.H"

using namespace Foam;

namespace
{

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

    // [S19b] a number its reading would stop on with SIGFPE
    strictDictionary::checkNumberRange(dictFile);
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
    const scalar resolution(degToRad(dict.get<scalar>("arcResolution")));
    {
        wordList known({"FoamFile", "name", "zMin", "zMax", "arcResolution"});
        known.append(profileCurve::keywords());
        strictDictionary::check(dict, known, "dieProfileToSTL");
    }

    if (!(zMax > zMin))
    {
        FatalIOErrorInFunction(dict)
            << "keywords 'zMin', 'zMax': need zMax > zMin, got " << zMin
            << ", " << zMax << " in dictionary " << dict.name()
            << exit(FatalIOError);
    }
    if (!(resolution > 0))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'arcResolution': must be > 0 in dictionary "
            << dict.name() << exit(FatalIOError);
    }

    const profileCurve curve(dict);
    for (const profileCurve::segment& s : curve.segments())
    {
        if (s.isArc())
        {
            Info<< "    arc: centre " << s.centre << ", radius " << s.radius
                << ", sweep " << radToDeg(s.sweep) << " deg" << endl;
        }
    }
    DynamicList<vector2D> pts;
    const scalar chordal = curve.discretise(resolution, pts);

    // Extrude and write: quad a b c d = (P_i, zMin) (P_i+1, zMin)
    // (P_i+1, zMax) (P_i, zMax); (a b c), (a c d) have their normal to the
    // right of the direction of travel
    const bool left = curve.freeSideLeft();
    const fileName outDir(caseDir/"constant"/"triSurface");
    mkDir(outDir);
    const fileName outFile(outDir/(name + ".stl"));

    OFstream os(outFile);
    os.precision(12);
    os  << "solid " << name << nl;
    for (label i = 0; i < pts.size() - 1; ++i)
    {
        const point a(pts[i].x(), pts[i].y(), zMin);
        const point b(pts[i + 1].x(), pts[i + 1].y(), zMin);
        const point c(pts[i + 1].x(), pts[i + 1].y(), zMax);
        const point d(pts[i].x(), pts[i].y(), zMax);
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
        << curve.length() << " m, from " << pts.first() << " to "
        << pts.last() << nl
        << "Largest chordal error of the arcs: " << chordal << " m" << nl
        << "Wrote " << 2*(pts.size() - 1) << " triangles, z in [" << zMin
        << ", " << zMax << "], free side "
        << (left ? "left" : "right") << ", to " << outFile
        << nl << endl;

    Info<< "End" << nl << endl;

    return 0;
}


// ************************************************************************* //

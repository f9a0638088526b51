/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Checks of a triangulated obstacle's file and surface. OpenFOAM's STL
    reader trusts the file: a binary STL that declares more triangles than
    it holds reads past its end, a NaN coordinate stops the octree with a
    floating-point exception, and an ASCII STL cut after a complete facet
    reads as a smaller die. The file is therefore checked before it is
    read, and the surface after.

\*---------------------------------------------------------------------------*/

#include "triSurfaceObstacle.H"
#include "OSspecific.H"
#include "triPointRef.H"
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The whole file as bytes
std::string readBytes(const Foam::fileName& file)
{
    std::ifstream is(file.c_str(), std::ios::binary);
    std::ostringstream os;
    os << is.rdbuf();
    return os.str();
}


// ASCII STL: starts with 'solid' and holds no NUL byte in its first 1 kB
bool isAscii(const std::string& s)
{
    std::size_t i = s.find_first_not_of(" \t\r\n");
    if (i == std::string::npos || s.compare(i, 5, "solid") != 0)
    {
        return false;
    }
    const std::size_t n = std::min(s.size(), std::size_t(1024));
    return std::memchr(s.data(), '\0', n) == nullptr;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rigidObstacles::triSurfaceObstacle::checkSTLFile
(
    const dictionary& dict,
    const fileName& file
)
{
    const word ext(file.ext());
    if (ext != "stl" && ext != "STL" && ext != "stlb")
    {
        return;
    }
    const std::string s(readBytes(file));

    if (ext == "stlb" || !isAscii(s))
    {
        // Binary: 80-byte header, triangle count, 50 bytes per triangle
        const std::size_t size = s.size();
        std::uint32_t n = 0;
        if (size >= 84)
        {
            std::memcpy(&n, s.data() + 80, 4);
        }
        const std::size_t expected = 84 + 50*std::size_t(n);
        if (size < 84 || size != expected)
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'file': binary STL " << file << " declares " << n
                << " triangles (84 + 50 x " << n << " = " << expected
                << " bytes) but holds " << size << " bytes: truncated or"
                << " not an STL file (dictionary " << dict.name() << ")"
                << exit(FatalIOError);
        }
        for (std::uint32_t t = 0; t < n; ++t)
        {
            for (int c = 3; c < 12; ++c)
            {
                float x;
                std::memcpy(&x, s.data() + 84 + 50*std::size_t(t) + 4*c, 4);
                if (!std::isfinite(x))
                {
                    FatalIOErrorInFunction(dict)
                        << "keyword 'file': binary STL " << file
                        << ": triangle " << t << " has a non-finite"
                        << " vertex coordinate (" << x << ")"
                        << " (dictionary " << dict.name() << ")"
                        << exit(FatalIOError);
                }
            }
        }
        return;
    }

    // ASCII: facet normal .. outer loop, 3 x vertex, endloop endfacet,
    // and endsolid at the end
    std::istringstream is(s);
    std::string line;
    label lineNo = 0, nFacet = 0, nEndFacet = 0, nVertex = 0;
    label lastKeywordLine = 0;
    std::string lastKeyword;
    while (std::getline(is, line))
    {
        ++lineNo;
        std::istringstream ls(line);
        std::string key;
        if (!(ls >> key))
        {
            continue;
        }
        lastKeyword = key;
        lastKeywordLine = lineNo;
        if (key == "facet")
        {
            if (nFacet != nEndFacet)
            {
                break;
            }
            ++nFacet;
        }
        else if (key == "endfacet")
        {
            if (nVertex != 3*nFacet)
            {
                FatalIOErrorInFunction(dict)
                    << "keyword 'file': ASCII STL " << file << " line "
                    << lineNo << ": facet " << nFacet - 1 << " has "
                    << nVertex - 3*(nFacet - 1) << " vertices, expected 3"
                    << " (dictionary " << dict.name() << ")"
                    << exit(FatalIOError);
            }
            ++nEndFacet;
        }
        else if (key == "vertex")
        {
            ++nVertex;
            for (int c = 0; c < 3; ++c)
            {
                std::string tok;
                ls >> tok;
                char* end = nullptr;
                const double x = std::strtod(tok.c_str(), &end);
                if (tok.empty() || *end != '\0' || !std::isfinite(x))
                {
                    FatalIOErrorInFunction(dict)
                        << "keyword 'file': ASCII STL " << file << " line "
                        << lineNo << ": vertex coordinate '" << tok.c_str()
                        << "' is not a finite number (dictionary "
                        << dict.name() << ")" << exit(FatalIOError);
                }
            }
        }
    }
    if (nFacet != nEndFacet)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'file': ASCII STL " << file << ": facet " << nFacet - 1
            << " (line " << lastKeywordLine << ") is not closed by"
            << " 'endfacet': the file is truncated or damaged (dictionary "
            << dict.name() << ")" << exit(FatalIOError);
    }
    if (lastKeyword != "endsolid")
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'file': ASCII STL " << file << " ends at line "
            << lastKeywordLine << " ('" << lastKeyword.c_str() << "') after "
            << nEndFacet << " facets without 'endsolid': the file is"
            << " truncated (dictionary " << dict.name() << ")"
            << exit(FatalIOError);
    }
}


void Foam::rigidObstacles::triSurfaceObstacle::checkSurface
(
    const dictionary& dict,
    const fileName& file,
    const triSurface& surf
)
{
    const pointField& pts = surf.localPoints();
    const List<labelledTri>& tris = surf.localFaces();

    forAll(pts, i)
    {
        if (!std::isfinite(mag(pts[i])))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'file': surface " << file << " has a non-finite"
                << " point " << pts[i] << " (dictionary " << dict.name()
                << ")" << exit(FatalIOError);
        }
    }

    // Degenerate triangles: area below 1e-12 of the squared extent
    const boundBox bb(pts, false);
    const scalar minArea = 1e-12*magSqr(bb.span());
    forAll(tris, f)
    {
        const labelledTri& t = tris[f];
        const scalar a = triPointRef(pts[t[0]], pts[t[1]], pts[t[2]]).mag();
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(a > minArea))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'file': surface " << file << " has a degenerate"
                << " triangle " << f << " (area " << a << " m^2, corners "
                << pts[t[0]] << " " << pts[t[1]] << " " << pts[t[2]] << ")"
                << " (dictionary " << dict.name() << ")"
                << exit(FatalIOError);
        }
    }

    // Edges: at most two triangles, which run through it in opposite
    // directions (normals on the same side)
    const edgeList& edges = surf.edges();
    const labelListList& edgeFaces = surf.edgeFaces();
    label nOpen = 0;
    forAll(edges, edgei)
    {
        const labelList& ef = edgeFaces[edgei];
        if (ef.size() > 2)
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'file': surface " << file << " is not a"
                << " manifold: edge " << edges[edgei] << " at "
                << pts[edges[edgei][0]] << " is shared by " << ef.size()
                << " triangles " << ef << " (dictionary " << dict.name()
                << ")" << exit(FatalIOError);
        }
        if (ef.size() == 1)
        {
            ++nOpen;
            continue;
        }
        const edge& e = edges[edgei];
        if
        (
            tris[ef[0]].edgeDirection(e) == tris[ef[1]].edgeDirection(e)
        )
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'file': surface " << file << ": neighbouring"
                << " triangles " << ef[0] << " and " << ef[1] << " (edge at "
                << pts[e[0]] << " " << pts[e[1]] << ") are oriented"
                << " oppositely: their normals point to different sides."
                << " Orient every triangle alike (towards the body)"
                << " (dictionary " << dict.name() << ")"
                << exit(FatalIOError);
        }
    }

    bool closed = false;
    if (dict.readIfPresent("closed", closed) && closed != (nOpen == 0))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'closed': surface " << file << " is "
            << (nOpen ? "open (" + Foam::name(nOpen) + " edges of one"
                " triangle)" : word("closed")) << ", the dictionary says"
            << " closed " << (closed ? "yes" : "no") << " (dictionary "
            << dict.name() << ")" << exit(FatalIOError);
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "profileObstacle.H"
#include "strictDictionary.H"
#include "addToRunTimeSelectionTable.H"
#include "IFstream.H"

namespace Foam
{
namespace rigidObstacles
{
    defineTypeNameAndDebug(profileObstacle, 0);
    addToRunTimeSelectionTable(rigidObstacle, profileObstacle, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::rigidObstacles::profileObstacle::profileDict
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    fileName file;
    if (!dict.readIfPresent("file", file))
    {
        return dict;
    }
    file.expand();
    if (!file.isAbsolute())
    {
        file = caseDir/file;
    }
    IFstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'file': cannot open the profile dictionary " << file
            << " named in dictionary " << dict.name() << exit(FatalIOError);
    }
    // The file may be the dictionary of dieProfileToSTL as well
    const dictionary profile(is);
    wordList known({"FoamFile", "name", "zMin", "zMax", "arcResolution"});
    known.append(profileCurve::keywords());
    strictDictionary::check(profile, known, "profile of the obstacle");
    return profile;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidObstacles::profileObstacle::profileObstacle
(
    const dictionary& dict,
    const fileName& caseDir
)
:
    rigidObstacle(dict),
    curve_(profileDict(dict, caseDir))
{
    // The profile's entries here or in the file named by 'file'
    wordList own({"file"});
    if (!dict.found("file"))
    {
        own.append(profileCurve::keywords());
    }
    checkKeywords(dict, own);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

bool Foam::rigidObstacles::profileObstacle::nearestInitial
(
    const point& x0,
    const scalar maxDistance,
    obstaclePoint& cp,
    const label
) const
{
    const profileCurve::nearestPoint np
    (
        curve_.nearest(vector2D(x0.x(), x0.y()))
    );
    const point p(np.p.x(), np.p.y(), x0.z());
    if (mag(x0 - p) > maxDistance)
    {
        return false;
    }
    cp.p = p;
    cp.n = vector(np.n.x(), np.n.y(), 0);
    cp.gap = (x0 - p) & cp.n;
    cp.hint = np.segmenti;

    // [C6] the derivatives with respect to x0 (the extrusion direction z
    // is a line of every segment): a clamped end or a corner stays put;
    // on a line p moves in its plane; on an arc of centre c, seen from
    // x0 at the distance rho, n turns with x0 (the curvature seen from
    // x0) and p moves by the ratio of the radius to rho
    const tensor zz(sqr(vector(0, 0, 1)));
    if (np.atEnd)
    {
        cp.dpdx = zz;
    }
    else if (np.curvature == 0)
    {
        cp.dpdx = tensor::I - sqr(cp.n);
    }
    else
    {
        const point c(p + cp.n/np.curvature);
        const scalar rho = mag(x0 - c);
        const tensor inPlaneTangent(tensor::I - zz - sqr(cp.n));
        cp.dndx = -sign(np.curvature)*inPlaneTangent/rho;
        cp.dpdx = zz + inPlaneTangent/(mag(np.curvature)*rho);
    }
    return true;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "profileCurve.H"
#include "strictDictionary.H"
#include "mathematicalConstants.H"
#include "error.H"

using namespace Foam::constant::mathematical;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Angle in [0, 2 pi)
Foam::scalar wrap(Foam::scalar a)
{
    a = std::fmod(a, twoPi);
    return a < 0 ? a + twoPi : a;
}


Foam::vector2D unit(const Foam::scalar a)
{
    return Foam::vector2D(std::cos(a), std::sin(a));
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::profileCurve::read(const dictionary& dict)
{
    const scalar scale(dict.getOrDefault<scalar>("scale", 1));
    if (!(scale > 0))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'scale': must be > 0, got " << scale
            << " in dictionary " << dict.name() << exit(FatalIOError);
    }

    const PtrList<entry> entries(dict.lookup("segments"));
    if (entries.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'segments': no segments in dictionary " << dict.name()
            << exit(FatalIOError);
    }

    // Joining tolerance: 1e-9 of the extent of the segment end points
    scalar extent = 0;
    for (const entry& e : entries)
    {
        if (e.isDict())
        {
            extent = max(extent, mag(e.dict().get<vector2D>("start")));
            extent = max(extent, mag(e.dict().get<vector2D>("end")));
        }
    }
    const scalar joinTol = 1e-9*max(scale*extent, SMALL);

    DynamicList<segment> segs(entries.size());

    for (const entry& e : entries)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'segments': expected 'line { .. }' or"
                << " 'arc { .. }', got " << e.keyword()
                << " in dictionary " << dict.name() << exit(FatalIOError);
        }
        // named after the profile's dictionary (messages name its file)
        dictionary sd(e.dict());
        sd.name() = dict.name() + ".segments." + e.keyword();
        segment s;
        s.start = scale*sd.get<vector2D>("start");
        s.end = scale*sd.get<vector2D>("end");

        if (segs.size() && mag(s.start - segs.last().end) > joinTol)
        {
            FatalIOErrorInFunction(sd)
                << "keyword 'start': " << s.start/scale << " does not join"
                << " the previous segment's end " << segs.last().end/scale
                << " in dictionary " << sd.name() << exit(FatalIOError);
        }
        if (segs.size())
        {
            s.start = segs.last().end;
        }

        strictDictionary::check
        (
            sd,
            e.keyword() == "arc"
          ? wordList({"start", "mid", "end", "nSegments"})
          : wordList({"start", "end"}),
            "profile segment " + e.keyword()
        );

        if (e.keyword() == "line")
        {
            if (mag(s.end - s.start) <= joinTol)
            {
                FatalIOErrorInFunction(sd)
                    << "line of zero length in dictionary " << sd.name()
                    << exit(FatalIOError);
            }
        }
        else if (e.keyword() == "arc")
        {
            // Circumcentre of start, mid, end
            const vector2D m(scale*sd.get<vector2D>("mid"));
            const vector2D b(m - s.start);
            const vector2D c(s.end - s.start);
            const scalar d = 2*(b.x()*c.y() - b.y()*c.x());
            const scalar size = max(mag(b), mag(c));
            if (mag(d) <= 1e-12*sqr(size))
            {
                FatalIOErrorInFunction(sd)
                    << "arc: start " << s.start/scale << ", mid " << m/scale
                    << " and end " << s.end/scale << " are collinear or"
                    << " coincide in dictionary " << sd.name()
                    << exit(FatalIOError);
            }
            s.centre = vector2D
            (
                s.start.x() + (c.y()*magSqr(b) - b.y()*magSqr(c))/d,
                s.start.y() + (b.x()*magSqr(c) - c.x()*magSqr(b))/d
            );
            s.radius = mag(s.start - s.centre);
            s.a0 = std::atan2
            (
                s.start.y() - s.centre.y(), s.start.x() - s.centre.x()
            );
            const vector2D dm(m - s.centre);
            const vector2D de(s.end - s.centre);
            const scalar toMid = wrap(std::atan2(dm.y(), dm.x()) - s.a0);
            const scalar toEnd = wrap(std::atan2(de.y(), de.x()) - s.a0);
            // Counter-clockwise when mid comes before end that way
            s.sweep = toMid < toEnd ? toEnd : -(twoPi - toEnd);
            s.nSegments = sd.getOrDefault<label>("nSegments", -1);
            if (sd.found("nSegments") && s.nSegments < 1)
            {
                FatalIOErrorInFunction(sd)
                    << "keyword 'nSegments': must be >= 1, got "
                    << s.nSegments << " in dictionary " << sd.name()
                    << exit(FatalIOError);
            }
        }
        else
        {
            FatalIOErrorInFunction(sd)
                << "unknown segment type '" << e.keyword()
                << "' (line or arc) in dictionary " << sd.name()
                << exit(FatalIOError);
        }
        segs.append(s);
    }

    segments_.transfer(segs);

    if (dict.getOrDefault<bool>("mirror", false))
    {
        appendMirror(joinTol);
    }
}


void Foam::profileCurve::appendMirror(const scalar joinTol)
{
    const vector2D last(segments_.last().end);
    if (mag(last.x()) > joinTol)
    {
        FatalIOErrorInFunction(dict_)
            << "keyword 'mirror': the profile must end on x = 0 to be"
            << " mirrored, it ends at " << last << " in dictionary "
            << dict_.name() << exit(FatalIOError);
    }
    segments_.last().end.x() = 0;

    auto mirrored = [](const vector2D& v) { return vector2D(-v.x(), v.y()); };

    const label n = segments_.size();
    segments_.setSize(2*n);
    for (label i = 0; i < n; ++i)
    {
        // Walked back: the mirror image of segment n-1-i, reversed. An
        // arc's point at angle a maps to angle pi - a, and reversing the
        // walk keeps the sense of the sweep
        const segment& s = segments_[n - 1 - i];
        segment& m = segments_[n + i];
        m = s;
        m.start = mirrored(s.end);
        m.end = mirrored(s.start);
        if (s.isArc())
        {
            m.centre = mirrored(s.centre);
            m.a0 = pi - (s.a0 + s.sweep);
        }
    }
}


Foam::vector2D Foam::profileCurve::normal
(
    const segment& s,
    const scalar a
) const
{
    if (s.isArc())
    {
        // Left of a counter-clockwise arc is its centre
        return -side_*sign(s.sweep)*unit(a);
    }
    const vector2D t((s.end - s.start)/mag(s.end - s.start));
    return side_*vector2D(-t.y(), t.x());
}


Foam::profileCurve::nearestPoint Foam::profileCurve::nearestOn
(
    const label si,
    const vector2D& p
) const
{
    const segment& s = segments_[si];
    nearestPoint np;
    np.segmenti = si;

    if (s.isArc())
    {
        const vector2D d(p - s.centre);
        const scalar a = std::atan2(d.y(), d.x());
        const scalar along =
            s.sweep > 0 ? wrap(a - s.a0) : wrap(s.a0 - a);
        scalar aq = a;
        if (along > mag(s.sweep))
        {
            // Beyond the arc: the nearer end point
            aq =
                magSqr(p - s.start) <= magSqr(p - s.end)
              ? s.a0 : s.a0 + s.sweep;
            np.atEnd = true;
        }
        np.p = s.centre + s.radius*unit(aq);
        np.n = normal(s, aq);
        np.curvature =
            (((s.centre - np.p) & np.n) > 0 ? 1 : -1)/s.radius;
    }
    else
    {
        const vector2D e(s.end - s.start);
        const scalar t = ((p - s.start) & e)/magSqr(e);
        const scalar u = min(max(t, 0.0), 1.0);
        np.atEnd = t != u;
        np.p = s.start + u*e;
        np.n = normal(s, 0);
        np.curvature = 0;
    }
    return np;
}


Foam::scalar Foam::profileCurve::distanceBound
(
    const segment& s,
    const vector2D& p
) const
{
    if (s.isArc())
    {
        return mag(mag(p - s.centre) - s.radius);
    }
    const vector2D e(s.end - s.start);
    const vector2D d(p - s.start);
    return mag(e.x()*d.y() - e.y()*d.x())/mag(e);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::profileCurve::profileCurve(const dictionary& dict)
:
    dict_(dict),
    segments_(),
    side_(1),
    length_(0)
{
    const word freeSide(dict.get<word>("freeSide"));
    if (freeSide == "left")
    {
        side_ = 1;
    }
    else if (freeSide == "right")
    {
        side_ = -1;
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'freeSide': expected left or right, got '"
            << freeSide << "' in dictionary " << dict.name()
            << exit(FatalIOError);
    }

    read(dict);

    for (const segment& s : segments_)
    {
        length_ += s.isArc() ? s.radius*mag(s.sweep) : mag(s.end - s.start);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::profileCurve::nearestPoint Foam::profileCurve::nearest
(
    const vector2D& p
) const
{
    // The die is searched at every face in every residual evaluation:
    // evaluate first the segment with the smallest distance bound, then,
    // in walking order, only the segments whose bound does not exceed its
    // distance (with a margin far above round-off). The segment that a
    // loop over all segments picks (the first at the least distance) is
    // among them, so the answer is the same bit for bit.
    label likely = 0;
    scalar likelyBound = GREAT;
    forAll(segments_, si)
    {
        const scalar b = distanceBound(segments_[si], p);
        if (b < likelyBound)
        {
            likelyBound = b;
            likely = si;
        }
    }
    const nearestPoint npLikely(nearestOn(likely, p));
    const scalar reach = mag(p - npLikely.p)*(1 + 1e-9) + 1e-12*length_;

    nearestPoint best;
    scalar bestDist2 = GREAT;
    forAll(segments_, si)
    {
        if (si != likely && distanceBound(segments_[si], p) > reach)
        {
            continue;
        }
        const nearestPoint np(si == likely ? npLikely : nearestOn(si, p));
        const scalar d2 = magSqr(p - np.p);
        if (d2 < bestDist2)
        {
            bestDist2 = d2;
            best = np;
        }
    }

    // At a joint whose tangent turns, both segments give the corner: take
    // the bisector of their normals (on a smooth joint they agree anyway).
    // A point inside its segment is no other segment's: no corner
    const label n = segments_.size();
    const scalar tol = 1e-12*max(length(), SMALL);
    const segment& sb = segments_[best.segmenti];
    if (mag(best.p - sb.start) > tol && mag(best.p - sb.end) > tol)
    {
        return best;
    }
    for (const label nbr : {best.segmenti - 1, best.segmenti + 1})
    {
        if (nbr < 0 || nbr >= n)
        {
            continue;
        }
        const nearestPoint np(nearestOn(nbr, p));
        if (mag(np.p - best.p) <= tol && mag(np.n - best.n) > 1e-12)
        {
            best.n = (best.n + np.n)/mag(best.n + np.n);
            best.curvature = 0;
            best.atEnd = true;
        }
    }
    return best;
}


Foam::scalar Foam::profileCurve::discretise
(
    const scalar resolution,
    DynamicList<vector2D>& points
) const
{
    scalar chordal = 0;
    points.clear();
    points.append(segments_.first().start);
    for (const segment& s : segments_)
    {
        if (s.isArc())
        {
            const label n =
                s.nSegments > 0
              ? s.nSegments
              : max(label(std::ceil(mag(s.sweep)/resolution - 1e-9)), 1);
            for (label i = 1; i < n; ++i)
            {
                points.append(s.centre + s.radius*unit(s.a0 + s.sweep*i/n));
            }
            chordal = max(chordal, s.radius*(1 - std::cos(0.5*s.sweep/n)));
        }
        points.append(s.end);
    }
    return chordal;
}


// ************************************************************************* //

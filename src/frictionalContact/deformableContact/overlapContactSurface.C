/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "overlapContactSurface.H"
#include "polygonOverlap.H"
#include "DynamicList.H"

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

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.

Description
    deformableContact: the slave faces against the master surface
    ([C10]-[C13] in doc/theory.md), the forces of both sides, their
    diagonal tangent, the held linearisation and the commit.

\*---------------------------------------------------------------------------*/

#include "deformableContactFvPatchVectorField.H"
#include "volFields.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- One overlap of a slave face with a master face [C11]
struct faceOverlap
{
    label master;
    scalar length;      // overlap length l_sm, in the master's measure
    scalar projected;   // length of the slave segment's projection
    scalar gap;         // (x_s - x_m) . n_m at the overlap's midpoint
};

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::deformableContactFvPatchVectorField::evaluatePair
(
    const side& sl,
    const side& ms,
    const scalar deltaT,
    List<slaveFace>& faces
) const
{
    faces.setSize(sl.X.size());
    const label nM = ms.X.size();

    // Candidates by a sweep along the direction in which the master
    // surface extends most: the master faces sorted by the lower end of
    // their interval (widened by the search distance); a slave face's
    // candidates start within one interval length before its own
    // [C11]: O(n log n)
    boundBox bb(ms.a, false);
    bb.add(ms.b);
    const vector span(bb.span());
    const direction ax =
        span.x() >= span.y() && span.x() >= span.z() ? 0
      : (span.y() >= span.z() ? 1 : 2);
    scalarField lo(nM);
    scalarField hi(nM);
    scalar maxLength = 0;
    forAll(lo, m)
    {
        lo[m] = min(ms.a[m][ax], ms.b[m][ax]) - searchDistance_;
        hi[m] = max(ms.a[m][ax], ms.b[m][ax]) + searchDistance_;
        maxLength = max(maxLength, hi[m] - lo[m]);
    }
    labelList order(identity(nM));
    std::sort
    (
        order.begin(), order.end(),
        [&](const label i, const label j) { return lo[i] < lo[j]; }
    );
    scalarList sortedLo(nM);
    forAll(order, k)
    {
        sortedLo[k] = lo[order[k]];
    }

    DynamicList<faceOverlap> overlaps(8);
    forAll(faces, i)
    {
        slaveFace& sf = faces[i];
        sf = slaveFace();
        if (heldOutOfReach(i))
        {
            continue;
        }
        const point& as = sl.a[i];
        const point& bs = sl.b[i];
        const scalar sLo = min(as[ax], bs[ax]);
        const scalar sHi = max(as[ax], bs[ax]);

        overlaps.clear();
        label k = label
        (
            std::lower_bound
            (
                sortedLo.begin(), sortedLo.end(), sLo - maxLength
            ) - sortedLo.begin()
        );
        for (; k < nM && sortedLo[k] <= sHi; ++k)
        {
            const label m = order[k];
            if (hi[m] < sLo)
            {
                continue;
            }
            // facing surfaces only
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
            // the gap is linear over the overlap: its midpoint value is
            // its mean
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

        scalar total = 0;
        for (const faceOverlap& o : overlaps)
        {
            total += o.length;
        }
        if (total <= 0)
        {
            continue;
        }

        // [C10] weighted gap, normal, coverage; [C12] slip
        sf.inReach = true;
        sf.masters.setSize(overlaps.size());
        sf.weights.setSize(overlaps.size());
        sf.gap = 0;
        vector n(Zero);
        scalar projected = 0;
        vector dsMaster(Zero);
        forAll(overlaps, j)
        {
            const faceOverlap& o = overlaps[j];
            const scalar w = o.length/total;
            sf.masters[j] = o.master;
            sf.weights[j] = w;
            sf.gap += w*o.gap;
            n += w*ms.n[o.master];
            projected += w*o.projected;
            dsMaster += w*(ms.D[o.master] - ms.Dold[o.master]);
        }
        sf.n = n/max(mag(n), VSMALL);
        sf.area = min(total/max(projected, VSMALL), scalar(1))*sl.area[i];

        const vector ds((sl.D[i] - sl.Dold[i]) - dsMaster);
        frictionInput& in = sf.input;
        in.gN = smoothedPenetration(-sf.gap);
        in.gT = (tensor::I - sqr(sf.n)) & (state()[i].totalSlip + ds);
        in.n = sf.n;
        in.dt = deltaT;
        faceUpdate(i, in, sf.result);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformableContactFvPatchVectorField::force
(
    const solidPatchKinematics& k,
    vectorField& f
) const
{
    checkPair();
    side sl;
    side ms;
    List<slaveFace> faces;
    evaluate(sl, ms, faces, k.deltaT);
    vectorField fs;
    vectorField fm;
    pairForces(faces, ms.X.size(), fs, fm);
    f = slave_ ? fs : fm;
}


void Foam::deformableContactFvPatchVectorField::tangent
(
    const solidPatchKinematics& k,
    List<faceForceTangent>& df
) const
{
    // [C13] the slave face's exact tangent with the master held (a flat
    // master under each face: dgap/dx = n, dgT/dx = I - n n), [C6]; the
    // master face sees sum_s w_sm^2 K_s
    checkPair();
    side sl;
    side ms;
    List<slaveFace> faces;
    evaluate(sl, ms, faces, k.deltaT);

    df.setSize(patch().size());
    df = faceForceTangent();

    forAll(faces, i)
    {
        const slaveFace& sf = faces[i];
        if (!sf.inReach)
        {
            continue;
        }
        const frictionResult& res = sf.result;
        const vector& n = sf.n;
        const tensor P(tensor::I - sqr(n));
        const vector dgNdx(-smoothedPenetrationSlope(-sf.gap)*n);
        const tensor dtTdx((res.dtTdgT & P) + res.dtTdgN*dgNdx);
        const tensor K(sf.area*(n*(res.dtNdgN*dgNdx) - dtTdx));

        if (slave_)
        {
            // the current area: da = |a|, a = J F^-T . S0; f = c da t
            const tensor& F = sl.F[i];
            const tensor FinvT(inv(F).T());
            const vector a(det(F)*(FinvT & sl.S0[i]));
            const scalar da = mag(a);
            const tensor dAreadF(da*FinvT - a*(inv(F) & (a/da)));
            const vector t(res.tN*n - res.tT);
            const scalar c = sf.area/max(da, VSMALL);
            df[i].dfdD = K;
            for (direction d = 0; d < 3; ++d)
            {
                df[i].dfdF[d] = (c*t[d])*dAreadF;
            }
        }
        else
        {
            forAll(sf.masters, j)
            {
                df[sf.masters[j]].dfdD += sqr(sf.weights[j])*K;
            }
        }
    }
}


void Foam::deformableContactFvPatchVectorField::linearise
(
    const solidPatchKinematics& k
)
{
    if (!slave_)
    {
        return;
    }
    checkPair();
    beginHold();
    side sl;
    side ms;
    List<slaveFace> faces;
    evaluate(sl, ms, faces, k.deltaT);
    forAll(faces, i)
    {
        holdFace(i, faces[i].inReach, faces[i].input, faces[i].result);
    }
    startHold();
}


void Foam::deformableContactFvPatchVectorField::release()
{
    if (slave_)
    {
        releaseHold();
    }
}


void Foam::deformableContactFvPatchVectorField::commit
(
    const solidPatchKinematics& k
)
{
    checkPair();
    const label timeIndex = db().time().timeIndex();
    side sl;
    side ms;
    List<slaveFace> faces;

    if (slave_)
    {
        evaluate(sl, ms, faces, k.deltaT);
        vectorField fs;
        pairForces(faces, ms.X.size(), fs, committedMasterForce_);
        committedTimeIndex_ = timeIndex;

        beginCommit();
        forAll(faces, i)
        {
            const slaveFace& sf = faces[i];
            if (sf.inReach)
            {
                commitFace
                (
                    i, sf.result, sf.n, sf.area, sf.gap, mag(sl.S0[i]),
                    sl.X[i] + sl.D[i]
                );
            }
            else
            {
                commitOpenFace(i);
            }
        }
        endCommit();
        return;
    }

    // The master: the forces of the step as the slave had them before its
    // state moved on (if it committed first)
    const deformableContactFvPatchVectorField& s = partner();
    vectorField fm;
    if (s.committedTimeIndex_ == timeIndex)
    {
        fm = s.committedMasterForce_;
        kinematics(ms);
    }
    else
    {
        evaluate(sl, ms, faces, k.deltaT);
        vectorField fs;
        pairForces(faces, ms.X.size(), fs, fm);
    }
    commitReaction(fm, ms.n, ms.area, mag(ms.S0));
}


void Foam::deformableContactFvPatchVectorField::report
(
    const solidPatchKinematics& k
) const
{
    reportFaces(k.time);
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    contactFaces: the slave-face loop against a master surface
    (doc/theory.md [C1]-[C6], [C10], [C12]), shared by frictionalContact
    (a rigid obstacle) and deformableContact (the partner body's patch):
    master point -> the law's input -> law -> force, its exact tangent
    against a master without unknowns, the hold and the commit of the
    evaluated faces.

\*---------------------------------------------------------------------------*/

#include "contactFaces.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactFaces::evaluateSlaveFace
(
    const label i,
    const contactSurface& master,
    const vector& dOwn,
    const scalar area,
    const scalar dt,
    slaveFace& sf,
    const slaveFace* held
) const
{
    sf = slaveFace();
    if (heldOutOfReach(i) || !master.masterPointOf(i, sf))
    {
        return;
    }

    // [C10] the force acts on the covered part of the face
    sf.area = sf.coverage*area;

    // [C3], [C12] slip relative to the master in the current tangent plane
    // (objective rate, [F29]): the face's motion over the step less that of
    // the master's material point(s) under it; [C2b] smoothed penetration
    const vector ds(dOwn - sf.motion);
    frictionInput& in = sf.input;
    in.gN = smoothedPenetration(augmentedPenetration(i, sf.gap));
    in.gT = (tensor::I - sqr(sf.n)) & (state()[i].totalSlip + ds);
    in.n = sf.n;
    in.dt = dt;
    in.shearYield = shearYield(i);
    if (held)
    {
        // the law's consistent tangent at the held result [F7], with the
        // turn of the tangent plane inside the law
        linearAbout(held->input, held->result, in, sf.result);
        sf.result.tT += held->dtTdn & (in.n - held->input.n);
    }
    else
    {
        faceUpdate(i, in, sf.result);
    }

    // [S14c] a face predicted to close: the penalty's line through its
    // gap (a pull while open), no friction
    const scalar pen = augmentedPenetration(i, sf.gap);
    if (predictedClosed(i) && pen < onsetWidth())
    {
        sf.result.tN = law().KN()*pen;
        sf.result.tT = Zero;
    }
}


void Foam::contactFaces::evaluateSlaveFaces
(
    const contactSurface& master,
    const vectorField& dOwn,
    const scalarField& area,
    const scalar dt,
    List<slaveFace>& faces
) const
{
    faces.setSize(dOwn.size());
    forAll(faces, i)
    {
        evaluateSlaveFace(i, master, dOwn[i], area[i], dt, faces[i]);
    }
}


Foam::tensor Foam::contactFaces::tangentialTurn
(
    const frictionState& old,
    const frictionInput& in,
    const frictionResult& res
) const
{
    // [F7] the law's tangential traction as its normal turns at the same
    // slip: d tT/d n on the tangent plane, by central differences in n
    // along two tangents t_j: sum_j (d tT/d t_j) t_j. A result without
    // tangential traction (an open face, a frictionless law, no elastic
    // slip) keeps none as the plane turns
    if (res.tT == vector::zero)
    {
        return Zero;
    }
    const scalar h = 1e-6;
    const vector& n = in.n;
    const tensor P(tensor::I - sqr(n));
    vector t1(P & vector(1, 0, 0));
    if (magSqr(t1) < 0.1)
    {
        t1 = P & vector(0, 1, 0);
    }
    t1 /= mag(t1);
    const vector t2(n ^ t1);
    tensor turn(Zero);
    for (const vector& tj : {t1, t2})
    {
        frictionInput inp(in);
        frictionInput inm(in);
        inp.n = (n + h*tj)/mag(n + h*tj);
        inm.n = (n - h*tj)/mag(n - h*tj);
        frictionResult rp;
        frictionResult rm;
        law().update(old, inp, rp);
        law().update(old, inm, rm);
        turn += ((rp.tT - rm.tT)/(2*h))*tj;
    }
    return turn;
}


void Foam::contactFaces::slaveFaceTangent
(
    const label i,
    const masterPoint& mp,
    const vector& dOwn,
    const tensor& F,
    const vector& S0,
    const scalar dt,
    faceForceTangent& df
) const
{
    // [C6] the exact derivative of f = da (tN n - tT) with respect to the
    // face displacement and deformation gradient, the face state held
    const frictionState& old = state()[i];
    const vector& n = mp.n;
    const tensor& N = mp.dndx;
    const tensor P(tensor::I - sqr(n));
    const vector v(old.totalSlip + dOwn - mp.motion);

    frictionInput in;
    const scalar pen = augmentedPenetration(i, mp.gap);
    in.gN = smoothedPenetration(pen);
    in.gT = P & v;
    in.n = n;
    in.dt = dt;
    in.shearYield = shearYield(i);
    frictionResult res;
    law().update(old, in, res);

    // [S14c] a face predicted to close: the penalty's line through its
    // gap, no friction (evaluateSlaveFace)
    const bool lineOnly = predictedClosed(i) && pen < onsetWidth();
    if (lineOnly)
    {
        res.tN = law().KN()*pen;
        res.dtNdgN = law().KN();
        res.tT = Zero;
    }

    // gN = smoothed(-gap) [C2b]; gT = (I - n n).v [C3]
    const vector dgNdx
    (
        -(lineOnly ? 1 : smoothedPenetrationSlope(pen))*mp.dgapdx
    );
    const tensor dvdx(tensor::I - mp.dmotiondx);
    const tensor dgTdx((P & dvdx) - (n & v)*N - n*(N.T() & v));

    // the law's tangent [F7]; on a curved master also the turn of the
    // tangent plane inside the law
    tensor dtTdx(Zero);
    if (!lineOnly)
    {
        dtTdx = (res.dtTdgT & dgTdx) + res.dtTdgN*dgNdx;
    }
    if (!lineOnly && magSqr(N) > 0)
    {
        dtTdx += tangentialTurn(old, in, res) & N;
    }

    // [C4] area da = |a|, a = J F^-T . S0
    const tensor FinvT(inv(F).T());
    const vector a(currentAreaVector(F, S0));
    const scalar area = mag(a);
    const tensor dAreadF(area*FinvT - a*(inv(F) & (a/area)));

    const vector t(res.tN*n - res.tT);
    df.dfdD = area*(n*(res.dtNdgN*dgNdx) + res.tN*N - dtTdx);
    for (direction r = 0; r < 3; ++r)
    {
        df.dfdF[r] = t[r]*dAreadF;
    }
}


Foam::tmp<Foam::scalarField> Foam::contactFaces::augmentedPenetrations
(
    const contactSurface& master
) const
{
    tmp<scalarField> tp(new scalarField(contactPatch().size(), -GREAT));
    scalarField& p = tp.ref();
    forAll(p, i)
    {
        masterPoint mp;
        if (master.masterPointOf(i, mp))
        {
            p[i] = augmentedPenetration(i, mp.gap);
        }
    }
    return tp;
}


Foam::scalar Foam::contactFaces::contactOnsetFraction
(
    const scalarField& p0,
    const scalarField& p1
) const
{
    // [S14b] linear in the fraction between the two ends
    const scalar e = onsetWidth();
    scalar fraction = 1;
    onsetFace_ = -1;
    onsetClosing_ = 0;
    forAll(p0, i)
    {
        if (p0[i] < -e && p1[i] > e)
        {
            ++onsetClosing_;
            const scalar f = -p0[i]/(p1[i] - p0[i]);
            if (f < fraction)
            {
                fraction = f;
                onsetFace_ = i;
                onsetP0_ = p0[i];
                onsetP1_ = p1[i];
            }
        }
    }
    onsetFaceFraction_ = fraction;
    reduce(onsetClosing_, sumOp<label>());
    return returnReduce(fraction, minOp<scalar>());
}


bool Foam::contactFaces::lastContactOnset
(
    scalar& fraction,
    string& where
) const
{
    if (onsetFace_ < 0)
    {
        return false;
    }
    fraction = onsetFaceFraction_;
    OStringStream os;
    os  << "face " << onsetFace_ << " of " << contactPatch().name()
        << " at " << contactPatch().Cf()[onsetFace_] << ", penetration "
        << onsetP0_ << " -> " << onsetP1_ << " m (onset width "
        << onsetWidth() << " m), " << onsetClosing_
        << " faces of the patch closing";
    where = os.str();
    return true;
}


Foam::label Foam::contactFaces::markPredictedClosed
(
    const scalarField& p0,
    const scalarField& p1
)
{
    // [S14c] the faces [S14b] would stop at
    const scalar e = onsetWidth();
    if (predictedClosed_.size() != p0.size())
    {
        predictedClosed_.setSize(p0.size());
        predictedClosed_ = false;
    }
    label nNew = 0;
    forAll(p0, i)
    {
        if (!predictedClosed_[i] && p0[i] < -e && p1[i] > e)
        {
            predictedClosed_[i] = true;
            ++nNew;
        }
    }
    return returnReduce(nNew, sumOp<label>());
}


Foam::labelList Foam::contactFaces::facesLeftReach
(
    const List<slaveFace>& faces
) const
{
    DynamicList<label> left;
    forAll(faces, i)
    {
        if (!faces[i].inReach && committedInReach_[i])
        {
            left.append(i);
        }
    }
    return labelList(std::move(left));
}


Foam::label Foam::contactFaces::reportPressedThrough
(
    const labelList& left,
    const scalarList& gaps,
    const vectorField& x,
    const scalar searchDistance
) const
{
    label n = 0;
    scalar deepest = 0;
    point at(Zero);
    forAll(left, j)
    {
        if (gaps[j] < -searchDistance)
        {
            ++n;
            if (-gaps[j] > deepest)
            {
                deepest = -gaps[j];
                at = x[left[j]];
            }
        }
    }
    reduce(n, sumOp<label>());
    if (n)
    {
        const scalar deepestAll = returnReduce(deepest, maxOp<scalar>());
        if (deepest != deepestAll)
        {
            at = Zero;
        }
        reduce(at, maxMagSqrOp<vector>());
        Info<< "    patch " << contactPatch().name() << ": " << n
            << " faces within reach at the last converged state are"
            << " pressed through the other surface beyond the search distance "
            << searchDistance << " m (the deepest by " << deepestAll
            << " m at " << at << "): the solve is rejected. If a smaller"
            << " step does not keep them, a part of the surface next to"
            << " them that is not in the contact patch (a tool's side) may"
            << " let the body through; otherwise raise 'searchDistance'"
            << endl;
    }
    return n;
}


void Foam::contactFaces::holdSlaveFaces(const List<slaveFace>& faces)
{
    beginHold();
    forAll(faces, i)
    {
        holdFace(i, faces[i].inReach, faces[i].input, faces[i].result);
    }
    startHold();
}


void Foam::contactFaces::commitSlaveFaces
(
    const List<slaveFace>& faces,
    const vectorField& S0,
    const vectorField& x
)
{
    beginCommit();
    forAll(faces, i)
    {
        const slaveFace& sf = faces[i];
        if (sf.inReach)
        {
            commitFace(i, sf.result, sf.n, sf.area, sf.gap, mag(S0[i]), x[i]);
        }
        else
        {
            // out of reach: an open face, fresh if it comes back
            commitOpenFace(i);
        }
    }
    endCommit();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    deformableContact: the slave faces against the master surface
    ([C10]-[C13] in doc/theory.md): the candidates, the slave-face loop of
    contactFaces against the overlaps (overlapContactSurface), the forces
    of both sides, their derivatives, the held linearisation and the
    commit.

\*---------------------------------------------------------------------------*/

#include "deformableContactFvPatchVectorField.H"
#include "volFields.H"
#include "HashSet.H"
#include <ctime>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Adds the CPU time of its scope to 'sum' [s]; std::clock resolves
//  microseconds where OpenFOAM's cpuTime counts 10 ms ticks, too coarse for
//  the many short calls of a pair
class pairTimer
{
    scalar& sum_;
    const std::clock_t start_ = std::clock();

public:

    explicit pairTimer(scalar& sum)
    :
        sum_(sum)
    {}

    ~pairTimer()
    {
        sum_ += scalar(std::clock() - start_)/CLOCKS_PER_SEC;
    }
};


//- [C13] The outputs of slave face sf: its force f_s and the share
//  -w_sm f_s of each of the given masters (zero where it does not overlap
//  them or is out of reach)
static void pairOutputs
(
    const slaveFace& sf,
    const labelList& masters,
    List<vector>& out
)
{
    out.setSize(1 + masters.size());
    out = Zero;
    if (!sf.inReach)
    {
        return;
    }
    const vector f(contactFaces::slaveForce(sf));
    out[0] = f;
    forAll(masters, j)
    {
        const label k = sf.masters.find(masters[j]);
        if (k >= 0)
        {
            out[1 + j] = -sf.weights[k]*f;
        }
    }
}


//- Where slave face i's derivatives d with respect to face 'col' (of the
//  slave if slaveCol, else of the master) go: output 0 is the slave
//  face's row, output 1 + j master face masters[j]'s; a face's derivative
//  with respect to itself is its own tangent, any other a coupling (the
//  slave's column in its global face numbering [C14])
struct pairDerivatives
{
    List<faceForceTangent>& slaveOwn;
    List<faceForceTangent>& masterOwn;
    DynamicList<faceCoupling>& slaveCoupling;
    DynamicList<faceCoupling>& masterCoupling;
    label slavePatch;
    label masterPatch;
    const globalIndex& slaveFaces;

    void add
    (
        const label i,
        const labelList& masters,
        const bool slaveCol,
        const label col,
        const List<faceForceTangent>& d
    ) const
    {
        forAll(d, o)
        {
            const bool slaveRow = o == 0;
            const label row = slaveRow ? i : masters[o - 1];
            if (slaveRow == slaveCol && row == col)
            {
                faceForceTangent& t = slaveRow ? slaveOwn[row] : masterOwn[row];
                t.dfdD += d[o].dfdD;
                for (direction r = 0; r < 3; ++r)
                {
                    t.dfdF[r] += d[o].dfdF[r];
                }
                continue;
            }
            faceCoupling e;
            e.face = row;
            e.patch = slaveCol ? slavePatch : masterPatch;
            e.otherFace = slaveCol ? slaveFaces.toGlobal(col) : col;
            e.df = d[o];
            (slaveRow ? slaveCoupling : masterCoupling).append(e);
        }
    }
};

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::deformableContactFvPatchVectorField::candidates
(
    const side& sl,
    const side& ms,
    const scalar margin,
    labelListList& cand
) const
{
    const pairTimer timer(cost_.search);
    overlapContactSurface::findCandidates
    (
        sl, ms, searchDistance_, margin, cand
    );
}


void Foam::deformableContactFvPatchVectorField::evaluatePair
(
    const side& sl,
    const side& ms,
    const scalar deltaT,
    List<slaveFace>& faces
) const
{
    labelListList cand;
    candidates(sl, ms, 0, cand);
    evaluateSlaveFaces
    (
        overlapContactSurface(sl, ms, cand, searchDistance_),
        sl.D - sl.Dold, sl.area, deltaT, faces
    );
}


bool Foam::deformableContactFvPatchVectorField::takeCached
(
    const bool forSlave,
    const side& sl,
    const side& ms,
    const scalar time,
    const scalar deltaT,
    List<faceForceTangent>& own,
    DynamicList<faceCoupling>& c
) const
{
    tangentCache& k = cache_;
    bool hit =
        k.valid
     && k.forSlave == forSlave
     && k.time == time
     && k.deltaT == deltaT
     && k.slaveD == sl.D && k.slaveF == sl.F
     && k.masterD == ms.D && k.masterF == ms.F;
    // [C14] every processor takes the cache or none (the evaluation
    // communicates)
    reduce(hit, andOp<bool>());
    if (hit)
    {
        own.transfer(k.own);
        c.transfer(k.couplings);
        ++cost_.nCached;
    }
    k = tangentCache();
    return hit;
}


void Foam::deformableContactFvPatchVectorField::slaveFaceDerivatives
(
    const label i,
    const slaveFace& base,
    const contactSurface& master,
    side& sl,
    side& s,
    const label fi,
    const scalar deltaT,
    List<faceForceTangent>& d
) const
{
    const labelList& masters = base.masters;
    const scalar hD = 1e-6*faceLength(s, fi);
    const scalar hF = 1e-6;
    const vector D0(s.D[fi]);
    const tensor F0(s.F[fi]);

    List<vector> outP;
    List<vector> outM;
    d.setSize(1 + masters.size());
    d = faceForceTangent();
    for (direction c = 0; c < 12; ++c)
    {
        const scalar h = c < 3 ? hD : hF;
        for (const scalar sign : {1.0, -1.0})
        {
            if (c < 3)
            {
                s.D[fi] = D0;
                s.D[fi][c] += sign*h;
            }
            else
            {
                s.F[fi] = F0;
                s.F[fi][c - 3] += sign*h;
            }
            faceGeometry(s, fi);
            slaveFace sf;
            evaluateSlaveFace
            (
                i, master, sl.D[i] - sl.Dold[i], sl.area[i], deltaT, sf,
                &base
            );
            pairOutputs(sf, masters, sign > 0 ? outP : outM);
        }
        s.D[fi] = D0;
        s.F[fi] = F0;
        faceGeometry(s, fi);

        forAll(d, o)
        {
            const vector dOut((outP[o] - outM[o])/(2*h));
            for (direction r = 0; r < 3; ++r)
            {
                if (c < 3)
                {
                    d[o].dfdD[3*r + c] = dOut[r];
                }
                else
                {
                    d[o].dfdF[r][c - 3] = dOut[r];
                }
            }
        }
    }
}


void Foam::deformableContactFvPatchVectorField::pairTangent
(
    side& sl,
    side& ms,
    const scalar deltaT,
    List<faceForceTangent>& slaveOwn,
    List<faceForceTangent>& masterOwn,
    DynamicList<faceCoupling>& slaveCoupling,
    DynamicList<faceCoupling>& masterCoupling
) const
{
    // [C13] for every slave face in contact: the derivatives of its force
    // f_s and of its share -w_sm f_s of each master face's force with
    // respect to the kinematics (D, F) of the faces it involves (itself and
    // the masters it overlaps), by central differences of the face's
    // geometry with the law linear about its result (the law's consistent
    // tangent, [F7]): face-local, so a handful of face evaluations per
    // face and derivative
    labelListList cand;
    candidates(sl, ms, 0, cand);
    // a view of sl and ms: sees the perturbations of slaveFaceDerivatives
    const overlapContactSurface master(sl, ms, cand, searchDistance_);

    slaveOwn.setSize(sl.X.size());
    slaveOwn = faceForceTangent();
    masterOwn.setSize(ms.X.size());
    masterOwn = faceForceTangent();
    slaveCoupling.clear();
    masterCoupling.clear();
    const globalIndex slaveFaces(sl.X.size());
    const pairDerivatives to
    {
        slaveOwn, masterOwn, slaveCoupling, masterCoupling,
        patch().index(), partner().patch().index(), slaveFaces
    };

    List<faceForceTangent> d;
    forAll(sl.X, i)
    {
        slaveFace base;
        evaluateSlaveFace
        (
            i, master, sl.D[i] - sl.Dold[i], sl.area[i], deltaT, base
        );
        if (!base.inReach)
        {
            continue;
        }
        base.dtTdn = tangentialTurn(state()[i], base.input, base.result);
        const labelList masters(base.masters);

        slaveFaceDerivatives(i, base, master, sl, sl, i, deltaT, d);
        to.add(i, masters, true, i, d);
        for (const label mi : masters)
        {
            slaveFaceDerivatives(i, base, master, sl, ms, mi, deltaT, d);
            to.add(i, masters, false, mi, d);
        }
    }
    ++cost_.nTangent;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformableContactFvPatchVectorField::force
(
    const solidPatchKinematics& k,
    vectorField& f
) const
{
    checkPair();
    const pairTimer timer(slaveSide().cost_.forces);
    side sl;
    side ms;
    List<slaveFace> faces;
    evaluate(sl, ms, faces, k.deltaT);
    vectorField fs;
    vectorField fm;
    pairForces(faces, ms.X.size(), fs, fm);
    if (slave_)
    {
        f = fs;
        return;
    }
    reduceMasterForces(fm, patch().size());
    f = fm;
}


void Foam::deformableContactFvPatchVectorField::tangent
(
    const solidPatchKinematics& k,
    List<faceForceTangent>& df
) const
{
    DynamicList<faceCoupling> c;
    tangentAndCouplings(k, df, c);
}


void Foam::deformableContactFvPatchVectorField::tangentAndCouplings
(
    const solidPatchKinematics& k,
    List<faceForceTangent>& df,
    DynamicList<faceCoupling>& c
) const
{
    // This side's own-face tangents and couplings [C13]
    // One evaluation of the pair's derivatives per Jacobian: the side
    // asked first computes both sides' and leaves the other's in the
    // slave's cache, the other takes them if the iterate is the same
    checkPair();
    const deformableContactFvPatchVectorField& s = slaveSide();
    const pairTimer timer(s.cost_.tangent);
    side sl;
    side ms;
    s.kinematics(sl);
    s.partnerKinematics(ms, false);
    if (s.takeCached(slave_, sl, ms, k.time, k.deltaT, df, c))
    {
        return;
    }
    List<faceForceTangent> slaveOwn;
    List<faceForceTangent> masterOwn;
    DynamicList<faceCoupling> cs;
    DynamicList<faceCoupling> cm;
    s.pairTangent(sl, ms, k.deltaT, slaveOwn, masterOwn, cs, cm);
    if (Pstream::parRun())
    {
        // [C14] the master rows (global numbering, this processor's slave
        // faces' shares) to the master faces' processors; the own-face
        // tangents travel as couplings of a face to itself
        const label masterPatch = s.partner().patch().index();
        forAll(masterOwn, mi)
        {
            const faceForceTangent& t = masterOwn[mi];
            if (t.dfdD != tensor::zero || t.dfdF[0] != tensor::zero
             || t.dfdF[1] != tensor::zero || t.dfdF[2] != tensor::zero)
            {
                faceCoupling e;
                e.face = mi;
                e.patch = masterPatch;
                e.otherFace = mi;
                e.df = t;
                cm.append(e);
            }
        }
        const globalIndex masterFaces(s.partner().patch().size());
        sendToRowOwners(cm, masterFaces);
        masterOwn.setSize(masterFaces.localSize());
        masterOwn = faceForceTangent();
    }

    tangentCache& cache = s.cache_;
    cache.valid = true;
    cache.forSlave = !slave_;
    cache.time = k.time;
    cache.deltaT = k.deltaT;
    cache.slaveD = sl.D;
    cache.slaveF = sl.F;
    cache.masterD = ms.D;
    cache.masterF = ms.F;
    cache.own.transfer(slave_ ? masterOwn : slaveOwn);
    cache.couplings.transfer(slave_ ? cm : cs);

    df.transfer(slave_ ? slaveOwn : masterOwn);
    c.transfer(slave_ ? cs : cm);
}


void Foam::deformableContactFvPatchVectorField::couplingCandidates
(
    const scalar margin,
    DynamicList<faceCoupling>& c
) const
{
    // [C13] slave face i couples to its candidate masters; master face m
    // to the slave faces that may overlap it and to their other candidates
    checkPair();
    const deformableContactFvPatchVectorField& s = slaveSide();
    const pairTimer timer(s.cost_.pattern);
    const deformableContactFvPatchVectorField& m = s.partner();
    side sl;
    side ms;
    s.kinematics(sl);
    s.partnerKinematics(ms, false);
    labelListList cand;
    s.candidates(sl, ms, margin, cand);
    // [C14] master faces in the master's global numbering (the gathered
    // surface), slave columns of master rows in the slave's
    const globalIndex slaveFaces(sl.X.size());

    c.clear();
    faceCoupling e;
    // a pair of master faces shares the candidate lists of many slave
    // faces: each coupling listed once (the pattern is a set, and every
    // entry listed is a stencil to add and, in parallel, to send)
    HashSet<labelPair, labelPair::Hash<>> masterPairs;
    forAll(cand, i)
    {
        for (const label mi : cand[i])
        {
            if (slave_)
            {
                e.face = i;
                e.patch = m.patch().index();
                e.otherFace = mi;
                c.append(e);
                continue;
            }
            e.face = mi;
            e.patch = s.patch().index();
            e.otherFace = slaveFaces.toGlobal(i);
            c.append(e);
            for (const label mj : cand[i])
            {
                if (mj != mi && masterPairs.insert(labelPair(mi, mj)))
                {
                    e.patch = patch().index();
                    e.otherFace = mj;
                    c.append(e);
                }
            }
        }
    }
    if (!slave_)
    {
        sendToRowOwners(c, globalIndex(patch().size()));
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
    side sl;
    side ms;
    List<slaveFace> faces;
    evaluate(sl, ms, faces, k.deltaT);
    holdSlaveFaces(faces);
}


void Foam::deformableContactFvPatchVectorField::release()
{
    if (slave_)
    {
        releaseHold();
    }
}


bool Foam::deformableContactFvPatchVectorField::augment
(
    const solidPatchKinematics& k
)
{
    // the slave carries the law and its multipliers; the master nothing
    if (!slave_ || !augmented())
    {
        return false;
    }
    checkPair();
    side sl;
    side ms;
    List<slaveFace> faces;
    evaluate(sl, ms, faces, k.deltaT);
    if (!augmentSlaveFaces(faces))
    {
        return false;
    }
    // the derivatives cached for this iterate hold the old multipliers
    cache_ = tangentCache();
    return true;
}


void Foam::deformableContactFvPatchVectorField::resetAugmentation
(
    const scalar extrapolation
)
{
    if (slave_)
    {
        multipliers().predict(extrapolation);
        cache_ = tangentCache();
    }
}


Foam::label Foam::deformableContactFvPatchVectorField::facesPressedThrough
(
    const solidPatchKinematics& k
) const
{
    // [C2e] the slave faces that left the search distance against the
    // master surface searched as far as the bodies moved in the step: a
    // face within reach at its start is at most that far through
    if (!slave_)
    {
        return 0;
    }
    checkPair();
    side sl;
    side ms;
    List<slaveFace> faces;
    evaluate(sl, ms, faces, k.deltaT);
    const labelList left(facesLeftReach(faces));
    if (!returnReduce(left.size(), sumOp<label>()))
    {
        return 0;
    }
    scalar moved = 0;
    for (const label i : left)
    {
        moved = max(moved, mag(sl.D[i] - sl.Dold[i]));
    }
    reduce(moved, maxOp<scalar>());
    if (ms.D.size())
    {
        moved += max(mag(ms.D - ms.Dold));
    }
    const scalar reach = searchDistance_ + moved;
    labelListList cand;
    overlapContactSurface::findCandidates(sl, ms, reach, 0, cand);
    const overlapContactSurface wide(sl, ms, cand, reach);
    scalarList gaps(left.size(), GREAT);
    forAll(left, j)
    {
        masterPoint mp;
        if (wide.masterPointOf(left[j], mp))
        {
            gaps[j] = mp.gap;
        }
    }
    return reportPressedThrough(left, gaps, sl.X + sl.D, searchDistance_);
}


void Foam::deformableContactFvPatchVectorField::commit
(
    const solidPatchKinematics& k
)
{
    checkPair();
    side sl;
    side ms;
    List<slaveFace> faces;

    if (slave_)
    {
        evaluate(sl, ms, faces, k.deltaT);
        vectorField fs;
        pairForces(faces, ms.X.size(), fs, committedMasterForce_);
        reduceMasterForces(committedMasterForce_, partner().patch().size());
        committedTime_ = k.time;

        commitSlaveFaces(faces, sl.S0, sl.X + sl.D);
        return;
    }

    // The master: the forces of the step as the slave had them before its
    // state moved on (if it committed first)
    const deformableContactFvPatchVectorField& s = partner();
    vectorField fm;
    if (s.committedTime_ == k.time)
    {
        fm = s.committedMasterForce_;
    }
    else
    {
        evaluate(sl, ms, faces, k.deltaT);
        vectorField fs;
        pairForces(faces, ms.X.size(), fs, fm);
        reduceMasterForces(fm, patch().size());
    }
    // this processor's master faces
    kinematics(ms);
    commitReaction(fm, ms.n, ms.area, mag(ms.S0));
}


void Foam::deformableContactFvPatchVectorField::report
(
    const solidPatchKinematics& k
) const
{
    reportFaces(k.time);
    if (debug && slave_)
    {
        // The pair's share of the run's CPU time (the search is part of
        // the forces and derivatives)
        const pairCost& c = cost_;
        const scalar run = max(db().time().elapsedCpuTime(), SMALL);
        Info<< "    deformableContact " << patch().name() << ": CPU time "
            << "search " << c.search << " s, forces " << c.forces
            << " s, derivatives " << c.tangent << " s (" << c.nTangent
            << " computed, " << c.nCached << " taken from the cache), "
            << "pattern " << c.pattern << " s; together "
            << 100*(c.forces + c.tangent + c.pattern)/run
            << " % of the run's " << run << " s" << endl;
    }
}


// ************************************************************************* //

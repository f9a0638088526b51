/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    deformableContact in parallel ([C14] in doc/theory.md): the master
    surface gathered to every processor (each evaluates its own slave faces
    against all of it), the reactions summed onto the master faces'
    processors and the master rows' derivatives sent there. In serial
    every function here leaves its arguments as they are.

\*---------------------------------------------------------------------------*/

#include "deformableContactFvPatchVectorField.H"
#include "ListListOps.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Replace f by the concatenation of every processor's f, in processor
//  order
template<class T>
static void gatherAll(List<T>& f)
{
    List<List<T>> all(Pstream::nProcs());
    all[Pstream::myProcNo()].transfer(f);
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    f = ListListOps::combine<List<T>>(all, accessOp<List<T>>());
}

template<class T>
static void gatherField(Field<T>& f)
{
    List<T>& l = f;
    gatherAll(l);
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::deformableContactFvPatchVectorField::gatherSide(side& s)
{
    // [C14] a contact surface is small against the volume: every
    // processor holds all of it. The deformed geometry is recomputed from
    // the gathered D and F (the same operations as on the owner)
    if (!Pstream::parRun())
    {
        return;
    }
    gatherField(s.X);
    gatherField(s.S0);
    gatherField(s.D);
    gatherField(s.Dold);
    gatherField(s.F);
    gatherField(s.Xa);
    gatherField(s.Xb);
    gatherAll(s.Xv);
    const label n = s.X.size();
    s.v = s.Xv;
    s.a.setSize(n);
    s.b.setSize(n);
    s.area.setSize(n);
    s.n.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        faceGeometry(s, i);
    }
}


void Foam::deformableContactFvPatchVectorField::partnerKinematics
(
    side& s,
    const bool committed
) const
{
    if (committed)
    {
        partner().committedKinematics(s);
    }
    else
    {
        partner().kinematics(s);
    }
    gatherSide(s);
}


void Foam::deformableContactFvPatchVectorField::reduceMasterForces
(
    vectorField& f,
    const label nLocal
)
{
    // [C10], [C14] f_m = -sum_s w_sm f_s: each processor holds the shares
    // of its slave faces
    if (!Pstream::parRun())
    {
        return;
    }
    Pstream::listCombineGather(f, plusEqOp<vector>());
    Pstream::listCombineScatter(f);
    const globalIndex numbering(nLocal);
    f = vectorField(SubField<vector>(f, nLocal, numbering.localStart()));
}


void Foam::deformableContactFvPatchVectorField::sendToRowOwners
(
    DynamicList<faceCoupling>& c,
    const globalIndex& rows
)
{
    // [C14] the master rows' derivatives are computed where the slave
    // faces are; the matrix rows are the master faces' processor's
    if (!Pstream::parRun())
    {
        return;
    }
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    List<DynamicList<label>> labels(nProcs);
    List<DynamicList<tensor>> values(nProcs);
    DynamicList<faceCoupling> mine(c.size());
    for (faceCoupling& e : c)
    {
        const label proci = rows.whichProcID(e.face);
        e.face = rows.toLocal(proci, e.face);
        if (proci == me)
        {
            mine.append(e);
            continue;
        }
        labels[proci].append(e.face);
        labels[proci].append(e.patch);
        labels[proci].append(e.otherFace);
        values[proci].append(e.df.dfdD);
        for (const tensor& t : e.df.dfdF)
        {
            values[proci].append(t);
        }
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci != me)
        {
            UOPstream to(proci, buffers);
            to << labels[proci] << values[proci];
        }
    }
    buffers.finishedSends();

    c.transfer(mine);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci == me)
        {
            continue;
        }
        UIPstream from(proci, buffers);
        labelList l;
        List<tensor> v;
        from >> l >> v;
        for (label k = 0; 3*k < l.size(); ++k)
        {
            faceCoupling e;
            e.face = l[3*k];
            e.patch = l[3*k + 1];
            e.otherFace = l[3*k + 2];
            e.df.dfdD = v[4*k];
            for (direction r = 0; r < 3; ++r)
            {
                e.df.dfdF[r] = v[4*k + 1 + r];
            }
            c.append(e);
        }
    }
}


// ************************************************************************* //

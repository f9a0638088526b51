/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    deformableContact: the predictor that keeps the contact for a pair of
    deformable bodies ([S18b] in doc/theory.md): the slave faces in contact
    at the last converged state keep their converged gap against the
    predicted master surface, unless they are predicted to slide past the
    master faces under them.

\*---------------------------------------------------------------------------*/

#include "deformableContactFvPatchVectorField.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::deformableContactFvPatchVectorField::predictedSlip
(
    const side& sl,
    const label i,
    const masterPoint& p
)
{
    // [C3], [C12] the slave face's motion over the step relative to the
    // master's material point(s) under it, in the tangent plane
    const vector ds(sl.D[i] - sl.Dold[i] - p.motion);
    return mag(ds - (p.n & ds)*p.n);
}


Foam::scalar Foam::deformableContactFvPatchVectorField::masterLength
(
    const side& ms,
    const masterPoint& p
)
{
    // the weighted size of the master faces under a slave face
    scalar l = 0;
    forAll(p.masters, j)
    {
        l += p.weights[j]*faceLength(ms, p.masters[j]);
    }
    return l;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::deformableContactFvPatchVectorField::predictorCorrection
(
    const solidPatchKinematics& k,
    vectorField& dD
) const
{
    // [S18b] as against a rigid obstacle: the extrapolated step repeats the
    // last one's closing of the gap and predicts the faces out of contact
    // again. Here the master surface moves with its body, so the gaps of
    // both states are the pair's [C10]-[C11b]: at the prediction (both
    // bodies extrapolated) and at the converged state (both sides' face
    // displacements as committed). The slave's faces are corrected; the
    // master's follow their body. Every processor takes part (the master
    // surface is gathered, [C14])
    if (!slave_)
    {
        return 0;
    }

    side sl;
    side ms;
    List<slaveFace> predicted;
    evaluate(sl, ms, predicted, k.deltaT);

    // The converged state: the committed face displacements of both
    // sides, with the predicted deformation gradients (the solver keeps no
    // converged gradient; within a face the gradient tilts the polygon, and
    // its change over a step moves the gap by far less than the
    // extrapolated closing it corrects)
    side slOld(sl);
    side msOld(ms);
    slOld.D = slOld.Dold;
    msOld.D = msOld.Dold;
    forAll(slOld.D, i)
    {
        faceGeometry(slOld, i);
    }
    forAll(msOld.D, m)
    {
        faceGeometry(msOld, m);
    }
    List<slaveFace> converged;
    evaluatePair(slOld, msOld, k.deltaT, converged);

    // n: the master's normal, into the slave body. A face predicted to
    // slide by half a master face or more meets another part of the
    // master surface, whose predicted shape is the extrapolation's guess
    // (a travelling indentation extrapolated in time is none): its
    // converged gap is not kept
    label nCorrected = 0;
    forAll(dD, i)
    {
        const slaveFace& o = converged[i];
        const slaveFace& p = predicted[i];
        if
        (
            o.inReach && p.inReach
         && predictedSlip(sl, i, p) < 0.5*masterLength(ms, p)
         && keepContact(i, o.gap, p.gap, p.n, dD[i])
        )
        {
            ++nCorrected;
        }
    }
    return nCorrected;
}


// ************************************************************************* //

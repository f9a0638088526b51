/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    frictionalContact: forces and their tangent handed to the solver, the commit
    of a converged step, reports and the entries written for restart.

\*---------------------------------------------------------------------------*/

#include "frictionalContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionalContactFvPatchVectorField::force
(
    const solidPatchKinematics& k,
    vectorField& f
) const
{
    // [C1] traction on the body: tN n - tT, times the current area
    List<slaveFace> faces;
    evaluate(k, faces);
    f.setSize(faces.size());
    forAll(faces, i)
    {
        f[i] = slaveForce(faces[i]);
    }
}


void Foam::frictionalContactFvPatchVectorField::tangent
(
    const solidPatchKinematics& k,
    List<faceForceTangent>& df
) const
{
    // [C6] the exact derivative of each face's force, the obstacle's
    // geometry and motion differentiated with respect to the face centre
    df.setSize(k.F.size());
    df = faceForceTangent();
    const rigidContactSurface& obstacle = surface_->bind(k);
    forAll(df, i)
    {
        masterPoint mp;
        if (obstacle.masterPointOf(i, mp, true))
        {
            slaveFaceTangent
            (
                i, mp, k.D[i] - k.Dold[i], k.F[i], k.Sf0[i], k.deltaT, df[i]
            );
        }
    }
}


void Foam::frictionalContactFvPatchVectorField::linearise
(
    const solidPatchKinematics& k
)
{
    List<slaveFace> faces;
    evaluate(k, faces);
    holdSlaveFaces(faces);
}


Foam::scalar Foam::frictionalContactFvPatchVectorField::firstContactFraction
(
    const solidPatchKinematics& k0,
    const solidPatchKinematics& k1
) const
{
    // [S14b] the onset along the change, the obstacle where it is at the
    // end of the step in both
    const scalarField p0(augmentedPenetrations(surface_->bind(k0)));
    return contactOnsetFraction(p0, augmentedPenetrations(surface_->bind(k1)));
}


Foam::label Foam::frictionalContactFvPatchVectorField::predictContacts
(
    const solidPatchKinematics& k0,
    const solidPatchKinematics& k1
)
{
    // [S14c] the faces [S14b] stops at, the obstacle at the end of the step
    const scalarField p0(augmentedPenetrations(surface_->bind(k0)));
    return markPredictedClosed(p0, augmentedPenetrations(surface_->bind(k1)));
}


void Foam::frictionalContactFvPatchVectorField::release()
{
    releaseHold();
}


Foam::label Foam::frictionalContactFvPatchVectorField::predictorCorrection
(
    const solidPatchKinematics& k,
    vectorField& dD
) const
{
    // [S18b] the extrapolated step repeats the last one's closing of the
    // gap from outside the smoothed onset [C2b] to within it, and so
    // predicts the faces out of contact again. A face in contact at the
    // converged state (gap below the onset width, the obstacle where it was
    // then) whose predicted gap is larger gets the converged gap back,
    // along the obstacle's normal at the new time. Copies of the search
    // records: the cache [C2c] is not touched by the query
    label nCorrected = 0;
    forAll(dD, i)
    {
        obstaclePoint cpOld;
        if
        (
           !surface_->nearestQuery
            (
                i, k.Cf0[i] + k.Dold[i], k.time - k.deltaT, k.Sf0[i], cpOld
            )
         || !convergedInContact(i, cpOld.gap)
        )
        {
            continue;
        }

        obstaclePoint cp;
        if
        (
            surface_->nearestQuery(i, k.Cf0[i] + k.D[i], k.time, k.Sf0[i], cp)
         && keepContact(i, cpOld.gap, cp.gap, cp.n, dD[i])
        )
        {
            ++nCorrected;
        }
    }
    return nCorrected;
}


bool Foam::frictionalContactFvPatchVectorField::augment
(
    const solidPatchKinematics& k
)
{
    if (!augmented())
    {
        return false;
    }
    List<slaveFace> faces;
    evaluate(k, faces);
    return augmentSlaveFaces(faces);
}


void Foam::frictionalContactFvPatchVectorField::resetAugmentation
(
    const scalar extrapolation
)
{
    multipliers().predict(extrapolation);
}


Foam::label Foam::frictionalContactFvPatchVectorField::facesPressedThrough
(
    const solidPatchKinematics& k
) const
{
    // [C2e] the obstacle searched without a limit for the faces that left
    // the search distance
    List<slaveFace> faces;
    evaluate(k, faces);
    const labelList left(facesLeftReach(faces));
    const vectorField x(k.Cf0 + k.D);
    scalarList gaps(left.size(), GREAT);
    forAll(left, j)
    {
        obstaclePoint cp;
        if (surface_->obstacle().nearest(x[left[j]], k.time, GREAT, cp))
        {
            gaps[j] = cp.gap;
        }
    }
    return reportPressedThrough(left, gaps, x, surface_->searchDistance());
}


void Foam::frictionalContactFvPatchVectorField::commit
(
    const solidPatchKinematics& k
)
{
    List<slaveFace> faces;
    evaluate(k, faces);
    commitSlaveFaces(faces, k.Sf0, k.Cf0 + k.D);
}


void Foam::frictionalContactFvPatchVectorField::report
(
    const solidPatchKinematics& k
) const
{
    reportFaces(k.time);

    surface_->report(patch().name());
}


void Foam::frictionalContactFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    surface_->write(os);
    writeFaces(os);
    surface_->writeSearches(os);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        frictionalContactFvPatchVectorField
    );
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Residual of the momentum balance ([S1], [S10]-[S13], [S20]).

\*---------------------------------------------------------------------------*/

#include "solidDiscretisation.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidDiscretisation::residual(vectorField& R)
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();

    R.setSize(mesh_.nCells());
    R = Zero;
    scalarField fMag(mesh_.nCells(), Zero);

    // [S1] internal faces: P.S0 leaves the owner, enters the neighbour
    forAll(own, facei)
    {
        const vector flux
        (
            laws_.cellLaw(own[facei]).stress
            (
                internalFaceF(facei), oldState(-1, facei),
                trialInternal_[facei]
            ) & Sf[facei]
        );
        R[own[facei]] += flux;
        R[nei[facei]] -= flux;
        const scalar m = mag(flux);
        fMag[own[facei]] += m;
        fMag[nei[facei]] += m;
    }

    const scalar dt = mesh_.time().deltaTValue();

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelUList& fc = p.faceCells();
        const vectorField& S = p.Sf();
        const solidBoundaries::patchKind kind = bcs_.kind(patchi);

        if (kind == solidBoundaries::EMPTY)
        {
            continue;
        }

        if (kind == solidBoundaries::FORCE)
        {
            const forceKinematics fk(*this, patchi, dt);
            const solidPatchKinematics& k = fk.k;
            vectorField f(fc.size());
            bcs_.forcePatch(patchi).force(k, f);
            forAll(fc, i)
            {
                R[fc[i]] += f[i];
                fMag[fc[i]] += mag(f[i]);
            }
            continue;
        }

        List<materialState>& trial = trialPatch_[patchi];
        forAll(fc, i)
        {
            vector flux
            (
                laws_.cellLaw(fc[i]).stress
                (
                    boundaryFaceF(patchi, i), oldState(patchi, i), trial[i]
                ) & S[i]
            );
            if (kind == solidBoundaries::SYMMETRY)
            {
                // only the normal traction acts on a symmetry plane
                const vector& n = patchNormal_[patchi][i];
                flux = (n & flux)*n;
            }
            R[fc[i]] += flux;
            fMag[fc[i]] += mag(flux);
        }
    }

    // [S13] inertia, backward Euler in the displacement
    if (inertia_)
    {
        const scalarField& V = mesh_.V();
        const vectorField& u = u_.primitiveField();
        forAll(R, celli)
        {
            const vector acc
            (
                2/(dt + deltaT0_)
               *(
                    (u[celli] - D0_[celli])/dt
                  - (D0_[celli] - D00_[celli])/deltaT0_
                )
            );
            const vector inertiaForce(inertiaDensity_[celli]*V[celli]*acc);
            R[celli] -= inertiaForce;
            fMag[celli] += mag(inertiaForce);
        }
    }

    // Floored [S14]: a body released to zero stress must still converge
    forceScale_ = max(Foam::sqrt(gSumSqr(fMag)), forceFloor_);
}


// ************************************************************************* //

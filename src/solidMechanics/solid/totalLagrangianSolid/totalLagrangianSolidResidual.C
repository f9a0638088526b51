/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.

Description
    Residual of the momentum balance ([S1], [S10]-[S13]).

\*---------------------------------------------------------------------------*/

#include "totalLagrangianSolid.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::totalLagrangianSolid::updateGradient()
{
    // [S10]
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& u = Dwork_.primitiveField();
    tensorField& G = gradD_.primitiveFieldRef();

    G = Zero;

    forAll(own, facei)
    {
        const vector dD(u[nei[facei]] - u[own[facei]]);
        G[own[facei]] += ownLs_[facei]*dD;
        G[nei[facei]] += neiLs_[facei]*dD;
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelUList& fc = p.faceCells();
        const vectorField& ls = patchLs_[patchi];

        switch (patchKinds_[patchi])
        {
            case FIXED:
            {
                const fvPatchVectorField& Db = D_.boundaryField()[patchi];
                forAll(fc, i)
                {
                    G[fc[i]] += ls[i]*(Db[i] - u[fc[i]]);
                }
                break;
            }
            case COUPLED:
            {
                const vectorField uN
                (
                    Dwork_.boundaryField()[patchi].patchNeighbourField()
                );
                forAll(fc, i)
                {
                    G[fc[i]] += ls[i]*(uN[i] - u[fc[i]]);
                }
                break;
            }
            case SYMMETRY:
            {
                const vectorField n(p.nf());
                forAll(fc, i)
                {
                    G[fc[i]] += ls[i]*(-2*(n[i] & u[fc[i]])*n[i]);
                }
                break;
            }
            default:
                break;
        }
    }

    gradD_.correctBoundaryConditions();

    forAll(G, celli)
    {
        Jcell_[celli] = det(tensor::I + G[celli].T());
    }
}


void Foam::totalLagrangianSolid::forcePatchKinematics
(
    const label patchi,
    vectorField& Dface,
    tensorField& F
) const
{
    const fvPatch& p = mesh_.boundary()[patchi];
    const labelUList& fc = p.faceCells();
    const vectorField d(p.Cf() - p.Cn());
    const vectorField& u = Dwork_.primitiveField();
    const tensorField& G = gradD_.primitiveField();

    Dface.setSize(fc.size());
    F.setSize(fc.size());
    forAll(fc, i)
    {
        const tensor& Gi = G[fc[i]];
        Dface[i] = u[fc[i]] + (d[i] & Gi);
        F[i] = tensor::I + Gi.T();
    }
}


void Foam::totalLagrangianSolid::residual(vectorField& R)
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const vectorField& u = Dwork_.primitiveField();
    const tensorField& G = gradD_.primitiveField();
    const mechanicalLaw& law = law_();

    R = Zero;
    scalarField fMag(mesh_.nCells(), Zero);

    // [S1] internal faces: P.S0 leaves the owner, enters the neighbour
    forAll(own, facei)
    {
        const label P = own[facei];
        const label N = nei[facei];
        const tensor F(internalFaceDefGrad(facei));
        materialState old;
        old.CpInv = CpInv_[facei];
        old.epsilonP = epsilonPf_[facei];
        const vector flux(law.stress(F, old, trialInternal_[facei]) & Sf[facei]);
        R[P] += flux;
        R[N] -= flux;
        const scalar m = mag(flux);
        fMag[P] += m;
        fMag[N] += m;
    }

    const scalar t = mesh_.time().value();
    const scalar dt = mesh_.time().deltaTValue();

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelUList& fc = p.faceCells();
        const vectorField& S = p.Sf();
        const patchKind kind = patchKinds_[patchi];
        List<materialState>& trial = trialPatch_[patchi];

        if (kind == EMPTY)
        {
            continue;
        }

        if (kind == FORCE)
        {
            vectorField Dface;
            tensorField F;
            forcePatchKinematics(patchi, Dface, F);
            const solidPatchKinematics k
            {
                S, p.Cf(), Dface, forcePatchD0_[patchi], F, t, dt
            };
            vectorField f(fc.size());
            forcePatches_[patchi]->force(k, f);
            forAll(fc, i)
            {
                R[fc[i]] += f[i];
                fMag[fc[i]] += mag(f[i]);
            }
            continue;
        }

        const symmTensorField& CpInvB = CpInv_.boundaryField()[patchi];
        const scalarField& epsPB = epsilonPf_.boundaryField()[patchi];

        vectorField delta;
        vectorField dD(fc.size());
        tensorField GN;
        scalarField w;

        if (kind == COUPLED)
        {
            delta = p.delta();
            w = p.weights();
            GN = gradD_.boundaryField()[patchi].patchNeighbourField();
            const vectorField uN
            (
                Dwork_.boundaryField()[patchi].patchNeighbourField()
            );
            forAll(fc, i)
            {
                dD[i] = uN[i] - u[fc[i]];
            }
        }
        else
        {
            delta = p.Cf() - p.Cn();
            w.setSize(fc.size(), 1);
            GN = tensorField(G, fc);
            if (kind == FIXED)
            {
                const fvPatchVectorField& Db = D_.boundaryField()[patchi];
                forAll(fc, i)
                {
                    dD[i] = Db[i] - u[fc[i]];
                }
            }
            else
            {
                // SYMMETRY: the tangential part of the extrapolated value
                const vectorField n(p.nf());
                forAll(fc, i)
                {
                    const vector uB(u[fc[i]] + (delta[i] & G[fc[i]]));
                    dD[i] = (uB - (n[i] & uB)*n[i]) - u[fc[i]];
                }
            }
        }

        forAll(fc, i)
        {
            const label P = fc[i];
            const tensor F
            (
                volumeAveraged
                (
                    faceDefGrad(G[P], GN[i], w[i], delta[i], dD[i]),
                    w[i]*Jcell_[P] + (1 - w[i])*det(tensor::I + GN[i].T())
                )
            );
            materialState old;
            old.CpInv = CpInvB[i];
            old.epsilonP = epsPB[i];
            vector flux(law.stress(F, old, trial[i]) & S[i]);
            if (kind == SYMMETRY)
            {
                const vector n(S[i]/mag(S[i]));
                flux = (n & flux)*n;
            }
            R[P] += flux;
            fMag[P] += mag(flux);
        }
    }

    // [S13] inertia, backward Euler in the displacement
    if (inertia_)
    {
        const scalarField& V = mesh_.V();
        const scalar rho = inertiaDensity_;
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
            const vector inertiaForce(rho*V[celli]*acc);
            R[celli] -= inertiaForce;
            fMag[celli] += mag(inertiaForce);
        }
    }

    // Floored [S14]: a body released to zero stress must still converge
    forceScale_ = max(Foam::sqrt(gSumSqr(fMag)), forceFloor_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::totalLagrangianSolid::residual
(
    const Eigen::VectorXd& x,
    Eigen::VectorXd& R
)
{
    unpack(x, Dwork_.primitiveFieldRef());
    Dwork_.correctBoundaryConditions();
    updateGradient();

    vectorField Rcell(mesh_.nCells());
    residual(Rcell);
    pack(Rcell, R);
}


void Foam::totalLagrangianSolid::updatePreconditioner
(
    const Eigen::VectorXd& x,
    const label newtonIter,
    const label lastKrylov
)
{
    bool patchStiffness = false;
    forAll(forcePatches_, patchi)
    {
        if (forcePatches_[patchi] && forcePatches_[patchi]->hasStiffness())
        {
            patchStiffness = true;
        }
    }

    const bool dtChanged =
        inertia_ && mag(mesh_.time().deltaTValue() - preconDeltaT_) > 0;

    // The elastic operator is fixed in the total Lagrangian description:
    // factorised once unless the law softens or patches add stiffness
    const bool refresh =
        preconDeltaT_ < 0 || newtonIter == 0 || lastKrylov > krylovRefresh_;

    if (fdJacobian_.valid())
    {
        if (refresh || !fdJacobian_->valid())
        {
            Eigen::VectorXd R;
            residual(x, R);
            const scalar h = 1e-7*max(gMaxNorm(x), typicalDisplacement());
            if (fdJacobian_->update(*this, x, R, h))
            {
                preconDeltaT_ = mesh_.time().deltaTValue();
                return;
            }

            // A far-off iterate can make the Jacobian singular: the compact
            // operator stands in for this iteration, and the finite-difference
            // Jacobian is tried again at the next one (a run must not lose it
            // for good because of one wild trial)
            WarningInFunction
                << "Factorisation of the finite-difference Jacobian failed;"
                << " using the compact preconditioner until it factorises"
                << " again" << endl;
            unpack(x, Dwork_.primitiveFieldRef());
            Dwork_.correctBoundaryConditions();
            updateGradient();
            assemblePreconditioner(patchStiffness, law_->plastic());
            return;
        }
        else
        {
            return;
        }
    }

    if ((patchStiffness || law_->plastic()) && refresh)
    {
        unpack(x, Dwork_.primitiveFieldRef());
        Dwork_.correctBoundaryConditions();
        updateGradient();
        assemblePreconditioner(patchStiffness, law_->plastic());
    }
    else if (preconDeltaT_ < 0 || dtChanged)
    {
        assemblePreconditioner(false, false);
    }
}


void Foam::totalLagrangianSolid::precondition
(
    const Eigen::VectorXd& r,
    Eigen::VectorXd& z
) const
{
    if (fdJacobian_.valid() && fdJacobian_->valid())
    {
        fdJacobian_->solve(r, z);
    }
    else
    {
        precon_.solve(r, z);
    }
}


// ************************************************************************* //

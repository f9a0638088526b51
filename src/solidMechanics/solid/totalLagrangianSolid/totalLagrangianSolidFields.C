/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.

Description
    Step set-up, commit of a converged step and the fields written for
    post-processing.

\*---------------------------------------------------------------------------*/

#include "totalLagrangianSolid.H"
#include "volPointInterpolation.H"
#include "pointFields.H"
#include "OFstream.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::totalLagrangianSolid::updateOutputFields()
{
    // Cauchy stress and plastic strain: face values of the converged step
    // averaged over each cell's faces, weighted by face area
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& magSf = mesh_.magSf();
    symmTensorField sigma(mesh_.nCells(), Zero);
    scalarField epsP(mesh_.nCells(), Zero);
    scalarField area(mesh_.nCells(), Zero);

    forAll(own, facei)
    {
        const label P = own[facei];
        const label N = nei[facei];
        const tensor F(internalFaceDefGrad(facei));
        materialState s;
        materialState old;
        old.CpInv = CpInv_[facei];
        old.epsilonP = epsilonPf_[facei];
        // The committed history is already the end-of-step state, so the
        // stress is evaluated from it without a further plastic correction
        const symmTensor sig(mechanicalLaw::cauchy(law_->stress(F, old, s), F));
        const scalar a = magSf[facei];
        for (const label c : {P, N})
        {
            sigma[c] += a*sig;
            epsP[c] += a*old.epsilonP;
            area[c] += a;
        }
    }

    forAll(mesh_.boundary(), patchi)
    {
        if (patchKinds_[patchi] == EMPTY)
        {
            continue;
        }
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        const scalarField& a = mesh_.boundary()[patchi].magSf();
        const scalarField& epsB = epsilonPf_.boundaryField()[patchi];
        const bool hasHistory =
            patchKinds_[patchi] != FORCE && patchKinds_[patchi] != EMPTY;
        forAll(fc, i)
        {
            if (hasHistory)
            {
                epsP[fc[i]] += a[i]*epsB[i];
                area[fc[i]] += a[i];
            }
        }
    }

    // Internal faces carry the stress average; the boundary faces with a
    // history add to the plastic strain only (their stress is one-sided)
    scalarField areaInt(mesh_.nCells(), Zero);
    forAll(own, facei)
    {
        areaInt[own[facei]] += magSf[facei];
        areaInt[nei[facei]] += magSf[facei];
    }

    volSymmTensorField& sigmaOut =
        mesh_.lookupObjectRef<volSymmTensorField>("sigma");
    volScalarField& sigmaEqOut =
        mesh_.lookupObjectRef<volScalarField>("sigmaEq");

    forAll(sigma, celli)
    {
        sigmaOut[celli] = sigma[celli]/max(areaInt[celli], VSMALL);
        sigmaEqOut[celli] = Foam::sqrt(1.5*magSqr(dev(sigmaOut[celli])));
    }
    sigmaOut.correctBoundaryConditions();
    sigmaEqOut.correctBoundaryConditions();

    if (law_->plastic())
    {
        volScalarField& epsOut =
            mesh_.lookupObjectRef<volScalarField>("epsilonPEq");
        forAll(epsP, celli)
        {
            epsOut[celli] = epsP[celli]/max(area[celli], VSMALL);
        }
        epsOut.correctBoundaryConditions();
    }

    pointVectorField& pointD = mesh_.lookupObjectRef<pointVectorField>("pointD");
    pointD = volPointInterpolation::New(mesh_).interpolate(D_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::totalLagrangianSolid::beginStep
(
    Eigen::VectorXd& x,
    Eigen::VectorXd& xStart,
    const bool predict
)
{
    // Boundary values at the new time (uniformFixedValue and the like)
    D_.correctBoundaryConditions();

    pack(D0_, xStart);
    x = xStart;

    if (predict)
    {
        const scalar ratio = mesh_.time().deltaTValue()/deltaT0_;
        Eigen::VectorXd x00;
        pack(D00_, x00);
        x += ratio*(xStart - x00);
    }
}


void Foam::totalLagrangianSolid::holdLinearisation(const bool on)
{
    forAll(forcePatches_, patchi)
    {
        if (patchKinds_[patchi] != FORCE)
        {
            continue;
        }
        if (on)
        {
            // The fields hold the last evaluated iterate
            const fvPatch& p = mesh_.boundary()[patchi];
            vectorField Dface;
            tensorField F;
            forcePatchKinematics(patchi, Dface, F);
            const solidPatchKinematics k
            {
                p.Sf(), p.Cf(), Dface, forcePatchD0_[patchi], F,
                mesh_.time().value(), mesh_.time().deltaTValue()
            };
            forcePatches_[patchi]->linearise(k);
        }
        else
        {
            forcePatches_[patchi]->release();
        }
    }
}


void Foam::totalLagrangianSolid::commit(const Eigen::VectorXd& x)
{
    // Recompute the trial state of the converged iterate
    Eigen::VectorXd R;
    residual(x, R);

    forAll(trialInternal_, facei)
    {
        CpInv_[facei] = trialInternal_[facei].CpInv;
        epsilonPf_[facei] = trialInternal_[facei].epsilonP;
    }

    const scalar t = mesh_.time().value();
    const scalar dt = mesh_.time().deltaTValue();

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const patchKind kind = patchKinds_[patchi];

        if (kind == FIXED || kind == SYMMETRY || kind == COUPLED)
        {
            symmTensorField& CpB = CpInv_.boundaryFieldRef()[patchi];
            scalarField& epsB = epsilonPf_.boundaryFieldRef()[patchi];
            const List<materialState>& trial = trialPatch_[patchi];
            forAll(trial, i)
            {
                CpB[i] = trial[i].CpInv;
                epsB[i] = trial[i].epsilonP;
            }
        }
        else if (kind == FORCE)
        {
            vectorField Dface;
            tensorField F;
            forcePatchKinematics(patchi, Dface, F);
            const solidPatchKinematics k
            {
                p.Sf(), p.Cf(), Dface, forcePatchD0_[patchi], F, t, dt
            };
            forcePatches_[patchi]->commit(k);
            forcePatches_[patchi]->report(k);
            forcePatchD0_[patchi] = Dface;
        }
    }

    // Displacement history and the written field
    D00_ = D0_;
    D0_ = Dwork_.primitiveField();
    deltaT0_ = dt;

    D_.primitiveFieldRef() = D0_;
    D_.correctBoundaryConditions();
    forAll(mesh_.boundary(), patchi)
    {
        if (patchKinds_[patchi] == FORCE)
        {
            vectorField Dface;
            tensorField F;
            forcePatchKinematics(patchi, Dface, F);
            D_.boundaryFieldRef()[patchi] == Dface;
        }
    }

    if (inertia_)
    {
        volVectorField& vel = mesh_.lookupObjectRef<volVectorField>("V");
        vel.primitiveFieldRef() = (D0_ - D00_)/dt;
        vel.correctBoundaryConditions();

        // [S13b] reported so a mass-scaled run shows it stays quasi-static
        Info<< "    kinetic energy "
            << 0.5*inertiaDensity_*gSum(mesh_.V()*magSqr(vel.primitiveField()))
            << " J" << endl;
    }
}


void Foam::totalLagrangianSolid::prepareWrite()
{
    Dwork_.primitiveFieldRef() = D0_;
    Dwork_.correctBoundaryConditions();
    updateGradient();
    updateOutputFields();
}


void Foam::totalLagrangianSolid::reportForces() const
{
    // Reaction force on each fixed patch: the sum of P.S0 over its faces
    const vectorField& u = Dwork_.primitiveField();
    const tensorField& G = gradD_.primitiveField();

    forAll(mesh_.boundary(), patchi)
    {
        if (patchKinds_[patchi] != FIXED)
        {
            continue;
        }
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelUList& fc = p.faceCells();
        const vectorField delta(p.Cf() - p.Cn());
        const fvPatchVectorField& Db = D_.boundaryField()[patchi];
        const symmTensorField& CpB = CpInv_.boundaryField()[patchi];
        const scalarField& epsB = epsilonPf_.boundaryField()[patchi];

        vector total(Zero);
        forAll(fc, i)
        {
            const label P = fc[i];
            const tensor F
            (
                volumeAveraged
                (
                    faceDefGrad(G[P], G[P], 1, delta[i], Db[i] - u[P]),
                    Jcell_[P]
                )
            );
            materialState old, s;
            old.CpInv = CpB[i];
            old.epsilonP = epsB[i];
            total += law_->stress(F, old, s) & p.Sf()[i];
        }
        reduce(total, sumOp<vector>());

        Info<< "    reaction force on " << p.name() << ": " << total
            << " N" << endl;

        if (Pstream::master())
        {
            const fileName dir
            (
                mesh_.time().globalPath()/"postProcessing"/"solidForces"
            );
            mkDir(dir);
            const fileName file(dir/(p.name() + ".dat"));
            const bool fresh = !isFile(file);
            OFstream os(file, IOstream::ASCII, IOstream::currentVersion,
                IOstream::UNCOMPRESSED, true);
            if (fresh)
            {
                os  << "# time Fx Fy Fz [N] (reaction on patch "
                    << p.name() << ")" << nl;
            }
            os  << mesh_.time().value() << ' ' << total.x() << ' '
                << total.y() << ' ' << total.z() << nl;
        }
    }
}


// ************************************************************************* //

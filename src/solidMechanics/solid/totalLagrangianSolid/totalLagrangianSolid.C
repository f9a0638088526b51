/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "totalLagrangianSolid.H"
#include "emptyFvPatch.H"
#include "symmetryPlaneFvPatch.H"
#include "symmetryFvPatch.H"
#include "wedgeFvPatch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(totalLagrangianSolid, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Solved components of a (possibly 2-D) mesh
static labelList solvedComponents(const fvMesh& mesh)
{
    labelList comps;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh.solutionD()[d] == 1)
        {
            comps.append(d);
        }
    }
    return comps;
}


//- History field read from the start time if written, else its initial
//  value; written only when the law is plastic
template<class Type>
static tmp<GeometricField<Type, fvsPatchField, surfaceMesh>> historyField
(
    const fvMesh& mesh,
    const word& name,
    const Type& initial,
    const bool write
)
{
    IOobject io
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::READ_IF_PRESENT,
        write ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
    );

    if (io.typeHeaderOk<GeometricField<Type, fvsPatchField, surfaceMesh>>())
    {
        return tmp<GeometricField<Type, fvsPatchField, surfaceMesh>>::New
        (
            io, mesh
        );
    }

    io.readOpt() = IOobject::NO_READ;
    return tmp<GeometricField<Type, fvsPatchField, surfaceMesh>>::New
    (
        io,
        mesh,
        dimensioned<Type>(name, dimless, initial)
    );
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::totalLagrangianSolid::classifyPatches()
{
    const fvBoundaryMesh& patches = mesh_.boundary();
    patchKinds_.setSize(patches.size());
    forcePatches_.setSize(patches.size(), nullptr);

    forAll(patches, patchi)
    {
        const fvPatch& p = patches[patchi];
        fvPatchVectorField& pf = D_.boundaryFieldRef()[patchi];

        if (isA<emptyFvPatch>(p))
        {
            patchKinds_[patchi] = EMPTY;
        }
        else if (p.coupled())
        {
            patchKinds_[patchi] = COUPLED;
        }
        else if (isA<symmetryPlaneFvPatch>(p) || isA<symmetryFvPatch>(p))
        {
            patchKinds_[patchi] = SYMMETRY;
        }
        else if (dynamic_cast<solidForceBoundary*>(&pf))
        {
            patchKinds_[patchi] = FORCE;
            forcePatches_[patchi] = dynamic_cast<solidForceBoundary*>(&pf);
        }
        else if (pf.fixesValue())
        {
            patchKinds_[patchi] = FIXED;
        }
        else
        {
            FatalErrorInFunction
                << "Patch " << p.name() << " of field D (file "
                << D_.objectPath() << ") has boundary condition type '"
                << pf.type() << "', which largeStrainSolidFoam does not"
                << " support." << nl
                << "Expected a fixed-value type (fixedValue,"
                << " uniformFixedValue, ...), solidTraction,"
                << " frictionalContact, or a symmetryPlane/symmetry, empty"
                << " or processor patch" << nl
                << exit(FatalError);
        }
    }
}


void Foam::totalLagrangianSolid::computeGradientWeights()
{
    // [S10] weighted least squares with weights 1/|d|^2 on the reference mesh
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const volVectorField& C = mesh_.C();

    symmTensorField dd(mesh_.nCells(), Zero);

    forAll(own, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const symmTensor wdd(sqr(d)/magSqr(d));
        dd[own[facei]] += wdd;
        dd[nei[facei]] += wdd;
    }

    List<vectorField> patchDelta(mesh_.boundary().size());

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelUList& fc = p.faceCells();
        vectorField& delta = patchDelta[patchi];

        switch (patchKinds_[patchi])
        {
            case FIXED:
                delta = p.Cf() - p.Cn();
                break;
            case COUPLED:
                delta = p.delta();
                break;
            case SYMMETRY:
            {
                // the mirror image of the cell across the plane
                const vectorField n(p.nf());
                delta = 2*((n & (p.Cf() - p.Cn()))*n);
                break;
            }
            default:
                continue;
        }

        forAll(fc, i)
        {
            dd[fc[i]] += sqr(delta[i])/magSqr(delta[i]);
        }
    }

    // Empty directions of a 2-D mesh: unit diagonal keeps dd invertible
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh_.solutionD()[d] != 1)
        {
            vector e(Zero);
            e[d] = 1;
            dd += sqr(e);
        }
    }

    forAll(dd, celli)
    {
        const scalar scale = tr(dd[celli])/3;
        if (det(dd[celli]) < 1e-10*pow3(scale))
        {
            FatalErrorInFunction
                << "Cell " << celli << " at " << C[celli]
                << " has too few neighbours for a least-squares gradient"
                << " (its other faces carry tractions)." << nl
                << "Refine the mesh so there are at least two cells across"
                << " every traction-loaded wall" << nl << exit(FatalError);
        }
    }

    const symmTensorField invDd(inv(dd));

    ownLs_.setSize(own.size());
    neiLs_.setSize(own.size());
    forAll(own, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const vector wd(d/magSqr(d));
        ownLs_[facei] = invDd[own[facei]] & wd;
        neiLs_[facei] = invDd[nei[facei]] & wd;
    }

    patchLs_.setSize(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        const vectorField& delta = patchDelta[patchi];
        vectorField& ls = patchLs_[patchi];
        ls.setSize(delta.size());
        forAll(delta, i)
        {
            ls[i] = invDd[fc[i]] & (delta[i]/magSqr(delta[i]));
        }
    }
}


void Foam::totalLagrangianSolid::assemblePreconditioner
(
    const bool withPatchStiffness,
    const bool withMaterialTangent
)
{
    // [S16] compact-stencil operator: a face passes the traction
    // c A (D_N - D_P), c = |S|/|d|, with A the acoustic tensor of the law
    // (elastic: mu I + (lambda + mu) n n; plastic: the consistent tangent's)
    const mechanicalLaw& law = law_();
    const scalar mu = law.mu();
    const scalar lambda = law.lambda();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const volVectorField& C = mesh_.C();

    // With volume averaging the compact face stencil carries only the
    // deviatoric part, mu I + mu/3 n n; the volumetric part acts through
    // the cells' divergence and is added below as K V div^T div
    const scalar lambdaCompact =
        volumetricAveraging_ ? lambda - law.bulkModulus() : lambda;

    auto faceStiffness = [&](const vector& S, const vector& d)
    {
        const scalar magS = mag(S);
        const vector n(S/magS);
        return (magS/mag(d))*(mu*tensor::I + (lambdaCompact + mu)*sqr(n));
    };

    precon_.clear();

    scalar meanDiag = 0;

    forAll(own, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        tensor K;
        if (withMaterialTangent)
        {
            materialState old;
            old.CpInv = CpInv_[facei];
            old.epsilonP = epsilonPf_[facei];
            const scalar magS = mag(Sf[facei]);
            K = (magS/mag(d))
               *law.acousticTensor
                (
                    internalFaceDefGrad(facei), old, Sf[facei]/magS
                );
        }
        else
        {
            K = faceStiffness(Sf[facei], d);
        }
        precon_.addCoupling(own[facei], nei[facei], K);
        meanDiag += 2*tr(K);
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelUList& fc = p.faceCells();
        const vectorField& S = p.Sf();

        switch (patchKinds_[patchi])
        {
            case FIXED:
            case COUPLED:
            {
                const vectorField d
                (
                    patchKinds_[patchi] == FIXED ? p.Cf() - p.Cn() : p.delta()
                );
                forAll(fc, i)
                {
                    precon_.addDiagonal(fc[i], faceStiffness(S[i], d[i]));
                }
                break;
            }
            case SYMMETRY:
            {
                const vectorField d(p.Cf() - p.Cn());
                forAll(fc, i)
                {
                    const vector n(S[i]/mag(S[i]));
                    precon_.addDiagonal
                    (
                        fc[i],
                        (mag(S[i])/mag(d[i]))*(lambda + 2*mu)*sqr(n)
                    );
                }
                break;
            }
            case FORCE:
            {
                if (!withPatchStiffness)
                {
                    break;
                }
                vectorField Dface;
                tensorField F;
                forcePatchKinematics(patchi, Dface, F);
                const solidPatchKinematics k
                {
                    mesh_.Sf().boundaryField()[patchi],
                    mesh_.Cf().boundaryField()[patchi],
                    Dface, forcePatchD0_[patchi], F,
                    mesh_.time().value(), mesh_.time().deltaTValue()
                };
                tensorField K(fc.size(), Zero);
                if (forcePatches_[patchi]->stiffness(k, K))
                {
                    forAll(fc, i)
                    {
                        precon_.addDiagonal(fc[i], K[i]);
                    }
                }
                break;
            }
            default:
                break;
        }
    }

    if (volumetricAveraging_)
    {
        addVolumetricStiffness();
    }

    const scalarField& V = mesh_.V();
    const scalar nCells = max(mesh_.nCells(), 1);
    meanDiag /= (nCells*vector::nComponents);

    const scalar dt = mesh_.time().deltaTValue();
    const scalar inertiaCoeff =
        inertia_ ? 2*inertiaDensity_/(dt*(dt + deltaT0_)) : 0;

    // A tiny diagonal shift keeps M definite when rigid-body modes are
    // held only by the nonlinear boundary terms
    forAll(V, celli)
    {
        precon_.addDiagonal
        (
            celli,
            (inertiaCoeff*V[celli] + 1e-9*meanDiag)*tensor::I
        );
    }

    if (!precon_.factorise())
    {
        FatalErrorInFunction
            << "Factorisation of the preconditioner failed" << nl
            << exit(FatalError);
    }
    preconDeltaT_ = dt;
}


Foam::labelListList Foam::totalLagrangianSolid::residualInfluence() const
{
    // The face stress uses the gradients of the two cells it joins, each
    // built from their face neighbours: two hops
    const labelListList& cc = mesh_.cellCells();
    labelListList influence(mesh_.nCells());
    labelHashSet set(32);
    forAll(cc, celli)
    {
        set.clear();
        set.insert(celli);
        for (const label n1 : cc[celli])
        {
            set.insert(n1);
            for (const label n2 : cc[n1])
            {
                set.insert(n2);
            }
        }
        influence[celli] = set.sortedToc();
    }
    return influence;
}


void Foam::totalLagrangianSolid::addVolumetricStiffness()
{
    // [S16] K V_P b_Q b_R^T for every pair of cells Q, R in the
    // least-squares divergence of cell P: div D_P = sum_Q b_Q . D_Q
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const cellList& cellFaces = mesh_.cells();
    const scalarField& V = mesh_.V();
    const scalar K = law_->bulkModulus();

    DynamicList<label> cells(16);
    DynamicList<vector> b(16);

    forAll(cellFaces, P)
    {
        cells.clear();
        b.clear();
        cells.append(P);
        b.append(Zero);

        for (const label facei : cellFaces[P])
        {
            if (facei < mesh_.nInternalFaces())
            {
                const bool isOwner = own[facei] == P;
                const vector& ls = isOwner ? ownLs_[facei] : neiLs_[facei];
                // G_P += ls (D_N - D_P) for the owner, ls (D_N - D_P) with
                // the face's N,P for the neighbour: sign by side
                const label Q = isOwner ? nei[facei] : own[facei];
                const scalar sign = isOwner ? 1 : -1;
                cells.append(Q);
                b.append(sign*ls);
                b[0] -= sign*ls;
            }
            else
            {
                const label patchi =
                    mesh_.boundaryMesh().whichPatch(facei);
                const label i =
                    facei - mesh_.boundaryMesh()[patchi].start();
                const vector& ls = patchLs_[patchi][i];
                switch (patchKinds_[patchi])
                {
                    case FIXED:
                    case COUPLED:
                        b[0] -= ls;
                        break;
                    case SYMMETRY:
                    {
                        const vector n
                        (
                            mesh_.boundary()[patchi].nf()()[i]
                        );
                        b[0] -= 2*(ls & n)*n;
                        break;
                    }
                    default:
                        break;
                }
            }
        }

        const scalar KV = K*V[P];
        forAll(cells, q)
        {
            forAll(cells, r)
            {
                precon_.addBlock(cells[q], cells[r], KV*(b[q]*b[r]));
            }
        }
    }
}


void Foam::totalLagrangianSolid::unpack
(
    const Eigen::VectorXd& x,
    vectorField& v
) const
{
    const label nc = comps_.size();
    forAll(v, celli)
    {
        vector& vi = v[celli];
        vi = Zero;
        for (label a = 0; a < nc; ++a)
        {
            vi[comps_[a]] = x(celli*nc + a);
        }
    }
}


void Foam::totalLagrangianSolid::pack
(
    const vectorField& v,
    Eigen::VectorXd& x
) const
{
    const label nc = comps_.size();
    x.resize(v.size()*nc);
    forAll(v, celli)
    {
        for (label a = 0; a < nc; ++a)
        {
            x(celli*nc + a) = v[celli][comps_[a]];
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::totalLagrangianSolid::totalLagrangianSolid(const fvMesh& mesh)
:
    mesh_(mesh),
    mechanicalProperties_
    (
        IOobject
        (
            "mechanicalProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    law_(mechanicalLaw::New(mechanicalProperties_.subDict("mechanicalLaw"))),
    D_
    (
        IOobject
        (
            "D",
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh
    ),
    Dwork_
    (
        IOobject("Dwork", mesh.time().timeName(), mesh),
        D_,
        calculatedFvPatchVectorField::typeName
    ),
    gradD_
    (
        IOobject("gradDwork", mesh.time().timeName(), mesh),
        mesh,
        dimensionedTensor(dimless, Zero)
    ),
    Jcell_(mesh.nCells(), 1),
    volumetricAveraging_(true),
    volumetricAveragingWeight_(1),
    emptyProjector_(Zero),
    CpInv_(historyField(mesh, "CpInv", symmTensor::I, law_->plastic())),
    epsilonPf_(historyField(mesh, "epsilonPf", scalar(0), law_->plastic())),
    comps_(solvedComponents(mesh)),
    inertia_(false),
    inertiaDensity_(0),
    D0_(D_.primitiveField()),
    D00_(D_.primitiveField()),
    deltaT0_(mesh.time().deltaTValue()),
    precon_(mesh.nCells(), comps_),
    preconDeltaT_(-1),
    krylovRefresh_
    (
        mesh.solutionDict().subDict("solid")
       .lookupOrDefault<label>("krylovRefresh", 15)
    ),
    preconditionerType_
    (
        mesh.solutionDict().subDict("solid")
       .lookupOrDefault<word>("preconditioner", "fdJacobian")
    ),
    forceScale_(0),
    forceFloor_(0),
    bodySize_(mag(mesh.bounds().span()))
{
    const word d2dt2
    (
        mesh.schemesDict().subDict("d2dt2Schemes").get<word>("default")
    );
    if (d2dt2 == "Euler")
    {
        inertia_ = true;
    }
    else if (d2dt2 != "steadyState")
    {
        FatalIOErrorInFunction(mesh.schemesDict())
            << "Keyword 'default' in d2dt2Schemes of "
            << mesh.schemesDict().name() << " is '" << d2dt2
            << "'; expected steadyState (quasi-static) or Euler (inertia)"
            << nl << exit(FatalIOError);
    }
    if (inertia_ && law_->rho() <= 0)
    {
        FatalIOErrorInFunction(mechanicalProperties_)
            << "Keyword 'rho' in " << mechanicalProperties_.name()
            << " must be > 0 when d2dt2Schemes is Euler" << nl
            << exit(FatalIOError);
    }

    // [S13b] mass scaling: quasi-static forming runs with a heavier body so
    // that the rate-dependent friction's instabilities resolve dynamically
    const scalar massScaling =
        mechanicalProperties_.lookupOrDefault<scalar>("massScaling", 1);
    if (!(massScaling >= 1 && massScaling <= 1e12))
    {
        FatalIOErrorInFunction(mechanicalProperties_)
            << "Keyword 'massScaling' in " << mechanicalProperties_.name()
            << " is " << massScaling << "; expected a value in [1, 1e12]"
            << nl << exit(FatalIOError);
    }
    if (inertia_)
    {
        inertiaDensity_ = massScaling*law_->rho();
    }
    else if (massScaling != 1)
    {
        IOWarningInFunction(mechanicalProperties_)
            << "Keyword 'massScaling' in " << mechanicalProperties_.name()
            << " has no effect: the run is quasi-static (d2dt2Schemes "
            << "steadyState)" << endl;
    }

    // Constructing from a tmp drops the write option: set it here so the
    // plastic history reaches every written time (and a restart)
    const IOobject::writeOption historyWrite =
        law_->plastic() ? IOobject::AUTO_WRITE : IOobject::NO_WRITE;
    CpInv_.writeOpt() = historyWrite;
    epsilonPf_.writeOpt() = historyWrite;

    volumetricAveraging_ =
        mechanicalProperties_.lookupOrDefault<bool>("volumetricAveraging", true);
    volumetricAveragingWeight_ =
        mechanicalProperties_.lookupOrDefault<scalar>
        (
            "volumetricAveragingWeight", 1
        );
    if (volumetricAveragingWeight_ < 0 || volumetricAveragingWeight_ > 1)
    {
        FatalIOErrorInFunction(mechanicalProperties_)
            << "Keyword 'volumetricAveragingWeight' in "
            << mechanicalProperties_.name() << " is "
            << volumetricAveragingWeight_ << "; expected a value in [0, 1]"
            << nl << exit(FatalIOError);
    }
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh.solutionD()[d] != 1)
        {
            emptyProjector_.component(4*d) = 1;
        }
    }

    // A restart with inertia reads the velocity to recover D at t - dt
    if (inertia_)
    {
        IOobject velIo
        (
            "V", mesh.time().timeName(), mesh, IOobject::READ_IF_PRESENT
        );
        if (velIo.typeHeaderOk<volVectorField>())
        {
            const volVectorField vel(velIo, mesh);
            D00_ = D0_ - vel.primitiveField()*deltaT0_;
        }
    }

    classifyPatches();
    computeGradientWeights();

    // [S14] force-scale floor: the face-force magnitudes each cell would
    // balance under a uniform stress of E x 1e-6, summed as in residual()
    {
        const scalar sigma = 1e-6*law_->E();
        scalarField fMag(mesh.nCells(), Zero);
        const scalarField& magSf = mesh.magSf();
        forAll(mesh.owner(), facei)
        {
            fMag[mesh.owner()[facei]] += sigma*magSf[facei];
            fMag[mesh.neighbour()[facei]] += sigma*magSf[facei];
        }
        forAll(mesh.boundary(), patchi)
        {
            if (patchKinds_[patchi] != EMPTY)
            {
                const fvPatch& p = mesh.boundary()[patchi];
                forAll(p, i)
                {
                    fMag[p.faceCells()[i]] += sigma*p.magSf()[i];
                }
            }
        }
        forceFloor_ = Foam::sqrt(gSumSqr(fMag));
    }

    if (preconditionerType_ == "fdJacobian")
    {
        fdJacobian_.reset
        (
            new finiteDifferenceJacobian(residualInfluence(), comps_.size())
        );
        Info<< "Preconditioner: finite-difference Jacobian, "
            << returnReduce(fdJacobian_->nColours(), maxOp<label>())
            << " colours" << endl;
    }
    else if (preconditionerType_ != "compact")
    {
        FatalIOErrorInFunction(mesh.solutionDict())
            << "Keyword 'preconditioner' in dictionary "
            << mesh.solutionDict().name() << "/solid is '"
            << preconditionerType_ << "'; expected fdJacobian or compact"
            << nl << exit(FatalIOError);
    }

    // Plastic history at the faces of every patch the stress is evaluated on
    trialInternal_.setSize(mesh.nInternalFaces());
    trialPatch_.setSize(mesh.boundary().size());
    forcePatchD0_.setSize(mesh.boundary().size());
    forAll(mesh.boundary(), patchi)
    {
        trialPatch_[patchi].setSize(mesh.boundary()[patchi].size());
        if (patchKinds_[patchi] == FORCE)
        {
            // the written patch value is the face displacement (restart)
            forcePatchD0_[patchi] = D_.boundaryField()[patchi];
        }
    }

    Info<< "Total Lagrangian solid: " << comps_.size() << "-D, "
        << returnReduce(mesh.nCells(), sumOp<label>()) << " cells, law "
        << law_->type() << ", E " << law_->E() << " Pa, nu " << law_->nu()
        << (inertia_ ? ", with inertia" : ", quasi-static");
    if (inertia_ && massScaling > 1)
    {
        Info<< " (mass scaling " << massScaling << ")";
    }
    Info<< nl << endl;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "solidDiscretisation.H"
#include "faceColumns.H"
#include "strictDictionary.H"
#include "calculatedFvPatchFields.H"
#include "ListListOps.H"
#include "solidRestartState.H"
#include "processorPlace.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(solidDiscretisation, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- History field read from the start time if written, else its initial
//  value; written only when the law is plastic
template<class Type>
static tmp<GeometricField<Type, fvsPatchField, surfaceMesh>> historyField
(
    const fvMesh& mesh,
    const word& name,
    const Type& initial
)
{
    typedef GeometricField<Type, fvsPatchField, surfaceMesh> fieldType;
    IOobject io
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::READ_IF_PRESENT,
        IOobject::NO_WRITE
    );
    if (io.typeHeaderOk<fieldType>())
    {
        return tmp<fieldType>::New(io, mesh);
    }
    io.readOpt() = IOobject::NO_READ;
    return tmp<fieldType>::New
    (
        io, mesh, dimensioned<Type>(name, dimless, initial)
    );
}


//- Projector on the unsolved direction of a plane-strain mesh
static tensor emptyProjector(const fvMesh& mesh, const bool axisymmetric)
{
    tensor E(Zero);
    if (!axisymmetric)
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (mesh.geometricD()[d] != 1)
            {
                E.component(4*d) = 1;
            }
        }
    }
    return E;
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::solidDiscretisation::computeForceFloor() const
{
    const scalar sigma = 1e-6*laws_.maxE();
    scalarField fMag(mesh_.nCells(), Zero);
    const scalarField& magSf = mesh_.magSf();
    forAll(mesh_.owner(), facei)
    {
        fMag[mesh_.owner()[facei]] += sigma*magSf[facei];
        fMag[mesh_.neighbour()[facei]] += sigma*magSf[facei];
    }
    forAll(mesh_.boundary(), patchi)
    {
        if (bcs_.kind(patchi) != solidBoundaries::EMPTY)
        {
            const fvPatch& p = mesh_.boundary()[patchi];
            forAll(p, i)
            {
                fMag[p.faceCells()[i]] += sigma*p.magSf()[i];
            }
        }
    }
    return Foam::sqrt(gSumSqr(fMag));
}


Foam::materialState Foam::solidDiscretisation::oldState
(
    const label patchi,
    const label facei
) const
{
    materialState s;
    if (patchi < 0)
    {
        s.CpInv = CpInv_[facei];
        s.epsilonP = epsilonPf_[facei];
    }
    else
    {
        s.CpInv = CpInv_.boundaryField()[patchi][facei];
        s.epsilonP = epsilonPf_.boundaryField()[patchi][facei];
    }
    return s;
}


Foam::tensor Foam::solidDiscretisation::internalFaceF(const label facei) const
{
    const label P = mesh_.owner()[facei];
    const label N = mesh_.neighbour()[facei];
    const vectorField& u = u_.primitiveField();
    const vectorField& C = mesh_.C().primitiveField();
    const scalar w = mesh_.weights()[facei];

    return fbar_.apply
    (
        volumetricAveraging::faceDefGrad
        (
            G_[P], G_[N], w, C[N] - C[P], u[N] - u[P]
        ),
        w*J_[P] + (1 - w)*J_[N]
    );
}


bool Foam::solidDiscretisation::boundaryFaceDefGrad
(
    const label patchi,
    const label i,
    tensor& F,
    scalar& Jbar,
    faceColumns* columns,
    const tensorField* cofactors
) const
{
    const fvPatch& p = mesh_.boundary()[patchi];
    const label P = p.faceCells()[i];
    const vector& uP = u_[P];
    const tensor& GP = G_[P];
    const vector& delta = patchDelta_[patchi][i];

    // the derivative columns' pieces: P's stencil, the face's direction
    // e, L = I - e e (the tangential part of the cell gradients [S11])
    const gradientStencil* sP = columns ? &grad_.stencil(P) : nullptr;
    const label globalP = columns ? grad_.cellNumbering().toGlobal(P) : -1;
    const vector e(delta/mag(delta));
    const tensor L(tensor::I - sqr(e));

    Jbar = J_[P];
    switch (bcs_.kind(patchi))
    {
        case solidBoundaries::COUPLED:
        {
            // the neighbour's values, exchanged by setIterate()
            const scalar w = p.weights()[i];
            const tensor& GN = GNbr_[patchi][i];
            F = volumetricAveraging::faceDefGrad
            (
                GP, GN, w, delta, uNbr_[patchi][i] - uP
            );
            Jbar = w*J_[P] + (1 - w)*det(tensor::I + GN.T());
            if (columns)
            {
                columns->addStencil(*sP, w, L, (*cofactors)[P]);
                columns->addStencil
                (
                    grad_.neighbourStencil(patchi, i), 1 - w, L,
                    cofactor(GN)
                );
                columns->addCompact
                (
                    grad_.neighbourCell(patchi, i), e/mag(delta)
                );
                columns->addCompact(globalP, -e/mag(delta));
            }
            return true;
        }
        case solidBoundaries::FIXED:
        {
            const vector& Db = D_.boundaryField()[patchi][i];
            F = volumetricAveraging::faceDefGrad(GP, GP, 1, delta, Db - uP);
            if (columns)
            {
                columns->addStencil(*sP, 1, L, (*cofactors)[P]);
                columns->addCompact(globalP, -e/mag(delta));
            }
            return true;
        }
        case solidBoundaries::SYMMETRY:
        {
            // the tangential part of the extrapolated value:
            // dD = (I - n n).(u_P + delta.G_P) - u_P
            const vector& n = patchNormal_[patchi][i];
            const vector uB(uP + (delta & GP));
            F = volumetricAveraging::faceDefGrad
            (
                GP, GP, 1, delta, (uB - (n & uB)*n) - uP
            );
            if (columns)
            {
                const tensor Pn(tensor::I - sqr(n));
                columns->addStencil(*sP, 1, L, (*cofactors)[P]);
                const vector c(e/mag(delta));
                const label self = columns->slot(globalP);
                addScaled
                (
                    columns->dG[self], 1,
                    outerMatrix
                    (
                        c,
                        (Pn & (tensor::I + dotDerivative(delta, sP->self)))
                      - tensor::I
                    )
                );
                forAll(sP->cells, j)
                {
                    addScaled
                    (
                        columns->dG[columns->slot(sP->cells[j])], 1,
                        outerMatrix(c, (delta & sP->coeffs[j])*Pn)
                    );
                }
            }
            return true;
        }
        case solidBoundaries::WEDGE:
        {
            // [S20] the cell's F, rotated onto the face by the caller: the
            // same volume change, so no volume averaging
            F = tensor::I + GP.T();
            if (columns)
            {
                columns->addStencil(*sP, 1, tensor::I, (*cofactors)[P]);
            }
            return true;
        }
        default:
            return false;
    }
}


Foam::tensor Foam::solidDiscretisation::boundaryFaceF
(
    const label patchi,
    const label i
) const
{
    tensor F;
    scalar Jbar;
    if (!boundaryFaceDefGrad(patchi, i, F, Jbar))
    {
        FatalErrorInFunction
            << "No face deformation gradient on patch "
            << mesh_.boundary()[patchi].name() << abort(FatalError);
    }
    if (bcs_.kind(patchi) == solidBoundaries::WEDGE)
    {
        const tensor& T = bcs_.wedgeRotation(patchi);
        return T & F & T.T();
    }
    return fbar_.apply(F, Jbar);
}


void Foam::solidDiscretisation::gatherCouplingStencils()
{
    // [C13] in parallel a contact pair's face may couple to a face of the
    // other surface on another processor: every processor keeps the
    // stencils of all faces of the coupled force patches
    couplingStencils_.setSize(mesh_.boundary().size());
    couplingDelta_.setSize(mesh_.boundary().size());
    if (!Pstream::parRun())
    {
        return;
    }
    forAll(mesh_.boundary(), patchi)
    {
        if
        (
            bcs_.kind(patchi) != solidBoundaries::FORCE
         || !bcs_.forcePatch(patchi).couplesToOtherFaces()
        )
        {
            continue;
        }
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        List<List<gradientStencil>> stencils(Pstream::nProcs());
        List<vectorField> delta(Pstream::nProcs());
        List<gradientStencil>& own = stencils[Pstream::myProcNo()];
        own.setSize(fc.size());
        forAll(fc, i)
        {
            own[i] = grad_.stencil(fc[i]);
        }
        delta[Pstream::myProcNo()] = patchDelta_[patchi];
        Pstream::gatherList(stencils);
        Pstream::scatterList(stencils);
        Pstream::gatherList(delta);
        Pstream::scatterList(delta);
        couplingStencils_[patchi] =
            ListListOps::combine<List<gradientStencil>>
            (
                stencils, accessOp<List<gradientStencil>>()
            );
        couplingDelta_[patchi] =
            ListListOps::combine<vectorField>(delta, accessOp<vectorField>());
    }
}


const Foam::gradientStencil& Foam::solidDiscretisation::couplingStencil
(
    const label patchi,
    const label facei
) const
{
    if (Pstream::parRun())
    {
        return couplingStencils_[patchi][facei];
    }
    return grad_.stencil(mesh_.boundary()[patchi].faceCells()[facei]);
}


const Foam::vector& Foam::solidDiscretisation::couplingDelta
(
    const label patchi,
    const label facei
) const
{
    return
        Pstream::parRun()
      ? couplingDelta_[patchi][facei]
      : patchDelta_[patchi][facei];
}


void Foam::solidDiscretisation::forcePatchKinematics
(
    const label patchi,
    vectorField& Dface,
    tensorField& F
) const
{
    // [C2] the face value extrapolated from the cell with its gradient
    const labelUList& fc = mesh_.boundary()[patchi].faceCells();
    const vectorField& d = patchDelta_[patchi];

    Dface.setSize(fc.size());
    F.setSize(fc.size());
    forAll(fc, i)
    {
        const tensor& Gi = G_[fc[i]];
        Dface[i] = u_[fc[i]] + (d[i] & Gi);
        F[i] = tensor::I + Gi.T();
    }
}


// * * * * * * * * * * * * * * * * * Set-up  * * * * * * * * * * * * * * * * //

void Foam::solidDiscretisation::setPatchGeometry()
{
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        patchDelta_[patchi] =
            bcs_.kind(patchi) == solidBoundaries::COUPLED
          ? p.delta()
          : tmp<vectorField>(p.Cf() - p.Cn());
        patchNormal_[patchi] = p.nf();
    }
}


void Foam::solidDiscretisation::attachForcePatches()
{
    forAll(mesh_.boundary(), patchi)
    {
        if (bcs_.kind(patchi) == solidBoundaries::FORCE)
        {
            bcs_.forcePatch(patchi).attach(*this);
        }
    }
}


void Foam::solidDiscretisation::setHistoryOutput()
{
    // Constructing from a tmp drops the write option: set it here so the
    // plastic history reaches every written time (and a restart)
    const IOobject::writeOption historyWrite =
        laws_.plastic() ? IOobject::AUTO_WRITE : IOobject::NO_WRITE;
    CpInv_.writeOpt() = historyWrite;
    epsilonPf_.writeOpt() = historyWrite;
    if (laws_.plastic())
    {
        // [S19b] a restart without the history would start it virgin
        solidRestartState::require
        (
            mesh_, "CpInv", "the plastic history (inverse plastic right"
            " Cauchy-Green tensor at faces)"
        );
        solidRestartState::require
        (
            mesh_, "epsilonPf", "the plastic history (equivalent plastic"
            " strain at faces)"
        );
    }
}


Foam::scalar Foam::solidDiscretisation::readInertia
(
    const dictionary& mechanicalProperties
)
{
    const dictionary& schemes = mesh_.schemesDict();
    // the solver discretises the momentum balance itself: of fvSchemes it
    // reads d2dt2Schemes' default alone, and a per-field entry there
    // ('d2dt2(D) Euler;') or a misspelled 'default' would be ignored
    strictDictionary::check
    (
        schemes.subDict("d2dt2Schemes"), {"default"},
        "largeStrainSolidFoam reads only 'default' there: steadyState"
        " (quasi-static) or Euler (inertia)"
    );
    const word d2dt2(schemes.subDict("d2dt2Schemes").get<word>("default"));
    if (d2dt2 == "Euler")
    {
        inertia_ = true;
    }
    else if (d2dt2 != "steadyState")
    {
        FatalIOErrorInFunction(schemes)
            << "Keyword 'default' in d2dt2Schemes of " << schemes.name()
            << " is '" << d2dt2 << "'; expected steadyState (quasi-static)"
            << " or Euler (inertia)" << nl << exit(FatalIOError);
    }
    for (label bodyi = 0; inertia_ && bodyi < laws_.size(); ++bodyi)
    {
        if (laws_[bodyi].rho() <= 0)
        {
            FatalIOErrorInFunction(mechanicalProperties)
                << "Keyword 'rho' in " << mechanicalProperties.name()
                << " (body " << laws_.name(bodyi) << ") must be > 0 when"
                << " d2dt2Schemes is Euler" << nl << exit(FatalIOError);
        }
    }

    // [S13b] mass scaling: quasi-static forming runs with a heavier body so
    // that the rate-dependent friction's instabilities resolve dynamically
    const scalar massScaling =
        mechanicalProperties.lookupOrDefault<scalar>("massScaling", 1);
    if (!(massScaling >= 1 && massScaling <= 1e12))
    {
        FatalIOErrorInFunction(mechanicalProperties)
            << "Keyword 'massScaling' in " << mechanicalProperties.name()
            << " is " << massScaling << "; expected a value in [1, 1e12]"
            << nl << exit(FatalIOError);
    }
    if (inertia_)
    {
        forAll(inertiaDensity_, celli)
        {
            inertiaDensity_[celli] = massScaling*laws_.cellLaw(celli).rho();
        }
    }
    else if (massScaling != 1)
    {
        IOWarningInFunction(mechanicalProperties)
            << "Keyword 'massScaling' in " << mechanicalProperties.name()
            << " has no effect: the run is quasi-static (d2dt2Schemes "
            << "steadyState)" << endl;
    }
    return massScaling;
}


void Foam::solidDiscretisation::initialisePatchStates
(
    const volVectorField& D
)
{
    forAll(mesh_.boundary(), patchi)
    {
        trialPatch_[patchi].setSize(mesh_.boundary()[patchi].size());
        if (bcs_.kind(patchi) == solidBoundaries::FORCE)
        {
            // the written patch value is the face displacement (restart)
            forcePatchD0_[patchi] = D.boundaryField()[patchi];
        }
    }
}


void Foam::solidDiscretisation::reportSetup(const scalar massScaling) const
{
    Info<< "Total Lagrangian solid: " << mesh_.nGeometricD() << "-D"
        << (bcs_.axisymmetric() ? " axisymmetric" : "") << ", "
        << returnReduce(mesh_.nCells(), sumOp<label>()) << " cells, ";
    if (laws_.size() == 1)
    {
        Info<< "law " << laws_[0].type() << ", E " << laws_[0].E()
            << " Pa, nu " << laws_[0].nu();
    }
    else
    {
        Info<< laws_.size() << " bodies";
    }
    Info<< (inertia_ ? ", with inertia" : ", quasi-static");
    if (inertia_ && massScaling > 1)
    {
        Info<< " (mass scaling " << massScaling << ")";
    }
    Info<< nl << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidDiscretisation::forceKinematics::forceKinematics
(
    const solidDiscretisation& disc,
    const label patchi,
    const scalar deltaT
)
:
    Dface_(),
    F_(),
    // Dface_ and F_ are filled before k refers to them (the aggregate's
    // clauses are evaluated in order)
    k
    {
        disc.mesh_.boundary()[patchi].Sf(),
        disc.mesh_.boundary()[patchi].Cf(),
        (disc.forcePatchKinematics(patchi, Dface_, F_), Dface_),
        disc.forcePatchD0_[patchi],
        F_,
        disc.mesh_.time().value(),
        deltaT
    }
{}


Foam::solidDiscretisation::solidDiscretisation
(
    const dictionary& mechanicalProperties,
    const bodyLaws& laws,
    const volVectorField& D,
    const solidBoundaries& bcs
)
:
    mesh_(D.mesh()),
    laws_(laws),
    bcs_(bcs),
    D_(D),
    grad_(mesh_, bcs),
    fbar_
    (
        mechanicalProperties,
        bcs.axisymmetric() ? 3 : mesh_.nGeometricD(),
        emptyProjector(mesh_, bcs.axisymmetric())
    ),
    u_
    (
        IOobject("Dwork", mesh_.time().timeName(), mesh_),
        D,
        calculatedFvPatchVectorField::typeName
    ),
    G_
    (
        IOobject("gradDwork", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedTensor(dimless, Zero)
    ),
    J_(mesh_.nCells(), 1),
    CpInv_(historyField(mesh_, "CpInv", symmTensor::I)),
    epsilonPf_(historyField(mesh_, "epsilonPf", scalar(0))),
    trialInternal_(mesh_.nInternalFaces()),
    trialPatch_(mesh_.boundary().size()),
    inertia_(false),
    inertiaDensity_(mesh_.nCells(), Zero),
    D0_(D.primitiveField()),
    D00_(D.primitiveField()),
    deltaT0_(mesh_.time().deltaTValue()),
    forcePatchD0_(mesh_.boundary().size()),
    patchDelta_(mesh_.boundary().size()),
    patchNormal_(mesh_.boundary().size()),
    uNbr_(mesh_.boundary().size()),
    GNbr_(mesh_.boundary().size()),
    patternMissed_(false),
    forceScale_(0),
    forceFloor_(0)
{
    setPatchGeometry();
    // The force boundaries get the solid they load before anything asks
    // them for a force (the coupling stencils below already do)
    attachForcePatches();
    gatherCouplingStencils();
    setHistoryOutput();
    const scalar massScaling = readInertia(mechanicalProperties);
    initialisePatchStates(D);

    forceFloor_ = computeForceFloor();

    setIterate(D0_);

    reportSetup(massScaling);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidDiscretisation::setIterate(const vectorField& u)
{
    u_.primitiveFieldRef() = u;
    u_.correctBoundaryConditions();

    grad_.gradient(u_, D_, G_.primitiveFieldRef());
    G_.correctBoundaryConditions();

    forAll(mesh_.boundary(), patchi)
    {
        if (bcs_.kind(patchi) == solidBoundaries::COUPLED)
        {
            uNbr_[patchi] = u_.boundaryField()[patchi].patchNeighbourField();
            GNbr_[patchi] = G_.boundaryField()[patchi].patchNeighbourField();
        }
    }

    forAll(J_, celli)
    {
        J_[celli] = det(tensor::I + G_[celli].T());
    }
}


void Foam::solidDiscretisation::setPreviousStep
(
    const vectorField& D00,
    const scalar dt0
)
{
    D00_ = D00;
    deltaT0_ = dt0;
}


Foam::tmp<Foam::vectorField> Foam::solidDiscretisation::faceDisplacement
(
    const label patchi
) const
{
    tmp<vectorField> tD(new vectorField);
    tensorField F;
    forcePatchKinematics(patchi, tD.ref(), F);
    return tD;
}


Foam::label Foam::solidDiscretisation::correctPrediction(vectorField& u)
{
    setIterate(u);
    vectorField du(u.size(), Zero);
    labelField nFaces(u.size(), 0);
    label nCorrected = 0;
    for (const label patchi : bcs_.contactPatchIDs())
    {
        const forceKinematics fk(*this, patchi, mesh_.time().deltaTValue());
        vectorField dD(fk.k.D.size(), Zero);
        if (bcs_.contactPatch(patchi).predictorCorrection(fk.k, dD) == 0)
        {
            continue;
        }
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        forAll(fc, i)
        {
            if (magSqr(dD[i]) > 0)
            {
                du[fc[i]] += dD[i];
                ++nFaces[fc[i]];
                ++nCorrected;
            }
        }
    }
    scalar largest = 0;
    forAll(u, celli)
    {
        if (nFaces[celli])
        {
            u[celli] += du[celli]/nFaces[celli];
            largest = max(largest, mag(du[celli]/nFaces[celli]));
        }
    }
    reduce(nCorrected, sumOp<label>());
    reduce(largest, maxOp<scalar>());
    if (nCorrected)
    {
        Info<< "    predictor: " << nCorrected << " contact faces kept at"
            << " their converged gap (largest correction " << largest
            << " m)" << endl;
    }
    return nCorrected;
}


void Foam::solidDiscretisation::holdLinearisation(const bool on)
{
    for (const label patchi : bcs_.contactPatchIDs())
    {
        if (!on)
        {
            bcs_.contactPatch(patchi).release();
            continue;
        }
        // the fields hold the last evaluated iterate
        const forceKinematics fk(*this, patchi, mesh_.time().deltaTValue());
        bcs_.contactPatch(patchi).linearise(fk.k);
    }
}


bool Foam::solidDiscretisation::augmentedForcePatches() const
{
    for (const label patchi : bcs_.contactPatchIDs())
    {
        if (bcs_.contactPatch(patchi).augmentable())
        {
            return true;
        }
    }
    return false;
}


bool Foam::solidDiscretisation::augmentForcePatches()
{
    bool again = false;
    for (const label patchi : bcs_.contactPatchIDs())
    {
        const forceKinematics fk(*this, patchi, mesh_.time().deltaTValue());
        // every patch (no short cut: the call is collective)
        if (bcs_.contactPatch(patchi).augment(fk.k))
        {
            again = true;
        }
    }
    return again;
}


Foam::label Foam::solidDiscretisation::forcePatchFacesPressedThrough()
{
    label n = 0;
    for (const label patchi : bcs_.contactPatchIDs())
    {
        const forceKinematics fk(*this, patchi, mesh_.time().deltaTValue());
        n += bcs_.contactPatch(patchi).facesPressedThrough(fk.k);
    }
    return n;
}


Foam::PtrList<Foam::solidDiscretisation::forceKinematics>
Foam::solidDiscretisation::contactPatchKinematics(const vectorField& u)
{
    const scalar dt = mesh_.time().deltaTValue();
    setIterate(u);
    PtrList<forceKinematics> k(mesh_.boundary().size());
    for (const label patchi : bcs_.contactPatchIDs())
    {
        k.set(patchi, new forceKinematics(*this, patchi, dt));
    }
    return k;
}


Foam::scalar Foam::solidDiscretisation::firstContactFraction
(
    const vectorField& u0,
    const vectorField& u1
)
{
    const PtrList<forceKinematics> k0(contactPatchKinematics(u0));
    const PtrList<forceKinematics> k1(contactPatchKinematics(u1));
    scalar fraction = 1;
    for (const label patchi : bcs_.contactPatchIDs())
    {
        // every patch (no short cut: the call is collective)
        fraction =
            min
            (
                fraction,
                bcs_.contactPatch(patchi).firstContactFraction
                (
                    k0[patchi].k, k1[patchi].k
                )
            );
    }
    return fraction;
}


Foam::label Foam::solidDiscretisation::predictContacts
(
    const vectorField& u0,
    const vectorField& u1
)
{
    // (u0 last: the iterate the solve goes on from)
    const PtrList<forceKinematics> k1(contactPatchKinematics(u1));
    const PtrList<forceKinematics> k0(contactPatchKinematics(u0));
    label nMarked = 0;
    for (const label patchi : bcs_.contactPatchIDs())
    {
        // every patch (the call is collective)
        nMarked +=
            bcs_.contactPatch(patchi).predictContacts
            (
                k0[patchi].k, k1[patchi].k
            );
    }
    return nMarked;
}


void Foam::solidDiscretisation::clearPredictedContacts()
{
    for (const label patchi : bcs_.contactPatchIDs())
    {
        bcs_.contactPatch(patchi).clearPredictedContacts();
    }
}


Foam::string Foam::solidDiscretisation::describeContactOnset() const
{
    // this processor's first onset, then the earliest over the processors
    scalar fraction = GREAT;
    string where;
    for (const label patchi : bcs_.contactPatchIDs())
    {
        scalar f;
        string w;
        if (bcs_.contactPatch(patchi).lastContactOnset(f, w) && f < fraction)
        {
            fraction = f;
            where = w;
        }
    }
    const label proci = gatherProcessorPlace(fraction, where, false);
    if (proci < 0 || fraction >= GREAT)
    {
        return "";
    }
    return where + onProcessor(proci);
}


Foam::label Foam::solidDiscretisation::widenContactOnset
(
    const scalar factor
)
{
    label nPatches = 0;
    for (const label patchi : bcs_.contactPatchIDs())
    {
        if (bcs_.contactPatch(patchi).widenContactOnset(factor))
        {
            ++nPatches;
        }
    }
    return nPatches;
}


void Foam::solidDiscretisation::resetAugmentation
(
    const scalar extrapolation
)
{
    for (const label patchi : bcs_.contactPatchIDs())
    {
        bcs_.contactPatch(patchi).resetAugmentation(extrapolation);
    }
}


void Foam::solidDiscretisation::commit(const scalar dt)
{
    // The trial state of the current iterate
    vectorField R(mesh_.nCells());
    residual(R);

    forAll(trialInternal_, facei)
    {
        CpInv_[facei] = trialInternal_[facei].CpInv;
        epsilonPf_[facei] = trialInternal_[facei].epsilonP;
    }

    forAll(mesh_.boundary(), patchi)
    {
        const solidBoundaries::patchKind kind = bcs_.kind(patchi);
        if (kind != solidBoundaries::FORCE && kind != solidBoundaries::EMPTY)
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
    }

    // The force boundaries after the whole plastic history: a contact takes
    // the next step's flow stress from it [F35]
    forAll(mesh_.boundary(), patchi)
    {
        if (bcs_.kind(patchi) == solidBoundaries::FORCE)
        {
            const forceKinematics fk(*this, patchi, dt);
            const solidPatchKinematics& k = fk.k;
            bcs_.forcePatch(patchi).commit(k);
            forcePatchD0_[patchi] = k.D;
        }
    }

    D00_ = D0_;
    D0_ = u_.primitiveField();
    deltaT0_ = dt;
}


void Foam::solidDiscretisation::reportForcePatches() const
{
    forAll(mesh_.boundary(), patchi)
    {
        if (bcs_.kind(patchi) != solidBoundaries::FORCE)
        {
            continue;
        }
        const forceKinematics fk(*this, patchi, deltaT0_);
        const solidPatchKinematics& k = fk.k;
        bcs_.forcePatch(patchi).report(k);
    }
}


Foam::tmp<Foam::scalarField> Foam::solidDiscretisation::cellPlasticStrain
(
    const labelUList& cells
) const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const surfaceScalarField& magSf = mesh_.magSf();

    tmp<scalarField> teps(new scalarField(cells.size(), 0));
    scalarField& eps = teps.ref();
    forAll(cells, i)
    {
        scalar sumA = 0;
        scalar sumE = 0;
        for (const label f : mesh_.cells()[cells[i]])
        {
            if (mesh_.isInternalFace(f))
            {
                sumA += magSf[f];
                sumE += magSf[f]*epsilonPf_[f];
                continue;
            }
            const label patchi = pbm.whichPatch(f);
            const solidBoundaries::patchKind kind = bcs_.kind(patchi);
            if (kind == solidBoundaries::FORCE || kind == solidBoundaries::EMPTY)
            {
                continue;
            }
            const label j = f - pbm[patchi].start();
            const scalar a = magSf.boundaryField()[patchi][j];
            sumA += a;
            sumE += a*epsilonPf_.boundaryField()[patchi][j];
        }
        eps[i] = sumE/max(sumA, VSMALL);
    }
    return teps;
}


void Foam::solidDiscretisation::cellAverages
(
    symmTensorField& sigma,
    scalarField& epsilonP
) const
{
    // Internal faces carry the stress average (the boundary faces' stress
    // is one-sided); the boundary faces with a history add to the plastic
    // strain. The committed history is the end-of-step state, so the
    // stress needs no further plastic correction.
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& magSf = mesh_.magSf();

    sigma.setSize(mesh_.nCells());
    sigma = Zero;
    epsilonP.setSize(mesh_.nCells());
    epsilonP = Zero;
    scalarField area(mesh_.nCells(), Zero);
    scalarField areaInt(mesh_.nCells(), Zero);

    forAll(own, facei)
    {
        const tensor F(internalFaceF(facei));
        const materialState old(oldState(-1, facei));
        materialState s;
        const symmTensor sig
        (
            mechanicalLaw::cauchy
            (
                laws_.cellLaw(own[facei]).stress(F, old, s), F
            )
        );
        const scalar a = magSf[facei];
        for (const label c : {own[facei], nei[facei]})
        {
            sigma[c] += a*sig;
            epsilonP[c] += a*old.epsilonP;
            area[c] += a;
            areaInt[c] += a;
        }
    }

    forAll(mesh_.boundary(), patchi)
    {
        const solidBoundaries::patchKind kind = bcs_.kind(patchi);
        if (kind == solidBoundaries::FORCE || kind == solidBoundaries::EMPTY)
        {
            continue;
        }
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        const scalarField& a = mesh_.boundary()[patchi].magSf();
        const scalarField& epsB = epsilonPf_.boundaryField()[patchi];
        forAll(fc, i)
        {
            epsilonP[fc[i]] += a[i]*epsB[i];
            area[fc[i]] += a[i];
        }
    }

    forAll(sigma, celli)
    {
        sigma[celli] /= max(areaInt[celli], VSMALL);
        epsilonP[celli] /= max(area[celli], VSMALL);
    }
}


Foam::vector Foam::solidDiscretisation::reactionForce(const label patchi) const
{
    // The sum of P.S0 over the faces of a fixed patch
    const fvPatch& p = mesh_.boundary()[patchi];
    vector total(Zero);
    forAll(p, i)
    {
        materialState s;
        total +=
            laws_.cellLaw(p.faceCells()[i]).stress
            (
                boundaryFaceF(patchi, i), oldState(patchi, i), s
            ) & p.Sf()[i];
    }
    return total;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "totalLagrangianSolid.H"
#include "OStringStream.H"
#include "HashSet.H"
#include "calculatedFvPatchFields.H"
#include "cpuTime.H"
#include "solidRestartState.H"
#include "eigenVector.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(totalLagrangianSolid, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField>
Foam::totalLagrangianSolid::previousDisplacement(const volVectorField& D)
{
    IOobject io
    (
        "Dprevious",
        D.time().timeName(),
        D.mesh(),
        IOobject::READ_IF_PRESENT,
        IOobject::AUTO_WRITE
    );
    if (io.typeHeaderOk<volVectorField>())
    {
        return tmp<volVectorField>::New(io, D.mesh());
    }
    // plain values: D's force patches (contact state) are not repeated
    return tmp<volVectorField>::New
    (
        io, D, calculatedFvPatchVectorField::typeName
    );
}


Foam::labelList Foam::totalLagrangianSolid::solvedComponents
(
    const fvMesh& mesh
)
{
    labelList comps;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh.geometricD()[d] == 1)
        {
            comps.append(d);
        }
    }
    return comps;
}


Foam::vectorField Foam::totalLagrangianSolid::unpack
(
    const Eigen::VectorXd& x
) const
{
    vectorField v(mesh_.nCells());
    unpack(x, v);
    return v;
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
    laws_(mechanicalProperties_, mesh),
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
    Dprevious_(previousDisplacement(D_)),
    bcs_(D_),
    discretisation_(mechanicalProperties_, laws_, D_, bcs_),
    comps_(solvedComponents(mesh)),
    jacobian_
    (
        discretisation_.jacobianPattern(),
        comps_,
        discretisation_.cellNumbering()
    ),
    linearSolver_(),
    predictorContact_
    (
        mesh.solutionDict().subDict("solid")
       .lookupOrDefault<bool>("predictorContact", true)
    ),
    bodySize_(mag(mesh.bounds().span())),
    tangentGuess_(),
    tangentTime_(-GREAT),
    tangentCommits_(-1),
    nCommits_(0),
    previousStep_(false),
    fixedValues0_(),
    checkStep_(1e-8)
{
    // D is a displacement in metres: a field file of other dimensions is
    // a wrong file, which the solver's arithmetic would not notice before
    // the first write
    if (D_.dimensions() != dimLength)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, D_.objectPath(), -1
        )   << "Keyword 'dimensions' in " << D_.objectPath() << " is "
            << D_.dimensions() << "; expected " << dimLength
            << " (the displacement D, metres)" << nl
            << exit(FatalIOError);
    }

    // Constructing from a tmp drops the write option
    Dprevious_.writeOpt() = IOobject::AUTO_WRITE;

    // [S19b] without it a restart's predictor and inertia term differ
    solidRestartState::require
    (
        mesh, "Dprevious", "the displacement of the step before"
    );

    jacobian_.setCoordinates(mesh.C().primitiveField());

    const dictionary& solidDict = mesh.solutionDict().subDict("solid");
    linearSolver_ = newLinearSolver();
    Info<< "    " << linearSolver_->description().c_str() << endl;

    if (solidDict.lookupOrDefault<bool>("checkJacobian", false))
    {
        const label n = returnReduce(nDofs(), sumOp<label>());
        if (n > 20000)
        {
            FatalIOErrorInFunction(solidDict)
                << "Keyword 'checkJacobian' in dictionary " << solidDict.name()
                << ": the finite-difference check costs two residual"
                << " evaluations per unknown; " << n << " unknowns is more"
                << " than the 20000 it is meant for" << nl
                << exit(FatalIOError);
        }
        check_.reset(new jacobianCheck());

        // Steps of 1e-8 of the body (strains near 1e-7): the truncation
        // error is near 1e-14 for smooth laws, the plastic return
        // mapping's tolerance (1e-14 of the stress) gives 1e-7. A law
        // with a steep rate dependence (rate-and-state at slip increments
        // of that order) needs smaller steps
        checkStep_ =
            solidDict.lookupOrDefault<scalar>("checkJacobianStep", 1e-8);
        Info<< "    checkJacobian: every Jacobian is compared with central"
            << " differences (" << n << " unknowns)" << endl;
    }

    // The step before the written one: Dprevious if written (a restart
    // with the same predictor and inertia as the uninterrupted run [S19]);
    // a run written before Dprevious existed recovers it from the velocity
    const scalar dt0 = mesh.time().deltaT0Value();
    IOobject velIo
    (
        "V", mesh.time().timeName(), mesh, IOobject::READ_IF_PRESENT
    );
    IOobject previousIo
    (
        "Dprevious", mesh.time().timeName(), mesh, IOobject::READ_IF_PRESENT
    );
    if (previousIo.typeHeaderOk<volVectorField>())
    {
        discretisation_.setPreviousStep(Dprevious_.primitiveField(), dt0);
        previousStep_ = true;
    }
    else if (discretisation_.inertia() && velIo.typeHeaderOk<volVectorField>())
    {
        previousStep_ = true;
        const volVectorField vel(velIo, mesh);
        discretisation_.setPreviousStep
        (
            D_.primitiveField() - vel.primitiveField()*dt0, dt0
        );
    }

    // [S18c] the given displacements of the state read (a restart's too)
    fixedValues0_ = fixedValues();
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::totalLagrangianSolid::~totalLagrangianSolid()
{
    if (check_.valid())
    {
        Info<< "Jacobian check: largest relative difference "
            << check_->largest() << " in " << check_->nChecks()
            << " Jacobians" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::vectorField>
Foam::totalLagrangianSolid::fixedValues() const
{
    List<vectorField> values(mesh_.boundary().size());
    forAll(values, patchi)
    {
        if (bcs_.kind(patchi) == solidBoundaries::FIXED)
        {
            values[patchi] = D_.boundaryField()[patchi];
        }
    }
    return values;
}


void Foam::totalLagrangianSolid::setFixedValues
(
    const List<vectorField>& a,
    const List<vectorField>& b,
    const scalar s
)
{
    forAll(a, patchi)
    {
        if (bcs_.kind(patchi) == solidBoundaries::FIXED)
        {
            D_.boundaryFieldRef()[patchi] ==
                a[patchi] + s*(b[patchi] - a[patchi]);
        }
    }
}


bool Foam::totalLagrangianSolid::tangentPrediction
(
    const Eigen::VectorXd& xStart,
    Eigen::VectorXd& x
)
{
    // [S18c] linearised at the last converged state: D_n with its given
    // displacements. The residual there is the load of the forces and
    // obstacles of the new time; the given displacements' change enters
    // through the residual's derivative along it, a central difference
    // over 1e-3 of the change (error 1e-6 of a nonlinear response; exact
    // for a linear one). The change itself at D_n would be no guide: the
    // ironing die's first push inverts its top cells there, where neither
    // the residual nor its Jacobian says anything useful
    const List<vectorField> fixedValues1(fixedValues());
    setFixedValues(fixedValues0_, fixedValues1, 0);

    string why;
    Eigen::VectorXd R;
    Eigen::VectorXd dx;
    residual(xStart, R);
    const bool jacobianOk = gFinite(R) && updateJacobian(xStart);
    if (jacobianOk)
    {
        const scalar s = 1e-3;
        Eigen::VectorXd Rplus;
        Eigen::VectorXd Rminus;
        setFixedValues(fixedValues0_, fixedValues1, s);
        residual(xStart, Rplus);
        setFixedValues(fixedValues0_, fixedValues1, -s);
        residual(xStart, Rminus);
        R += (Rplus - Rminus)/(2*s);
    }
    setFixedValues(fixedValues0_, fixedValues1, 1);

    if (!jacobianOk)
    {
        why = gFinite(R) ? failure() : "the residual is not finite";
    }
    else if (!gFinite(R))
    {
        why = "the residual's derivative is not finite";
    }
    else
    {
        // as tight as the Newton solve's first ([S16b]
        // initialForcingTerm): an error here is Newton's to remove
        dx.setZero(xStart.size());
        const linearSolver::performance perf = solveJacobian(R, dx, 1e-4);
        if (!gFinite(dx))
        {
            why = "the linear solve's correction is not finite";
        }
        else if (!perf.converged && !(perf.relativeResidual < 1))
        {
            // [S16c] not a descent direction
            why =
                "the linear solve stopped at relative residual "
              + Foam::name(perf.relativeResidual) + " (" + perf.reason + ")";
        }
    }

    // the linear solver starts the Newton solve as at any step [S19]
    linearSolver_->forgetHistory();
    discretisation_.setIterate(discretisation_.D0());

    if (!why.empty())
    {
        Info<< "    tangent predictor not used, the step starts from the"
            << " last converged state: " << why.c_str() << endl;
        return false;
    }
    x = xStart + dx;
    Info<< "    predictor: the tangent guess [S18c], largest change "
        << gMaxNorm(dx) << " m" << endl;
    return true;
}


void Foam::totalLagrangianSolid::beginStep
(
    Eigen::VectorXd& x,
    Eigen::VectorXd& xStart,
    const timeStepController::predictorType predictor
)
{
    // Boundary values at the new time (uniformFixedValue and the like)
    D_.correctBoundaryConditions();

    // [S19] nothing of the previous steps' linear solves carries over
    linearSolver_->forgetHistory();

    pack(discretisation_.D0(), xStart);
    x = xStart;

    // [S18c] tangentFirst: the tangent where the extrapolation has no
    // step to extrapolate (it would give D_n)
    const timeStepController::predictorType kind =
        predictor != timeStepController::TANGENT_FIRST ? predictor
      : previousStep_ ? timeStepController::EXTRAPOLATE
      : timeStepController::TANGENT;

    // [S18] the step's size over the last one's, 0 where nothing is
    // extrapolated
    const scalar ratio =
        kind == timeStepController::EXTRAPOLATE
      ? mesh_.time().deltaTValue()/discretisation_.deltaT0()
      : 0;

    // [C5b] every attempt starts from the last converged multipliers,
    // [C5f] extrapolated as the displacements are
    discretisation_.resetAugmentation(ratio);

    if (kind == timeStepController::EXTRAPOLATE)
    {
        Eigen::VectorXd x00;
        pack(discretisation_.D00(), x00);
        x += ratio*(xStart - x00);
    }
    else if (kind == timeStepController::TANGENT)
    {
        // [S18c] the continuation retry [S14e] asks again for the same
        // step: the same guess, without a second Jacobian and solve
        const scalar t = mesh_.time().value();
        if (tangentCommits_ == nCommits_ && tangentTime_ == t)
        {
            x = tangentGuess_;
        }
        else
        {
            tangentPrediction(xStart, x);
            tangentGuess_ = x;
            tangentTime_ = t;
            tangentCommits_ = nCommits_;
        }
    }

    // [S18b] faces in contact at the last converged state kept in contact
    // by the prediction
    if (predictor != timeStepController::NONE && predictorContact_)
    {
        vectorField u(unpack(x));
        if (discretisation_.correctPrediction(u))
        {
            pack(u, x);
        }
    }
}


bool Foam::totalLagrangianSolid::augmentable() const
{
    return discretisation_.augmentedForcePatches();
}


bool Foam::totalLagrangianSolid::augment(const Eigen::VectorXd& x)
{
    discretisation_.setIterate(unpack(x));
    return discretisation_.augmentForcePatches();
}


Foam::label Foam::totalLagrangianSolid::contactFacesPressedThrough
(
    const Eigen::VectorXd& x
)
{
    discretisation_.setIterate(unpack(x));
    return discretisation_.forcePatchFacesPressedThrough();
}


Foam::string Foam::totalLagrangianSolid::describeUnknown(const label i) const
{
    const label nc = comps_.size();
    const label celli = i/nc;
    const char* xyz = "xyz";
    OStringStream os;
    os  << "cell " << celli << " at " << mesh_.C()[celli]
        << ", component " << xyz[comps_[i % nc]];
    wordHashSet patches;
    for (const label facei : mesh_.cells()[celli])
    {
        if (!mesh_.isInternalFace(facei))
        {
            patches.insert
            (
                mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(facei)]
               .name()
            );
        }
    }
    if (patches.size())
    {
        os  << ", next to " << flatOutput(patches.sortedToc());
    }
    return os.str();
}


Foam::scalar Foam::totalLagrangianSolid::firstContactFraction
(
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& dx
)
{
    return discretisation_.firstContactFraction(unpack(x), unpack(x + dx));
}


Foam::label Foam::totalLagrangianSolid::predictContacts
(
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& dx
)
{
    return discretisation_.predictContacts(unpack(x), unpack(x + dx));
}


void Foam::totalLagrangianSolid::clearPredictedContacts()
{
    discretisation_.clearPredictedContacts();
}


Foam::string Foam::totalLagrangianSolid::describeContactOnset() const
{
    return discretisation_.describeContactOnset();
}


Foam::label Foam::totalLagrangianSolid::widenContactOnset
(
    const scalar factor
)
{
    return discretisation_.widenContactOnset(factor);
}


void Foam::totalLagrangianSolid::commit(const Eigen::VectorXd& x)
{
    discretisation_.setIterate(unpack(x));
    discretisation_.commit(mesh_.time().deltaTValue());
    ++nCommits_;
    previousStep_ = true;

    D_.primitiveFieldRef() = discretisation_.D0();
    D_.correctBoundaryConditions();
    forAll(mesh_.boundary(), patchi)
    {
        if (bcs_.kind(patchi) == solidBoundaries::FORCE)
        {
            // the face displacement: the contact's slip and a restart
            // start from it
            D_.boundaryFieldRef()[patchi] ==
                discretisation_.faceDisplacement(patchi);
        }
    }
    Dprevious_.primitiveFieldRef() = discretisation_.D00();
    Dprevious_.correctBoundaryConditions();

    fixedValues0_ = fixedValues();
}


Foam::dictionary Foam::totalLagrangianSolid::state() const
{
    dictionary dict;
    dict.add("deltaT0", discretisation_.deltaT0());
    return dict;
}


void Foam::totalLagrangianSolid::setState(const dictionary& dict)
{
    discretisation_.setPreviousStep
    (
        Dprevious_.primitiveField(), dict.get<scalar>("deltaT0")
    );
}


void Foam::totalLagrangianSolid::residual
(
    const Eigen::VectorXd& x,
    Eigen::VectorXd& R
)
{
    discretisation_.setIterate(unpack(x));

    vectorField Rcell(mesh_.nCells());
    discretisation_.residual(Rcell);
    pack(Rcell, R);
}


bool Foam::totalLagrangianSolid::updateJacobian(const Eigen::VectorXd& x)
{
    cpuTime timer;
    const vectorField u(unpack(x));
    discretisation_.setIterate(u);
    discretisation_.jacobian(jacobian_);
    if (discretisation_.patternMissed())
    {
        // [C13] a contact pair moved past the pattern's margin: a new
        // pattern, a new linear solver for it, the values again
        linearSolver_.clear();
        jacobian_.setPattern(discretisation_.jacobianPattern());
        linearSolver_ = newLinearSolver();
        discretisation_.jacobian(jacobian_);
        if (debug)
        {
            Info<< "        Jacobian pattern rebuilt (contact pairs)" << endl;
        }
    }
    shiftDiagonal();
    const scalar tAssembly = timer.cpuTimeIncrement();

    List<vectorField> Uf;
    List<vectorField> Vf;
    discretisation_.meanCouplings(Uf, Vf);
    List<Eigen::VectorXd> U(Uf.size());
    List<Eigen::VectorXd> V(Vf.size());
    forAll(Uf, t)
    {
        pack(Uf[t], U[t]);
        pack(Vf[t], V[t]);
    }

    if (check_.valid())
    {
        check_->compare(*this, x, jacobian_, U, V, checkStep_*bodySize_);
        discretisation_.setIterate(u);
    }

    const bool ok =
        linearSolver_->update()
     && meanCouplings_.update(U, V, linearSolver_());

    if (debug)
    {
        Info<< "        Jacobian assembly " << tAssembly << " s, linear solver"
            << " update " << timer.cpuTimeIncrement() << " s (CPU)" << endl;
    }
    return ok;
}


Foam::autoPtr<Foam::linearSolver>
Foam::totalLagrangianSolid::newLinearSolver() const
{
    // subOrEmptyDict copies a found sub-dictionary without its parent;
    // copied again with the parent (not moved: that would prefix the
    // parent's name a second time)
    const dictionary& solidDict = mesh_.solutionDict().subDict("solid");
    const dictionary userDict(solidDict.subOrEmptyDict("linearSolver"));
    return linearSolver::New(dictionary(solidDict, userDict), jacobian_);
}


void Foam::totalLagrangianSolid::shiftDiagonal()
{
    // [S16] 1e-9 of the mean diagonal: the Jacobian of a body held only by
    // contact that has just opened (or by nothing but friction in stick)
    // is singular in its rigid-body modes; shifted, the factorisation
    // stays defined and a Jacobian-free retry's preconditioner bounded.
    // Elsewhere it changes the Newton step by 1e-9
    const label nc = jacobian_.nComponents();
    labelList diag(jacobian_.nRows());
    scalar sum = 0;
    forAll(diag, r)
    {
        diag[r] = jacobian_.find(r, jacobian_.globalRow(r));
        for (label a = 0; a < nc; ++a)
        {
            sum += mag(jacobian_(diag[r], a, a));
        }
    }
    const scalar shift =
        1e-9*returnReduce(sum, sumOp<scalar>())
       /max(returnReduce(jacobian_.nLocalUnknowns(), sumOp<label>()), 1);
    forAll(diag, r)
    {
        for (label a = 0; a < nc; ++a)
        {
            jacobian_(diag[r], a, a) += shift;
        }
    }
}


Foam::string Foam::totalLagrangianSolid::failure() const
{
    const string why(linearSolver_->updateFailure());
    return
        "the Jacobian could not be factorised (singular) by the linear"
        " solver " + linearSolver_->description() + ", sub-dictionary"
        " linearSolver of " + mesh_.solutionDict().name()
      + "/solid" + (why.empty() ? string() : ": " + why);
}


Foam::linearSolver::performance Foam::totalLagrangianSolid::solveJacobian
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& dx,
    const scalar relTol
)
{
    return meanCouplings_.solve(linearSolver_(), b, dx, relTol);
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "newtonSolver.H"
#include "IOstreams.H"
#include "cpuTime.H"
#include "OStringStream.H"
#include "processorPlace.H"
#include "boundedEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::newtonSolver::method>
Foam::newtonSolver::methodNames
({
    { method::exact, "exact" },
    { method::jacobianFree, "jacobianFree" },
});


const Foam::Enum<Foam::newtonSolver::onsetStop>
Foam::newtonSolver::onsetStopNames
({
    { onsetStop::always, "always" },
    { onsetStop::afterLineSearch, "afterLineSearch" },
    { onsetStop::never, "never" },
    // (the former switch)
    { onsetStop::always, "yes" },
    { onsetStop::never, "no" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

using strictDictionary::readBounded;

//- [S14b] The smallest fraction of a step kept when it stops at a contact
//  onset: a face just short of its onset does not stall the solve
static const scalar minOnsetFraction = 1e-2;

//- [S14f] A stalled solve stops early only above this residual (of |F|):
//  below it Newton is near the answer, where faces cycling between
//  stick and slip may still settle (the ironing's steps at 1e-7-1e-6)
static const scalar stalledFarResidual = 1e-4;

// The ranges of the controls (strictDictionary::readBounded)
static bool positive(const scalar& x) { return x > 0; }
static bool nonNegative(const scalar& x) { return x >= 0; }
static bool inUnitInterval(const scalar& x) { return x > 0 && x < 1; }
static bool atLeastOne(const label& n) { return n >= 1; }
static bool nonNegativeCount(const label& n) { return n >= 0; }

//- |R|, or GREAT where R is not finite (a trial the line search rejects)
static scalar finiteNorm(const Eigen::VectorXd& R)
{
    return gFinite(R) ? gNorm(R) : GREAT;
}


static bool readDisplacementTest(const dictionary& dict)
{
    const word name
    (
        dict.lookupOrDefault<word>("displacementTest", "estimate")
    );
    if (name != "estimate" && name != "correction")
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'displacementTest' in dictionary " << dict.name()
            << " is '" << name << "'; expected estimate or correction" << nl
            << exit(FatalIOError);
    }
    return name == "estimate";
}


static newtonSolver::method readMethod(const dictionary& dict)
{
    const word name(dict.lookupOrDefault<word>("newtonMethod", "exact"));
    if (!newtonSolver::methodNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'newtonMethod' in dictionary " << dict.name()
            << " is '" << name << "'; expected one of "
            << newtonSolver::methodNames.sortedToc() << nl
            << exit(FatalIOError);
    }
    return newtonSolver::methodNames[name];
}


static newtonSolver::onsetStop readOnsetStop(const dictionary& dict)
{
    const word name
    (
        dict.lookupOrDefault<word>("stopAtContactOnset", "afterLineSearch")
    );
    if (!newtonSolver::onsetStopNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'stopAtContactOnset' in dictionary " << dict.name()
            << " is '" << name << "'; expected always, afterLineSearch or"
            << " never" << nl << exit(FatalIOError);
    }
    return newtonSolver::onsetStopNames[name];
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::newtonSolver::newtonSolver(const dictionary& dict)
:
    method_(readMethod(dict)),
    forceTol_
    (
        readBounded<scalar>
        (
            dict, "forceTolerance", 1e-7, positive, "a value > 0"
        )
    ),
    acceptableForceTol_
    (
        readBounded<scalar>
        (
            dict, "acceptableForceTolerance", 0, nonNegative,
            "a value >= 0 (0: off)"
        )
    ),
    stallIterations_
    (
        readBounded<label>
        (
            dict, "stallIterations", 8, atLeastOne, "an integer >= 1"
        )
    ),
    stallStopIterations_
    (
        readBounded<label>
        (
            dict, "stallStopIterations", 0, nonNegativeCount,
            "an integer >= 0 (0: off)"
        )
    ),
    displacementTol_
    (
        readBounded<scalar>
        (
            dict, "displacementTolerance", 1e-7, positive, "a value > 0"
        )
    ),
    maxNewton_
    (
        readBounded<label>
        (
            dict, "maxNewtonIterations", 25, atLeastOne, "an integer >= 1"
        )
    ),
    verbose_(dict.lookupOrDefault<bool>("verbose", false)),
    rejectPredictor_(dict.lookupOrDefault<bool>("rejectPredictor", false)),
    initialForcing_
    (
        readBounded<scalar>
        (
            dict, "initialForcingTerm", 1e-4, inUnitInterval,
            "a value in (0, 1)"
        )
    ),
    finalChordStep_(dict.lookupOrDefault<bool>("finalChordStep", true)),
    estimateError_(readDisplacementTest(dict)),
    holdLinearisation_
    (
        dict.lookupOrDefault<bool>("holdContactLinearisation", true)
    ),
    stopAtContactOnset_(readOnsetStop(dict)),
    contactLookAhead_
    (
        readBounded<label>
        (
            dict, "contactLookAhead", 0, nonNegativeCount,
            "a number of linear solves >= 0 (0: off)"
        )
    ),
    onsetContinuation_
    (
        readBounded<scalar>
        (
            dict, "onsetContinuation", 10,
            [](const scalar f) { return f >= 1 && std::isfinite(f); },
            "a factor >= 1 (1: off)"
        )
    ),
    krylovRefresh_
    (
        readBounded<label>
        (
            dict, "krylovRefresh", 15, nonNegativeCount, "an integer >= 0"
        )
    ),
    augmentInside_
    (
        dict.lookupOrDefault<bool>("augmentBetweenIterations", true)
    ),
    augmentForceFactor_
    (
        readBounded<scalar>
        (
            dict, "augmentForceFactor", 1e4,
            [](const scalar f) { return f >= 1; },
            "a value >= 1 (the multipliers are updated once |R|/|F| is"
            " below it times forceTolerance)"
        )
    ),
    augmentForcing_
    (
        readBounded<scalar>
        (
            dict, "augmentForcingTerm", 1e-3, inUnitInterval,
            "a value in (0, 1)"
        )
    ),
    gmres_(dict),
    lineSearch_(dict, stopAtContactOnset_ == onsetStop::afterLineSearch),
    nResidualEvaluations_(0),
    jacobianFree_(false)
{
    if (dict.found("preconditioner"))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'preconditioner' in dictionary " << dict.name()
            << " was removed: the Jacobian is now assembled exactly"
            << " (doc/theory.md [S21])." << nl
            << "Choose the method with 'newtonMethod exact;' (default) or"
            << " 'newtonMethod jacobianFree;' and the linear solver with"
            << " 'linearSolver { type eigenLU; }'" << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::newtonSolver::evaluate
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    Eigen::VectorXd& R
)
{
    ++nResidualEvaluations_;
    sys.residual(x, R);
}


Foam::string Foam::newtonSolver::largestResidual
(
    const nonlinearSystem& sys,
    const Eigen::VectorXd& R
) const
{
    // (collective: every processor's largest entry to the master)
    Eigen::Index imax = -1;
    scalar value = R.size() ? R.cwiseAbs().maxCoeff(&imax) : -1;
    string place(imax >= 0 ? sys.describeUnknown(imax) : "");
    const label proci = gatherProcessorPlace(value, place, true);
    OStringStream os;
    os  << value << " N at " << place.c_str() << onProcessor(proci).c_str();
    return os.str();
}


Foam::scalar Foam::newtonSolver::contactOnsetFraction
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& dx
) const
{
    const scalar onset = sys.firstContactFraction(x, dx);
    if (onset >= 1)
    {
        return 1;
    }
    if (verbose_)
    {
        const string where(sys.describeContactOnset());
        Info<< "        contact onset at " << onset << " of the step";
        if (!where.empty())
        {
            Info<< ": " << where.c_str();
        }
        Info<< endl;
    }
    return max(onset, minOnsetFraction);
}


bool Foam::newtonSolver::lookAhead
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const scalar linTol,
    Eigen::VectorXd& dx,
    linearSolver::performance& perf,
    result& res
)
{
    // [S14c] contact faces open at x that the correction closes are not
    // in this Jacobian: the correction carries them deep into their
    // obstacles. Solve again with them on the penalty's line through
    // their gaps (residual and Jacobian at x), until the correction closes
    // no other face
    label nLookAhead = 0;
    Eigen::VectorXd Rp(x.size());
    while
    (
        nLookAhead < contactLookAhead_
     && sys.predictContacts(x, dx) > 0
    )
    {
        ++nLookAhead;
        evaluate(sys, x, Rp);
        if (!sys.updateJacobian(x))
        {
            sys.clearPredictedContacts();
            res.reason = sys.failure();
            return false;
        }
        dx.setZero(x.size());
        const scalar normRp = gNorm(Rp);
        perf =
            sys.solveJacobian
            (
                Rp, dx, normRp > 0 ? min(linTol/normRp, 0.1) : 0.1
            );
        if (!gFinite(dx))
        {
            break;
        }
    }
    if (nLookAhead > 0)
    {
        sys.clearPredictedContacts();
        res.contactLookAheadSolves += nLookAhead;
        if (verbose_)
        {
            Info<< "        " << nLookAhead << " look-ahead solves"
                << " with the faces the step closes" << endl;
        }
    }
    return true;
}


bool Foam::newtonSolver::descentDirection
(
    const linearSolver::performance& perf,
    const bool chord,
    result& res
) const
{
    // [S16c] a Krylov solve that stopped short (maxIterations, a
    // breakdown) is a Newton direction only while its true residual is
    // below |R|: then R.M dx > 0, a descent direction of |R|^2. Otherwise
    // the line search only creeps on the non-smooth parts of R: the solve
    // fails, as a Jacobian that cannot be factorised does (the step is
    // retried Jacobian-free, then cut back [S18]); a chord step is first
    // retried with a new Jacobian
    const scalar rel = perf.relativeResidual;
    const bool descent = rel < 1;
    Info<< "        linear solve not converged ("
        << (perf.reason.empty() ? string("no reason") : perf.reason).c_str()
        << ", " << perf.iterations << " iterations, true relative"
        << " residual " << rel << "): "
        << (
               descent ? "correction taken (a descent direction)"
             : chord ? "no descent direction, new Jacobian"
             : "no descent direction, the Newton solve fails"
           )
        << endl;
    if (!descent && !chord)
    {
        res.reason =
            "the linear solve failed: " + perf.reason
          + ", true relative residual |b - M dx|/|b| = "
          + Foam::name(rel) + " (not below 1: no descent direction)";
    }
    return descent;
}


bool Foam::newtonSolver::step
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& R,
    const scalar linTol,
    const label it,
    bool& chord,
    label& lastKrylov,
    Eigen::VectorXd& dx,
    result& res
)
{
    if (!jacobianFree_)
    {
        // [S14] exact Newton: the assembled Jacobian at x, solved to the
        // forcing term (a direct solver solves exactly); a chord step
        // [S16b] solves with the Jacobian and set-up already in place
        cpuTime timer;
        if (!chord && !sys.updateJacobian(x))
        {
            res.reason = sys.failure();
            return false;
        }
        const scalar tJacobian = timer.cpuTimeIncrement();
        dx.setZero(x.size());
        const scalar normR = gNorm(R);
        const scalar relTol = normR > 0 ? min(linTol/normR, 0.1) : 0.1;
        linearSolver::performance perf = sys.solveJacobian(R, dx, relTol);

        if (contactLookAhead_ > 0 && !chord && gFinite(dx))
        {
            if (!lookAhead(sys, x, linTol, dx, perf, res))
            {
                return false;
            }
        }
        if (verbose_)
        {
            Info<< "        " << (chord ? "chord step, " : "")
                << "Jacobian " << tJacobian << " s, linear solve "
                << timer.cpuTimeIncrement() << " s (CPU)" << endl;
        }
        lastKrylov = perf.iterations;
        if (!gFinite(dx))
        {
            res.reason =
                perf.reason.empty()
              ? string("the linear solve gave a non-finite correction")
              : perf.reason;
            return false;
        }
        if (!perf.converged && !descentDirection(perf, chord, res))
        {
            if (!chord)
            {
                return false;
            }
            chord = false;
            return step(sys, x, R, linTol, it, chord, lastKrylov, dx, res);
        }
        return true;
    }

    // [S15] Jacobian-free: the assembled Jacobian (refreshed when the last
    // Krylov solve needed many iterations) preconditions GMRES, during
    // which the contact faces keep their active set [S15b]
    if (it == 0 || lastKrylov < 0 || lastKrylov > krylovRefresh_)
    {
        if (!sys.updateJacobian(x))
        {
            res.reason = sys.failure();
            return false;
        }
    }
    if (holdLinearisation_)
    {
        sys.holdLinearisation(true);
    }
    lastKrylov = gmres_.solve(sys, x, R, linTol, dx, nResidualEvaluations_);
    if (holdLinearisation_)
    {
        sys.holdLinearisation(false);
    }
    return true;
}


void Foam::newtonSolver::iterationState::restart
(
    const Eigen::VectorXd& x,
    const label itStart
)
{
    recentNorms.clear();
    recentNorms.append(normR);
    xBest = x;
    normBest = normR;
    itBest = itStart;
    dxPrev = dxCur = 0;
    fullPrev = fullLast = false;
    firstSolve = true;
    chordTaken = false;
}


Foam::scalar Foam::newtonSolver::relativeForceResidual
(
    const scalar normR,
    const scalar forceScale
)
{
    return forceScale > 0 ? normR/forceScale : (normR > 0 ? 1 : 0);
}


void Foam::newtonSolver::measureResiduals
(
    const nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& xStart,
    iterationState& s,
    result& res
) const
{
    s.forceScale = sys.forceScale();
    res.forceResidual = relativeForceResidual(s.normR, s.forceScale);

    const scalar increment =
        max(gMaxNorm(x - xStart), 1e-6*sys.typicalDisplacement());
    res.displacementResidual = s.dxCur/increment;
    if (estimateError_ && s.fullLast && s.fullPrev && s.dxCur < s.dxPrev)
    {
        // [S16b] the error of this iterate from the observed contraction
        // theta: |x - x*| <= theta/(1 - theta) |dx|
        const scalar theta = s.dxCur/s.dxPrev;
        res.displacementResidual *= min(1, theta/(1 - theta));
    }
}


void Foam::newtonSolver::updateMultipliers
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const label it,
    iterationState& s,
    result& res
)
{
    // [C5b] inexact Uzawa: near the solution the multipliers are updated
    // at the iterate and Newton goes on from it with them (its next step
    // absorbs the update, with maxNewtonIterations more); a solve
    // converges only where they did not change
    if (!sys.augment(x))
    {
        res.multipliersConverged = true;
        return;
    }
    ++res.augmentations;
    evaluate(sys, x, s.R);
    s.normR = finiteNorm(s.R);
    s.normRprev = s.normR;
    s.restart(x, it);
    s.itLimit = it + maxNewton_;
    s.afterUpdate = true;
    s.forceScale = sys.forceScale();
    res.forceResidual = relativeForceResidual(s.normR, s.forceScale);
    res.displacementResidual = GREAT;
}


bool Foam::newtonSolver::endsUnconverged
(
    nonlinearSystem& sys,
    Eigen::VectorXd& x,
    const label it,
    iterationState& s,
    result& res
)
{
    const scalar bestResidual =
        s.forceScale > 0 ? s.normBest/s.forceScale : 1;
    // a solve that ends without converging returns its best iterate
    const auto returnBest = [&]()
    {
        if (s.normBest < s.normR)
        {
            x = s.xBest;
            evaluate(sys, x, s.R);
            res.forceResidual = bestResidual;
        }
    };
    const bool accept =
        bestResidual <= acceptableForceTol_
     && (it == s.itLimit || it - s.itBest >= stallIterations_);
    if (accept || it == s.itLimit)
    {
        returnBest();
        res.converged = accept;
        res.accepted = accept;
        if (!accept)
        {
            res.reason = "no convergence in maxNewtonIterations";
        }
        return true;
    }
    if
    (
        stallStopIterations_ > 0 && it - s.itBest >= stallStopIterations_
     && bestResidual > stalledFarResidual
    )
    {
        // [S14f] the best |R| has not fallen by 10 % in
        // stallStopIterations iterations, far from the answer: the
        // retries start now, not at itLimit
        returnBest();
        res.reason =
            "stalled: |R| not 10 % below its best for "
          + Foam::name(stallStopIterations_) + " iterations";
        return true;
    }
    return false;
}


Foam::scalar Foam::newtonSolver::linearTolerance
(
    iterationState& s,
    const scalar forceTol
) const
{
    // Eisenstat-Walker forcing term (choice 2), no tighter than needed to
    // reach the force tolerance; after a step that barely lowered |R| (an
    // active set changing) the tightest, since a loose solve with an
    // outdated preconditioner then misleads Newton further
    scalar eta;
    if (s.afterUpdate)
    {
        // [C5b] the update's correction is needed only to the accuracy of
        // the next update (a fraction of it)
        eta = augmentForcing_;
        s.firstSolve = false;
    }
    else if (s.firstSolve)
    {
        eta = initialForcing_;
        s.firstSolve = false;
    }
    else
    {
        const scalar ratio = s.normR/max(s.normRprev, VSMALL);
        eta = ratio < 0.9 ? min(0.1, max(0.9*sqr(ratio), 1e-4)) : 1e-4;
    }
    return max(eta*s.normR, 0.1*forceTol*s.forceScale);
}


bool Foam::newtonSolver::chordStep
(
    const nonlinearSystem& sys,
    const iterationState& s,
    const result& res,
    const scalar forceTol,
    const scalar displacementTol,
    bool& updateChord
) const
{
    // [S16b] the force test is met and only the displacement test is
    // left, in Newton's quadratic phase (the last correction below the
    // square root of the tolerance: the next one about its square): the
    // correction that decides the test is solved with the Jacobian and
    // set-up of the last iteration. Once per solve (a chord step converges
    // only linearly), and only with an iterative linear solver, whose
    // correction differs from Newton's by its tolerance already (a direct
    // solver's steps stay exact Newton steps)
    const bool finalChord =
        finalChordStep_ && !jacobianFree_ && s.haveJacobian && !s.chordTaken
     && sys.inexactJacobianSolve()
     && res.forceResidual <= forceTol
     && res.displacementResidual <= Foam::sqrt(displacementTol);

    // [C5b] the step that absorbs a multiplier update: the update leaves
    // the Jacobian as it was (a constant shift of the penetration) and is
    // made near the solution, where the last correction hardly changed
    // it, so the Jacobian and set-up of the iteration before serve (a
    // chord step, also with a direct solver)
    updateChord = s.afterUpdate && s.haveJacobian && !jacobianFree_;
    return finalChord || updateChord;
}


void Foam::newtonSolver::limitCorrection
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    Eigen::VectorXd& dx,
    result& res
) const
{
    // A correction larger than 1 % of the body is not a Newton step but
    // the answer of a (nearly) singular Jacobian: a body held only by
    // contact that has just opened moves freely. It is scaled down, and
    // the line search finds how far it may go
    const scalar maxCorrection = 1e4*sys.typicalDisplacement();
    const scalar dxMax = gMaxNorm(dx);
    if (dxMax > maxCorrection)
    {
        dx *= maxCorrection/dxMax;
    }

    // [S14b] the step stops where a contact face that is open at x
    // reaches its obstacle: past it the linearisation (no contact
    // stiffness there) does not hold, and the full step would drive the
    // face through the obstacle. 'always': here, before the line search;
    // 'afterLineSearch' (default): only where no fraction of the step
    // lowers |R| (faces that the step closes only a little, as the rings
    // of a widening Hertz contact, then cost no stop each)
    if (stopAtContactOnset_ == onsetStop::always)
    {
        const scalar onset = contactOnsetFraction(sys, x, dx);
        if (onset < 1)
        {
            dx *= onset;
            ++res.contactOnsetStops;
        }
    }
}


Foam::newtonLineSearch::outcome Foam::newtonSolver::searchLine
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    iterationState& s,
    result& res
)
{
    const auto trial = [&](const scalar l)
    {
        s.xTrial = x + l*s.dx;
        evaluate(sys, s.xTrial, s.Rtrial);
        return finiteNorm(s.Rtrial);
    };
    const auto onset = [&]()
    {
        return contactOnsetFraction(sys, x, s.dx);
    };
    const newtonLineSearch::outcome out =
        lineSearch_.search
        (
            s.normR,
            lineSearch_.referenceNorm(s.recentNorms),
            trial,
            onset,
            s.predicted
        );
    res.contactOnsetStops += out.onsetStop;
    return out;
}


void Foam::newtonSolver::restartFromStart
(
    nonlinearSystem& sys,
    Eigen::VectorXd& x,
    const Eigen::VectorXd& xStart,
    const label it,
    iterationState& s,
    result& res
)
{
    // [S16b] the predictor lies across an active-set switch: no fraction
    // of the step from it helps; restart from the last converged state
    // (this iteration counts)
    if (verbose_)
    {
        Info<< "        " << s.lastKrylov << " linear iterations, no"
            << " decrease from the predictor: restart from the last"
            << " converged state" << endl;
    }
    s.predicted = false;
    res.predictorRejected = true;
    x = xStart;
    evaluate(sys, x, s.R);
    s.normRprev = s.normR;
    s.normR = finiteNorm(s.R);
    s.restart(x, it + 1);
    s.dx.setZero();
    s.haveJacobian = false;
    s.lastKrylov = -1;
}


void Foam::newtonSolver::takeStep
(
    Eigen::VectorXd& x,
    const label it,
    const bool chord,
    const newtonLineSearch::outcome& ls,
    iterationState& s
) const
{
    if (verbose_)
    {
        Info<< "        " << s.lastKrylov << " linear iterations, step "
            << ls.lambda << (ls.decreased ? "" : " (no decrease)") << endl;
    }

    s.dx *= ls.lambda;
    s.dxPrev = s.dxCur;
    s.dxCur = gMaxNorm(s.dx);
    s.fullPrev = s.fullLast;
    // (a chord step's contraction is not Newton's: no estimate from it)
    s.fullLast = ls.decreased && ls.lambda == 1 && !chord;
    x = s.xTrial;
    s.R = s.Rtrial;
    s.normRprev = s.normR;
    s.normR = ls.norm;
    s.recentNorms.append(s.normR);
    if (s.normR < s.normBest)
    {
        if (s.normR < 0.9*s.normBest)
        {
            s.itBest = it + 1;
        }
        s.normBest = s.normR;
        s.xBest = x;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::newtonSolver::result Foam::newtonSolver::solve
(
    nonlinearSystem& sys,
    Eigen::VectorXd& x,
    const Eigen::VectorXd& xStart,
    const bool jacobianFree,
    const scalar toleranceScale
)
{
    // the tolerances of this solve (toleranceScale > 1: [C5b]'s
    // intermediate solves)
    const scalar forceTol = toleranceScale*forceTol_;
    const scalar displacementTol = toleranceScale*displacementTol_;

    result res;
    nResidualEvaluations_ = 0;
    jacobianFree_ =
        jacobianFree
     || method_ == method::jacobianFree
     || sys.approximateJacobianSolve();

    iterationState s(x.size());
    evaluate(sys, x, s.R);
    s.normR = gNorm(s.R);
    s.normRprev = s.normR;
    s.restart(x, 0);
    s.itLimit = maxNewton_;
    // [S16b] was the initial guess extrapolated (a predictor)?
    s.predicted = rejectPredictor_ && gMaxNorm(x - xStart) > 0;

    // [C5b] multipliers updated between the iterations
    const bool augmenting = augmentInside_ && sys.augmentable();

    for (label it = 0; it <= s.itLimit; ++it)
    {
        if (!gFinite(s.R))
        {
            res.reason = "residual is not finite";
            break;
        }

        measureResiduals(sys, x, xStart, s, res);
        if (verbose_)
        {
            Info<< "    Newton " << it << ": force residual "
                << res.forceResidual << ", displacement correction "
                << res.displacementResidual << endl;
            Info<< "        largest residual "
                << largestResidual(sys, s.R).c_str() << endl;
        }

        res.multipliersConverged = false;
        if (augmenting && res.forceResidual <= augmentForceFactor_*forceTol)
        {
            updateMultipliers(sys, x, it, s, res);
        }

        if
        (
            res.forceResidual <= forceTol
         && res.displacementResidual <= displacementTol
        )
        {
            res.converged = true;
            break;
        }
        res.multipliersConverged = false;
        if (endsUnconverged(sys, x, it, s, res))
        {
            break;
        }

        const scalar linTol = linearTolerance(s, forceTol);
        bool updateChord = false;
        bool chord =
            chordStep(sys, s, res, forceTol, displacementTol, updateChord);
        s.afterUpdate = false;
        if (!step(sys, x, s.R, linTol, it, chord, s.lastKrylov, s.dx, res))
        {
            break;
        }
        s.haveJacobian = true;
        s.chordTaken = s.chordTaken || (chord && !updateChord);
        res.chordSteps += chord;
        res.krylovIterations += s.lastKrylov;
        ++res.newtonIterations;

        limitCorrection(sys, x, s.dx, res);
        const newtonLineSearch::outcome ls = searchLine(sys, x, s, res);
        if (ls.rejectPredictor)
        {
            restartFromStart(sys, x, xStart, it, s, res);
            continue;
        }
        s.predicted = false;
        if (ls.norm >= GREAT)
        {
            res.reason = "residual is not finite after the line search";
            break;
        }
        takeStep(x, it, chord, ls, s);
    }

    res.residualEvaluations = nResidualEvaluations_;
    return res;
}


// ************************************************************************* //

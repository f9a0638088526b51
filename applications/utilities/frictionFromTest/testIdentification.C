/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

\*---------------------------------------------------------------------------*/

#include "testIdentification.H"
#include "error.H"
#include "eigenResiduals.H"
#include <unsupported/Eigen/NonLinearOptimization>

// * * * * * * * * * * * * * * * Local Classes * * * * * * * * * * * * * * * //

namespace Foam
{

//- The residuals of an identification as Eigen's functor, of
//  x = 1 + ln(p/p0)
struct testIdentificationResiduals
:
    public eigenResiduals
{
    testIdentification* id;
    scalarList p0;
    int nOut;

    testIdentificationResiduals
    (
        testIdentification* id,
        const scalarList& p0,
        const int nOut
    )
    :
        id(id),
        p0(p0),
        nOut(nOut)
    {}

    int inputs() const { return p0.size(); }
    int values() const { return nOut; }

    scalarList parameters(const Eigen::VectorXd& x) const
    {
        scalarList p(p0.size());
        forAll(p, i)
        {
            p[i] = p0[i]*std::exp(x[i] - 1);
        }
        return p;
    }

    Eigen::VectorXd x(const scalarList& p) const
    {
        Eigen::VectorXd x(p.size());
        forAll(p, i)
        {
            x[i] = 1 + std::log(p[i]/p0[i]);
        }
        return x;
    }

    //- The residuals at x; -1 (stop) for a trial point within the
    //  tolerance of the last linearisation, the current iterate: the
    //  step is converged and need not run
    int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const
    {
        const scalarList p(parameters(x));
        if (id->nearLinearisation(p))
        {
            return -1;
        }
        id->linearise(p, r, nullptr);
        return 0;
    }

    //- dr/dx = p dr/dp
    int df(const Eigen::VectorXd& x, Eigen::MatrixXd& Jx) const
    {
        const scalarList p(parameters(x));
        Eigen::VectorXd r;
        id->linearise(p, r, &Jx);
        forAll(p, j)
        {
            Jx.col(j) *= p[j];
        }
        return 0;
    }
};

}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::testIdentification::testIdentification
(
    simulationModel& model,
    const scalarField& measured,
    const scalarField& sigma,
    const settings& s
)
:
    model_(model),
    measured_(measured),
    sigma_(sigma),
    set_(s)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Eigen::VectorXd Foam::testIdentification::residuals
(
    const scalarField& values
) const
{
    Eigen::VectorXd r(measured_.size());
    forAll(measured_, i)
    {
        r[i] = values.empty() ? 1e10 : (values[i] - measured_[i])/sigma_[i];
    }
    return r;
}


bool Foam::testIdentification::linearise
(
    const scalarList& p,
    Eigen::VectorXd& r,
    Eigen::MatrixXd* Jp
)
{
    // The point and, when the Jacobian is asked for, both sides in every
    // parameter: one batch of runs
    const bool withJ = Jp;
    const label nP = p.size();
    List<scalarList> ps(1, p);
    const scalar h = set_.relativeStep;
    if (withJ)
    {
        for (label j = 0; j < nP; ++j)
        {
            for (const scalar s : {1.0, -1.0})
            {
                scalarList q(p);
                q[j] = p[j]*std::exp(s*h);
                ps.append(q);
            }
        }
    }
    const List<simulationModel::run> runs(model_.evaluate(ps));
    r = residuals(runs[0].values);
    if (!withJ)
    {
        return !runs[0].values.empty();
    }
    Eigen::MatrixXd& J = *Jp;
    J.resize(measured_.size(), nP);
    for (label j = 0; j < nP; ++j)
    {
        const simulationModel::run& plus = runs[1 + 2*j];
        const simulationModel::run& minus = runs[2 + 2*j];
        const bool hasPlus = !plus.values.empty();
        const bool hasMinus = !minus.values.empty();
        const bool hasCentre = !runs[0].values.empty();
        // d/dp of the residuals, from the sides that ran (x = ln p)
        Eigen::VectorXd d = Eigen::VectorXd::Zero(measured_.size());
        if (hasPlus && hasMinus)
        {
            d = (residuals(plus.values) - residuals(minus.values))/(2*h);
        }
        else if (hasCentre && (hasPlus || hasMinus))
        {
            d = hasPlus
              ? Eigen::VectorXd((residuals(plus.values) - r)/h)
              : Eigen::VectorXd((r - residuals(minus.values))/h);
        }
        J.col(j) = d/p[j];
    }
    lastP_ = p;
    lastJ_ = J;
    return !runs[0].values.empty();
}


bool Foam::testIdentification::nearLinearisation(const scalarList& p) const
{
    if (lastJ_.rows() == 0)
    {
        return false;
    }
    forAll(p, j)
    {
        if (mag(std::log(p[j]/lastP_[j])) > set_.tolerance)
        {
            return false;
        }
    }
    return true;
}


Foam::testIdentification::result Foam::testIdentification::fit
(
    const scalarList& p0
)
{
    const label nP = p0.size(), n = measured_.size();
    if (n <= nP)
    {
        FatalErrorInFunction
            << n << " measured points for " << nP << " parameters: an"
            << " identification needs more points than parameters"
            << exit(FatalError);
    }
    testIdentificationResiduals f(this, p0, int(n));

    // The start: its run must give values, and each parameter must move
    // the model (else the case does not read the law, or the parameter
    // does not act on the measured quantities)
    {
        Eigen::VectorXd r;
        Eigen::MatrixXd J;
        if (!linearise(p0, r, &J))
        {
            const simulationModel::run r0 =
                model_.evaluate(List<scalarList>(1, p0))[0];
            if (r0.outside >= 0)
            {
                const testMeasurements::series& s =
                    model_.measurements().all()[r0.outside];
                FatalIOErrorInFunction(*s.dict)
                    << "keyword 'file': measured points beyond what the"
                    << " model simulates (" << model_.stage() << "): "
                    << r0.why.c_str() << "; measure within the simulated"
                    << " stroke or simulate further" << exit(FatalIOError);
            }
            FatalErrorInFunction
                << "the model at the start values gives no values: "
                << r0.why.c_str() << exit(FatalError);
        }
        for (label j = 0; j < nP; ++j)
        {
            if (!(J.col(j).norm() > 0))
            {
                FatalErrorInFunction
                    << "the measured quantities do not change with parameter"
                    << " '" << model_.names()[j] << "' of the friction law:"
                    << " does the model case read the law from its lawFile,"
                    << " and does the law act on the measured quantities?"
                    << exit(FatalError);
            }
        }
    }

    Eigen::LevenbergMarquardt<testIdentificationResiduals> lm(f);
    lm.parameters.xtol = set_.tolerance;
    lm.parameters.ftol = 1e-12;
    lm.parameters.gtol = 0;
    lm.parameters.maxfev = set_.maxEvaluations;
    lastJ_.resize(0, 0);
    // The first step changes a parameter by at most about a factor e
    lm.parameters.factor = 1;
    // Stop when a step changes no parameter by more than the relative
    // tolerance: MINPACK's own test is on the trust region, which stays
    // wide on data the model fits exactly and costs a batch of runs more
    Eigen::VectorXd x = Eigen::VectorXd::Ones(nP);
    int status = lm.minimizeInit(x);
    word why;
    if (status != Eigen::LevenbergMarquardtSpace::ImproperInputParameters)
    {
        do
        {
            const Eigen::VectorXd x0(x);
            status = lm.minimizeOneStep(x);
            if (status == Eigen::LevenbergMarquardtSpace::UserAsked)
            {
                why = "step below tolerance";
            }
            else if
            (
                status == Eigen::LevenbergMarquardtSpace::Running
             && (x - x0).lpNorm<Eigen::Infinity>() <= set_.tolerance
            )
            {
                why = "step below tolerance";
                break;
            }
        } while (status == Eigen::LevenbergMarquardtSpace::Running);
    }

    result res;
    res.start = p0;
    res.value = f.parameters(x);
    res.nEvaluations = lm.nfev + lm.njev;
    static const char* statusNames[] =
    {
        "improper input", "relative reduction small",
        "relative error small", "relative error and reduction small",
        "cosine small", "too many evaluations", "ftol too small",
        "xtol too small", "gtol too small", "user asked"
    };
    res.status =
        why.size() ? why
      : word(statusNames[std::max(0, std::min(status, 9))], false);

    // The intervals from the Jacobian at the solution, or at the last
    // step's start when the solution is within the tolerance of it
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    if (nearLinearisation(res.value))
    {
        J = lastJ_;
        r = residuals(model_.evaluate(List<scalarList>(1, res.value))[0].values);
    }
    else if (!linearise(res.value, r, &J))
    {
        FatalErrorInFunction
            << "the model gives no values at the identified parameters"
            << exit(FatalError);
    }
    const leastSquaresIntervals ci(r, J, set_.confidence);
    res.halfWidth = ci.halfWidth;
    res.stdError = ci.stdError;
    res.rms = ci.rms;
    res.dof = ci.dof;
    return res;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionFit.H"
#include "leastSquaresIntervals.H"
#include "frictionPointDriver.H"
#include "lawParameters.H"
#include "quietMessages.H"
#include "error.H"
#include "eigenResiduals.H"
#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

// * * * * * * * * * * * * * * * Local Classes * * * * * * * * * * * * * * * //

namespace Foam
{

//- The residuals of a fit as Eigen's functor, of x = ln(p/p_start)
struct frictionFitResiduals
:
    public eigenResiduals
{
    const frictionFit* fit;
    int nIn;
    int nOut;
    label* nEval;

    frictionFitResiduals
    (
        const frictionFit* fit,
        const int nIn,
        const int nOut,
        label* nEval
    )
    :
        fit(fit),
        nIn(nIn),
        nOut(nOut),
        nEval(nEval)
    {}

    int inputs() const { return nIn; }
    int values() const { return nOut; }

    scalarList parameters(const Eigen::VectorXd& x) const
    {
        scalarList p(nIn);
        forAll(p, i)
        {
            p[i] = fit->start()[i]*std::exp(x[i]);
        }
        return p;
    }

    int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const
    {
        ++*nEval;
        const scalarField mu(fit->simulate(parameters(x)));
        forAll(mu, i)
        {
            r[i] = mu[i] - fit->data().mu[i];
        }
        return 0;
    }
};

}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionFit::frictionFit
(
    const dictionary& lawDict,
    const wordList& parameters,
    const record& data,
    const settings& s,
    const dictionary& dict
)
:
    lawDict_(lawDict),
    names_(parameters),
    start_(parameters.size()),
    data_(data),
    set_(s)
{
    if (names_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'parameters': no parameter to fit"
            << exit(FatalIOError);
    }
    forAll(names_, i)
    {
        start_[i] = lawParameters::get(lawDict_, names_[i], dict, "parameters");
        if (!(start_[i] > 0))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'parameters': '" << names_[i] << "' starts at "
                << start_[i] << "; the fit works on the logarithm of each"
                << " parameter and needs a start value > 0"
                << exit(FatalIOError);
        }
    }
    const label n = data_.t.size();
    if (n <= names_.size())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'record': " << n << " rows for " << names_.size()
            << " parameters " << names_ << "; a fit needs more rows than"
            << " parameters" << exit(FatalIOError);
    }
    for (label i = 1; i < n; ++i)
    {
        if (!(data_.t[i] > data_.t[i - 1]))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'record': the times must increase; row " << i + 1
                << " has t = " << data_.t[i] << " after " << data_.t[i - 1]
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::dictionary Foam::frictionFit::lawDict(const scalarList& p) const
{
    return lawParameters::with(lawDict_, names_, p);
}


Foam::autoPtr<Foam::frictionLaw> Foam::frictionFit::law
(
    const scalarList& p
) const
{
    return frictionLaw::New(lawDict(p));
}


Foam::scalarField Foam::frictionFit::simulate(const scalarList& p) const
{
    autoPtr<frictionLaw> l;
    {
        quietMessages quiet;
        l = law(p);
    }
    frictionPointDriver drv(*l, set_.pressure);

    // Run-in to steady sliding at the first row's rate
    const label n = data_.t.size();
    const scalar d0 = data_.drive[0];
    if (set_.runInTime > 0)
    {
        const scalar dt0 = set_.runInTime/set_.runInSteps;
        for (label i = 0; i < set_.runInSteps; ++i)
        {
            drv.step(drv.slip() + d0*dt0, dt0);
        }
    }
    const bool spring = set_.drive == LOAD_POINT;
    if (spring)
    {
        drv.setSpringStretch(drv.last().tT.x()/set_.stiffness);
    }

    scalarField mu(n);
    mu[0] = drv.last().tN > 0 ? drv.last().tT.x()/drv.last().tN : 0;
    for (label i = 1; i < n; ++i)
    {
        const scalar h = (data_.t[i] - data_.t[i - 1])/set_.subSteps;
        for (label j = 0; j < set_.subSteps; ++j)
        {
            if (spring)
            {
                drv.springSliderMove
                (
                    set_.mass, set_.stiffness, data_.drive[i]*h, h
                );
            }
            else
            {
                drv.step(drv.slip() + data_.drive[i]*h, h);
            }
        }
        mu[i] = drv.last().tT.x()/set_.pressure;
    }
    return mu;
}


Foam::frictionFit::result Foam::frictionFit::fit(const scalar confidence) const
{
    const label nP = names_.size(), n = data_.t.size();
    label nEval = 0;
    frictionFitResiduals f(this, int(nP), int(n), &nEval);
    Eigen::NumericalDiff<frictionFitResiduals, Eigen::Central> nd(f);
    Eigen::LevenbergMarquardt
    <
        Eigen::NumericalDiff<frictionFitResiduals, Eigen::Central>
    > lm(nd);
    lm.parameters.ftol = 1e-15;
    lm.parameters.xtol = 1e-12;
    lm.parameters.maxfev = 2000;

    Eigen::VectorXd x = Eigen::VectorXd::Zero(nP);
    const int status = lm.minimize(x);

    result res;
    res.names = names_;
    res.start = start_;
    res.value = f.parameters(x);
    res.status = status;
    res.confidence = confidence;
    res.dof = n - nP;

    // Covariance at the solution: J in ln p, so dr/dp = (dr/dx)/p
    Eigen::VectorXd r(n);
    f(x, r);
    Eigen::MatrixXd J(n, nP);
    nd.df(x, J);
    for (label j = 0; j < nP; ++j)
    {
        J.col(j) /= res.value[j];
    }
    const leastSquaresIntervals ci(r, J, confidence);
    res.rms = ci.rms;
    res.stdError = ci.stdError;
    res.halfWidth = ci.halfWidth;
    res.nEvaluations = nEval;
    return res;
}


// ************************************************************************* //

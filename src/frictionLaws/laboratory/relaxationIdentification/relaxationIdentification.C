/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include <boost/math/distributions/students_t.hpp>
#include "relaxationIdentification.H"
#include "error.H"
#include "Ostream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- d y/d s at s[i] of the quadratic through three rows around i
static scalar threePointSlope
(
    const scalarList& s,
    const scalarList& y,
    const label i
)
{
    const label n = s.size();
    const label j0 = n < 3 ? 0 : min(max(i - 1, label(0)), n - 3);
    const label nPts = min(n, label(3));
    scalar d = 0;
    for (label j = j0; j < j0 + nPts; ++j)
    {
        // derivative of the Lagrange basis polynomial of node j at s[i]
        scalar den = 1, num = 0;
        for (label k = j0; k < j0 + nPts; ++k)
        {
            if (k == j) continue;
            den *= s[j] - s[k];
            scalar prod = 1;
            for (label l = j0; l < j0 + nPts; ++l)
            {
                if (l != j && l != k) prod *= s[i] - s[l];
            }
            num += prod;
        }
        d += y[j]*num/den;
    }
    return d;
}

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::relaxationIdentification::line Foam::relaxationIdentification::fitLine
(
    const scalarList& x,
    const scalarList& y
)
{
    line L;
    L.n = x.size();
    const label n = x.size();
    scalar xm = 0, ym = 0;
    forAll(x, i)
    {
        xm += x[i]/n;
        ym += y[i]/n;
    }
    scalar sxx = 0, sxy = 0;
    forAll(x, i)
    {
        sxx += sqr(x[i] - xm);
        sxy += (x[i] - xm)*(y[i] - ym);
    }
    L.c1 = sxy/sxx;
    L.c0 = ym - L.c1*xm;
    scalar ssr = 0;
    forAll(x, i)
    {
        ssr += sqr(y[i] - L.c0 - L.c1*x[i]);
    }
    const scalar s2 = n > 2 ? ssr/(n - 2) : 0;
    L.se1 = std::sqrt(s2/sxx);
    L.se0 = std::sqrt(s2*(1.0/n + xm*xm/sxx));
    L.rms = std::sqrt(ssr/n);
    return L;
}


Foam::scalar Foam::relaxationIdentification::tQuantile(const label dof) const
{
    boost::math::students_t dist(dof);
    return boost::math::quantile(dist, 0.5 + 0.5*confidence_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::relaxationIdentification::relaxationIdentification
(
    const scalarList& V,
    const scalarList& Fss,
    const scalarList& kc,
    const scalarList& omegac,
    const scalar M,
    const scalar sigma,
    const scalar VStar,
    const scalar confidence,
    const bool logLinearSlope,
    const dictionary& dict,
    const word& key,
    const fileName& file
)
:
    V_(V),
    Fss_(Fss),
    kc_(kc),
    omegac_(omegac),
    sigma_(sigma),
    VStar_(VStar),
    M_(M),
    confidence_(confidence)
{
    const label n = V.size();
    auto bad = [&](const label row, const std::string& what)
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': file " << file << ", row "
            << row + 1 << " (V = " << (row < n ? V[row] : 0) << " m/s): "
            << what.c_str() << exit(FatalIOError);
    };

    if (n < 3)
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': file " << file << " has " << n
            << " rows; the power law has 2 parameters and its confidence"
            << " interval needs at least one row more (3 rows)"
            << exit(FatalIOError);
    }
    for (label i = 0; i < n; ++i)
    {
        if (!(V[i] > 0) || (i > 0 && !(V[i] > V[i - 1])))
        {
            bad(i, "the velocities must be positive and increasing");
        }
        if (!(kc[i] > 0))
        {
            bad(i, "the critical stiffness k_c must be > 0");
        }
        if (!(omegac[i] > 0))
        {
            bad(i, "the frequency omega_c must be > 0");
        }
    }

    // Slope of the steady friction [F32]
    scalarList s(n);
    forAll(V, i)
    {
        s[i] = std::log(V[i]);
    }
    const line Fline = fitLine(s, Fss);
    dFss_.setSize(n);
    forAll(V, i)
    {
        const scalar dFds =
            logLinearSlope ? Fline.c1 : threePointSlope(s, Fss, i);
        dFss_[i] = dFds/V[i];
    }

    tau_.setSize(n);
    La_.setSize(n);
    scalarList x(n), y(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar den = kc[i] - M*sqr(omegac[i]);
        if (!(dFss_[i] < 0))
        {
            bad
            (
                i, "the steady friction does not fall with V there (F_ss'"
                " = " + std::to_string(dFss_[i]) + " Pa s/m): no"
                " velocity weakening, no stick-slip for this law"
            );
        }
        if (!(den > 0))
        {
            bad(i, "k_c - M omega_c^2 <= 0: check the mass and units");
        }
        tau_[i] = -dFss_[i]/den;
        La_[i] = V[i]*tau_[i];
        x[i] = std::log10(V[i]/VStar);
        y[i] = std::log10(tau_[i]);
    }

    // tau = t** (V/V*)^-gamma in log-log
    tauFit_ = fitLine(x, y);
    const scalar t = tQuantile(n - 2);
    tStar_.value = std::pow(10.0, tauFit_.c0);
    tStar_.interval = Pair<scalar>
    (
        std::pow(10.0, tauFit_.c0 - t*tauFit_.se0),
        std::pow(10.0, tauFit_.c0 + t*tauFit_.se0)
    );
    gamma_.value = -tauFit_.c1;
    gamma_.interval = Pair<scalar>
    (
        gamma_.value - t*tauFit_.se1, gamma_.value + t*tauFit_.se1
    );

    // Direct and evolution effects, row by row
    a_.setSize(n);
    b_.setSize(n);
    scalarList mu(n), lnV(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar Fv = -dFss_[i]/sqr(tau_[i]*omegac[i]);
        a_[i] = V[i]*Fv/sigma;
        b_[i] = (a_[i] - V[i]*dFss_[i]/sigma)/gamma_.value;
        mu[i] = Fss[i]/sigma;
        lnV[i] = std::log(V[i]/VStar);
    }
    const scalar tm = tQuantile(n - 1);
    auto meanOf = [&](const scalarList& v)
    {
        estimate e;
        scalar m = 0, s2 = 0;
        forAll(v, i) m += v[i]/n;
        forAll(v, i) s2 += sqr(v[i] - m)/(n - 1);
        e.value = m;
        const scalar h = tm*std::sqrt(s2/n);
        e.interval = Pair<scalar>(m - h, m + h);
        return e;
    };
    aMean_ = meanOf(a_);
    bMean_ = meanOf(b_);
    muFit_ = fitLine(lnV, mu);
    muStar_.value = muFit_.c0;
    muStar_.interval = Pair<scalar>
    (
        muFit_.c0 - t*muFit_.se0, muFit_.c0 + t*muFit_.se0
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::relaxationIdentification::writeLaw(Ostream& os) const
{
    auto ci = [&](const estimate& e)
    {
        return
            "  // " + std::to_string(label(std::round(100*confidence_)))
          + " % interval [" + name(e.interval.first()) + ", "
          + name(e.interval.second()) + "]";
    };
    os  << "// Relaxation law identified by frictionLawDriver (doc/theory.md"
        << " [F32], [F27])" << nl
        << "// from " << V_.size() << " rows, V = " << V_.first() << " to "
        << V_.last() << " m/s; KN, KT: automatic in frictionalContact" << nl
        << "type            rateState;" << nl
        << "stateLaw        relaxation;" << nl
        << "VStar           " << VStar_ << ";" << nl
        << "relaxationTime  " << tStar_.value << ";" << ci(tStar_).c_str()
        << nl
        << "gamma           " << gamma_.value << ";" << ci(gamma_).c_str()
        << nl
        << "a               " << aMean_.value << ";" << ci(aMean_).c_str()
        << nl
        << "b               " << bMean_.value << ";" << ci(bMean_).c_str()
        << nl
        << "muStar          " << muStar_.value << ";"
        << ci(muStar_).c_str() << nl;
}


// ************************************************************************* //

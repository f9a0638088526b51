/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "tabulated.H"
#include "interpolation2DTable.H"
#include "fileNameList.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(tabulated, 0);
    addToRunTimeSelectionTable(frictionLaw, tabulated, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::frictionLaws::tabulated::rowValue
(
    const row& r,
    const scalar v,
    scalar& slope,
    bool& out
)
{
    // [F39] linear in v, clamped (slope 0) beyond the row's ends
    const label n = r.size();
    if (n == 1 || v <= r[0].first())
    {
        out = out || (n > 1 && v < r[0].first());
        slope = 0;
        return r[0].second();
    }
    if (v >= r[n - 1].first())
    {
        out = out || v > r[n - 1].first();
        slope = 0;
        return r[n - 1].second();
    }
    label i = 0;
    while (v >= r[i + 1].first())
    {
        ++i;
    }
    const scalar dx = r[i + 1].first() - r[i].first();
    slope = (r[i + 1].second() - r[i].second())/dx;
    return r[i].second() + slope*(v - r[i].first());
}


void Foam::frictionLaws::tabulated::checkTable
(
    const table& t,
    const dictionary& dict,
    const word& key
) const
{
    const scalar upper = factor_ ? 1 : GREAT;
    if (t.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': the friction table is empty"
            << " (dictionary " << dict.name() << ")" << exit(FatalIOError);
    }
    forAll(t, i)
    {
        const row& r = t[i].second();
        if (i > 0 && !(t[i].first() > t[i - 1].first()))
        {
            FatalIOErrorInFunction(dict)
                << "keyword '" << key << "': the pressures of the friction"
                << " table must increase from row to row; row " << i
                << " has p = " << t[i].first() << " after "
                << t[i - 1].first() << " (dictionary " << dict.name()
                << ")" << exit(FatalIOError);
        }
        if (r.empty())
        {
            FatalIOErrorInFunction(dict)
                << "keyword '" << key << "': row " << i << " (p = "
                << t[i].first() << ") of the friction table has no"
                << " (v value) pairs (dictionary " << dict.name() << ")"
                << exit(FatalIOError);
        }
        forAll(r, j)
        {
            if (j > 0 && !(r[j].first() > r[j - 1].first()))
            {
                FatalIOErrorInFunction(dict)
                    << "keyword '" << key << "': the slip rates of the"
                    << " friction table must increase within each row; row "
                    << i << " (p = " << t[i].first() << ") has v = "
                    << r[j].first() << " after " << r[j - 1].first()
                    << " (dictionary " << dict.name() << ")"
                    << exit(FatalIOError);
            }
            if (!(r[j].second() >= 0) || !(r[j].second() <= upper))
            {
                FatalIOErrorInFunction(dict)
                    << "keyword '" << key << "': value " << r[j].second()
                    << " at p = " << t[i].first() << ", v = "
                    << r[j].first() << " outside [0, "
                    << (factor_ ? "1" : "inf") << ") for "
                    << (factor_ ? "m" : "mu") << " (dictionary "
                    << dict.name() << ")" << exit(FatalIOError);
            }
        }
    }
}


Foam::scalar Foam::frictionLaws::tabulated::tableValue
(
    const table& t,
    const scalar p,
    const scalar v,
    scalar& dp,
    scalar& dv,
    bool& outP,
    bool& outV
)
{
    // [F39] linear in v within the rows, then linear in p between them
    const label n = t.size();
    if (n == 1 || p <= t[0].first() || p >= t[n - 1].first())
    {
        const label i = (n == 1 || p <= t[0].first()) ? 0 : n - 1;
        outP = outP || (n > 1 && (p < t[0].first() || p > t[n - 1].first()));
        dp = 0;
        return rowValue(t[i].second(), v, dv, outV);
    }
    label i = 0;
    while (p >= t[i + 1].first())
    {
        ++i;
    }
    const scalar p0 = t[i].first();
    const scalar p1 = t[i + 1].first();
    const scalar w = (p - p0)/(p1 - p0);
    scalar s0, s1;
    const scalar x0 = rowValue(t[i].second(), v, s0, outV);
    const scalar x1 = rowValue(t[i + 1].second(), v, s1, outV);
    dp = (x1 - x0)/(p1 - p0);
    dv = (1 - w)*s0 + w*s1;
    return (1 - w)*x0 + w*x1;
}


void Foam::frictionLaws::tabulated::readTables(const dictionary& dict)
{
    if (!dict.found("temperatures"))
    {
        // one table: inline, or read by OpenFOAM's reader
        tables_.setSize(1);
        word key("table");
        if (dict.found("file"))
        {
            key = "file";
            const interpolation2DTable<scalar> t(dict);
            tables_[0] = static_cast<const table&>(t);
        }
        else
        {
            dict.readEntry("table", tables_[0]);
        }
        checkTable(tables_[0], dict, key);
        return;
    }

    // [F39] one table per temperature
    dict.readEntry("temperatures", temperatures_);
    word key("tables");
    if (dict.found("files"))
    {
        key = "files";
        const fileNameList files(dict.get<fileNameList>("files"));
        tables_.setSize(files.size());
        forAll(files, i)
        {
            const interpolation2DTable<scalar> t(files[i]);
            tables_[i] = static_cast<const table&>(t);
        }
    }
    else
    {
        dict.readEntry("tables", tables_);
    }
    if (temperatures_.empty() || tables_.size() != temperatures_.size())
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': " << tables_.size()
            << " tables for the " << temperatures_.size()
            << " temperatures of keyword 'temperatures' (one each, in the"
            << " same order; dictionary " << dict.name() << ")"
            << exit(FatalIOError);
    }
    forAll(temperatures_, i)
    {
        if (i > 0 && !(temperatures_[i] > temperatures_[i - 1]))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'temperatures': the temperatures must increase;"
                << " " << temperatures_[i] << " after "
                << temperatures_[i - 1] << " (dictionary " << dict.name()
                << ")" << exit(FatalIOError);
        }
        checkTable(tables_[i], dict, key);
    }

    // the contact's temperature, constant: the two tables and the weight
    temperature_ = dict.get<scalar>("temperature");
    const label n = temperatures_.size();
    if
    (
        n > 1
     && (temperature_ < temperatures_[0] || temperature_ > temperatures_[n - 1])
    )
    {
        WarningInFunction
            << "friction law " << dict.name() << ": temperature "
            << temperature_ << " K outside the tables' [" << temperatures_[0]
            << ", " << temperatures_[n - 1] << "] K, clamped" << endl;
    }
    Ti_ = 0;
    Tw_ = 0;
    if (n == 1 || temperature_ <= temperatures_[0])
    {
        return;
    }
    if (temperature_ >= temperatures_[n - 1])
    {
        Ti_ = n - 1;
        return;
    }
    while (temperature_ >= temperatures_[Ti_ + 1])
    {
        ++Ti_;
    }
    Tw_ =
        (temperature_ - temperatures_[Ti_])
       /(temperatures_[Ti_ + 1] - temperatures_[Ti_]);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionLaws::tabulated::tabulated(const dictionary& dict)
:
    flowStressFriction(dict),
    factor_(false),
    tables_(),
    temperatures_(),
    temperature_(-1),
    Ti_(0),
    Tw_(0),
    rateDependent_(false),
    warnedP_(false),
    warnedV_(false)
{
    const word q(dict.get<word>("quantity"));
    if (q == "m")
    {
        factor_ = true;
    }
    else if (q != "mu")
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'quantity': '" << q << "' is neither mu (tau = mu"
            << " tN) nor m (tau = m k) (dictionary " << dict.name() << ")"
            << exit(FatalIOError);
    }

    readTables(dict);
    checkKeywords
    (
        dict,
        {
            "quantity", "table", "file", "temperatures", "tables", "files",
            "temperature"
        }
    );

    for (const table& t : tables_)
    {
        for (const auto& r : t)
        {
            rateDependent_ = rateDependent_ || r.second().size() > 1;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::frictionLaws::tabulated::value
(
    const scalar p,
    const scalar v,
    const bool sliding,
    scalar& dp,
    scalar& dv
) const
{
    // [F39] each table at (p, v), then linear in the temperature
    bool outV = false;
    bool outP = false;
    scalar x = tableValue(tables_[Ti_], p, v, dp, dv, outP, outV);
    if (Tw_ > 0)
    {
        scalar dp1, dv1;
        const scalar x1 =
            tableValue(tables_[Ti_ + 1], p, v, dp1, dv1, outP, outV);
        x = (1 - Tw_)*x + Tw_*x1;
        dp = (1 - Tw_)*dp + Tw_*dp1;
        dv = (1 - Tw_)*dv + Tw_*dv1;
    }

    // one warning per law and direction; the stick check's v = 0 is the
    // static end of the table, not an extrapolation
    if (outP && !warnedP_)
    {
        warnedP_ = true;
        WarningInFunction
            << "friction table of " << dictName_ << ": contact pressure "
            << p << " Pa outside a table's range of pressures, clamped"
            << " (warned once)"
            << endl;
    }
    if (outV && sliding && !warnedV_)
    {
        warnedV_ = true;
        WarningInFunction
            << "friction table of " << dictName_ << ": slip rate " << v
            << " m/s outside a row's range of rates, clamped (warned once)"
            << endl;
    }
    return x;
}


Foam::scalar Foam::frictionLaws::tabulated::shearStrength
(
    const scalar tN,
    const scalar k,
    const scalar v,
    const bool sliding,
    scalar& dtN,
    scalar& dv
) const
{
    scalar dxdp, dxdv;
    const scalar x = value(tN, v, sliding, dxdp, dxdv);
    if (factor_)
    {
        dtN = k*dxdp;
        dv = k*dxdv;
        return x*k;
    }
    dtN = x + tN*dxdp;
    dv = tN*dxdv;
    return x*tN;
}

// ************************************************************************* //

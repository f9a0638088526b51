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
    const dictionary& dict,
    const word& key
) const
{
    const scalar upper = factor_ ? 1 : GREAT;
    if (table_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': the friction table is empty"
            << " (dictionary " << dict.name() << ")" << exit(FatalIOError);
    }
    forAll(table_, i)
    {
        const row& r = table_[i].second();
        if (i > 0 && !(table_[i].first() > table_[i - 1].first()))
        {
            FatalIOErrorInFunction(dict)
                << "keyword '" << key << "': the pressures of the friction"
                << " table must increase from row to row; row " << i
                << " has p = " << table_[i].first() << " after "
                << table_[i - 1].first() << " (dictionary " << dict.name()
                << ")" << exit(FatalIOError);
        }
        if (r.empty())
        {
            FatalIOErrorInFunction(dict)
                << "keyword '" << key << "': row " << i << " (p = "
                << table_[i].first() << ") of the friction table has no"
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
                    << i << " (p = " << table_[i].first() << ") has v = "
                    << r[j].first() << " after " << r[j - 1].first()
                    << " (dictionary " << dict.name() << ")"
                    << exit(FatalIOError);
            }
            if (!(r[j].second() >= 0) || !(r[j].second() <= upper))
            {
                FatalIOErrorInFunction(dict)
                    << "keyword '" << key << "': value " << r[j].second()
                    << " at p = " << table_[i].first() << ", v = "
                    << r[j].first() << " outside [0, "
                    << (factor_ ? "1" : "inf") << ") for "
                    << (factor_ ? "m" : "mu") << " (dictionary "
                    << dict.name() << ")" << exit(FatalIOError);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionLaws::tabulated::tabulated(const dictionary& dict)
:
    flowStressFriction(dict),
    factor_(false),
    table_(),
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

    word key("table");
    if (dict.found("file"))
    {
        // OpenFOAM's reader of two-dimensional tables
        key = "file";
        const interpolation2DTable<scalar> t(dict);
        table_ = static_cast<const table&>(t);
    }
    else
    {
        dict.readEntry("table", table_);
    }
    checkTable(dict, key);

    for (const auto& r : table_)
    {
        rateDependent_ = rateDependent_ || r.second().size() > 1;
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
    // [F39] linear in v within the rows, then linear in p between them
    const label n = table_.size();
    bool outV = false;
    bool outP = false;
    scalar x;
    if (n == 1 || p <= table_[0].first() || p >= table_[n - 1].first())
    {
        const label i = (n == 1 || p <= table_[0].first()) ? 0 : n - 1;
        outP = n > 1 && (p < table_[0].first() || p > table_[n - 1].first());
        x = rowValue(table_[i].second(), v, dv, outV);
        dp = 0;
    }
    else
    {
        label i = 0;
        while (p >= table_[i + 1].first())
        {
            ++i;
        }
        const scalar p0 = table_[i].first();
        const scalar p1 = table_[i + 1].first();
        const scalar w = (p - p0)/(p1 - p0);
        scalar s0, s1;
        const scalar x0 = rowValue(table_[i].second(), v, s0, outV);
        const scalar x1 = rowValue(table_[i + 1].second(), v, s1, outV);
        x = (1 - w)*x0 + w*x1;
        dp = (x1 - x0)/(p1 - p0);
        dv = (1 - w)*s0 + w*s1;
    }

    // one warning per law and direction; the stick check's v = 0 is the
    // static end of the table, not an extrapolation
    if (outP && !warnedP_)
    {
        warnedP_ = true;
        WarningInFunction
            << "friction table of " << dictName_ << ": contact pressure "
            << p << " Pa outside the table's [" << table_[0].first() << ", "
            << table_[n - 1].first() << "] Pa, clamped (warned once)"
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

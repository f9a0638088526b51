/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "hardeningCurve.H"
#include "checkedFunction1.H"
#include "Constant.H"
#include "TableBase.H"
#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::hardeningCurve::readTable
(
    const word& keyword,
    const dictionary& dict
)
{
    const auto& table =
        dynamic_cast<const Function1Types::TableBase<scalar>&>(function_());

    x_ = table.x()();
    y_ = table.y()();
    slope_.setSize(max(x_.size() - 1, 0));
    forAll(slope_, i)
    {
        slope_[i] = (y_[i + 1] - y_[i])/(x_[i + 1] - x_[i]);
    }

    // The Function1 must be what the slopes assume: linear between the
    // points (at two inner points of each segment) and clamped beyond the
    // last point (and before the first one, if epsP = 0 lies there)
    scalarList probes;
    forAll(slope_, i)
    {
        const scalar dx = x_[i + 1] - x_[i];
        probes.append(x_[i] + 0.25*dx);
        probes.append(x_[i] + 0.6*dx);
    }
    probes.append(x_.last() + 0.5*(x_.last() - x_.first()) + 1);
    if (x_.first() > 0)
    {
        probes.append(scalar(0));
    }

    scalar scale = VSMALL;
    for (const scalar y : y_)
    {
        scale = max(scale, mag(y));
    }

    // Out-of-bounds 'error' tables stop inside the Function1: report the
    // keyword instead
    const bool throwing = FatalError.throwExceptions();
    for (const scalar x : probes)
    {
        scalar expected = 0;
        bool ok = true;
        try
        {
            expected = function_->value(x);
        }
        catch (const Foam::error&)
        {
            ok = false;
        }
        scalar H;
        if (!ok || mag(expected - tableValue(x, H)) > 1e-12*scale)
        {
            FatalError.throwExceptions(throwing);
            FatalIOErrorInFunction(dict)
                << "Keyword '" << keyword << "' in dictionary " << dict.name()
                << ": the hardening table must be interpolated linearly and"
                << " clamped beyond its ends (interpolationScheme linear;"
                << " outOfBounds clamp), so that its slope is exact; at"
                << " epsilonP = " << x << " it gives "
                << (ok ? Foam::name(expected) : word("an error"))
                << " instead of " << tableValue(x, H) << nl
                << exit(FatalIOError);
        }
    }
    FatalError.throwExceptions(throwing);
}


Foam::scalar Foam::hardeningCurve::tableValue
(
    const scalar epsP,
    scalar& H
) const
{
    // Segment i with x_i <= epsP < x_(i+1)
    const label i =
        label(std::upper_bound(x_.begin(), x_.end(), epsP) - x_.begin()) - 1;

    if (i < 0)
    {
        H = 0;
        return y_.first();
    }
    if (i >= slope_.size())
    {
        H = 0;
        return y_.last();
    }
    H = slope_[i];
    return y_[i] + H*(epsP - x_[i]);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hardeningCurve::hardeningCurve
(
    const word& keyword,
    const dictionary& dict
)
:
    function_(checkedFunction1<scalar>(keyword, dict)),
    kind_(kind::constant),
    constant_(0),
    swift_(dynamic_cast<const Function1Types::swift*>(function_.get()))
{
    if (swift_)
    {
        kind_ = kind::swift;
    }
    else if (isA<Function1Types::Constant<scalar>>(function_()))
    {
        kind_ = kind::constant;
        constant_ = function_->value(0);
    }
    else if (isA<Function1Types::TableBase<scalar>>(function_()))
    {
        kind_ = kind::table;
        readTable(keyword, dict);
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << keyword << "' in dictionary " << dict.name()
            << ": Function1 type '" << function_->type() << "' has no exact"
            << " slope, which the return mapping and its consistent tangent"
            << " need; expected one of constant, swift, table, tableFile,"
            << " csv" << nl << exit(FatalIOError);
    }
}


// ************************************************************************* //

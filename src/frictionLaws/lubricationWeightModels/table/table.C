/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "table.H"
#include "checkedFunction1.H"
#include "addToRunTimeSelectionTable.H"
#include "strictDictionary.H"

namespace Foam
{
namespace lubricationWeightModels
{
    defineTypeNameAndDebug(table, 0);
    addToRunTimeSelectionTable(lubricationWeightModel, table, dictionary);
}
}


Foam::lubricationWeightModels::table::table(const dictionary& dict)
:
    alpha_(checkedFunction1<scalar>("alpha", dict))
{
    for (label i = 0; i <= 150; ++i)
    {
        const scalar v = std::pow(10.0, -12 + 0.1*i);
        const scalar a = alpha_->value(v);
        if (!(a >= 0 && a <= 1))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'alpha' must be in [0, 1], got " << a
                << " at slip rate " << v << " m/s (dictionary "
                << dict.name() << ")" << exit(FatalIOError);
        }
    }
    strictDictionary::check
    (
        dict, {"type", "alpha", "alphaCoeffs"}, "lubrication weight table"
    );
}


void Foam::lubricationWeightModels::table::alpha
(
    const scalar v,
    scalar& a,
    scalar& dadv
) const
{
    a = alpha_->value(v);
    const scalar h = 1e-6*max(v, scalar(1e-12));
    const scalar vm = max(v - h, scalar(0));
    dadv = (alpha_->value(v + h) - alpha_->value(vm))/(v + h - vm);
}

// ************************************************************************* //

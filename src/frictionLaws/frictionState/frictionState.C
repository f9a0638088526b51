/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionState.H"

// * * * * * * * * * * * * * * * * Operators * * * * * * * * * * * * * * * * //

bool Foam::operator==(const frictionState& a, const frictionState& b)
{
    bool same =
        a.totalSlip == b.totalSlip
     && a.plasticSlip == b.plasticSlip
     && a.cumulatedSlip == b.cumulatedSlip
     && a.slipRate == b.slipRate
     && a.status == b.status;
    for (label i = 0; i < frictionState::nScalars; ++i)
    {
        same = same && a.scalars[i] == b.scalars[i];
    }
    for (label i = 0; i < frictionState::nVectors; ++i)
    {
        same = same && a.vectors[i] == b.vectors[i];
    }
    return same;
}


bool Foam::operator!=(const frictionState& a, const frictionState& b)
{
    return !(a == b);
}

// ************************************************************************* //

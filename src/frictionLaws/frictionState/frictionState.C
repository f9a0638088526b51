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
#include "IOstreams.H"
#include "token.H"

// * * * * * * * * * * * * * * * * Operators * * * * * * * * * * * * * * * * //

bool Foam::operator==(const frictionState& a, const frictionState& b)
{
    return
        a.totalSlip == b.totalSlip
     && a.plasticSlip == b.plasticSlip
     && a.tearSlip == b.tearSlip
     && a.normalSlip == b.normalSlip
     && a.cumulatedSlip == b.cumulatedSlip
     && a.contactAge == b.contactAge
     && a.lubricationWeight == b.lubricationWeight
     && a.slipRate == b.slipRate
     && a.status == b.status;
}


bool Foam::operator!=(const frictionState& a, const frictionState& b)
{
    return !(a == b);
}


Foam::Ostream& Foam::operator<<(Ostream& os, const frictionState& s)
{
    os  << token::BEGIN_LIST
        << s.totalSlip << token::SPACE
        << s.plasticSlip << token::SPACE
        << s.tearSlip << token::SPACE
        << s.normalSlip << token::SPACE
        << s.cumulatedSlip << token::SPACE
        << s.contactAge << token::SPACE
        << s.lubricationWeight << token::SPACE
        << s.slipRate << token::SPACE
        << s.status
        << token::END_LIST;

    os.check(FUNCTION_NAME);
    return os;
}


Foam::Istream& Foam::operator>>(Istream& is, frictionState& s)
{
    is.readBegin("frictionState");
    is  >> s.totalSlip >> s.plasticSlip >> s.tearSlip >> s.normalSlip
        >> s.cumulatedSlip
        >> s.contactAge >> s.lubricationWeight >> s.slipRate >> s.status;
    is.readEnd("frictionState");

    is.check(FUNCTION_NAME);
    return is;
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionParameters.H"
#include "error.H"
#include "scalarList.H"

const Foam::Pair<Foam::scalar> Foam::frictionParameters::representable
(
    1e-30, 1e30
);


void Foam::frictionParameters::check
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const scalar lo, const bound loKind,
    const scalar hi, const bound hiKind
)
{
    const bool badLo =
        (loKind == closed && !(value >= lo))
     || (loKind == open && !(value > lo));
    const bool badHi =
        (hiKind == closed && !(value <= hi))
     || (hiKind == open && !(value < hi));

    if (badLo || badHi)
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "' must be";
        if (loKind != none)
        {
            FatalIOError<< (loKind == closed ? " >= " : " > ") << lo;
        }
        if (loKind != none && hiKind != none)
        {
            FatalIOError<< " and";
        }
        if (hiKind != none)
        {
            FatalIOError<< (hiKind == closed ? " <= " : " < ") << hi;
        }
        FatalIOError
            << ", got " << value << " (dictionary " << dict.name() << ")"
            << exit(FatalIOError);
    }

    // [F2b] a magnitude the law's arithmetic keeps finite
    const scalar m = mag(value);
    if (m != 0 && !(m >= representable.first() && m <= representable.second()))
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "' is " << value << ", outside the"
            << " magnitudes the law's arithmetic keeps finite: expected 0 or "
            << representable.first() << " <= |" << key << "| <= "
            << representable.second() << " (dictionary " << dict.name()
            << ")" << exit(FatalIOError);
    }
}


Foam::scalar Foam::frictionParameters::positive
(
    const dictionary& dict,
    const word& key
)
{
    const scalar v = dict.get<scalar>(key);
    check(dict, key, v, 0, open);
    return v;
}


Foam::scalar Foam::frictionParameters::nonNegative
(
    const dictionary& dict,
    const word& key
)
{
    const scalar v = dict.get<scalar>(key);
    check(dict, key, v, 0, closed);
    return v;
}


Foam::scalar Foam::frictionParameters::nonNegative
(
    const dictionary& dict,
    const word& key,
    scalar deflt
)
{
    const scalar v = dict.getOrDefault<scalar>(key, deflt);
    check(dict, key, v, 0, closed);
    return v;
}


Foam::scalar Foam::frictionParameters::positive
(
    const dictionary& dict,
    const word& key,
    scalar deflt
)
{
    const scalar v = dict.getOrDefault<scalar>(key, deflt);
    check(dict, key, v, 0, open);
    return v;
}


Foam::scalar Foam::frictionParameters::unitInterval
(
    const dictionary& dict,
    const word& key
)
{
    const scalar v = dict.get<scalar>(key);
    check(dict, key, v, 0, closed, 1, closed);
    return v;
}

Foam::Pair<Foam::scalar> Foam::frictionParameters::range
(
    const dictionary& dict,
    const word& key,
    const Pair<scalar>& deflt
)
{
    const scalarList r
    (
        dict.getOrDefault<scalarList>
        (
            key, scalarList({deflt.first(), deflt.second()})
        )
    );
    if (r.size() == 2)
    {
        check(dict, key, r[0], 0, none);
        check(dict, key, r[1], 0, none);
    }
    if (r.size() != 2 || !(r[0] > 0) || !(r[1] > r[0]))
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "' must be (lo hi) with 0 < lo < hi,"
            << " got " << r << " (dictionary " << dict.name() << ")"
            << exit(FatalIOError);
    }
    return Pair<scalar>(r[0], r[1]);
}

// ************************************************************************* //

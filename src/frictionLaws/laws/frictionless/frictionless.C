/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionless.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(frictionless, 0);
    addToRunTimeSelectionTable(frictionLaw, frictionless, dictionary);
}
}

// KT is not needed: give it a default so the dictionary may omit it
static Foam::dictionary withDefaultKT(const Foam::dictionary& dict)
{
    Foam::dictionary d(dict);
    if (!d.found("KT"))
    {
        d.add("KT", d.getOrDefault<Foam::scalar>("KN", 1));
    }
    return d;
}


Foam::frictionLaws::frictionless::frictionless(const dictionary& dict)
:
    frictionLaw(withDefaultKT(dict))
{
    checkKeywords(dict, wordList());
}


void Foam::frictionLaws::frictionless::update
(
    const frictionState& old,
    const frictionInput& in,
    frictionResult& out
) const
{
    openContact(old, in, out);
    if (normalContact(in, out))
    {
        out.state.status = frictionState::SLIP;
    }
}

// ************************************************************************* //

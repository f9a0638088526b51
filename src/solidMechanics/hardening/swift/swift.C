/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "swift.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace Function1Types
{
    makeScalarFunction1(swift);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::Function1Types::swift::swift
(
    const word& entryName,
    const dictionary& dict
)
:
    Function1<scalar>(entryName),
    K_(dict.get<scalar>("K")),
    eps0_(dict.get<scalar>("eps0")),
    n_(dict.get<scalar>("n"))
{
    if (K_ <= 0 || eps0_ < 0 || n_ < 0 || (eps0_ == 0 && n_ == 0))
    {
        FatalIOErrorInFunction(dict)
            << "Swift hardening '" << entryName << "' in dictionary "
            << dict.name() << ": expected K > 0, eps0 >= 0, n >= 0; got K "
            << K_ << ", eps0 " << eps0_ << ", n " << n_ << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::Function1Types::swift::writeData(Ostream& os) const
{
    os.beginBlock(name_);
    os.writeEntry("type", type());
    os.writeEntry("K", K_);
    os.writeEntry("eps0", eps0_);
    os.writeEntry("n", n_);
    os.endBlock();
}


// ************************************************************************* //

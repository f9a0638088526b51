/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "volumetricAveraging.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::volumetricAveraging::volumetricAveraging
(
    const dictionary& mechanicalProperties,
    const label nD,
    const tensor& E
)
:
    on_
    (
        mechanicalProperties.lookupOrDefault<bool>("volumetricAveraging", true)
    ),
    weight_
    (
        mechanicalProperties.lookupOrDefault<scalar>
        (
            "volumetricAveragingWeight", 1
        )
    ),
    nD_(nD),
    E_(E)
{
    if (!(weight_ >= 0 && weight_ <= 1))
    {
        FatalIOErrorInFunction(mechanicalProperties)
            << "Keyword 'volumetricAveragingWeight' in "
            << mechanicalProperties.name() << " is " << weight_
            << "; expected a value in [0, 1]" << nl << exit(FatalIOError);
    }
}


// ************************************************************************* //

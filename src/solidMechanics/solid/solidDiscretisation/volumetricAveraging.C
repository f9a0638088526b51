/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
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

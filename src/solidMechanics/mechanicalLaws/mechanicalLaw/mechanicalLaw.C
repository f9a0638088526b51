/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "mechanicalLaw.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(mechanicalLaw, 0);
    defineRunTimeSelectionTable(mechanicalLaw, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::mechanicalLaw::readBounded
(
    const dictionary& dict,
    const word& key,
    const scalar lower,
    const scalar upper,
    const bool open
)
{
    const scalar value = dict.get<scalar>(key);

    const bool ok =
        open
      ? (value > lower && value < upper)
      : (value >= lower && value <= upper);

    if (!ok)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' in dictionary " << dict.name()
            << " is " << value << "; expected a value in "
            << (open ? "(" : "[") << lower << ", " << upper
            << (open ? ")" : "]") << nl
            << exit(FatalIOError);
    }

    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaw::mechanicalLaw(const dictionary& dict)
:
    dict_(dict),
    rho_(readBounded(dict, "rho", 0, GREAT, false)),
    E_(readBounded(dict, "E", 0, GREAT)),
    nu_(readBounded(dict, "nu", -1, 0.5))
{}


// ************************************************************************* //

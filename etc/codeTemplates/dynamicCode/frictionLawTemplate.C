/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionLawTemplate.H"
#include "addToRunTimeSelectionTable.H"

//{{{ begin codeInclude
${codeInclude}
//}}} end codeInclude

namespace Foam
{

//{{{ begin localCode
${localCode}
//}}} end localCode

// dynamicCode: SHA1 = ${SHA1sum}; the loader the 'coded' law checks
extern "C" void ${typeName}_${SHA1sum}(bool load)
{}

namespace frictionLaws
{
    defineTypeNameAndDebug(${typeName}FrictionLaw, 0);
    addRemovableToRunTimeSelectionTable
    (
        frictionLaw,
        ${typeName}FrictionLaw,
        dictionary
    );
}

} // End namespace Foam


Foam::frictionLaws::${typeName}FrictionLaw::${typeName}FrictionLaw
(
    const dictionary& dict
)
:
    flowStressFriction(dict),
    needsShearYield_(dict.getOrDefault<bool>("needsShearYield", true)),
    rateDependent_(dict.getOrDefault<bool>("rateDependent", false))
{}


Foam::scalar Foam::frictionLaws::${typeName}FrictionLaw::shearStrength
(
    const scalar tN,
    const scalar k,
    const scalar v,
    const bool sliding,
    scalar& dtN,
    scalar& dv
) const
{
    // [F40] the user's code sets tau and its slopes dtauDtN, dtauDv
    scalar tau = 0;
    scalar& dtauDtN = dtN;
    scalar& dtauDv = dv;
    dtauDtN = 0;
    dtauDv = 0;

//{{{ begin code
    ${code}
//}}} end code

    return tau;
}

// ************************************************************************* //

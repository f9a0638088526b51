/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "neoHookean.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(neoHookean, 0);
    addToRunTimeSelectionTable(mechanicalLaw, neoHookean, dictionary);
}
}


Foam::mechanicalLaws::neoHookean::neoHookean(const dictionary& dict)
:
    mechanicalLaw(dict)
{}


Foam::tensor Foam::mechanicalLaws::neoHookean::stress
(
    const tensor& F,
    const materialState& old,
    materialState& updated
) const
{
    updated = old;

    if (!admissible(F))
    {
        return rejectedStress();
    }
    const scalar J = det(F);

    // [S4]
    const tensor FinvT(inv(F).T());
    return mu()*(F - FinvT) + lambda()*Foam::log(J)*FinvT;
}


// ************************************************************************* //

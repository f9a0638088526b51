/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "blockJacobiLU.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace linearSolvers
{
    defineTypeNameAndDebug(blockJacobiLU, 0);
    addToRunTimeSelectionTable(linearSolver, blockJacobiLU, dictionary);
}
}

// ************************************************************************* //

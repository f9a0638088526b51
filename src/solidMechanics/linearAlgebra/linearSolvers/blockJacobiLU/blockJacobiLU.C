/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
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

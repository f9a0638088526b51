/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "linearSolver.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(linearSolver, 0);
    defineRunTimeSelectionTable(linearSolver, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearSolver::linearSolver
(
    const dictionary& dict,
    const blockSparseMatrix& matrix
)
:
    dict_(dict),
    matrix_(matrix)
{}




Foam::wordList Foam::linearSolver::defaultChoiceKeywords
(
    const dictionary& dict,
    std::initializer_list<word> own
)
{
    wordList known(own);
    if (!dict.found("type"))
    {
        known.append("options");
    }
    return known;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "compressedColumns.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::compressedColumns::compressedColumns(const blockSparseMatrix& matrix)
{
    // Entries counted per column, then placed row by row (so each column's
    // rows come out sorted)
    const label nc = matrix.nComponents();
    const label n = matrix.nLocalUnknowns();
    const label lo = matrix.cellNumbering().offset(Pstream::myProcNo());
    const labelList& rowStart = matrix.rowStart();
    const labelList& colCells = matrix.colCells();

    colStart_.assign(n + 1, 0);
    for (label r = 0; r < matrix.nRows(); ++r)
    {
        for (label s = rowStart[r]; s < rowStart[r + 1]; ++s)
        {
            const label c = colCells[s] - lo;
            for (label b = 0; b < nc; ++b)
            {
                colStart_[c*nc + b + 1] += nc;
            }
        }
    }
    for (label j = 0; j < n; ++j)
    {
        colStart_[j + 1] += colStart_[j];
    }
    const label nnz = colStart_[n];
    rowIndex_.assign(nnz, 0);
    values_.assign(nnz, 0);
    toColumns_.assign(matrix.values().size(), 0);
    std::vector<int> next(colStart_.begin(), colStart_.end() - 1);
    for (label r = 0; r < matrix.nRows(); ++r)
    {
        for (label a = 0; a < nc; ++a)
        {
            for (label s = rowStart[r]; s < rowStart[r + 1]; ++s)
            {
                const label c = colCells[s] - lo;
                for (label b = 0; b < nc; ++b)
                {
                    const int k = next[c*nc + b]++;
                    rowIndex_[k] = r*nc + a;
                    toColumns_[(s*nc + a)*nc + b] = k;
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::compressedColumns::gather(const blockSparseMatrix& matrix)
{
    const scalarList& v = matrix.values();
    forAll(v, i)
    {
        values_[toColumns_[i]] = v[i];
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "blockSparseMatrix.H"
#include "error.H"
#include "HashSet.H"
#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blockSparseMatrix::blockSparseMatrix
(
    const labelListList& columns,
    const labelList& comps,
    const globalIndex& cellNumbering
)
:
    comps_(comps),
    nc_(comps.size()),
    cellNumbering_(cellNumbering),
    rowStart_(columns.size() + 1, 0),
    colCells_(),
    values_()
{
    setPattern(columns);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::blockSparseMatrix::setPattern(const labelListList& columns)
{
    rowStart_.setSize(columns.size() + 1);
    rowStart_ = 0;
    std::vector<label> cols;
    DynamicList<label> all(columns.size()*16);
    forAll(columns, r)
    {
        cols.assign(columns[r].begin(), columns[r].end());
        cols.push_back(globalRow(r));
        std::sort(cols.begin(), cols.end());
        cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
        for (const label c : cols)
        {
            all.append(c);
        }
        rowStart_[r + 1] = all.size();
    }
    colCells_.transfer(all);
    values_.setSize(colCells_.size()*nc_*nc_);
    values_ = 0;
}


void Foam::blockSparseMatrix::zero()
{
    values_ = 0;
}


Foam::label Foam::blockSparseMatrix::find(const label r, const label c) const
{
    const label* first = colCells_.cdata() + rowStart_[r];
    const label* last = colCells_.cdata() + rowStart_[r + 1];
    const label* it = std::lower_bound(first, last, c);
    return (it != last && *it == c) ? label(it - colCells_.cdata()) : -1;
}


void Foam::blockSparseMatrix::addToSlot(const label s, const tensor& K)
{
    scalar* v = values_.data() + s*nc_*nc_;
    for (label a = 0; a < nc_; ++a)
    {
        for (label b = 0; b < nc_; ++b)
        {
            v[a*nc_ + b] += K[3*comps_[a] + comps_[b]];
        }
    }
}


void Foam::blockSparseMatrix::addBlock
(
    const label r,
    const label c,
    const tensor& K
)
{
    const label s = find(r, c);
    if (s < 0)
    {
        FatalErrorInFunction
            << "Block (row cell " << globalRow(r) << ", column cell " << c
            << ") is not in the sparsity pattern" << abort(FatalError);
    }
    addToSlot(s, K);
}


bool Foam::blockSparseMatrix::local() const
{
    const label lo = cellNumbering_.offset(Pstream::myProcNo());
    const label hi = lo + nRows();
    for (const label c : colCells_)
    {
        if (c < lo || c >= hi)
        {
            return false;
        }
    }
    return true;
}


Eigen::SparseMatrix<double> Foam::blockSparseMatrix::localBlock() const
{
    const label lo = cellNumbering_.offset(Pstream::myProcNo());
    const label hi = lo + nRows();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(values_.size());
    for (label r = 0; r < nRows(); ++r)
    {
        for (label s = rowStart_[r]; s < rowStart_[r + 1]; ++s)
        {
            if (colCells_[s] < lo || colCells_[s] >= hi)
            {
                continue;
            }
            const label c = colCells_[s] - lo;
            for (label a = 0; a < nc_; ++a)
            {
                for (label b = 0; b < nc_; ++b)
                {
                    entries.emplace_back
                    (
                        r*nc_ + a, c*nc_ + b, operator()(s, a, b)
                    );
                }
            }
        }
    }
    Eigen::SparseMatrix<double> A(nLocalUnknowns(), nLocalUnknowns());
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    return A;
}


Eigen::SparseMatrix<double> Foam::blockSparseMatrix::eigenMatrix() const
{
    if (!local())
    {
        FatalErrorInFunction
            << "The matrix couples to other processors' cells: it has no"
            << " serial Eigen form (use localBlock() for block Jacobi)"
            << abort(FatalError);
    }
    return localBlock();
}


void Foam::blockSparseMatrix::multiply
(
    const Eigen::VectorXd& x,
    Eigen::VectorXd& y
) const
{
    const label lo = cellNumbering_.offset(Pstream::myProcNo());
    y.setZero(nLocalUnknowns());
    for (label r = 0; r < nRows(); ++r)
    {
        for (label s = rowStart_[r]; s < rowStart_[r + 1]; ++s)
        {
            const label c = colCells_[s] - lo;
            for (label a = 0; a < nc_; ++a)
            {
                scalar sum = 0;
                for (label b = 0; b < nc_; ++b)
                {
                    sum += operator()(s, a, b)*x(c*nc_ + b);
                }
                y(r*nc_ + a) += sum;
            }
        }
    }
}


// ************************************************************************* //

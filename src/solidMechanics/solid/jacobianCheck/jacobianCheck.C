/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "jacobianCheck.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::jacobianCheck::jacobianCheck()
:
    largest_(0),
    nChecks_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::jacobianCheck::compare
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const blockSparseMatrix& M,
    const List<Eigen::VectorXd>& U,
    const List<Eigen::VectorXd>& V,
    const scalar h
)
{
    const label nc = M.nComponents();
    const label nRows = M.nRows();
    const globalIndex& numbering = M.cellNumbering();

    // The low-rank columns of every processor (small meshes only)
    List<List<scalarField>> Vall(V.size());
    forAll(V, t)
    {
        Vall[t].setSize(Pstream::nProcs());
        Vall[t][Pstream::myProcNo()] =
            scalarField(UList<scalar>(const_cast<scalar*>(V[t].data()), V[t].size()));
        Pstream::gatherList(Vall[t]);
        Pstream::scatterList(Vall[t]);
    }
    auto lowRank = [&](const label row, const label proci, const label col)
    {
        scalar s = 0;
        forAll(U, t)
        {
            s += U[t](row)*Vall[t][proci][col];
        }
        return s;
    };

    // Row scales: the largest assembled entry of each row
    scalarList rowScale(nRows*nc, scalar(0));
    for (label r = 0; r < nRows; ++r)
    {
        for (label s = M.rowStart()[r]; s < M.rowStart()[r + 1]; ++s)
        {
            for (label a = 0; a < nc; ++a)
            {
                for (label b = 0; b < nc; ++b)
                {
                    rowScale[r*nc + a] =
                        max(rowScale[r*nc + a], mag(M(s, a, b)));
                }
            }
        }
    }

    scalar worst = 0;
    label worstRow = -1;
    label worstCol = -1;
    scalar worstM = 0;
    scalar worstFd = 0;

    Eigen::VectorXd xp(x), Rp, Rm;

    // Every global unknown in turn: the owning processor perturbs, all
    // evaluate (the residual communicates)
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        const bool mine = proci == Pstream::myProcNo();
        for (label c = 0; c < numbering.localSize(proci); ++c)
        {
            const label globalCell = numbering.toGlobal(proci, c);
            for (label b = 0; b < nc; ++b)
            {
                if (mine)
                {
                    xp(c*nc + b) = x(c*nc + b) + h;
                }
                sys.residual(xp, Rp);
                if (mine)
                {
                    xp(c*nc + b) = x(c*nc + b) - h;
                }
                sys.residual(xp, Rm);
                if (mine)
                {
                    xp(c*nc + b) = x(c*nc + b);
                }

                // column (globalCell, b) of M = -dR/dx
                for (label r = 0; r < nRows; ++r)
                {
                    const label s = M.find(r, globalCell);
                    for (label a = 0; a < nc; ++a)
                    {
                        const scalar fd =
                            -(Rp(r*nc + a) - Rm(r*nc + a))/(2*h);
                        const scalar m =
                            (s >= 0 ? M(s, a, b) : 0)
                          + lowRank(r*nc + a, proci, c*nc + b);
                        const scalar scale =
                            max(rowScale[r*nc + a], VSMALL);
                        const scalar diff = mag(m - fd)/scale;
                        if (diff > worst)
                        {
                            worst = diff;
                            worstRow = numbering.toGlobal(r)*nc + a;
                            worstCol = globalCell*nc + b;
                            worstM = m;
                            worstFd = fd;
                        }
                    }
                }
            }
        }
    }

    // The largest over all processors, with where it is
    const scalar globalWorst = returnReduce(worst, maxOp<scalar>());
    const label where = returnReduce
    (
        worst == globalWorst ? Pstream::myProcNo() : -1, maxOp<label>()
    );
    scalarField info(4, Zero);
    if (Pstream::myProcNo() == where)
    {
        info[0] = worstRow;
        info[1] = worstCol;
        info[2] = worstM;
        info[3] = worstFd;
    }
    reduce(info, sumOp<scalarField>());

    ++nChecks_;
    largest_ = max(largest_, globalWorst);

    Info<< "    Jacobian check: max |M - M_fd|/(row max) = " << globalWorst
        << " (unknown " << label(info[0]) << ", column " << label(info[1])
        << ": assembled " << info[2] << ", finite differences " << info[3]
        << ")" << endl;

    return globalWorst;
}


// ************************************************************************* //

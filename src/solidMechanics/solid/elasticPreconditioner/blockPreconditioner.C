/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "blockPreconditioner.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blockPreconditioner::blockPreconditioner
(
    const label nCells,
    const labelList& comps
)
:
    nCells_(nCells),
    comps_(comps),
    entries_(),
    A_(nCells*comps.size(), nCells*comps.size()),
    ldlt_(),
    analysed_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::blockPreconditioner::clear()
{
    entries_.clear();
}


void Foam::blockPreconditioner::addDiagonal(const label P, const tensor& K)
{
    addBlock(P, P, K);
}


void Foam::blockPreconditioner::addBlock
(
    const label P,
    const label Q,
    const tensor& K
)
{
    const label nc = comps_.size();
    for (label a = 0; a < nc; ++a)
    {
        for (label b = 0; b < nc; ++b)
        {
            entries_.emplace_back
            (
                P*nc + a, Q*nc + b, K.component(3*comps_[a] + comps_[b])
            );
        }
    }
}


void Foam::blockPreconditioner::addCoupling
(
    const label P,
    const label N,
    const tensor& K
)
{
    addBlock(P, P, K);
    addBlock(N, N, K);
    addBlock(P, N, -K);
    addBlock(N, P, -K);
}


bool Foam::blockPreconditioner::factorise()
{
    A_.setFromTriplets(entries_.begin(), entries_.end());
    if (!analysed_)
    {
        ldlt_.analyzePattern(A_);
        analysed_ = true;
    }
    ldlt_.factorize(A_);
    return ldlt_.info() == Eigen::Success;
}


void Foam::blockPreconditioner::solve
(
    const Eigen::VectorXd& r,
    Eigen::VectorXd& z
) const
{
    z = ldlt_.solve(r);
}


// ************************************************************************* //

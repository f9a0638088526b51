/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "finiteDifferenceJacobian.H"
#include "DynamicList.H"
#include "PstreamReduceOps.H"
#include "Pstream.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::finiteDifferenceJacobian::colour()
{
    // Which cells influence each cell (the transpose of influence_)
    const label n = influence_.size();
    List<DynamicList<label>> influencedBy(n);
    forAll(influence_, i)
    {
        for (const label j : influence_[i])
        {
            influencedBy[j].append(i);
        }
    }

    // Two cells conflict when they influence a common cell
    labelList cellColour(n, -1);
    DynamicList<label> used(64);
    List<DynamicList<label>> colours;

    forAll(influence_, i)
    {
        used.clear();
        for (const label j : influence_[i])
        {
            for (const label k : influencedBy[j])
            {
                if (cellColour[k] >= 0)
                {
                    used.append(cellColour[k]);
                }
            }
        }
        label c = 0;
        while (used.found(c))
        {
            ++c;
        }
        cellColour[i] = c;
        if (c >= colours.size())
        {
            colours.setSize(c + 1);
        }
        colours[c].append(i);
    }

    colours_.setSize(colours.size());
    forAll(colours, c)
    {
        colours_[c].transfer(colours[c]);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::finiteDifferenceJacobian::finiteDifferenceJacobian
(
    const labelListList& influence,
    const label nComp
)
:
    nComp_(nComp),
    influence_(influence),
    colours_(),
    M_(influence.size()*nComp, influence.size()*nComp),
    lu_(),
    analysed_(false),
    valid_(false)
{
    colour();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::finiteDifferenceJacobian::addColour
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& R,
    const scalar perturbation,
    const labelList& cells,
    Eigen::VectorXd& xp,
    Eigen::VectorXd& Rp,
    std::vector<Eigen::Triplet<double>>& entries
) const
{
    const label nc = nComp_;
    for (label a = 0; a < nc; ++a)
    {
        for (const label i : cells)
        {
            xp(i*nc + a) = x(i*nc + a) + perturbation;
        }

        sys.residual(xp, Rp);

        for (const label i : cells)
        {
            xp(i*nc + a) = x(i*nc + a);
            const label col = i*nc + a;
            for (const label j : influence_[i])
            {
                for (label b = 0; b < nc; ++b)
                {
                    const label row = j*nc + b;
                    entries.emplace_back
                    (
                        row, col, -(Rp(row) - R(row))/perturbation
                    );
                }
            }
        }
    }
}


bool Foam::finiteDifferenceJacobian::update
(
    nonlinearSystem& sys,
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& R,
    const scalar perturbation
)
{
    const label nc = nComp_;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(x.size()*nc*20);

    Eigen::VectorXd xp(x), Rp(R.size());

    // Processors perturb their colours in turn: a perturbation on one
    // processor changes the residual of cells next to it on another, which
    // would otherwise be taken for that processor's own column. Every
    // processor evaluates the residual the same number of times (it
    // communicates); those not in turn perturb nothing.
    labelList nColours(Pstream::nProcs(), 0);
    nColours[Pstream::myProcNo()] = colours_.size();
    Pstream::gatherList(nColours);
    Pstream::scatterList(nColours);
    const labelList noCells;

    forAll(nColours, proci)
    {
        const bool mine = (proci == Pstream::myProcNo());
        for (label c = 0; c < nColours[proci]; ++c)
        {
            const labelList& cells = mine ? colours_[c] : noCells;
            addColour(sys, x, R, perturbation, cells, xp, Rp, entries);
        }
    }

    M_.setFromTriplets(entries.begin(), entries.end());
    M_.makeCompressed();

    if (!analysed_)
    {
        lu_.analyzePattern(M_);
        analysed_ = true;
    }
    lu_.factorize(M_);
    valid_ = (lu_.info() == Eigen::Success);
    return valid_;
}


void Foam::finiteDifferenceJacobian::solve
(
    const Eigen::VectorXd& r,
    Eigen::VectorXd& z
) const
{
    z = lu_.solve(r);
}


// ************************************************************************* //

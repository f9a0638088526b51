/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "umfpackLU.H"
#include "addToRunTimeSelectionTable.H"
#include "eigenVector.H"
#include "strictDictionary.H"

namespace Foam
{
namespace linearSolvers
{
    defineTypeNameAndDebug(umfpackLU, 0);
    addToRunTimeSelectionTable(linearSolver, umfpackLU, dictionary);
}
}


const Foam::Enum<int> Foam::linearSolvers::umfpackLU::strategyNames
({
    { UMFPACK_STRATEGY_AUTO, "auto" },
    { UMFPACK_STRATEGY_SYMMETRIC, "symmetric" },
    { UMFPACK_STRATEGY_UNSYMMETRIC, "unsymmetric" },
});


const Foam::Enum<int> Foam::linearSolvers::umfpackLU::orderingNames
({
    { UMFPACK_ORDERING_AMD, "amd" },
    { UMFPACK_ORDERING_METIS, "metis" },
    { UMFPACK_ORDERING_CHOLMOD, "cholmod" },
    { UMFPACK_ORDERING_BEST, "best" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

int Foam::linearSolvers::umfpackLU::readChoice
(
    const dictionary& dict,
    const word& key,
    const Enum<int>& names,
    const word& deflt
)
{
    const word name(dict.lookupOrDefault<word>(key, deflt));
    if (!names.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' in dictionary " << dict.name()
            << " is '" << name << "'; expected one of " << names.sortedToc()
            << nl << exit(FatalIOError);
    }
    return names[name];
}


Foam::string Foam::linearSolvers::umfpackLU::statusMessage(const int status)
{
    switch (status)
    {
        case UMFPACK_WARNING_singular_matrix:
            return "singular matrix";
        case UMFPACK_ERROR_out_of_memory:
            return "out of memory";
        case UMFPACK_ERROR_invalid_matrix:
            return "invalid matrix";
        case UMFPACK_ERROR_different_pattern:
            return "the pattern changed since the analysis";
        case UMFPACK_WARNING_determinant_underflow:
            return "determinant underflow";
        case UMFPACK_WARNING_determinant_overflow:
            return "determinant overflow";
        default:
            return "UMFPACK status " + Foam::name(status);
    }
}


bool Foam::linearSolvers::umfpackLU::factorise()
{
    if (numeric_)
    {
        umfpack_di_free_numeric(&numeric_);
    }
    const int status = umfpack_di_numeric
    (
        columns_.colStart(), columns_.rowIndex(), columns_.values(),
        symbolic_, &numeric_, control_, info_
    );
    factorised_ = factorsCurrent_ = status == UMFPACK_OK;
    failure_.clear();
    if (status == UMFPACK_ERROR_out_of_memory)
    {
        FatalErrorInFunction
            << "UMFPACK ran out of memory factorising " << columns_.n()
            << " unknowns (" << columns_.nnz() << " entries); linear solver"
            << " umfpack of " << dict_.name() << exit(FatalError);
    }
    if (!factorsCurrent_)
    {
        failure_ =
            "UMFPACK: " + statusMessage(status) + " (linear solver umfpack"
            " of " + dict_.name() + ")";
    }
    if (debug)
    {
        // the fill sets the cost of every factorisation
        Info<< "        umfpack: factors L " << info_[UMFPACK_LNZ] << " U "
            << info_[UMFPACK_UNZ] << ", " << info_[UMFPACK_FLOPS]
            << " flops, peak memory "
            << info_[UMFPACK_PEAK_MEMORY]*info_[UMFPACK_SIZE_OF_UNIT]/1048576
            << " MB" << (failure_.empty() ? "" : ", ") << failure_.c_str()
            << endl;
    }
    return factorsCurrent_;
}


bool Foam::linearSolvers::umfpackLU::solveFactors
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x
)
{
    // UMFPACK refines the solution (UMFPACK_IRSTEP, 2 steps at most) while
    // its backward error exceeds round-off: the unsymmetric strategy's
    // threshold pivoting can leave 1e-12 without it
    x.resize(b.size());
    return
        umfpack_di_wsolve
        (
            UMFPACK_A, columns_.colStart(), columns_.rowIndex(),
            columns_.values(), x.data(), b.data(), numeric_, control_,
            info_, Wi_.data(), W_.data()
        ) == UMFPACK_OK;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearSolvers::umfpackLU::umfpackLU
(
    const dictionary& dict,
    const blockSparseMatrix& matrix
)
:
    linearSolver(dict, matrix),
    columns_(matrix),
    symbolic_(nullptr),
    numeric_(nullptr),
    factorised_(false),
    factorsCurrent_(false),
    reuse_(dict.lookupOrDefault<bool>("reuse", true)),
    maxReuseIterations_
    (
        dict.lookupOrDefault<label>("maxReuseIterations", 10)
    )
{
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'type' in dictionary " << dict.name() << " is "
            << "umfpack, a serial solver; a parallel run needs a"
            << " distributed one (type petsc)" << nl << exit(FatalIOError);
    }

    if (maxReuseIterations_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'maxReuseIterations' in dictionary " << dict.name()
            << " must be >= 1, got " << maxReuseIterations_ << nl
            << exit(FatalIOError);
    }

    umfpack_di_defaults(control_);
    control_[UMFPACK_STRATEGY] =
        readChoice(dict, "strategy", strategyNames, "symmetric");
    control_[UMFPACK_ORDERING] =
        readChoice(dict, "ordering", orderingNames, "metis");
    strictDictionary::check
    (
        dict,
        defaultChoiceKeywords
        (
            dict,
            {
                "type", "directCellLimit", "nestedDissectionCells",
                "krylovCells", "reuse",
                "maxReuseIterations", "strategy", "ordering"
            }
        ),
        "linear solver umfpack"
    );

    // The pattern alone (no values: they change, the analysis holds for
    // every matrix of the pattern)
    const int status = umfpack_di_symbolic
    (
        columns_.n(), columns_.n(), columns_.colStart(),
        columns_.rowIndex(), nullptr, &symbolic_, control_, info_
    );
    if (status != UMFPACK_OK)
    {
        FatalErrorInFunction
            << "UMFPACK could not analyse the pattern of " << columns_.n()
            << " unknowns, " << columns_.nnz() << " entries: "
            << statusMessage(status).c_str() << exit(FatalError);
    }
    if (debug)
    {
        Info<< "        umfpack: " << columns_.n() << " unknowns, "
            << columns_.nnz() << " entries, strategy "
            << strategyNames[int(info_[UMFPACK_STRATEGY_USED])]
            << ", ordering "
            << (
                   info_[UMFPACK_ORDERING_USED] == UMFPACK_ORDERING_AMD
                && info_[UMFPACK_STRATEGY_USED] == UMFPACK_STRATEGY_UNSYMMETRIC
                 ? word("colamd")
                 : orderingNames[int(info_[UMFPACK_ORDERING_USED])]
               )
            << endl;
    }

    Wi_.resize(columns_.n());
    W_.resize(5*columns_.n());

    gmres_.preconditioner().set(*this);
    gmres_.setMaxIterations(maxReuseIterations_);
    gmres_.set_restart(maxReuseIterations_ + 1);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::linearSolvers::umfpackLU::~umfpackLU()
{
    if (numeric_)
    {
        umfpack_di_free_numeric(&numeric_);
    }
    if (symbolic_)
    {
        umfpack_di_free_symbolic(&symbolic_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::linearSolvers::umfpackLU::description() const
{
    return
        "sparse LU (UMFPACK, strategy "
      + strategyNames[int(control_[UMFPACK_STRATEGY])] + ", ordering "
      + orderingNames[int(control_[UMFPACK_ORDERING])] + ")"
      + (
            reuse_
          ? ", factors reused by GMRES for up to "
          + Foam::name(maxReuseIterations_) + " iterations"
          : ""
        );
}


bool Foam::linearSolvers::umfpackLU::update()
{
    columns_.gather(matrix_);
    if (reuse_ && factorised_)
    {
        // solve() decides whether the earlier factors still do
        A_ = columns_.eigenMap();
        factorsCurrent_ = false;
        return true;
    }
    return factorise();
}


Foam::linearSolver::performance Foam::linearSolvers::umfpackLU::solve
(
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    const scalar relTol
)
{
    performance p;
    const scalar normB = b.norm();

    if (factorised_ && !factorsCurrent_)
    {
        // the current matrix, preconditioned by the earlier factors; as in
        // eigenLU the true residual decides (GMRES's is the left
        // preconditioned one)
        gmres_.compute(A_);
        gmres_.setTolerance(relTol);
        const Eigen::VectorXd x0(x);
        x = gmres_.solveWithGuess(b, x0);
        p.iterations = gmres_.iterations();
        if (gmres_.info() == Eigen::Success && allFinite(x))
        {
            p.relativeResidual =
                normB > 0
              ? scalar((b - columns_.eigenMap()*x).norm()/normB)
              : scalar(0);
            if (p.relativeResidual <= relTol)
            {
                p.converged = true;
                return p;
            }
        }
        factorise();
    }

    if (!factorsCurrent_)
    {
        x.setConstant(NAN);
        p.reason =
            failure_.empty()
          ? string("the matrix is not factorised (linear solver umfpack)")
          : failure_;
        return p;
    }

    const bool solved = solveFactors(b, x);
    p.relativeResidual =
        normB > 0
      ? scalar((b - columns_.eigenMap()*x).norm()/normB)
      : scalar(0);
    p.converged = solved && allFinite(x);
    if (!p.converged)
    {
        p.reason =
            solved
          ? string("the UMFPACK solve returned non-finite values")
          : string("the UMFPACK solve failed");
    }
    return p;
}


// ************************************************************************* //

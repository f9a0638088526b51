/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Keywords, the Krylov solver's set-up, the check for unused options.

\*---------------------------------------------------------------------------*/

#include "petscSolver.H"
#include "strictDictionary.H"
#include "HashSet.H"
#include <cctype>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::word Foam::linearSolvers::petscSolver::defaultPrefix
(
    const dictionary& dict
)
{
    // PETSc prefixes are letters, digits and underscores
    std::string name =
        &dict.parent() != &dictionary::null
      ? std::string(dict.parent().dictName()) : std::string("linearSolver");
    for (char& c : name)
    {
        if (!std::isalnum(static_cast<unsigned char>(c)))
        {
            c = '_';
        }
    }
    return word(name + "_");
}


void Foam::linearSolvers::petscSolver::readKeywords()
{
    static const wordHashSet keywords
    {
        "type", "ksp", "preconditioner", "maxIterations", "view", "prefix",
        "options", "directCellLimit", "nestedDissectionCells", "krylovCells",
        "nearNullSpace",
        "shiftZeroPivots",
        "reusePreconditioner", "refreshIterations"
    };
    static const wordList ksps{"gmres", "fgmres", "cg", "bcgs", "preonly"};
    static const wordList pcs
    {
        "gamg", "boomerAMG", "ml", "mumps", "ilu", "bjacobi", "jacobi",
        "none"
    };

    // The entries of 'options' are PETSc's (checked by PETSc itself)
    strictDictionary::check
    (
        dict_, keywords.sortedToc(),
        "linear solver petsc; raw PETSc options go into the sub-dictionary"
        " 'options'"
    );

    kspName_ = dict_.lookupOrDefault<word>("ksp", "gmres");
    if (!ksps.found(kspName_))
    {
        FatalIOErrorInFunction(dict_)
            << "Unknown value '" << kspName_ << "' of keyword 'ksp' in"
            << " dictionary " << dict_.name() << nl
            << "Valid values: " << ksps << " (others through options"
            << " { ksp_type ...; })" << exit(FatalIOError);
    }

    // Default: GAMG with the rigid-body near-null space, measured fastest
    // on 3-D and 2-D elastic operators (tests/benchmarks/linearSolvers)
    pcName_ = dict_.lookupOrDefault<word>("preconditioner", "gamg");
    if (!pcs.found(pcName_))
    {
        FatalIOErrorInFunction(dict_)
            << "Unknown value '" << pcName_ << "' of keyword"
            << " 'preconditioner' in dictionary " << dict_.name() << nl
            << "Valid values: " << pcs << " (others through options"
            << " { pc_type ...; })" << exit(FatalIOError);
    }

    maxIterations_ = dict_.lookupOrDefault<label>("maxIterations", 500);
    if (maxIterations_ < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword 'maxIterations' in dictionary " << dict_.name()
            << " is " << maxIterations_ << ": at least 1 expected"
            << exit(FatalIOError);
    }
    view_ = dict_.lookupOrDefault<bool>("view", false);

    // GAMG's and ML's near-null space. 3-D default: the translations.
    // From about 10 000 cells GAMG's aggregation leaves some cells alone,
    // whose 3 unknowns cannot carry the 6 rigid-body modes: the coarse
    // operator's cell block there is singular, and SOR, which PETSc runs
    // block-wise over the cells (inodes), meets its zero pivots. With
    // those cells the modes took far more Krylov iterations than the
    // translations on the same contact Jacobians (upsetting3D at 13 824
    // cells: 55-500 against 41-71), without them about as many (1 728
    // cells), with twice the set-up (doc/performance.md sections 15 and
    // 18.2). 2-D and BoomerAMG (whose vector interpolation, an option,
    // uses them): the modes
    const word nullSpace = dict_.lookupOrDefault<word>
    (
        "nearNullSpace",
        pcName_ != "boomerAMG" && matrix_.nComponents() == 3
      ? "translations" : "rigidBodyModes"
    );
    if (nullSpace != "rigidBodyModes" && nullSpace != "translations")
    {
        FatalIOErrorInFunction(dict_)
            << "Unknown value '" << nullSpace << "' of keyword"
            << " 'nearNullSpace' in dictionary " << dict_.name() << nl
            << "Valid values: (rigidBodyModes translations)"
            << exit(FatalIOError);
    }
    rigidBodyModes_ = nullSpace == "rigidBodyModes";

    // With the rigid-body modes, SOR on GAMG's levels (3-D) shifts its
    // zero pivots from the first set-up: the rows of one-cell aggregates'
    // rotations are exact zeros on the coarse levels, their corrections
    // too, so any pivot there does ([S16], doc/performance.md sections 15
    // and 18.2); PETSc's SOR is then point-wise instead of block-wise (what
    // the modes lose on the 3-D ring). Without the shift such a set-up
    // fails, and the failure is the caller's (the step is rejected): no
    // other near-null space is taken behind the user's back
    shiftZeroPivots_ = dict_.lookupOrDefault<bool>("shiftZeroPivots", true);

    // Off by default: on the 3-D ring it saved 11 % of the CPU at 31 000
    // cells (GAMG's set-up is cheap next to its solves) but raised the
    // Newton iterations of the 336-cell quarter by a third (the weaker
    // preconditioner makes GMRES stop right at the inexact Newton
    // tolerance) and made them differ between serial and parallel runs
    // (doc/performance.md section 12)
    reuse_ = dict_.lookupOrDefault<bool>("reusePreconditioner", false);
    refreshIterations_ =
        dict_.lookupOrDefault<label>("refreshIterations", 30);
    if (refreshIterations_ < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword 'refreshIterations' in dictionary " << dict_.name()
            << " is " << refreshIterations_ << ": at least 1 expected"
            << exit(FatalIOError);
    }

    if (dict_.found("options") && !dict_.isDict("options"))
    {
        FatalIOErrorInFunction(dict_)
            << "Keyword 'options' in dictionary " << dict_.name()
            << " must be a sub-dictionary of PETSc options, e.g."
            << " options { pc_gamg_threshold 0.02; }" << exit(FatalIOError);
    }

    // Dictionary options first: the defaults set by createKsp() give way
    // to them and to PETSC_OPTIONS
    check
    (
        options_.insert
        (
            dict_.found("options") ? dict_.subDict("options") : dictionary()
        ),
        "setting the options"
    );
}


void Foam::linearSolvers::petscSolver::createKsp()
{
    check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "creating the Krylov solver");
    check
    (
        KSPSetOptionsPrefix(ksp_, options_.prefix().c_str()),
        "setting the options prefix"
    );

    check(KSPSetType(ksp_, kspName_.c_str()), "setting the Krylov method");
    check
    (
        KSPSetTolerances
        (
            ksp_, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, maxIterations_
        ),
        "setting maxIterations"
    );

    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "getting the preconditioner");
    const char* pcType = PCNONE;
    if (pcName_ == "gamg") pcType = PCGAMG;
    else if (pcName_ == "boomerAMG") pcType = PCHYPRE;
    else if (pcName_ == "ml") pcType = PCML;
    else if (pcName_ == "mumps") pcType = PCLU;
    else if (pcName_ == "ilu" || pcName_ == "bjacobi") pcType = PCBJACOBI;
    else if (pcName_ == "jacobi") pcType = PCJACOBI;
    check(PCSetType(pc, pcType), "setting the preconditioner");

    if (pcName_ == "gamg" && matrix_.nComponents() == 3)
    {
        // Richardson with SOR on the levels: PETSc's Chebyshev with point
        // Jacobi rests on an eigenvalue estimate for a symmetric operator
        // and stalled GMRES on the sliding-friction Jacobian (relative
        // residual 0.9 after 500 iterations); SOR needs nonzero diagonals,
        // which the translations' coarse levels have (doc/performance.md
        // section 12). One sweep per level (PETSc's default: two): on the
        // 3-D frictional ring 27 % more Krylov iterations, each 40 % cheaper
        // (101 520 cells serially: 20 % less solve CPU, the same Newton
        // iterations; doc/performance.md section 12)
        setDefault("mg_levels_ksp_type", "richardson");
        setDefault("mg_levels_pc_type", "sor");
        setDefault("mg_levels_ksp_max_it", "1");
    }
    else if (pcName_ == "boomerAMG")
    {
        check(PCHYPRESetType(pc, "boomeramg"), "setting hypre's method");

        // hypre's recommendations for 3-D problems (HMIS coarsening,
        // extended+i interpolation truncated to 4 entries, strength 0.5):
        // less memory and set-up time than PETSc's defaults on 3-D elastic
        // operators; nodal coarsening with the rigid-body modes in the
        // interpolation was 10-30 times slower and took 5-20 times the
        // memory (tests/benchmarks/linearSolvers)
        if (matrix_.nComponents() == 3)
        {
            setDefault("pc_hypre_boomeramg_strong_threshold", "0.5");
            setDefault("pc_hypre_boomeramg_coarsen_type", "HMIS");
            setDefault("pc_hypre_boomeramg_interp_type", "ext+i");
            setDefault("pc_hypre_boomeramg_P_max", "4");
        }
    }
    else if (pcName_ == "mumps")
    {
        check
        (
            PCFactorSetMatSolverType(pc, MATSOLVERMUMPS),
            "selecting MUMPS"
        );
    }

    // The options (dictionary, PETSC_OPTIONS) override the above
    check
    (
        KSPSetFromOptions(ksp_),
        "reading the options (entries of 'options', PETSC_OPTIONS)"
    );
    setResidualNorm();
}


void Foam::linearSolvers::petscSolver::setResidualNorm()
{
    KSPType type = nullptr;
    check(KSPGetType(ksp_, &type), "querying the Krylov method");
    const std::string method(type);
    if (method == KSPPREONLY)
    {
        return;
    }
    check
    (
        KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE),
        "setting the initial guess"
    );

    if (options_.found("ksp_norm_type") || options_.found("ksp_pc_side"))
    {
        return;
    }
    if (method == KSPGMRES || method == KSPBCGS)
    {
        check(KSPSetPCSide(ksp_, PC_RIGHT), "setting the preconditioner side");
    }
    if
    (
        method == KSPGMRES || method == KSPBCGS || method == KSPFGMRES
     || method == KSPCG
    )
    {
        check
        (
            KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED),
            "setting the residual norm"
        );
    }
}


void Foam::linearSolvers::petscSolver::setDefault
(
    const std::string& option,
    const char* value
)
{
    check(options_.setDefault(option, value), "setting a default option");
}


void Foam::linearSolvers::petscSolver::checkUnusedOptions() const
{
    std::string fromDict, fromElsewhere;
    check(options_.unused(fromDict, fromElsewhere), "listing the options");

    const string hint =
        "They are misspelt, or not options of this solver ("
      + description_ + ");\nPETSC_OPTIONS=-help lists the options PETSc"
        " reads (with the prefix " + options_.prefix() + ")";
    if (fromDict.size())
    {
        FatalIOErrorInFunction(dict_.subDict("options"))
            << "PETSc did not use the entries" << fromDict.c_str()
            << " of 'options' in dictionary " << dict_.name() << nl
            << hint.c_str() << exit(FatalIOError);
    }
    if (fromElsewhere.size())
    {
        FatalErrorInFunction
            << "PETSc did not use the options" << fromElsewhere.c_str()
            << " (from PETSC_OPTIONS or a petscrc file) of the linear"
            << " solver of " << dict_.name() << nl
            << hint.c_str() << exit(FatalError);
    }
}


Foam::string Foam::linearSolvers::petscSolver::describe() const
{
    KSPType ksp = nullptr;
    PC pc = nullptr;
    PCType pcType = nullptr;
    KSPGetType(ksp_, &ksp);
    KSPGetPC(ksp_, &pc);
    PCGetType(pc, &pcType);

    std::string d = std::string("Krylov method ") + ksp + ", preconditioner ";
    std::string pcs(pcType ? pcType : "none");
    if (pcs == PCHYPRE)
    {
        const char* hypreType = nullptr;
        PCHYPREGetType(pc, &hypreType);
        pcs = "hypre " + std::string(hypreType ? hypreType : "");
    }
    else if (pcs == PCLU || pcs == PCCHOLESKY)
    {
        MatSolverType solver = nullptr;
        PCFactorGetMatSolverType(pc, &solver);
        pcs += " (" + std::string(solver ? solver : "petsc") + ")";
    }
    d += pcs;
    if (!dict_.found("preconditioner"))
    {
        d += " (default)";
    }
    MatType matType = nullptr;
    MatGetType(A_.mat(), &matType);
    d += ", matrix " + std::string(matType ? matType : "?")
        + " (block size " + std::to_string(matrix_.nComponents()) + ")";
    if (aggregationMultigrid() || pcName_ == "boomerAMG")
    {
        // Said once at the start, with the preconditioner it is for
        d += std::string(", near-null space ")
          + (
                rigidBodyModes_
              ? "the rigid-body modes of the cell centres"
              : "the " + std::to_string(matrix_.nComponents())
              + " translations of the block size"
            )
          + (dict_.found("nearNullSpace") ? "" : " (default)");
        if
        (
            rigidBodyModes_ && pcName_ == "gamg"
         && matrix_.nComponents() == 3
        )
        {
            d += shiftZeroPivots_
              ? " with SOR's zero pivots shifted"
              : " without SOR's zero-pivot shift (shiftZeroPivots no)";
        }
    }
    if (reuse_)
    {
        d += ", preconditioner reused while the solves take at most "
            + std::to_string(refreshIterations_) + " iterations";
    }
    d += ", maxIterations " + std::to_string(maxIterations_)
        + ", options prefix " + options_.prefix();
    return d;
}


// ************************************************************************* //

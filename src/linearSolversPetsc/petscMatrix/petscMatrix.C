/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "petscMatrix.H"
#include "petscSession.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::petscMatrix::petscMatrix(const blockSparseMatrix& matrix)
:
    matrix_(matrix),
    A_(nullptr),
    x_(nullptr),
    b_(nullptr),
    columns_(matrix.colCells().begin(), matrix.colCells().end()),
    rowValues_()
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::petscMatrix::~petscMatrix()
{
    // After PetscFinalize the objects are gone with PETSc
    if (petscSession::running())
    {
        petscSession::fpeGuard guard;
        VecDestroy(&x_);
        VecDestroy(&b_);
        MatDestroy(&A_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

PetscErrorCode Foam::petscMatrix::create(const char* prefix)
{
    const label nc = matrix_.nComponents();
    const label nRows = matrix_.nRows();
    const label lo = matrix_.cellNumbering().offset(Pstream::myProcNo());
    const label hi = lo + nRows;
    const labelList& start = matrix_.rowStart();

    // Blocks per block row in this processor's columns and in others'
    std::vector<PetscInt> nDiagonal(nRows, 0), nOff(nRows, 0);
    label maxRow = 0;
    for (label r = 0; r < nRows; ++r)
    {
        for (label s = start[r]; s < start[r + 1]; ++s)
        {
            const label c = columns_[s];
            ++((c >= lo && c < hi) ? nDiagonal[r] : nOff[r]);
        }
        maxRow = max(maxRow, start[r + 1] - start[r]);
    }
    rowValues_.resize(maxRow*nc*nc);

    const PetscInt n = nRows*nc;
    PetscCall(MatCreate(PETSC_COMM_WORLD, &A_));
    PetscCall(MatSetSizes(A_, n, n, PETSC_DETERMINE, PETSC_DETERMINE));
    PetscCall(MatSetBlockSize(A_, nc));
    PetscCall(MatSetType(A_, MATAIJ));
    PetscCall(MatSetOptionsPrefix(A_, prefix));
    PetscCall(MatSetFromOptions(A_));
    PetscCall
    (
        MatXAIJSetPreallocation
        (
            A_, nc, nDiagonal.data(), nOff.data(), nullptr, nullptr
        )
    );
    PetscCall(MatSetOption(A_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
    PetscCall(MatSetOption(A_, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE));

    // PETSc's ownership must be the decomposition's (same communicator,
    // ranks in the same order)
    PetscInt first = 0, last = 0;
    PetscCall(MatGetOwnershipRange(A_, &first, &last));
    PetscCheck
    (
        first == lo*nc && last == hi*nc,
        PETSC_COMM_SELF, PETSC_ERR_PLIB,
        "PETSc owns rows %d..%d, the decomposition %d..%d",
        int(first), int(last), int(lo*nc), int(hi*nc)
    );

    PetscCall(MatCreateVecs(A_, &x_, &b_));
    return 0;
}


PetscErrorCode Foam::petscMatrix::assemble()
{
    const label nc = matrix_.nComponents();
    const labelList& start = matrix_.rowStart();
    const scalarList& values = matrix_.values();

    for (label r = 0; r < matrix_.nRows(); ++r)
    {
        const label s0 = start[r];
        const label nb = start[r + 1] - s0;

        // Slot-major (nc x nc per block) to block-row-major
        for (label k = 0; k < nb; ++k)
        {
            const scalar* block = values.cdata() + (s0 + k)*nc*nc;
            for (label a = 0; a < nc; ++a)
            {
                for (label b = 0; b < nc; ++b)
                {
                    rowValues_[a*nb*nc + k*nc + b] = block[a*nc + b];
                }
            }
        }

        const PetscInt row = matrix_.globalRow(r);
        PetscCall
        (
            MatSetValuesBlocked
            (
                A_, 1, &row, nb, columns_.data() + s0, rowValues_.data(),
                INSERT_VALUES
            )
        );
    }
    PetscCall(MatAssemblyBegin(A_, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A_, MAT_FINAL_ASSEMBLY));
    return 0;
}


PetscErrorCode Foam::petscMatrix::setRigidBodyModes(label& nModes)
{
    nModes = 0;
    const vectorField& C = matrix_.coordinates();
    const label nc = matrix_.nComponents();
    const labelList& comps = matrix_.components();

    // Without coordinates on every processor: none (PETSc's multigrids
    // then use the nc translations from the block size)
    const bool haveCoordinates = C.size() == matrix_.nRows();
    if (!returnReduce(haveCoordinates, andOp<bool>()))
    {
        return 0;
    }

    // Centred coordinates: the modes' orthonormalisation then does not
    // lose digits to a far origin
    vector mean = sum(C);
    reduce(mean, sumOp<vector>());
    mean /= max(returnReduce(C.size(), sumOp<label>()), 1);

    Vec coordinates = nullptr;
    PetscCall(VecDuplicate(x_, &coordinates));
    PetscScalar* c = nullptr;
    PetscCall(VecGetArray(coordinates, &c));
    forAll(C, i)
    {
        for (label a = 0; a < nc; ++a)
        {
            c[i*nc + a] = C[i][comps[a]] - mean[comps[a]];
        }
    }
    PetscCall(VecRestoreArray(coordinates, &c));

    MatNullSpace modes = nullptr;
    PetscCall(MatNullSpaceCreateRigidBody(coordinates, &modes));
    PetscCall(MatSetNearNullSpace(A_, modes));

    PetscBool hasConstant = PETSC_FALSE;
    PetscInt nVectors = 0;
    const Vec* vectors = nullptr;
    PetscCall(MatNullSpaceGetVecs(modes, &hasConstant, &nVectors, &vectors));
    nModes = nVectors;

    PetscCall(MatNullSpaceDestroy(&modes));
    PetscCall(VecDestroy(&coordinates));
    return 0;
}


PetscErrorCode Foam::petscMatrix::toPetsc
(
    const Eigen::VectorXd& v,
    Vec p
) const
{
    PetscScalar* a = nullptr;
    PetscCall(VecGetArray(p, &a));
    for (Eigen::Index i = 0; i < v.size(); ++i)
    {
        a[i] = v(i);
    }
    PetscCall(VecRestoreArray(p, &a));
    return 0;
}


PetscErrorCode Foam::petscMatrix::fromPetsc
(
    Vec p,
    Eigen::VectorXd& v
) const
{
    const PetscScalar* a = nullptr;
    v.resize(matrix_.nLocalUnknowns());
    PetscCall(VecGetArrayRead(p, &a));
    for (Eigen::Index i = 0; i < v.size(); ++i)
    {
        v(i) = a[i];
    }
    PetscCall(VecRestoreArrayRead(p, &a));
    return 0;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The exact Jacobian M = -dR/du of the residual ([S21] in doc/theory.md):
    every term of residual() differentiated through the gradient stencils,
    the compact face difference, F-bar, the law's consistent tangent and the
    force patches' tangents.

\*---------------------------------------------------------------------------*/

#include "solidDiscretisation.H"
#include "HashTable.H"
#include "faceColumns.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- The 3 x 3 block d(A : dF) for a 3 x 9 flux tangent A: K_ik = A_i . dF_k
inline tensor fluxBlock
(
    const Eigen::Matrix<double, 3, 9, Eigen::RowMajor>& A,
    const tensorDerivative& dF
)
{
    tensor K;
    for (direction i = 0; i < 3; ++i)
    {
        for (direction k = 0; k < 3; ++k)
        {
            scalar s = 0;
            for (direction b = 0; b < 9; ++b)
            {
                s += A(i, b)*dF[k][b];
            }
            K[3*i + k] = s;
        }
    }
    return K;
}

//- fluxBlock(A, dFbar) with dFbar the F-bar derivative of the column
//  dG, dJbar, in the solved components only (the matrix keeps no others:
//  4 of the 9 entries in plane strain)
inline tensor solvedFluxBlock
(
    const Eigen::Matrix<double, 3, 9, Eigen::RowMajor>& A,
    const volumetricAveraging::linearisation& lin,
    const tensorDerivative& dG,
    const vector& dJbar,
    const labelList& comps
)
{
    const tensorDerivative dF(transposed(dG));
    const vector ds
    (
        lin.active
      ? volumetricAveraging::scaleDerivative(lin, dF, dJbar)
      : vector::zero
    );
    tensor K(Zero);
    for (const label k : comps)
    {
        const tensor dFk
        (
            lin.active
          ? volumetricAveraging::derivative(lin, dF[k], ds[k])
          : dF[k]
        );
        for (const label i : comps)
        {
            scalar s = 0;
            for (direction b = 0; b < 9; ++b)
            {
                s += A(i, b)*dFk[b];
            }
            K[3*i + k] = s;
        }
    }
    return K;
}


//- Face displacement D_f = u_P + d.G_P and F = I + G_P^T: for a column
//  with dG_P/du_Q, dD_f/du_Q = delta_PQ I + d.dG_P/du_Q
static tensor dDface(const vector& d, const tensorDerivative& dG, bool self)
{
    return dotDerivative(d, dG) + (self ? tensor::I : tensor::zero);
}


//- The block df/du_Q of a face force with tangent t
static tensor forceBlock
(
    const faceForceTangent& t,
    const tensor& dD,
    const tensorDerivative& dG
)
{
    tensor K(t.dfdD & dD);
    for (direction i = 0; i < 3; ++i)
    {
        for (direction kk = 0; kk < 3; ++kk)
        {
            K[3*i + kk] += t.dfdF[i] && dG[kk].T();
        }
    }
    return K;
}

} // End namespace Foam



// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::solidDiscretisation::addInternalFaces
(
    const tensorField& cofactors,
    blockSparseMatrix& M
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf();
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& u = u_.primitiveField();
    const scalarField& weights = mesh_.weights();
    const globalIndex& numbering = grad_.cellNumbering();

    faceColumns columns;
    stressTangent dPdF;
    materialState scratch;

    forAll(own, facei)
    {
        const label P = own[facei];
        const label N = nei[facei];
        const scalar w = weights[facei];
        const vector d(C[N] - C[P]);
        const vector e(d/mag(d));
        const tensor L(tensor::I - sqr(e));

        const tensor F
        (
            volumetricAveraging::faceDefGrad(G_[P], G_[N], w, d, u[N] - u[P])
        );
        const scalar Jbar = w*J_[P] + (1 - w)*J_[N];

        columns.clear();
        columns.addStencil(grad_.stencil(P), w, L, cofactors[P]);
        columns.addStencil(grad_.stencil(N), 1 - w, L, cofactors[N]);
        columns.addCompact(numbering.toGlobal(N), e/mag(d));
        columns.addCompact(numbering.toGlobal(P), -e/mag(d));

        laws_.cellLaw(P).stressAndTangent
        (
            fbar_.apply(F, Jbar), oldState(-1, facei), scratch, dPdF
        );
        const auto A = tangentDotS(dPdF, Sf[facei]);
        const volumetricAveraging::linearisation lin(fbar_.linearise(F, Jbar));

        forAll(columns.cells, q)
        {
            const tensor K
            (
                solvedFluxBlock(A, lin, columns.dG[q], columns.dJ[q], M.components())
            );
            M.addBlock(P, columns.cells[q], -K);
            M.addBlock(N, columns.cells[q], K);
        }
    }
}


void Foam::solidDiscretisation::addBoundaryFaces
(
    const label patchi,
    const tensorField& cofactors,
    blockSparseMatrix& M
) const
{
    const fvPatch& p = mesh_.boundary()[patchi];
    const labelUList& faceCells = p.faceCells();
    const solidBoundaries::patchKind kind = bcs_.kind(patchi);

    faceColumns columns;
    stressTangent dPdF;
    materialState scratch;

    forAll(faceCells, i)
    {
        const label P = faceCells[i];

        // F before volume averaging, Jbar, and the columns' dG_f, dJbar:
        // the residual's face deformation gradient and its derivative
        tensor F;
        scalar Jbar;
        columns.clear();
        if (!boundaryFaceDefGrad(patchi, i, F, Jbar, &columns, &cofactors))
        {
            return;
        }

        const vector& S = p.Sf()[i];

        if (kind == solidBoundaries::WEDGE)
        {
            const tensor& T = bcs_.wedgeRotation(patchi);
            laws_.cellLaw(P).stressAndTangent
            (
                T & F & T.T(), oldState(patchi, i), scratch, dPdF
            );
            const auto A = tangentDotS(dPdF, S);
            forAll(columns.cells, q)
            {
                tensorDerivative dF(transposed(columns.dG[q]));
                for (direction k = 0; k < 3; ++k)
                {
                    dF[k] = T & dF[k] & T.T();
                }
                M.addBlock(P, columns.cells[q], -fluxBlock(A, dF));
            }
            continue;
        }

        laws_.cellLaw(P).stressAndTangent
        (
            fbar_.apply(F, Jbar), oldState(patchi, i), scratch, dPdF
        );
        Eigen::Matrix<double, 3, 9, Eigen::RowMajor> A(tangentDotS(dPdF, S));
        if (kind == solidBoundaries::SYMMETRY)
        {
            // only the normal traction acts: (n n) . flux
            const vector& n = patchNormal_[patchi][i];
            Eigen::Matrix3d nn;
            for (direction a = 0; a < 3; ++a)
            {
                for (direction b = 0; b < 3; ++b)
                {
                    nn(a, b) = n[a]*n[b];
                }
            }
            A = nn*A;
        }

        const volumetricAveraging::linearisation lin(fbar_.linearise(F, Jbar));
        forAll(columns.cells, q)
        {
            M.addBlock
            (
                P, columns.cells[q],
                -fluxBlock
                (
                    A,
                    volumetricAveraging::derivative
                    (
                        lin, transposed(columns.dG[q]), columns.dJ[q]
                    )
                )
            );
        }
    }
}


void Foam::solidDiscretisation::addForcePatch
(
    const label patchi,
    blockSparseMatrix& M
) const
{
    const fvPatch& p = mesh_.boundary()[patchi];
    const labelUList& faceCells = p.faceCells();
    const vectorField& d = patchDelta_[patchi];
    const solidForceBoundary& patch = bcs_.forcePatch(patchi);

    const forceKinematics fk(*this, patchi, mesh_.time().deltaTValue());

    // One evaluation gives a contact pair's own-face tangents and its
    // couplings to the partner's faces
    List<faceForceTangent> df;
    DynamicList<faceCoupling> c;
    patch.tangentAndCouplings(fk.k, df, c);

    forAll(faceCells, i)
    {
        const label P = faceCells[i];
        const gradientStencil& s = grad_.stencil(P);
        M.addBlock
        (
            P, s.cell,
            -forceBlock(df[i], dDface(d[i], s.self, true), s.self)
        );
        forAll(s.cells, j)
        {
            const tensorDerivative dG(outerIdentity(s.coeffs[j]));
            M.addBlock
            (
                P, s.cells[j],
                -forceBlock(df[i], dDface(d[i], dG, false), dG)
            );
        }
    }

    addForceCouplings(patchi, c, M);
}


void Foam::solidDiscretisation::addForceCouplings
(
    const label patchi,
    const UList<faceCoupling>& c,
    blockSparseMatrix& M
) const
{
    // [C13] a face force that depends on the kinematics of a face of
    // another patch (or another face of its own): the blocks of that face's
    // cell's gradient stencil in the row of the face's cell
    const labelUList& rowCells = mesh_.boundary()[patchi].faceCells();
    auto add = [&](const label r, const label col, const tensor& K)
    {
        const label slot = M.find(r, col);
        if (slot < 0)
        {
            patternMissed_ = true;
            return;
        }
        M.addToSlot(slot, -K);
    };
    for (const faceCoupling& e : c)
    {
        const label P = rowCells[e.face];
        const vector& d = couplingDelta(e.patch, e.otherFace);
        const gradientStencil& s = couplingStencil(e.patch, e.otherFace);
        add(P, s.cell, forceBlock(e.df, dDface(d, s.self, true), s.self));
        forAll(s.cells, j)
        {
            const tensorDerivative dG(outerIdentity(s.coeffs[j]));
            add(P, s.cells[j], forceBlock(e.df, dDface(d, dG, false), dG));
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelListList Foam::solidDiscretisation::jacobianPattern() const
{
    // A face's flux depends on the stencils of the two cells it joins (the
    // patch-mean couplings are kept out: meanCouplings())
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    List<DynamicList<label>> cols(mesh_.nCells());

    auto addStencil = [&](const label row, const gradientStencil& s)
    {
        cols[row].append(s.cell);
        cols[row].append(s.cells);
    };

    forAll(cols, P)
    {
        addStencil(P, grad_.stencil(P));
    }
    forAll(own, facei)
    {
        addStencil(own[facei], grad_.stencil(nei[facei]));
        addStencil(nei[facei], grad_.stencil(own[facei]));
    }
    forAll(mesh_.boundary(), patchi)
    {
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        const solidBoundaries::patchKind kind = bcs_.kind(patchi);
        if (kind == solidBoundaries::COUPLED)
        {
            forAll(faceCells, i)
            {
                addStencil(faceCells[i], grad_.neighbourStencil(patchi, i));
            }
        }
    }

    // [C13] force patches coupled to faces of other patches (contact
    // pairs): the current pairs and their neighbours within a face
    forAll(mesh_.boundary(), patchi)
    {
        if
        (
            bcs_.kind(patchi) != solidBoundaries::FORCE
         || !bcs_.forcePatch(patchi).couplesToOtherFaces()
        )
        {
            continue;
        }
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        DynamicList<faceCoupling> c;
        bcs_.forcePatch(patchi).couplingCandidates(1, c);
        for (const faceCoupling& e : c)
        {
            addStencil
            (
                faceCells[e.face],
                couplingStencil(e.patch, e.otherFace)
            );
        }
    }

    labelListList pattern(cols.size());
    forAll(cols, P)
    {
        pattern[P].transfer(cols[P]);
    }
    return pattern;
}


void Foam::solidDiscretisation::jacobian(blockSparseMatrix& M) const
{
    M.zero();
    patternMissed_ = false;

    // dJ_P = cofactors(F_P) : dF_P, cofactors(F) = J F^-T, once per cell
    tensorField cofactors(G_.size());
    forAll(cofactors, celli)
    {
        cofactors[celli] = cofactor(G_[celli]);
    }

    addInternalFaces(cofactors, M);

    forAll(mesh_.boundary(), patchi)
    {
        switch (bcs_.kind(patchi))
        {
            case solidBoundaries::EMPTY:
                break;
            case solidBoundaries::FORCE:
                addForcePatch(patchi, M);
                break;
            default:
                addBoundaryFaces(patchi, cofactors, M);
                break;
        }
    }

    // [S13] inertia: R -= rho V 2/(dt (dt + dt0)) u + ...
    if (inertia_)
    {
        const scalar dt = mesh_.time().deltaTValue();
        const scalar c = 2/(dt*(dt + deltaT0_));
        const scalarField& V = mesh_.V();
        const globalIndex& numbering = grad_.cellNumbering();
        forAll(V, P)
        {
            M.addBlock
            (
                P, numbering.toGlobal(P),
                (c*inertiaDensity_[P]*V[P])*tensor::I
            );
        }
    }

    // [C14] the pattern is rebuilt on every processor or on none (the
    // rebuild communicates: the contact pairs' candidates, the matrix)
    reduce(patternMissed_, orOp<bool>());
}


void Foam::solidDiscretisation::meanCouplings
(
    List<vectorField>& U,
    List<vectorField>& V
) const
{
    // [S21] f_i depends on <D> = sum_j |S0_j| D_j / sum_j |S0_j| [S12b]:
    // M -= C_i . d<D>/du_Q with C_i = df_i/d<D>, i.e. M += sum_a u_a v_a^T,
    // u_a = -C_i e_a at the rows of the patch's cells, v_a = e_a . d<D>/du
    // at the columns; d<D>/du_Q is gathered over all processors
    U.clear();
    V.clear();
    const globalIndex& numbering = grad_.cellNumbering();

    forAll(mesh_.boundary(), patchi)
    {
        if
        (
            bcs_.kind(patchi) != solidBoundaries::FORCE
         || !bcs_.forcePatch(patchi).couplesToMeanDisplacement()
        )
        {
            continue;
        }
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelUList& faceCells = p.faceCells();
        const vectorField& d = patchDelta_[patchi];

        const forceKinematics fk(*this, patchi, mesh_.time().deltaTValue());
        const solidPatchKinematics& k = fk.k;
        tensorField C(faceCells.size());
        bcs_.forcePatch(patchi).meanDisplacementTangent(k, C);

        // d<D>/du_Q, D_f = u_P + d.G_P
        const scalarField magS(mag(p.Sf()));
        const scalar area = gSum(magS);
        HashTable<tensor, label, Hash<label>> dMean(64);
        forAll(faceCells, i)
        {
            const gradientStencil& s = grad_.stencil(faceCells[i]);
            const scalar wi = magS[i]/area;
            dMean(s.cell, tensor::zero) +=
                wi*(tensor::I + dotDerivative(d[i], s.self));
            forAll(s.cells, j)
            {
                dMean(s.cells[j], tensor::zero) += (wi*(d[i] & s.coeffs[j]))*tensor::I;
            }
        }
        Pstream::mapCombineGather(dMean, plusEqOp<tensor>());
        Pstream::mapCombineScatter(dMean);

        for (direction a = 0; a < 3; ++a)
        {
            vectorField u(mesh_.nCells(), Zero);
            scalar uMax = 0;
            forAll(faceCells, i)
            {
                u[faceCells[i]] -= C[i].col(a);
                uMax = max(uMax, mag(C[i].col(a)));
            }
            if (returnReduce(uMax, maxOp<scalar>()) == 0)
            {
                continue;
            }
            vectorField v(mesh_.nCells(), Zero);
            forAllConstIters(dMean, iter)
            {
                if (numbering.isLocal(iter.key()))
                {
                    v[numbering.toLocal(iter.key())] = iter.val().row(a);
                }
            }
            U.append(u);
            V.append(v);
        }
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "leastSquaresGradient.H"
#include "processorFvPatch.H"
#include "cyclicFvPatch.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const gradientStencil& s)
{
    os  << s.cell << token::SPACE << s.self << token::SPACE << s.cells
        << token::SPACE << s.coeffs;
    return os;
}


Foam::Istream& Foam::operator>>(Istream& is, gradientStencil& s)
{
    is  >> s.cell >> s.self >> s.cells >> s.coeffs;
    return is;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::leastSquaresGradient::computeWeights()
{
    // [S10] weighted least squares with weights 1/|d|^2 on the reference mesh
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.C().primitiveField();

    symmTensorField dd(mesh_.nCells(), Zero);

    forAll(own, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const symmTensor wdd(sqr(d)/magSqr(d));
        dd[own[facei]] += wdd;
        dd[nei[facei]] += wdd;
    }

    List<vectorField> patchDelta(mesh_.boundary().size());

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        vectorField& delta = patchDelta[patchi];

        switch (bcs_.kind(patchi))
        {
            case solidBoundaries::FIXED:
                delta = p.Cf() - p.Cn();
                break;
            case solidBoundaries::COUPLED:
                delta = p.delta();
                break;
            case solidBoundaries::SYMMETRY:
            {
                // the mirror image of the cell across the plane
                const vectorField n(p.nf());
                delta = 2*((n & (p.Cf() - p.Cn()))*n);
                break;
            }
            default:
                continue;
        }

        const labelUList& fc = p.faceCells();
        forAll(fc, i)
        {
            dd[fc[i]] += sqr(delta[i])/magSqr(delta[i]);
        }
    }

    // Unsolved directions (2-D, and the hoop direction of an axisymmetric
    // mesh, whose gradient is the hoop strain below): a unit diagonal
    // keeps dd invertible and their least-squares gradient zero
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (mesh_.geometricD()[d] != 1)
        {
            vector e(Zero);
            e[d] = 1;
            dd += sqr(e);
        }
    }

    forAll(dd, celli)
    {
        const scalar scale = tr(dd[celli])/3;
        if (det(dd[celli]) < 1e-10*pow3(scale))
        {
            FatalErrorInFunction
                << "Cell " << celli << " at " << C[celli]
                << " has too few neighbours for a least-squares gradient"
                << " (its other faces carry tractions)." << nl
                << "Refine the mesh so there are at least two cells across"
                << " every traction-loaded wall" << nl << exit(FatalError);
        }
    }

    const symmTensorField invDd(inv(dd));

    ownLs_.setSize(own.size());
    neiLs_.setSize(own.size());
    forAll(own, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const vector wd(d/magSqr(d));
        ownLs_[facei] = invDd[own[facei]] & wd;
        neiLs_[facei] = invDd[nei[facei]] & wd;
    }

    patchLs_.setSize(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        const vectorField& delta = patchDelta[patchi];
        vectorField& ls = patchLs_[patchi];
        ls.setSize(fc.size(), Zero);
        forAll(delta, i)
        {
            ls[i] = invDd[fc[i]] & (delta[i]/magSqr(delta[i]));
        }
    }

    // [S20] hoop strain of an axisymmetric mesh: G_tt = u_r/r
    if (bcs_.axisymmetric())
    {
        hoop_.setSize(mesh_.nCells());
        forAll(C, celli)
        {
            hoop_[celli] = bcs_.hoopGradient(C[celli]);
        }
        hoopTensor_ = sqr(bcs_.hoopDirection());
    }
}


template<class Type>
void Foam::leastSquaresGradient::neighbourValues
(
    const List<List<Type>>& faceValues,
    List<List<Type>>& nbrValues
) const
{
    // processor patches: by message; cyclics: the other side's values
    nbrValues.setSize(mesh_.boundary().size());
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (bcs_.kind(patchi) != solidBoundaries::COUPLED)
        {
            continue;
        }
        if (isA<processorFvPatch>(p))
        {
            UOPstream toNbr
            (
                refCast<const processorFvPatch>(p).neighbProcNo(), pBufs
            );
            toNbr << faceValues[patchi];
        }
        else
        {
            nbrValues[patchi] =
                faceValues[refCast<const cyclicFvPatch>(p).neighbPatchID()];
        }
    }
    pBufs.finishedSends();
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (bcs_.kind(patchi) == solidBoundaries::COUPLED && isA<processorFvPatch>(p))
        {
            UIPstream fromNbr
            (
                refCast<const processorFvPatch>(p).neighbProcNo(), pBufs
            );
            fromNbr >> nbrValues[patchi];
        }
    }
}


void Foam::leastSquaresGradient::computeStencils()
{
    // [S21] dG_P/du_Q of gradient() below, term by term
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const cellList& cells = mesh_.cells();

    stencils_.setSize(mesh_.nCells());

    List<vectorField> nf(mesh_.boundary().size());
    forAll(nf, patchi)
    {
        nf[patchi] = mesh_.boundary()[patchi].nf();
    }

    // Global numbers of the cells across coupled faces
    List<labelList> nbrCells(mesh_.boundary().size());
    {
        List<labelList> faceCells(mesh_.boundary().size());
        forAll(mesh_.boundary(), patchi)
        {
            faceCells[patchi] = cellNumbering_.toGlobal
            (
                labelList(mesh_.boundary()[patchi].faceCells())
            );
        }
        neighbourValues(faceCells, nbrCells);
    }

    forAll(cells, P)
    {
        gradientStencil& s = stencils_[P];
        s.cell = cellNumbering_.toGlobal(P);
        s.self = zeroDerivative();
        DynamicList<label> sc(cells[P].size());
        DynamicList<vector> sa(cells[P].size());

        for (const label facei : cells[P])
        {
            if (mesh_.isInternalFace(facei))
            {
                // G[own] += ownLs (u_nei - u_own), G[nei] += neiLs (same)
                const bool isOwner = own[facei] == P;
                const vector a(isOwner ? ownLs_[facei] : -neiLs_[facei]);
                sc.append
                (
                    cellNumbering_.toGlobal(isOwner ? nei[facei] : own[facei])
                );
                sa.append(a);
                addScaled(s.self, -1, outerIdentity(a));
                continue;
            }

            const label patchi = mesh_.boundaryMesh().whichPatch(facei);
            const label i = facei - mesh_.boundaryMesh()[patchi].start();
            const vector& ls = patchLs_[patchi][i];

            switch (bcs_.kind(patchi))
            {
                case solidBoundaries::FIXED:
                    addScaled(s.self, -1, outerIdentity(ls));
                    break;
                case solidBoundaries::COUPLED:
                    sc.append(nbrCells[patchi][i]);
                    sa.append(ls);
                    addScaled(s.self, -1, outerIdentity(ls));
                    break;
                case solidBoundaries::SYMMETRY:
                {
                    // mirror image -2 (n . u_P) n
                    const vector& n = nf[patchi][i];
                    addScaled(s.self, 1, outerMatrix(ls, -2*sqr(n)));
                    break;
                }
                default:
                    break;
            }
        }

        if (hoop_.size())
        {
            for (direction k = 0; k < 3; ++k)
            {
                s.self[k] += hoop_[P][k]*hoopTensor_;
            }
        }

        s.cells.transfer(sc);
        s.coeffs.transfer(sa);
    }

    // The stencils of the cells across coupled faces, once
    List<List<gradientStencil>> faceCellStencils(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        if (bcs_.kind(patchi) == solidBoundaries::COUPLED)
        {
            faceCellStencils[patchi] = List<gradientStencil>
            (
                stencils_, mesh_.boundary()[patchi].faceCells()
            );
        }
    }
    neighbourValues(faceCellStencils, neighbourStencils_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::leastSquaresGradient::leastSquaresGradient
(
    const fvMesh& mesh,
    const solidBoundaries& bcs
)
:
    mesh_(mesh),
    bcs_(bcs),
    hoopTensor_(Zero),
    cellNumbering_(mesh.nCells())
{
    computeWeights();
    computeStencils();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::leastSquaresGradient::gradient
(
    const volVectorField& u,
    const volVectorField& D,
    tensorField& G
) const
{
    // [S10]
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& ui = u.primitiveField();

    G.setSize(mesh_.nCells());
    G = Zero;

    forAll(own, facei)
    {
        const vector dD(ui[nei[facei]] - ui[own[facei]]);
        G[own[facei]] += ownLs_[facei]*dD;
        G[nei[facei]] += neiLs_[facei]*dD;
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelUList& fc = p.faceCells();
        const vectorField& ls = patchLs_[patchi];

        switch (bcs_.kind(patchi))
        {
            case solidBoundaries::FIXED:
            {
                const fvPatchVectorField& Db = D.boundaryField()[patchi];
                forAll(fc, i)
                {
                    G[fc[i]] += ls[i]*(Db[i] - ui[fc[i]]);
                }
                break;
            }
            case solidBoundaries::COUPLED:
            {
                const vectorField uN
                (
                    u.boundaryField()[patchi].patchNeighbourField()
                );
                forAll(fc, i)
                {
                    G[fc[i]] += ls[i]*(uN[i] - ui[fc[i]]);
                }
                break;
            }
            case solidBoundaries::SYMMETRY:
            {
                const vectorField n(p.nf());
                forAll(fc, i)
                {
                    G[fc[i]] += ls[i]*(-2*(n[i] & ui[fc[i]])*n[i]);
                }
                break;
            }
            default:
                break;
        }
    }

    if (hoop_.size())
    {
        forAll(G, celli)
        {
            G[celli] += (hoop_[celli] & ui[celli])*hoopTensor_;
        }
    }
}


// ************************************************************************* //

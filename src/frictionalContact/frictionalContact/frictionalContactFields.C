/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.

Description
    frictionalContact: forces and their tangent handed to the solver, the commit
    of a converged step, reports and the entries written for restart.

\*---------------------------------------------------------------------------*/

#include "frictionalContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionalContactFvPatchVectorField::force
(
    const solidPatchKinematics& k,
    vectorField& f
) const
{
    frictionResult res;
    vector n;
    scalar area;
    scalar gap;
    forAll(f, i)
    {
        if (evaluateFace(i, k, res, n, area, gap))
        {
            // [C1] traction on the body: tN n - tT
            f[i] = area*(res.tN*n - res.tT);
        }
        else
        {
            f[i] = Zero;
        }
    }
}


void Foam::frictionalContactFvPatchVectorField::tangent
(
    const solidPatchKinematics& k,
    List<faceForceTangent>& df
) const
{
    // [C6] the exact derivative of f = da (tN n - tT) with respect to the
    // face displacement and deformation gradient, the face state held
    df.setSize(k.F.size());
    df = faceForceTangent();

    forAll(df, facei)
    {
        const frictionState& old = state()[facei];

        obstaclePoint cp;
        if (!nearestPoint(facei, k, cp))
        {
            continue;
        }

        const vector& n = cp.n;
        const tensor& N = cp.dndx;
        const tensor P(tensor::I - sqr(n));
        const vector v
        (
            old.totalSlip + (k.D[facei] - k.Dold[facei])
          - obstacle_->materialDisplacement(cp.p, k.time - k.deltaT, k.time)
        );

        frictionInput in;
        in.gN = smoothedPenetration(-cp.gap);
        in.gT = P & v;
        in.n = n;
        in.dt = k.deltaT;
        frictionResult res;
        law().update(old, in, res);

        // gN = smoothed(-gap) [C2b]; gT = (I - n n).v [C3]
        const vector dgNdx(-smoothedPenetrationSlope(-cp.gap)*cp.dgapdx);
        const tensor dvdx
        (
            tensor::I
          - (
                obstacle_->materialDisplacementGradient
                (
                    k.time - k.deltaT, k.time
                ) & cp.dpdx
            )
        );
        const tensor dgTdx
        (
            (P & dvdx) - (n & v)*N - n*(N.T() & v)
        );

        // the law's tangent [F7]; on a curved obstacle also the turn of
        // the tangent plane inside the law, by central differences in n
        tensor dtTdx((res.dtTdgT & dgTdx) + res.dtTdgN*dgNdx);
        if (magSqr(N) > 0)
        {
            const scalar h = 1e-6;
            vector t1(P & vector(1, 0, 0));
            if (magSqr(t1) < 0.1)
            {
                t1 = P & vector(0, 1, 0);
            }
            t1 /= mag(t1);
            const vector t2(n ^ t1);
            for (const vector& tj : {t1, t2})
            {
                frictionInput inp(in);
                frictionInput inm(in);
                inp.n = (n + h*tj)/mag(n + h*tj);
                inm.n = (n - h*tj)/mag(n - h*tj);
                frictionResult rp;
                frictionResult rm;
                law().update(old, inp, rp);
                law().update(old, inm, rm);
                dtTdx += ((rp.tT - rm.tT)/(2*h))*(N.T() & tj);
            }
        }

        // [C4] area da = |a|, a = J F^-T . S0
        const tensor& F = k.F[facei];
        const tensor FinvT(inv(F).T());
        const vector a(det(F)*(FinvT & k.Sf0[facei]));
        const scalar area = mag(a);
        const tensor dAreadF(area*FinvT - a*(inv(F) & (a/area)));

        const vector t(res.tN*n - res.tT);
        df[facei].dfdD =
            area*(n*(res.dtNdgN*dgNdx) + res.tN*N - dtTdx);
        for (direction i = 0; i < 3; ++i)
        {
            df[facei].dfdF[i] = t[i]*dAreadF;
        }
    }
}


void Foam::frictionalContactFvPatchVectorField::linearise
(
    const solidPatchKinematics& k
)
{
    beginHold();
    frictionInput in;
    frictionResult res;
    vector normal;
    scalar area;
    scalar gap;
    forAll(state(), i)
    {
        const bool inReach = evaluateFace(i, k, res, normal, area, gap, &in);
        holdFace(i, inReach, in, res);
    }
    startHold();
}


void Foam::frictionalContactFvPatchVectorField::release()
{
    releaseHold();
}


Foam::label Foam::frictionalContactFvPatchVectorField::predictorCorrection
(
    const solidPatchKinematics& k,
    vectorField& dD
) const
{
    // [S18b] the extrapolated step repeats the last one's closing of the
    // gap from outside the smoothed onset [C2b] to within it, and so
    // predicts the faces out of contact again. A face in contact at the
    // converged state (gap below the onset width, the obstacle where it was
    // then) whose predicted gap is larger gets the converged gap back,
    // along the obstacle's normal at the new time. Copies of the search
    // records: the cache [C2c] is not touched by the query
    label nCorrected = 0;
    forAll(dD, i)
    {
        const scalar cellDepth =
            patch().boundaryMesh().mesh().V()[patch().faceCells()[i]]
           /mag(k.Sf0[i]);
        const scalar refresh = searchRefreshFraction_*cellDepth;

        obstacleSearch oldSearch(search_[i]);
        obstaclePoint cpOld;
        if
        (
           !obstacle_->nearest
            (
                k.Cf0[i] + k.Dold[i], k.time - k.deltaT, searchDistance_,
                refresh, cpOld, oldSearch
            )
         || smoothedPenetration(-cpOld.gap) <= 0
        )
        {
            continue;
        }

        obstacleSearch newSearch(search_[i]);
        obstaclePoint cp;
        if
        (
            obstacle_->nearest
            (
                k.Cf0[i] + k.D[i], k.time, searchDistance_, refresh, cp,
                newSearch
            )
         && cp.gap > cpOld.gap
        )
        {
            dD[i] = (cpOld.gap - cp.gap)*cp.n;
            ++nCorrected;
        }
    }
    return nCorrected;
}


void Foam::frictionalContactFvPatchVectorField::commit
(
    const solidPatchKinematics& k
)
{
    beginCommit();

    frictionResult res;
    vector n;
    scalar area;
    scalar gap;
    forAll(state(), i)
    {
        if (evaluateFace(i, k, res, n, area, gap))
        {
            commitFace
            (
                i, res, n, area, gap, mag(k.Sf0[i]), k.Cf0[i] + k.D[i]
            );
        }
        else
        {
            // out of reach: an open face, fresh if it comes back
            commitOpenFace(i);
        }
    }

    endCommit();
}


void Foam::frictionalContactFvPatchVectorField::report
(
    const solidPatchKinematics& k
) const
{
    reportFaces(k.time);

    // [C2c] obstacle searches since the last report (this step and any
    // cut-back attempts before it)
    const labelPair n
    (
        returnReduce(obstacle_->searchCounts().first(), sumOp<label>()),
        returnReduce(obstacle_->searchCounts().second(), sumOp<label>())
    );
    if (n.first() + n.second() > 0)
    {
        Info<< "    contact " << patch().name() << ": obstacle searches "
            << n.first() << ", re-projections " << n.second() << endl;
    }
    obstacle_->resetSearchCounts();
}


void Foam::frictionalContactFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    os.writeKeyword("obstacle") << obstacleDict_;
    os.writeEntry("searchDistance", searchDistance_);
    os.writeEntry("searchRefreshFraction", searchRefreshFraction_);
    writeFaces(os);

    // [C2c] search records (triangulated obstacles): -1 not searched, -2
    // nothing in reach, else the triangle followed
    if (obstacle_->cachesSearches())
    {
        labelField tri(search_.size());
        vectorField x0(search_.size());
        forAll(search_, i)
        {
            tri[i] =
                !search_[i].searched ? -1
              : !search_[i].hit ? -2
              : search_[i].hint;
            x0[i] = search_[i].x0;
        }
        tri.writeEntry("searchTriangle", os);
        x0.writeEntry("searchPoint", os);
    }
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        frictionalContactFvPatchVectorField
    );
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "frictionalContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "wallFvPatch.H"
#include "volFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::frictionalContactFvPatchVectorField::copyFrom
(
    const frictionalContactFvPatchVectorField& ptf
)
{
    copyContactFaces(ptf);
    obstacleDict_ = ptf.obstacleDict_;
    obstacle_ = rigidObstacle::New(obstacleDict_, db().time().globalPath());
    searchDistance_ = ptf.searchDistance_;
    searchRefreshFraction_ = ptf.searchRefreshFraction_;
    search_ = ptf.search_;
}


void Foam::frictionalContactFvPatchVectorField::mapFaces
(
    const frictionalContactFvPatchVectorField& ptf,
    const fvPatchFieldMapper& mapper
)
{
    contactFaces::mapFaces(ptf, mapper);
    search_.setSize(mapper.size());
    search_ = obstacleSearch();
}


void Foam::frictionalContactFvPatchVectorField::readSearch
(
    const dictionary& dict
)
{
    const label n = patch().size();
    search_.setSize(n, obstacleSearch());

    // [C2c] the search records as written: a restart then re-projects
    // where the uninterrupted run would (the same triangles, bit for bit)
    if (dict.found("searchTriangle"))
    {
        const labelField tri("searchTriangle", dict, n);
        const vectorField x0("searchPoint", dict, n);
        forAll(search_, i)
        {
            search_[i].searched = tri[i] != -1;
            search_[i].hit = tri[i] >= 0;
            search_[i].hint = max(tri[i], label(-1));
            search_[i].x0 = x0[i];
        }
    }
}


bool Foam::frictionalContactFvPatchVectorField::nearestPoint
(
    const label facei,
    const solidPatchKinematics& k,
    obstaclePoint& cp
) const
{
    // [C2] the deformed face centre against the obstacle, the search
    // reused while the face moves less than a fraction of its cell [C2c]
    const point x(k.Cf0[facei] + k.D[facei]);
    const scalar cellDepth =
        patch().boundaryMesh().mesh().V()[patch().faceCells()[facei]]
       /mag(k.Sf0[facei]);
    return obstacle_->nearest
    (
        x, k.time, searchDistance_, searchRefreshFraction_*cellDepth,
        cp, search_[facei]
    );
}


bool Foam::frictionalContactFvPatchVectorField::evaluateFace
(
    const label facei,
    const solidPatchKinematics& k,
    frictionResult& res,
    vector& gapNormal,
    scalar& area,
    scalar& gap,
    frictionInput* input
) const
{
    if (heldOutOfReach(facei))
    {
        return false;
    }

    obstaclePoint cp;
    if (!nearestPoint(facei, k, cp))
    {
        return false;
    }
    gapNormal = cp.n;
    gap = cp.gap;

    // [C3] slip relative to the obstacle in the current tangent plane
    // (objective rate, [F29]): the face's motion over the step less that of
    // the obstacle's material point under it
    const vector ds
    (
        (k.D[facei] - k.Dold[facei])
      - obstacle_->materialDisplacement(cp.p, k.time - k.deltaT, k.time)
    );
    const tensor P(tensor::I - sqr(cp.n));

    frictionInput in;
    in.gN = smoothedPenetration(-cp.gap);
    in.gT = P & (state()[facei].totalSlip + ds);
    in.n = cp.n;
    in.dt = k.deltaT;

    faceUpdate(facei, in, res);
    if (input)
    {
        *input = in;
    }

    // [C4] current area, Nanson
    const tensor& F = k.F[facei];
    area = mag(det(F)*(inv(F).T() & k.Sf0[facei]));

    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(p, iF),
    searchDistance_(GREAT),
    searchRefreshFraction_(0.2)
{}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    calculatedFvPatchVectorField(p, iF, dict, false),
    obstacleDict_(dict.subDict("obstacle")),
    searchDistance_(-1),
    searchRefreshFraction_
    (
        dict.lookupOrDefault<scalar>("searchRefreshFraction", 0.2)
    )
{
    if (!isA<wallFvPatch>(p))
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << p.name() << " (dictionary " << dict.name()
            << "): type frictionalContact needs a patch of type 'wall' in"
            << " constant/polyMesh/boundary; it is of type '" << p.type()
            << "'" << nl << exit(FatalIOError);
    }

    // Default search distance: two cell depths
    const scalarField& V = p.boundaryMesh().mesh().V();
    scalar hMax = 0;
    forAll(p.faceCells(), i)
    {
        hMax = max(hMax, V[p.faceCells()[i]]/p.magSf()[i]);
    }
    reduce(hMax, maxOp<scalar>());
    searchDistance_ =
        dict.lookupOrDefault<scalar>("searchDistance", 2*max(hMax, SMALL));

    if (searchRefreshFraction_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'searchRefreshFraction' in dictionary " << dict.name()
            << " must be >= 0 (0: a full search at every evaluation), got "
            << searchRefreshFraction_ << nl << exit(FatalIOError);
    }
    if (!(searchDistance_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'searchDistance' in dictionary " << dict.name()
            << " must be > 0, got " << searchDistance_ << nl
            << exit(FatalIOError);
    }

    obstacle_ = rigidObstacle::New(obstacleDict_, db().time().globalPath());

    readContactFaces(dict);
    readSearch(dict);
    Info<< "    obstacle " << obstacleDict_.get<word>("type")
        << ", search distance " << searchDistance_ << " m" << endl;

    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=(patchInternalField());
    }
}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    calculatedFvPatchVectorField(ptf, p, iF, mapper),
    searchDistance_(ptf.searchDistance_),
    searchRefreshFraction_(ptf.searchRefreshFraction_)
{
    // iF may be a null field (reconstructPar): the time comes from the mesh
    copyContactFaces(ptf);
    obstacleDict_ = ptf.obstacleDict_;
    obstacle_ = rigidObstacle::New
    (
        obstacleDict_, p.boundaryMesh().mesh().time().globalPath()
    );
    mapFaces(ptf, mapper);
}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf
)
:
    calculatedFvPatchVectorField(ptf),
    solidForceBoundary(),
    contactFaces()
{
    copyFrom(ptf);
}


Foam::frictionalContactFvPatchVectorField::frictionalContactFvPatchVectorField
(
    const frictionalContactFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    calculatedFvPatchVectorField(ptf, iF),
    solidForceBoundary(),
    contactFaces()
{
    copyFrom(ptf);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionalContactFvPatchVectorField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    calculatedFvPatchVectorField::autoMap(m);
    const frictionalContactFvPatchVectorField old(*this);
    mapFaces(old, m);
}


void Foam::frictionalContactFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    calculatedFvPatchVectorField::rmap(ptf, addr);

    const frictionalContactFvPatchVectorField& fcptf =
        refCast<const frictionalContactFvPatchVectorField>(ptf);
    forAll(addr, i)
    {
        copyFace(fcptf, i, addr[i]);
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "solidOutputFields.H"
#include "volPointInterpolation.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

static IOobject outputIO(const fvMesh& mesh, const word& name)
{
    return IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::NO_READ,
        IOobject::AUTO_WRITE
    );
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidOutputFields::solidOutputFields(const totalLagrangianSolid& solid)
:
    solid_(solid),
    sigma_
    (
        outputIO(solid.D().mesh(), "sigma"),
        solid.D().mesh(),
        dimensionedSymmTensor(dimPressure, Zero)
    ),
    sigmaEq_
    (
        outputIO(solid.D().mesh(), "sigmaEq"),
        solid.D().mesh(),
        dimensionedScalar(dimPressure, Zero)
    ),
    pointD_
    (
        outputIO(solid.D().mesh(), "pointD"),
        pointMesh::New(solid.D().mesh()),
        dimensionedVector(dimLength, Zero)
    )
{
    const fvMesh& mesh = solid.D().mesh();
    if (solid.laws().plastic())
    {
        epsilonPEq_.reset
        (
            new volScalarField
            (
                outputIO(mesh, "epsilonPEq"),
                mesh,
                dimensionedScalar(dimless, Zero)
            )
        );
    }
    if (solid.discretisation().inertia())
    {
        V_.reset
        (
            new volVectorField
            (
                outputIO(mesh, "V"),
                mesh,
                dimensionedVector(dimVelocity, Zero)
            )
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidOutputFields::update()
{
    const solidDiscretisation& disc = solid_.discretisation();

    symmTensorField sigma;
    scalarField epsilonP;
    disc.cellAverages(sigma, epsilonP);

    sigma_.primitiveFieldRef() = sigma;
    sigmaEq_.primitiveFieldRef() = sqrt(1.5*magSqr(dev(sigma)));
    sigma_.correctBoundaryConditions();
    sigmaEq_.correctBoundaryConditions();

    if (epsilonPEq_.valid())
    {
        epsilonPEq_->primitiveFieldRef() = epsilonP;
        epsilonPEq_->correctBoundaryConditions();
    }

    pointD_ = volPointInterpolation::New(solid_.D().mesh())
        .interpolate(solid_.D());

    if (V_.valid())
    {
        V_->primitiveFieldRef() = (disc.D0() - disc.D00())/disc.deltaT0();
        V_->correctBoundaryConditions();
    }
}


void Foam::solidOutputFields::report() const
{
    const solidDiscretisation& disc = solid_.discretisation();
    const fvMesh& mesh = solid_.D().mesh();

    disc.reportForcePatches();

    forAll(mesh.boundary(), patchi)
    {
        if (solid_.boundaries().kind(patchi) != solidBoundaries::FIXED)
        {
            continue;
        }
        const word& name = mesh.boundary()[patchi].name();
        const vector total(returnReduce(disc.reactionForce(patchi), sumOp<vector>()));

        Info<< "    reaction force on " << name << ": " << total << " N"
            << endl;

        if (Pstream::master())
        {
            const fileName dir
            (
                mesh.time().globalPath()/"postProcessing"/"solidForces"
            );
            mkDir(dir);
            const fileName file(dir/(name + ".dat"));
            const bool fresh = !isFile(file);
            OFstream os
            (
                file, IOstream::ASCII, IOstream::currentVersion,
                IOstream::UNCOMPRESSED, true
            );
            if (fresh)
            {
                os  << "# time Fx Fy Fz [N] (reaction on patch " << name
                    << ")" << nl;
            }
            os  << mesh.time().value() << ' ' << total.x() << ' '
                << total.y() << ' ' << total.z() << nl;
            os.flush();
            if (!os.good())
            {
                FatalErrorInFunction
                    << "Writing " << file << " failed (the disk may be"
                    << " full or the folder not writable)" << nl
                    << exit(FatalError);
            }
        }
    }

    if (disc.inertia())
    {
        // [S13b] reported so a mass-scaled run shows it stays quasi-static
        const vectorField vel((disc.D0() - disc.D00())/disc.deltaT0());
        Info<< "    kinetic energy "
            << 0.5*gSum(disc.inertiaDensity()*mesh.V()*magSqr(vel))
            << " J" << endl;
    }
}


// ************************************************************************* //

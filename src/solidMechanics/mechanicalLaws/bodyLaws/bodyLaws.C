/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "bodyLaws.H"
#include "polyMesh.H"
#include "strictDictionary.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyLaws::bodyLaws
(
    const dictionary& mechanicalProperties,
    const polyMesh& mesh
)
:
    laws_(),
    names_(),
    cellBody_(mesh.nCells(), -1)
{
    const dictionary& mp = mechanicalProperties;
    strictDictionary::check
    (
        mp,
        {
            "mechanicalLaw", "bodies", "massScaling", "volumetricAveraging",
            "volumetricAveragingWeight"
        },
        "mechanical properties"
    );
    if (!mp.found("bodies"))
    {
        laws_.setSize(1);
        laws_.set(0, mechanicalLaw::New(mp.subDict("mechanicalLaw")));
        names_ = wordList(1, "solid");
        cellBody_ = 0;
        return;
    }
    if (mp.found("mechanicalLaw"))
    {
        FatalIOErrorInFunction(mp)
            << "File " << mp.name() << " has both 'mechanicalLaw' and"
            << " 'bodies': give one law for the whole mesh (mechanicalLaw)"
            << " or one per cell zone (bodies { <zone> { mechanicalLaw"
            << " {...} } })" << nl << exit(FatalIOError);
    }

    // [C9] one law per cell zone
    const dictionary& bodies = mp.subDict("bodies");
    const cellZoneMesh& zones = mesh.cellZones();
    names_ = bodies.toc();
    if (names_.empty())
    {
        FatalIOErrorInFunction(bodies)
            << "Keyword 'bodies' in " << mp.name() << " lists no body;"
            << " expected one sub-dictionary per cell zone, e.g. "
            << "bodies { <zone> { mechanicalLaw {...} } }" << nl
            << exit(FatalIOError);
    }
    laws_.setSize(names_.size());
    forAll(names_, bodyi)
    {
        const word& zoneName = names_[bodyi];
        if (!bodies.isDict(zoneName))
        {
            FatalIOErrorInFunction(bodies)
                << "Entry '" << zoneName << "' of 'bodies' in " << mp.name()
                << " is not a dictionary; expected " << zoneName
                << " { mechanicalLaw { ... } }" << nl << exit(FatalIOError);
        }
        strictDictionary::check
        (
            bodies.subDict(zoneName), {"mechanicalLaw"}, "body " + zoneName
        );
        const label zonei = zones.findZoneID(zoneName);
        if (zonei < 0)
        {
            FatalIOErrorInFunction(bodies)
                << "Body '" << zoneName << "' in 'bodies' of " << mp.name()
                << " names no cell zone of the mesh; its cell zones are "
                << zones.names() << nl << exit(FatalIOError);
        }
        laws_.set
        (
            bodyi,
            mechanicalLaw::New
            (
                bodies.subDict(zoneName).subDict("mechanicalLaw")
            )
        );
        for (const label celli : zones[zonei])
        {
            if (cellBody_[celli] >= 0)
            {
                FatalIOErrorInFunction(bodies)
                    << "Cell " << celli << " at "
                    << mesh.cellCentres()[celli] << " is in the zones of"
                    << " bodies '" << names_[cellBody_[celli]] << "' and '"
                    << zoneName << "' (bodies of " << mp.name() << "); a cell"
                    << " belongs to one body" << nl << exit(FatalIOError);
            }
            cellBody_[celli] = bodyi;
        }
    }

    // Every cell in one body
    labelList orphans;
    forAll(cellBody_, celli)
    {
        if (cellBody_[celli] < 0)
        {
            orphans.append(celli);
        }
    }
    const label nOrphans = returnReduce(orphans.size(), sumOp<label>());
    if (nOrphans)
    {
        wordList unlisted;
        for (const word& z : zones.names())
        {
            if (!bodies.found(z))
            {
                unlisted.append(z);
            }
        }
        FatalIOErrorInFunction(bodies)
            << nOrphans << " cells lie in no cell zone listed in 'bodies' of "
            << mp.name() << ": cell zones without a law " << unlisted
            << " (listed: " << names_ << "; cell zones of the mesh: "
            << zones.names() << ")";
        if (orphans.size())
        {
            FatalIOError
                << "; e.g. cell " << orphans[0] << " at "
                << mesh.cellCentres()[orphans[0]];
        }
        FatalIOError << nl << exit(FatalIOError);
    }

    forAll(names_, bodyi)
    {
        Info<< "Body " << names_[bodyi] << ": "
            << returnReduce(mesh.cellZones()[names_[bodyi]].size(), sumOp<label>())
            << " cells, law " << laws_[bodyi].type() << ", E "
            << laws_[bodyi].E() << " Pa, nu " << laws_[bodyi].nu() << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyLaws::planeStrainModulus
(
    const labelUList& cells
) const
{
    // a processor without cells of the patch gives no modulus, unless there
    // is one body
    scalar Eprime = -1;
    if (cells.size() || laws_.size() == 1)
    {
        const mechanicalLaw& l = cells.size() ? cellLaw(cells[0]) : laws_[0];
        Eprime = l.E()/(1 - sqr(l.nu()));
    }
    return returnReduce(Eprime, maxOp<scalar>());
}


bool Foam::bodyLaws::plastic() const
{
    for (const mechanicalLaw& l : laws_)
    {
        if (l.plastic())
        {
            return true;
        }
    }
    return false;
}


Foam::scalar Foam::bodyLaws::maxE() const
{
    scalar E = 0;
    for (const mechanicalLaw& l : laws_)
    {
        E = max(E, l.E());
    }
    return E;
}


// ************************************************************************* //

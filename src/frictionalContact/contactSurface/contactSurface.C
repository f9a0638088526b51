/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "contactSurface.H"
#include "fvMesh.H"
#include "volMesh.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::contactSurface::maxCellDepth(const fvPatch& p)
{
    const scalarField& V = p.boundaryMesh().mesh().V();
    scalar hMax = 0;
    forAll(p.faceCells(), i)
    {
        hMax = max(hMax, V[p.faceCells()[i]]/p.magSf()[i]);
    }
    reduce(hMax, maxOp<scalar>());
    return hMax;
}


Foam::scalar Foam::contactSurface::readSearchDistance
(
    const dictionary& dict,
    const fvPatch& p
)
{
    const scalar d =
        dict.lookupOrDefault<scalar>
        (
            "searchDistance", 2*max(maxCellDepth(p), SMALL)
        );
    if (!(d > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'searchDistance' in dictionary " << dict.name()
            << " must be > 0, got " << d << nl << exit(FatalIOError);
    }
    return d;
}


// ************************************************************************* //

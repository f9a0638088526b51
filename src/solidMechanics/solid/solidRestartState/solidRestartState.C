/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "solidRestartState.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidRestartState::solidRestartState(const Time& runTime)
:
    IOdictionary
    (
        IOobject
        (
            "solidState",
            runTime.timeName(),
            "uniform",
            runTime,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        )
    ),
    read_(found("time"))
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

bool Foam::solidRestartState::expected(const Time& runTime)
{
    return isFile(runTime.timePath()/"uniform"/"solidState", false);
}


void Foam::solidRestartState::require
(
    const objectRegistry& db,
    const word& name,
    const string& holds
)
{
    const Time& runTime = db.time();
    const IOobject io(name, runTime.timeName(), db);
    if (!expected(runTime) || isFile(io.objectPath()))
    {
        return;
    }
    FatalErrorInFunction
        << "Restart from time " << runTime.timeName() << ": the file "
        << io.objectPath() << " is missing from the time directory "
        << runTime.timePath() << ". It holds " << holds.c_str() << ", which"
        << " the next step starts from: without it the run would not"
        << " continue the one written. Restore the file, or restart from"
        << " another complete time" << nl << exit(FatalError);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::solidRestartState::writeData(Ostream& os) const
{
    const label precision = os.precision(17);
    const bool ok = IOdictionary::writeData(os);
    os.precision(precision);
    return ok;
}


// ************************************************************************* //

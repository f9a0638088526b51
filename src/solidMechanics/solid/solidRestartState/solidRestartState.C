/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam, GPL-3.0-or-later.
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
            IOobject::AUTO_WRITE
        )
    ),
    read_(found("time"))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::solidRestartState::writeData(Ostream& os) const
{
    const label precision = os.precision(17);
    const bool ok = IOdictionary::writeData(os);
    os.precision(precision);
    return ok;
}


// ************************************************************************* //

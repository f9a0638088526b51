/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "timeControls.H"
#include "IFstream.H"
#include "dictionary.H"
#include "strictDictionary.H"
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- A number entry of controlDict, finite; readEntry reports a missing one
static scalar finiteEntry(const dictionary& dict, const word& key)
{
    const scalar value = dict.get<scalar>(key);
    if (!std::isfinite(value))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' in " << dict.name() << " is "
            << value << "; expected a finite number" << nl
            << exit(FatalIOError);
    }
    return value;
}

//- A keyword of controlDict one or two letters from one that OpenFOAM's
//  Time (or its function objects and switches) reads is taken for a
//  misspelling of it: Time ignores an unknown keyword, so 'writePrecison'
//  would silently write 6 digits. Other keywords stay the user's
//  variables ($name elsewhere in the file), which controlDict commonly
//  holds
static void checkNearMisses(const dictionary& dict)
{
    static const wordList known
    {
        "FoamFile", "application", "startFrom", "startTime", "stopAt",
        "endTime", "deltaT", "writeControl", "writeInterval",
        "writeFrequency", "purgeWrite", "writeFormat", "writePrecision",
        "writeVersion", "writeCompression", "timeFormat", "timePrecision",
        "runTimeModifiable", "adjustTimeStep", "maxCo", "maxDeltaT",
        "graphFormat", "functions", "libs", "DebugSwitches", "InfoSwitches",
        "OptimisationSwitches", "DimensionSets", "DimensionedConstants",
        "fileHandler", "profiling", "printExecutionFormat",
        "cacheTemporaryObjects"
    };
    for (const word& key : dict.toc())
    {
        if (known.found(key))
        {
            continue;
        }
        const word meant = strictDictionary::nearest(key, known);
        if (!meant.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << key << "' in " << dict.name()
                << ". Did you mean '" << meant << "'? (OpenFOAM's Time would"
                << " ignore it and take its default)" << nl
                << exit(FatalIOError);
        }
    }
}

} // End namespace Foam


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::checkTimeControls(const argList& args)
{
    const fileName path(args.globalPath()/"system"/"controlDict");
    IFstream is(path);
    if (!is.good())
    {
        // Time names the missing file itself
        return;
    }
    const dictionary dict(is);
    checkNearMisses(dict);

    const scalar deltaT = finiteEntry(dict, "deltaT");
    if (!(deltaT > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'deltaT' in " << dict.name() << " is " << deltaT
            << "; expected the time step, > 0 [s]" << nl
            << exit(FatalIOError);
    }

    const scalar endTime = finiteEntry(dict, "endTime");
    if (dict.lookupOrDefault<word>("startFrom", "latestTime") == "startTime")
    {
        const scalar startTime = finiteEntry(dict, "startTime");
        if (endTime < startTime)
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'endTime' in " << dict.name() << " is "
                << endTime << ", before 'startTime' " << startTime
                << "; expected endTime >= startTime" << nl
                << exit(FatalIOError);
        }
    }

    const word control(dict.lookupOrDefault<word>("writeControl", "timeStep"));
    const scalar interval = finiteEntry(dict, "writeInterval");
    const bool steps = control == "timeStep";
    if (steps ? !(interval >= 1) : !(interval > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'writeInterval' in " << dict.name() << " is "
            << interval << "; expected "
            << (steps ? "a number of steps >= 1" : "an interval > 0")
            << " with writeControl " << control << nl
            << exit(FatalIOError);
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    frictionLawDriver: input checks and plots shared by the modes.

\*---------------------------------------------------------------------------*/

#include "driverModes.H"
#include "frictionParameters.H"
#include "OFstream.H"
#include <unistd.h>
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::driverModes::contactPressure(const dictionary& dict)
{
    return frictionParameters::positive(dict, "contactPressure");
}


Foam::scalar Foam::driverModes::shearYield
(
    const dictionary& dict,
    const frictionLaw& law
)
{
    return
        law.needsShearYield()
      ? frictionParameters::positive(dict, "shearYield")
      : -1;
}


Foam::scalar Foam::driverModes::nonNegative
(
    const dictionary& d,
    const word& key,
    const bool strict
)
{
    return
        strict
      ? frictionParameters::positive(d, key)
      : frictionParameters::nonNegative(d, key);
}


Foam::scalarList Foam::driverModes::logRange
(
    const dictionary& d,
    const word& key,
    const label n
)
{
    const scalarList r(d.get<scalarList>(key));
    if (r.size() != 2 || !(r[0] > 0) || !(r[1] >= r[0]) || n < 1)
    {
        FatalIOErrorInFunction(d)
            << "keyword '" << key << "' must be (lo hi) with 0 < lo <= hi,"
            << " got " << r << exit(FatalIOError);
    }
    scalarList v(n);
    forAll(v, i)
    {
        v[i] = n > 1 ? r[0]*std::pow(r[1]/r[0], scalar(i)/(n - 1)) : r[0];
    }
    return v;
}


void Foam::driverModes::checkWritable
(
    const dictionary& dict,
    const word& key,
    const fileName& path
)
{
    const fileName dir(path.path().empty() ? fileName(".") : path.path());
    const bool ok =
        !isDir(path) && isDir(dir) && ::access(dir.c_str(), W_OK) == 0
     && (!exists(path) || ::access(path.c_str(), W_OK) == 0);
    if (!ok)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' in " << dict.name() << ": cannot"
            << " write " << path << " ("
            << (
                   isDir(path) ? "it is a folder"
                 : !isDir(dir) ? "no folder " + dir
                 : "not writable"
               ).c_str()
            << "); expected a file in an existing, writable folder" << nl
            << exit(FatalIOError);
    }
}


void Foam::driverModes::checkWritten(OFstream& os)
{
    os.flush();
    if (!os.good())
    {
        FatalErrorInFunction
            << "Writing " << os.name() << " failed (the disk may be full)"
            << nl << exit(FatalError);
    }
}


void Foam::driverModes::plot
(
    const dictionary& dict,
    const fileName& output,
    const std::string& script
)
{
    if (!dict.getOrDefault<bool>("plot", true))
    {
        return;
    }
    if (Foam::system("command -v gnuplot > /dev/null 2>&1") != 0)
    {
        WarningInFunction << "gnuplot not found: no plot written" << endl;
        return;
    }
    const fileName png = output.lessExt() + ".png";
    const fileName gp = output.lessExt() + ".gp";
    {
        OFstream os(gp);
        os  << "set terminal pngcairo size 900,900\n"
            << "set output '" << png.c_str() << "'\n"
            << "set grid\n" << script.c_str();
        driverModes::checkWritten(os);
    }
    if (Foam::system("gnuplot '" + gp + "'") == 0)
    {
        Info<< "Plot: " << png << endl;
    }
    else
    {
        WarningInFunction << "gnuplot failed on " << gp << endl;
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

\*---------------------------------------------------------------------------*/

#include "reportFiles.H"
#include "OSspecific.H"
#include "error.H"
#include <unistd.h>

// * * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

void Foam::reportFiles::checkWritable
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


void Foam::reportFiles::checkWritten(OFstream& os)
{
    os.flush();
    if (!os.good())
    {
        FatalErrorInFunction
            << "Writing " << os.name() << " failed (the disk may be full or"
            << " the folder not writable)" << nl << exit(FatalError);
    }
}


bool Foam::reportFiles::gnuplot
(
    const fileName& base,
    const std::string& script,
    const label width,
    const label height
)
{
    if (Foam::system("command -v gnuplot > /dev/null 2>&1") != 0)
    {
        WarningInFunction << "gnuplot not found: no plot written" << endl;
        return false;
    }
    const fileName png(base + ".png");
    const fileName gp(base + ".gp");
    {
        OFstream os(gp);
        os  << "set terminal pngcairo size " << width << ',' << height << nl
            << "set output '" << png.c_str() << "'" << nl
            << "set grid" << nl << script.c_str();
        checkWritten(os);
    }
    if (Foam::system("gnuplot '" + gp + "' > /dev/null 2>&1") != 0)
    {
        WarningInFunction << "gnuplot failed on " << gp << endl;
        return false;
    }
    Info<< "Plot: " << png << endl;
    return true;
}


// ************************************************************************* //

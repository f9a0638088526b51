/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    frictionLawDriver mode fit: least-squares fit of named parameters of
    the law to a measured friction record, Levenberg-Marquardt, with
    confidence intervals (doc/theory.md [F34]). The law dictionary gives
    the start values.

        fit
        {
            record          "measured.dat"; // rows: time [s], slip rate or
                                            // load-point velocity [m/s],
                                            // friction coefficient [-]
            columns         (0 1 2);        // optional: which columns
            drive           slipRate;       // or loadPointVelocity
            stiffness       1e9;            // [Pa/m], loadPointVelocity
            mass            0;              // [kg/m^2], loadPointVelocity
            parameters      (a b L);        // keywords of the law
                                            // (sub-dictionary: lub/key)
            runInTime       300;            // steady sliding at row 0 first
            runInSteps      100;            // ... in so many steps
            subSteps        1;              // steps per record interval
            confidenceLevel 0.95;
            lawDictionary   "fittedLawDict";
        }

    Writes the table (time, measured mu, mu of the start values, mu of the
    fit), the fitted law dictionary and a figure of the three.

\*---------------------------------------------------------------------------*/

#include "driverModes.H"
#include "frictionFit.H"
#include "lawParameters.H"
#include "frictionDataTable.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::driverModes::fit(const dictionary& dict, const fileName& output)
{
    const dictionary& d = dict.subDict("fit");
    const dictionary& lawDict = dict.subDict("law");
    const frictionDataTable data
    (
        d, "record", d.getOrDefault<labelList>("columns", labelList({0, 1, 2}))
    );

    frictionFit::settings s;
    s.pressure = contactPressure(dict);
    const word drive(d.get<word>("drive"));
    if (drive == "loadPointVelocity")
    {
        s.drive = frictionFit::LOAD_POINT;
        s.stiffness = nonNegative(d, "stiffness", true);
        s.mass = d.found("mass") ? nonNegative(d, "mass") : 0;
    }
    else if (drive != "slipRate")
    {
        FatalIOErrorInFunction(d)
            << "keyword 'drive' must be slipRate or loadPointVelocity, got '"
            << drive << "'" << exit(FatalIOError);
    }
    s.runInTime = d.found("runInTime") ? nonNegative(d, "runInTime") : 0;
    s.subSteps = d.getOrDefault<label>("subSteps", 1);
    s.runInSteps = d.getOrDefault<label>("runInSteps", 100);
    const scalar level = d.getOrDefault<scalar>("confidenceLevel", 0.95);
    if (s.subSteps < 1 || s.runInSteps < 1 || !(level > 0 && level < 1))
    {
        FatalIOErrorInFunction(d)
            << "keywords 'subSteps' >= 1, 'runInSteps' >= 1 and"
            << " 'confidenceLevel' in (0, 1) required, got " << s.subSteps
            << ", " << s.runInSteps << " and " << level
            << exit(FatalIOError);
    }

    frictionFit::record rec;
    rec.t = data.column(0);
    rec.drive = data.column(1);
    rec.mu = data.column(2);
    const frictionFit f
    (
        lawDict, lawParameters::names(d, "parameters"), rec, s, d
    );
    const frictionFit::result r = f.fit(level);

    const scalarField muStart(f.simulate(f.start()));
    const scalarField muFit(f.simulate(r.value));
    {
        OFstream os(output);
        os.precision(12);
        os  << "# frictionLawDriver fit of " << data.file() << " (doc/theory.md"
            << " [F34]), law " << lawDict.get<word>("type") << nl
            << "# rms residual " << r.rms << " with " << r.dof
            << " degrees of freedom" << nl
            << "# time[s] muMeasured[-] muStart[-] muFit[-]" << nl;
        forAll(rec.t, i)
        {
            os  << rec.t[i] << ' ' << rec.mu[i] << ' ' << muStart[i] << ' '
                << muFit[i] << nl;
        }
        reportFiles::checkWritten(os);
    }

    const fileName lawFile
    (
        d.getOrDefault<fileName>("lawDictionary", "fittedLawDict")
    );
    reportFiles::checkWritable(d, "lawDictionary", lawFile);
    {
        OFstream os(lawFile);
        os.precision(10);
        os  << "// Fitted by frictionLawDriver to " << data.file()
            << " (doc/theory.md [F34])" << nl;
        forAll(r.names, j)
        {
            os  << "// " << r.names[j] << " = " << r.value[j] << " +- "
                << r.halfWidth[j] << " (" << label(std::round(100*level))
                << " % interval; start " << r.start[j] << ")" << nl;
        }
        f.lawDict(r.value).write(os, false);
        reportFiles::checkWritten(os);
    }

    Info<< "Fit of " << r.names << " to " << rec.t.size() << " rows ("
        << r.nEvaluations << " evaluations, status " << r.status << "), rms"
        << " residual " << r.rms << ":" << nl;
    forAll(r.names, j)
    {
        Info<< "    " << r.names[j] << " = " << r.value[j] << " +- "
            << r.halfWidth[j] << " (" << label(std::round(100*level))
            << " % interval; start " << r.start[j] << ")" << nl;
    }
    Info<< "Wrote " << output << " and the law to " << lawFile << endl;

    const std::string t = "'" + output + "'";
    plot
    (
        dict, output,
        "set xlabel 'time [s]'\nset ylabel 'mu = tT/tN [-]'\n"
        "set title 'least-squares fit of " + std::string(lawDict.get<word>("type"))
      + "'\nplot " + t + " u 1:2 w p pt 7 ps 0.5 t 'record', " + t
      + " u 1:3 w l lw 1 dt 2 t 'start values', " + t
      + " u 1:4 w l lw 2 t 'fit'\n"
    );
}


// ************************************************************************* //

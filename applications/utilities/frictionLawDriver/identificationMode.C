/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    frictionLawDriver mode identification: the relaxation law read off
    stick-slip measurements (doc/theory.md [F32]); no 'law' needed.

        identification
        {
            table           "measured.dat"; // rows: V [m/s], friction,
                                            // k_c [Pa/m], omega_c [rad/s]
            columns         (0 1 2 3);      // optional: which columns
            friction        coefficient;    // or stress [Pa]
            normalStress    1e4;            // sigma [Pa]
            mass            0;              // M [kg/m^2] of the block
            VStar           1e-6;           // V* [m/s]
            frictionSlope   local;          // or logLinear
            confidenceLevel 0.95;
            lawDictionary   "relaxationLawDict";
        }

    Writes the table (V, V/V*, t** phi_ss, L_a and their fits, a and b
    row by row), the law dictionary and a log-log figure of t** phi_ss
    and L_a against V/V* with the fitted power laws.

\*---------------------------------------------------------------------------*/

#include "driverModes.H"
#include "relaxationIdentification.H"
#include "frictionDataTable.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::driverModes::identification
(
    const dictionary& dict,
    const fileName& output
)
{
    const dictionary& d = dict.subDict("identification");
    const frictionDataTable data
    (
        d, "table",
        d.getOrDefault<labelList>("columns", labelList({0, 1, 2, 3}))
    );
    const scalar sigma = nonNegative(d, "normalStress", true);
    const scalar M = d.found("mass") ? nonNegative(d, "mass") : 0;
    const scalar VStar = d.getOrDefault<scalar>("VStar", 1e-6);
    const scalar level = d.getOrDefault<scalar>("confidenceLevel", 0.95);
    if (!(VStar > 0) || !(level > 0 && level < 1))
    {
        FatalIOErrorInFunction(d)
            << "keywords 'VStar' > 0 and 'confidenceLevel' in (0, 1)"
            << " required, got " << VStar << " and " << level
            << exit(FatalIOError);
    }
    const word friction(d.get<word>("friction"));
    const word slope(d.getOrDefault<word>("frictionSlope", "local"));
    if
    (
        (friction != "coefficient" && friction != "stress")
     || (slope != "local" && slope != "logLinear")
    )
    {
        FatalIOErrorInFunction(d)
            << "keyword 'friction' must be coefficient or stress and"
            << " 'frictionSlope' local or logLinear, got " << friction
            << " and " << slope << exit(FatalIOError);
    }

    scalarField Fss(data.column(1));
    if (friction == "coefficient")
    {
        Fss *= sigma;
    }
    const relaxationIdentification id
    (
        data.column(0), Fss, data.column(2), data.column(3), M, sigma,
        VStar, level, slope == "logLinear", d, "table", data.file()
    );

    const relaxationIdentification::line& f = id.tauFit();
    {
        OFstream os(output);
        os.precision(10);
        os  << "# frictionLawDriver identification of " << data.file()
            << " (doc/theory.md [F32]): mass " << M << " kg/m^2, sigma "
            << sigma << " Pa, V* " << VStar << " m/s" << nl
            << "# fit: t** phi_ss = 10^" << f.c0 << " (V/V*)^" << f.c1
            << ", L_a = 10^" << f.c0 + std::log10(VStar) << " (V/V*)^"
            << 1 + f.c1 << nl
            << "# V[m/s] V/V*[-] tStarPhiSs[s] La[m] tStarPhiSsFit[s]"
            << " LaFit[m] a[-] b[-] dFssdV[Pa.s/m]" << nl;
        forAll(id.V(), i)
        {
            const scalar x = id.V()[i]/VStar;
            const scalar fit = std::pow(10.0, f.c0)*std::pow(x, f.c1);
            os  << id.V()[i] << ' ' << x << ' ' << id.tau()[i] << ' '
                << id.La()[i] << ' ' << fit << ' ' << id.V()[i]*fit << ' '
                << id.a()[i] << ' ' << id.b()[i] << ' ' << id.dFssdV()[i]
                << nl;
        }
        reportFiles::checkWritten(os);
    }

    const fileName lawFile
    (
        d.getOrDefault<fileName>("lawDictionary", "relaxationLawDict")
    );
    reportFiles::checkWritable(d, "lawDictionary", lawFile);
    {
        OFstream os(lawFile);
        os.precision(10);
        id.writeLaw(os);
        reportFiles::checkWritten(os);
    }

    const label pct = label(std::round(100*level));
    Info<< "Identified relaxation law (" << pct << " % intervals):" << nl
        << "    t** = " << id.tStar().value << " s  ["
        << id.tStar().interval.first() << ", "
        << id.tStar().interval.second() << "]" << nl
        << "    gamma = " << id.gamma().value << "  ["
        << id.gamma().interval.first() << ", "
        << id.gamma().interval.second() << "]" << nl
        << "    L = V* t** = " << VStar*id.tStar().value << " m" << nl
        << "    a = " << id.aEstimate().value << "  ["
        << id.aEstimate().interval.first() << ", "
        << id.aEstimate().interval.second() << "]" << nl
        << "    b = " << id.bEstimate().value << "  ["
        << id.bEstimate().interval.first() << ", "
        << id.bEstimate().interval.second() << "]" << nl
        << "    mu* = " << id.muStar().value << nl
        << "Wrote " << output << " and the law to " << lawFile << endl;

    const std::string t = "'" + output + "'";
    plot
    (
        dict, output,
        "set multiplot layout 2,1 title 'relaxation law from stick-slip"
        " onsets'\nset logscale xy\nset format y '10^{%L}'\n"
        "set format x '10^{%L}'\nset xlabel 'V/V*'\nset key left top\n"
        "set ylabel 't** phi_{ss} [s]'\n"
        "plot " + t + " u 2:3 w p pt 7 ps 1.5 t 'from k_c, omega_c, F_{ss}',"
        " " + t + " u 2:5 w l lw 2 t 'power-law fit'\n"
        "set ylabel 'L_a [m]'\n"
        "plot " + t + " u 2:4 w p pt 7 ps 1.5 t 'L_a = V t** phi_{ss}', "
      + t + " u 2:6 w l lw 2 t 'power-law fit'\nunset multiplot\n"
    );
}


// ************************************************************************* //

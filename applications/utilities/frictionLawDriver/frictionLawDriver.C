/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Application
    frictionLawDriver

Group
    grpTriboFoamUtilities

Description
    Drives one contact point of any friction law, read from a dictionary,
    with no mesh (doc/theory.md section 8.6):
      mode prescribed:   a slip-rate history, any Function1 of time
                         (constant, table with steps, holds, reversals...);
      mode springSlider: a block of mass per unit area M (may be 0) under
                         the contact pressure, pulled through a spring k
                         whose end moves at V ([F22]).
    Writes a table (time, slip, slip rate, tN, tT, mu, contact age,
    lubrication weight, status) and, if gnuplot is found, a PNG plot.
    Use it to calibrate a law against a friction test. SI units.

Usage
    frictionLawDriver [-dict frictionLawDriverDict]

    See applications/utilities/frictionLawDriver/frictionLawDriverDict and
    tutorials/frictionLawDriver.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "frictionPointDriver.H"

using namespace Foam;

// Gnuplot script for the table 'data', written next to it
static void plot(const fileName& data, const word& mode)
{
    if (Foam::system("command -v gnuplot > /dev/null 2>&1") != 0)
    {
        WarningInFunction
            << "gnuplot not found: no plot written" << endl;
        return;
    }
    const fileName png = data.lessExt() + ".png";
    const fileName gp = data.lessExt() + ".gp";
    {
        OFstream os(gp);
        os  << "set terminal pngcairo size 900,900\n"
            << "set output '" << png.c_str() << "'\n"
            << "set multiplot layout 3,1 title 'frictionLawDriver: "
            << mode << "'\n"
            << "set xlabel 'time [s]'\nset grid\n"
            << "set ylabel 'mu = tT/tN [-]'\n"
            << "plot '" << data.c_str() << "' u 1:6 w l lw 2 notitle\n"
            << "set ylabel '|slip rate| [m/s]'\nset logscale y\n"
            << "plot '" << data.c_str()
            << "' u 1:(abs($3) > 0 ? abs($3) : 1/0) w l lw 2 notitle\n"
            << "unset logscale y\nset ylabel 'contact age (state)'\n"
            << "plot '" << data.c_str() << "' u 1:7 w l lw 2 notitle\n"
            << "unset multiplot\n";
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


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Drive a point-wise friction law through a slip-rate history or a"
        " spring-slider; writes a table and a PNG plot"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::noCheckProcessorDirectories();
    argList::addOption
    (
        "dict",
        "file",
        "driver dictionary (default: frictionLawDriverDict)"
    );

    argList args(argc, argv);

    const fileName dictFile
    (
        args.getOrDefault<fileName>("dict", "frictionLawDriverDict")
    );
    IFstream is(dictFile);
    if (!is.good())
    {
        FatalErrorInFunction
            << "cannot open driver dictionary " << dictFile
            << exit(FatalError);
    }
    const dictionary dict(is);

    const dictionary& lawDict = dict.subDict("law");
    autoPtr<frictionLaw> law = frictionLaw::New(lawDict);

    const scalar p = dict.get<scalar>("contactPressure");
    if (!(p > 0))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'contactPressure' must be > 0, got " << p
            << exit(FatalIOError);
    }
    const scalar dt = dict.get<scalar>("deltaT");
    const scalar endTime = dict.get<scalar>("endTime");
    const label every = dict.getOrDefault<label>("writeInterval", 1);
    const fileName output
    (
        dict.getOrDefault<fileName>("output", "frictionLawDriver.dat")
    );
    const word mode(dict.get<word>("mode"));

    frictionPointDriver drv(*law, p);
    DynamicList<frictionPointDriver::sample> rows;

    if (mode == "prescribed")
    {
        const dictionary& d = dict.subDict("prescribed");
        autoPtr<Function1<scalar>> v = Function1<scalar>::New("slipRate", d);

        // Optional run-in at the initial rate, to start from steady sliding
        const scalar runIn = d.getOrDefault<scalar>("runInTime", 0);
        if (runIn > 0)
        {
            const scalar v0 = v->value(0);
            const label n = label(std::ceil(runIn/dt));
            for (label i = 0; i < n; ++i)
            {
                drv.step(drv.slip() + v0*dt, dt);
            }
            drv.setTime(0);
        }

        if (law->nRateStates() >= 0)
        {
            scalar vMin = GREAT, vMax = 0;
            for (label i = 0; i <= 1000; ++i)
            {
                const scalar av = mag(v->value(endTime*i/1000));
                if (av > 0) { vMin = min(vMin, av); vMax = max(vMax, av); }
            }
            if (vMax > 0)
            {
                law->checkWellPosedness(vMin, max(vMax, 1.001*vMin), p, p);
            }
        }

        drv.runPrescribed(v(), endTime, dt, rows, every);
    }
    else if (mode == "springSlider")
    {
        const dictionary& d = dict.subDict("springSlider");
        const scalar M = d.getOrDefault<scalar>("mass", 0);
        const scalar k = d.get<scalar>("stiffness");
        const scalar V = d.get<scalar>("loadPointVelocity");
        if (M < 0 || !(k > 0))
        {
            FatalIOErrorInFunction(d)
                << "keywords 'mass' >= 0 and 'stiffness' > 0 required, got "
                << M << " and " << k << exit(FatalIOError);
        }

        // Run-in at V (steady sliding), then perturb the state
        const scalar runIn = d.getOrDefault<scalar>("runInTime", 0);
        const label n = label(std::ceil(runIn/dt));
        for (label i = 0; i < n; ++i)
        {
            drv.step(drv.slip() + V*dt, dt);
        }
        drv.setTime(0);
        drv.setSpringStretch(drv.last().tT.x()/k);
        // The law's first own state variable (contact age, phi)
        const scalar eps = d.getOrDefault<scalar>("statePerturbation", 0);
        for (const frictionStateEntry& e : law->stateLayout().entries())
        {
            if
            (
                eps != 0 && e.kind == frictionStateEntry::SCALAR
             && e.slot >= frictionState::firstLawSlot
            )
            {
                drv.state().scalarSlot(e.slot) *= 1 + eps;
                break;
            }
        }

        law->checkWellPosedness(1e-2*mag(V), 1e2*mag(V), p, p);

        drv.runSpringSlider(M, k, V, endTime, dt, rows, every);
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'mode' must be 'prescribed' or 'springSlider', got '"
            << mode << "'" << exit(FatalIOError);
    }

    {
        OFstream os(output);
        os.precision(12);
        os  << "# frictionLawDriver, law " << lawDict.get<word>("type")
            << ", mode " << mode << ", contactPressure " << p << nl;
        drv.writeHeader(os);
        drv.write(os, rows);
    }
    Info<< "Wrote " << rows.size() << " rows to " << output << endl;

    frictionLaw::reportIterationLimitHits();

    if (dict.getOrDefault<bool>("plot", true))
    {
        plot(output, mode);
    }

    Info<< "End" << endl;
    return 0;
}

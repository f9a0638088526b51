/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    frictionLawDriver mode stability: the critical stiffness k_c(V) and
    frequency omega_c(V) of steady sliding for any law with a rate form,
    for one or several block masses (doc/theory.md [F31]).

        stability
        {
            loadPointVelocities (1e-7 1e-4);    // [m/s], log spaced
            nVelocities         31;
            masses              (0 1e3);        // [kg/m^2]
        }

    Table: V, steady friction F_ss and mu_ss, F_ss', direct effect F_v,
    then k_c [Pa/m], omega_c [rad/s] and the kind (0 Hopf, 1 stable for
    every k, 2 unstable for every k) per mass.

\*---------------------------------------------------------------------------*/

#include "driverModes.H"
#include "slidingStability.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::driverModes::stability
(
    const dictionary& dict,
    const frictionLaw& law,
    const fileName& output
)
{
    const scalar p = contactPressure(dict);
    const dictionary& d = dict.subDict("stability");
    const scalarList V
    (
        logRange(d, "loadPointVelocities", d.get<label>("nVelocities"))
    );
    const scalarList masses(d.getOrDefault<scalarList>("masses", {0}));
    forAll(masses, j)
    {
        if (!(masses[j] >= 0))
        {
            FatalIOErrorInFunction(d)
                << "keyword 'masses': a block mass must be >= 0, got "
                << masses[j] << exit(FatalIOError);
        }
    }

    const slidingStability stab(law, p);
    {
        OFstream os(output);
        os.precision(12);
        os  << "# frictionLawDriver stability, law "
            << dict.subDict("law").get<word>("type") << ", contactPressure "
            << p << " Pa (doc/theory.md [F31])" << nl
            << "# V[m/s] Fss[Pa] muSs[-] dFssdV[Pa.s/m] Fv[Pa.s/m]";
        for (const scalar M : masses)
        {
            os  << " kc_M" << M << "[Pa/m] omegac_M" << M << "[rad/s] kind_M"
                << M;
        }
        os  << nl;
        for (const scalar v : V)
        {
            for (label j = 0; j < masses.size(); ++j)
            {
                const slidingStability::critical c =
                    stab.criticalStiffness(v, masses[j]);
                if (j == 0)
                {
                    os  << v << ' ' << c.lin.Fss << ' ' << c.lin.Fss/p << ' '
                        << c.lin.dFssdV << ' ' << c.lin.Fv;
                }
                os  << ' ' << c.kc << ' ' << c.omegac << ' ' << c.kind;
            }
            os  << nl;
        }
        reportFiles::checkWritten(os);
    }
    Info<< "Wrote k_c and omega_c at " << V.size() << " velocities for "
        << masses.size() << " masses to " << output << endl;

    const std::string data = "'" + output + "'";
    std::string kc = "plot ", om = "plot ";
    forAll(masses, j)
    {
        const std::string title = "M = " + std::string(name(masses[j]))
          + " kg/m^2";
        const std::string c = std::to_string(6 + 3*j);
        const std::string sep = j ? ", " : "";
        kc += sep + data + " u 1:($" + std::to_string(8 + 3*j) + " == 0 ? $"
          + c + " : 1/0) w lp lw 2 t '" + title + "'";
        om += sep + data + " u 1:($" + std::to_string(8 + 3*j) + " == 0 ? $"
          + std::to_string(7 + 3*j) + " : 1/0) w lp lw 2 t '" + title + "'";
    }
    plot
    (
        dict, output,
        "set multiplot layout 2,1 title 'stability of steady sliding: "
      + dict.subDict("law").get<word>("type") + "'\n"
        "set logscale xy\nset format xy '10^{%L}'\nset key left top\n"
        "set xlabel 'load-point velocity V [m/s]'\n"
        "set ylabel 'critical stiffness k_c [Pa/m]'\n" + kc + "\n"
        "set ylabel 'frequency omega_c [rad/s]'\n" + om + "\n"
        "unset multiplot\n"
    );
}


// ************************************************************************* //

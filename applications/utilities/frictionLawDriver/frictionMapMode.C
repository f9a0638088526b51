/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    frictionLawDriver mode frictionMap: the boundary friction map of the
    lubricated law, steady friction coefficient against sliding speed for
    several film thicknesses and contact pressures (doc/theory.md [F33]),
    with the regime of each point (boundary, mixed, hydrodynamic, from the
    lubrication weight) and the sign of the instantaneous rate
    sensitivity [F21] of the published form and of the film-memory
    variant [F30].

        frictionMap
        {
            slipRates           (1e-9 1);       // [m/s], log spaced
            nSlipRates          121;
            filmThicknessParameter lubrication/filmThickness;   // default
            filmThicknesses     (0 1e-7 1e-6 1e-5);     // [m]
            contactPressures    (1e7 1e8);      // [Pa]
            filmMemoryDistance  5e-6;           // [m] of the variant
        }

    Table: tN, D, v, mu_ss, alpha_ss, regime (0 boundary alpha < 0.1,
    1 mixed, 2 hydrodynamic alpha > 0.9), d tT/d ln v of the published
    form and of the film-memory variant [Pa].

\*---------------------------------------------------------------------------*/

#include "driverModes.H"
#include "lawParameters.H"
#include "quietMessages.H"
#include "OFstream.H"
#include "primitiveEntry.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::driverModes::frictionMap
(
    const dictionary& dict,
    const fileName& output
)
{
    const dictionary& d = dict.subDict("frictionMap");
    const dictionary& lawDict = dict.subDict("law");
    const scalarList v(logRange(d, "slipRates", d.get<label>("nSlipRates")));
    const scalarList D(d.get<scalarList>("filmThicknesses"));
    const scalarList tN(d.get<scalarList>("contactPressures"));
    const word Dname
    (
        lawParameters::name
        (
            d, "filmThicknessParameter", "lubrication/filmThickness"
        )
    );
    const scalar Df = nonNegative(d, "filmMemoryDistance", true);
    lawParameters::get(lawDict, Dname, d, "filmThicknessParameter");
    for (const scalar p : tN)
    {
        if (!(p > 0))
        {
            FatalIOErrorInFunction(d)
                << "keyword 'contactPressures': must be > 0, got " << p
                << exit(FatalIOError);
        }
    }

    OFstream os(output);
    os.precision(15);
    os  << "# frictionLawDriver frictionMap, law "
        << lawDict.get<word>("type") << " (doc/theory.md [F33]); film"
        << " memory variant D_f = " << Df << " m" << nl
        << "# tN[Pa] D[m] v[m/s] muSs[-] alphaSs[-] regime"
        << " dtTdlnvPublished[Pa] dtTdlnvFilmMemory[Pa]" << nl;

    scalar maxDiff = 0;
    label nIll[2] = {0, 0};
    for (const scalar p : tN)
    {
        for (const scalar h : D)
        {
            dictionary pub(lawDict);
            lawParameters::set(pub, Dname, h);
            pub.set("filmMemoryDistance", 0.0);
            dictionary mem(pub);
            mem.set
            (
                new primitiveEntry("filmMemoryDistance", token(Df))
            );
            autoPtr<frictionLaw> lawPub, lawMem;
            {
                quietMessages quiet;
                lawPub = frictionLaw::New(pub);
                lawMem = frictionLaw::New(mem);
            }
            frictionLaw::rateStates xp(scalar(0)), xm(scalar(0));
            for (const scalar vi : v)
            {
                lawPub->steadyRateStates(vi, p, xp);
                lawMem->steadyRateStates(vi, p, xm);
                const scalar Fp = lawPub->slidingTraction(vi, xp, p);
                const scalar Fm = lawMem->slidingTraction(vi, xm, p);
                maxDiff = max(maxDiff, mag(Fp - Fm)/p);
                const scalar alpha = xm[1];
                const label regime = alpha < 0.1 ? 0 : alpha > 0.9 ? 2 : 1;
                const scalar sp = lawPub->rateSensitivity(vi, xp, p);
                const scalar sm = lawMem->rateSensitivity(vi, xm, p);
                nIll[0] += sp < 0;
                nIll[1] += sm < 0;
                os  << p << ' ' << h << ' ' << vi << ' ' << Fp/p << ' '
                    << alpha << ' ' << regime << ' ' << sp << ' ' << sm << nl;
            }
            os  << nl;
        }
        os  << nl;
    }
    Info<< "Friction map: " << tN.size() << " pressures x " << D.size()
        << " film thicknesses x " << v.size() << " slip rates to " << output
        << nl << "    steady friction of the published form and the film"
        << " memory differ by at most " << maxDiff << " (tT/tN)" << nl
        << "    ill-posed points (d tT/d ln v < 0): published " << nIll[0]
        << ", film memory " << nIll[1] << endl;

    // One panel per pressure: mu_ss(v) per film thickness, ill-posed
    // points of the published form marked
    std::string script =
        "set multiplot layout " + std::to_string(tN.size()) + ",1 title"
        " 'boundary friction map: steady friction'\n"
        "set logscale xy\nset format x '10^{%L}'\n"
        "set xlabel 'sliding speed v [m/s]'\n"
        "set ylabel 'mu_{ss} [-]'\nset key left top\n";
    const std::string t = "'" + output + "'";
    forAll(tN, i)
    {
        script += "set title 'contact pressure " + std::string(name(tN[i]))
          + " Pa (points: published form ill posed)'\nplot ";
        forAll(D, j)
        {
            script += std::string(j ? ", " : "") + t + " every :::"
              + std::to_string(j) + "::" + std::to_string(j) + " index "
              + std::to_string(i) + " u 3:4 w l lw 2 t 'D = "
              + std::string(name(D[j])) + " m', " + t + " every :::"
              + std::to_string(j) + "::" + std::to_string(j) + " index "
              + std::to_string(i) + " u 3:($7 < 0 ? $4 : 1/0) w p pt 7 ps"
              " 0.6 lc rgb 'red' notitle";
        }
        script += "\n";
    }
    reportFiles::checkWritten(os);
    plot(dict, output, script + "unset multiplot\n");
}


// ************************************************************************* //

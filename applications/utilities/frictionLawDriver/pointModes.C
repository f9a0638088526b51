/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    frictionLawDriver modes that drive one point through time: a prescribed
    slip rate, and the spring-slider with a load-point history
    (doc/theory.md section 8.6, [F22]).

\*---------------------------------------------------------------------------*/

#include "driverModes.H"
#include "checkedFunction1.H"
#include "frictionPointDriver.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- The time stepping of a point history
struct pointHistory
{
    scalar p;
    scalar dt;
    scalar endTime;
    label every;

    explicit pointHistory(const dictionary& dict)
    :
        p(driverModes::contactPressure(dict)),
        dt(driverModes::nonNegative(dict, "deltaT", true)),
        endTime(driverModes::nonNegative(dict, "endTime", true)),
        every(dict.getOrDefault<label>("writeInterval", 1))
    {}
};


//- Slide at the rate v for runInTime (keyword of d) in steps dt, to start
//  from steady sliding; the clock is set back to 0
static void runIn
(
    frictionPointDriver& drv,
    const dictionary& d,
    const scalar v,
    const scalar dt
)
{
    const scalar runInTime = d.getOrDefault<scalar>("runInTime", 0);
    const label n = label(std::ceil(runInTime/dt));
    for (label i = 0; i < n; ++i)
    {
        drv.step(drv.slip() + v*dt, dt);
    }
    drv.setTime(0);
}


//- Table and plot of a point history
static void writeRows
(
    const dictionary& dict,
    const frictionPointDriver& drv,
    const UList<frictionPointDriver::sample>& rows,
    const fileName& output,
    const bool springSlider
)
{
    {
        OFstream os(output);
        os.precision(12);
        os  << "# frictionLawDriver, law "
            << dict.subDict("law").get<word>("type") << ", mode "
            << dict.get<word>("mode") << ", contactPressure "
            << dict.get<scalar>("contactPressure") << nl;
        drv.writeHeader(os, springSlider);
        drv.write(os, rows, springSlider);
        reportFiles::checkWritten(os);
    }
    Info<< "Wrote " << rows.size() << " rows to " << output << endl;

    // Third panel: the law's first own state variable, if any
    word stateLabel("status");
    label stateCol = 7;
    for (const frictionStateEntry& e : drv.law().stateLayout().entries())
    {
        if
        (
            e.kind == frictionStateEntry::SCALAR && e.show
         && e.slot >= frictionState::firstLawSlot
        )
        {
            stateLabel = frictionStateLayout::column(e);
            break;
        }
    }
    const std::string data = "'" + output + "'";
    driverModes::plot
    (
        dict, output,
        "set multiplot layout 3,1 title 'frictionLawDriver: "
      + dict.get<word>("mode") + "'\n"
        "set xlabel 'time [s]'\n"
        "set ylabel 'mu = tT/tN [-]'\n"
        "plot " + data + " u 1:6 w l lw 2 notitle\n"
        "set ylabel '|slip rate| [m/s]'\nset logscale y\n"
        "set format y '10^{%L}'\n"
        "plot " + data + " u 1:(abs($3) > 0 ? abs($3) : 1/0) w l lw 2"
        " notitle\n"
        "unset logscale y\nset format y '%g'\n"
        "set ylabel '" + stateLabel + "'\n"
        "plot " + data + " u 1:" + std::to_string(stateCol)
      + " w l lw 2 notitle\nunset multiplot\n"
    );
}

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::driverModes::prescribed
(
    const dictionary& dict,
    const frictionLaw& law,
    const fileName& output
)
{
    const pointHistory h(dict);
    const scalar p = h.p;
    const dictionary& d = dict.subDict("prescribed");
    autoPtr<Function1<scalar>> v = checkedFunction1<scalar>("slipRate", d);

    frictionPointDriver drv(law, p);
    drv.setShearYield(shearYield(dict, law));
    runIn(drv, d, v->value(0), h.dt);

    // Well-posedness on the history's rates at its pressure [F21]
    if (law.nRateStates() >= 0)
    {
        scalar vMin = GREAT, vMax = 0;
        for (label i = 0; i <= 1000; ++i)
        {
            const scalar av = mag(v->value(h.endTime*i/1000));
            if (av > 0) { vMin = min(vMin, av); vMax = max(vMax, av); }
        }
        if (vMax > 0)
        {
            law.checkWellPosedness(vMin, max(vMax, 1.001*vMin), p, p);
        }
    }

    DynamicList<frictionPointDriver::sample> rows;
    drv.runPrescribed(v(), h.endTime, h.dt, rows, h.every);
    writeRows(dict, drv, rows, output, false);
}


void Foam::driverModes::springSlider
(
    const dictionary& dict,
    const frictionLaw& law,
    const fileName& output
)
{
    const pointHistory h(dict);
    const scalar p = h.p;
    const dictionary& d = dict.subDict("springSlider");
    const scalar M = d.found("mass") ? nonNegative(d, "mass") : 0;
    const scalar k = nonNegative(d, "stiffness", true);
    autoPtr<Function1<scalar>> V =
        checkedFunction1<scalar>("loadPointVelocity", d);

    frictionPointDriver drv(law, p);
    drv.setShearYield(shearYield(dict, law));

    // Run-in at V(0) (steady sliding), then the spring at the steady force
    const scalar V0 = V->value(0);
    runIn(drv, d, V0, h.dt);
    drv.setSpringStretch(drv.last().tT.x()/k);

    // Optional perturbation of the law's first own state variable (the
    // contact age, phi): the onset of stick-slip at constant V
    const scalar eps = d.getOrDefault<scalar>("statePerturbation", 0);
    for (const frictionStateEntry& e : law.stateLayout().entries())
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

    if (law.nRateStates() >= 0 && mag(V0) > 0)
    {
        law.checkWellPosedness(1e-2*mag(V0), 1e2*mag(V0), p, p);
    }

    DynamicList<frictionPointDriver::sample> rows;
    drv.runSpringSlider(M, k, V(), h.endTime, h.dt, rows, h.every);
    writeRows(dict, drv, rows, output, true);
}


// ************************************************************************* //

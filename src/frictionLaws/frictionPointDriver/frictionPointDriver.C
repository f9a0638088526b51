/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionPointDriver.H"
#include "safeguardedNewton.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionPointDriver::frictionPointDriver
(
    const frictionLaw& law,
    const scalar pressure
)
:
    law_(law),
    p_(pressure),
    shearYield_(-1),
    time_(0),
    slip_(0),
    velocity_(0),
    loadPoint_(0),
    state_(law.initialState())
{
    state_.status = frictionState::STICK;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::frictionInput Foam::frictionPointDriver::input
(
    const scalar s,
    const scalar dt
) const
{
    frictionInput in;
    in.gN = p_/law_.KN();
    in.gT = vector(s, 0, 0);
    in.n = vector(0, 0, 1);
    in.dt = dt;
    in.shearYield = shearYield_;
    return in;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::frictionPointDriver::sample Foam::frictionPointDriver::step
(
    const scalar s,
    const scalar dt
)
{
    law_.update(state_, input(s, dt), last_);
    state_ = last_.state;
    velocity_ = (s - slip_)/dt;
    slip_ = s;
    time_ += dt;

    sample row;
    row.time = time_;
    row.slip = slip_;
    row.slipRate = velocity_;
    row.tN = last_.tN;
    row.tT = last_.tT.x();
    row.mu = last_.tN > 0 ? last_.tT.x()/last_.tN : 0;
    row.loadPoint = loadPoint_;
    row.state = state_;
    return row;
}


void Foam::frictionPointDriver::runPrescribed
(
    const Function1<scalar>& v,
    const scalar endTime,
    const scalar dt,
    DynamicList<sample>& out,
    const label every
)
{
    label i = 0;
    while (time_ < endTime - 1e-9*dt)
    {
        const scalar h = min(dt, endTime - time_);
        const sample row = step(slip_ + v.integrate(time_, time_ + h), h);
        if (++i % every == 0 || time_ >= endTime - 1e-9*dt)
        {
            out.append(row);
        }
    }
}


Foam::frictionPointDriver::sample
Foam::frictionPointDriver::springSliderStep
(
    const scalar M,
    const scalar k,
    const scalar V,
    const scalar dt
)
{
    return springSliderMove(M, k, V*dt, dt);
}


Foam::frictionPointDriver::sample
Foam::frictionPointDriver::springSliderMove
(
    const scalar M,
    const scalar k,
    const scalar dxL,
    const scalar dt
)
{
    const scalar V = dxL/dt;
    const scalar xL = loadPoint_ + dxL;
    const scalar x0 = slip_;
    const scalar v0 = velocity_;
    const scalar mdt2 = M/(dt*dt);

    // [F22]: R(x) = k (xL - x) - tT(x) - M ((x - x0)/dt - v0)/dt
    frictionResult trial;
    auto residual = [&](scalar x, scalar& R, scalar& dR)
    {
        law_.update(state_, input(x, dt), trial);
        R = k*(xL - x) - trial.tT.x() - mdt2*(x - x0 - v0*dt);
        dR = -k - trial.dtTdgT.xx() - mdt2;
    };

    // Bracket: R decreases with x for a stable tangent; expand both ends
    scalar w = max(max(mag(V), mag(v0))*dt, SMALL + 1e-12*mag(x0));
    scalar lo = x0 - w, hi = x0 + 2*w;
    scalar Rlo, Rhi, d;
    residual(lo, Rlo, d);
    for (label i = 0; i < 200 && Rlo < 0; ++i)
    {
        lo -= w; w *= 2;
        residual(lo, Rlo, d);
    }
    w = max(max(mag(V), mag(v0))*dt, SMALL + 1e-12*mag(x0));
    residual(hi, Rhi, d);
    for (label i = 0; i < 200 && Rhi > 0; ++i)
    {
        hi += w; w *= 2;
        residual(hi, Rhi, d);
    }

    const scalar scaleR = k*mag(xL - x0) + mag(last_.tT.x()) + p_;
    const safeguardedNewton::result sol = safeguardedNewton::solve
    (
        residual, lo, hi, x0 + v0*dt, 1e-15*(mag(x0) + mag(hi - lo)),
        1e-13*scaleR
    );

    loadPoint_ = xL;
    return step(sol.x, dt);
}


void Foam::frictionPointDriver::runSpringSlider
(
    const scalar M,
    const scalar k,
    const Function1<scalar>& V,
    const scalar endTime,
    const scalar dt,
    DynamicList<sample>& out,
    const label every
)
{
    label i = 0;
    while (time_ < endTime - 1e-9*dt)
    {
        // load point moved exactly by the integral of V over the step
        const scalar h = min(dt, endTime - time_);
        const sample row =
            springSliderMove(M, k, V.integrate(time_, time_ + h), h);
        if (++i % every == 0 || time_ >= endTime - 1e-9*dt)
        {
            out.append(row);
        }
    }
}


namespace Foam
{
    //- The law's own scalar variables shown in ParaView: the table columns
    //  between mu and the status
    static DynamicList<const frictionStateEntry*> lawColumns
    (
        const frictionStateLayout& layout
    )
    {
        DynamicList<const frictionStateEntry*> cols;
        for (const frictionStateEntry& e : layout.entries())
        {
            if
            (
                e.kind == frictionStateEntry::SCALAR && e.show
             && e.slot >= frictionState::firstLawSlot
            )
            {
                cols.append(&e);
            }
        }
        return cols;
    }
}


void Foam::frictionPointDriver::writeHeader
(
    Ostream& os,
    const bool loadPoint
) const
{
    os  << "# time[s] slip[m] slipRate[m/s] tN[Pa] tT[Pa] mu[-]";
    for (const frictionStateEntry* e : lawColumns(law_.stateLayout()))
    {
        os  << ' ' << frictionStateLayout::column(*e);
    }
    os  << " status" << (loadPoint ? " loadPoint[m]" : "") << nl;
}


void Foam::frictionPointDriver::write
(
    Ostream& os,
    const UList<sample>& rows,
    const bool loadPoint
) const
{
    const DynamicList<const frictionStateEntry*> cols =
        lawColumns(law_.stateLayout());
    for (const sample& r : rows)
    {
        os  << r.time << ' ' << r.slip << ' ' << r.slipRate << ' ' << r.tN
            << ' ' << r.tT << ' ' << r.mu;
        for (const frictionStateEntry* e : cols)
        {
            os  << ' ' << r.state.scalarSlot(e->slot);
        }
        os  << ' ' << r.state.status;
        if (loadPoint)
        {
            os  << ' ' << r.loadPoint;
        }
        os  << nl;
    }
}

// ************************************************************************* //

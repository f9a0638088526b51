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
#include "reportFiles.H"

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
    reportFiles::gnuplot(output.lessExt(), script);
}


// ************************************************************************* //

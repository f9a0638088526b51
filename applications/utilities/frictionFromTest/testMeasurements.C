/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

\*---------------------------------------------------------------------------*/

#include "testMeasurements.H"
#include "frictionDataTable.H"
#include "strictDictionary.H"
#include "OSspecific.H"
#include <fstream>
#include <sstream>
#include "error.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Linear interpolation of (xs, ys) at x, xs not decreasing; false outside
bool interpolate
(
    const Foam::scalarList& xs,
    const Foam::scalarList& ys,
    const Foam::scalar x,
    Foam::scalar& y
)
{
    const Foam::label n = xs.size();
    // A measured point at the table's end counts as inside: the tables
    // print x to 6 digits
    const Foam::scalar tol = 1e-9*(1 + std::abs(x));
    if (n == 0 || x < xs[0] - tol || x > xs[n - 1] + tol)
    {
        return false;
    }
    for (Foam::label i = 1; i < n; ++i)
    {
        if (x <= xs[i] + tol && xs[i] > xs[i - 1])
        {
            const Foam::scalar w =
                std::min(std::max((x - xs[i - 1])/(xs[i] - xs[i - 1]), 0.0), 1.0);
            y = (1 - w)*ys[i - 1] + w*ys[i];
            return true;
        }
    }
    y = ys[n - 1];
    return true;
}

}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::testMeasurements::testMeasurements(const dictionary& dict)
:
    nPoints_(0)
{
    const wordList names(dict.toc());
    for (const word& name : names)
    {
        if (!dict.isDict(name))
        {
            FatalIOErrorInFunction(dict)
                << "keyword '" << name << "': a series of measured points is"
                << " a sub-dictionary { file ...; response ...; ... }"
                << exit(FatalIOError);
        }
        const dictionary& d = dict.subDict(name);
        strictDictionary::check
        (
            d,
            {
                "file", "columns", "response", "responseColumns",
                "responseEntry", "sigma", "xLabel", "yLabel"
            },
            "frictionFromTest measurements"
        );
        series s;
        s.name = name;
        s.dict = &d;
        s.responseEntry = d.getOrDefault<word>("responseEntry", word::null);
        const bool scalarSeries = !s.responseEntry.empty();
        if (scalarSeries == d.found("responseColumns"))
        {
            FatalIOErrorInFunction(d)
                << "keyword 'responseColumns' (x y of a table) or"
                << " 'responseEntry' (a 'name value' line) expected, one of"
                << " the two" << exit(FatalIOError);
        }
        const frictionDataTable data
        (
            d, "file",
            d.getOrDefault<labelList>
            (
                "columns", scalarSeries ? labelList({0}) : labelList({0, 1})
            )
        );
        s.file = data.file();
        s.y = data.column(scalarSeries ? 0 : 1);
        s.x = scalarSeries ? scalarList(s.y.size(), scalar(0)) : data.column(0);
        s.xLabel = d.getOrDefault<string>("xLabel", "x");
        s.yLabel = d.getOrDefault<string>("yLabel", name);
        s.response = d.get<fileName>("response");
        s.response.expand();
        if (!scalarSeries)
        {
            const labelList rc(d.get<labelList>("responseColumns"));
            if (rc.size() != 2 || min(rc) < 0)
            {
                FatalIOErrorInFunction(d)
                    << "keyword 'responseColumns': two columns (x y), 0-based,"
                    << " expected; got " << rc << exit(FatalIOError);
            }
            s.responseColumns = labelPair(rc[0], rc[1]);
        }
        s.sigma = d.getOrDefault<scalar>("sigma", 1);
        if (!(s.sigma > 0) || !std::isfinite(s.sigma))
        {
            FatalIOErrorInFunction(d)
                << "keyword 'sigma': the standard deviation of the"
                << " measurement, > 0, expected; got " << s.sigma
                << exit(FatalIOError);
        }
        if (s.x.empty())
        {
            FatalIOErrorInFunction(d)
                << "keyword 'file': no measured point in " << s.file
                << exit(FatalIOError);
        }
        nPoints_ += s.x.size();
        series_.append(s);
    }
    if (series_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "no series of measured points: expected at least one"
            << " sub-dictionary { file ...; response ...; }"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::testMeasurements::responseScalar
(
    const series& s,
    const fileName& runDir,
    scalar& value
)
{
    // Plain streams: the file is not in OpenFOAM's syntax ('#' comments)
    std::ifstream is(runDir/s.response);
    std::string line;
    while (std::getline(is, line))
    {
        std::istringstream ls(line);
        std::string name;
        if (ls >> name && name == s.responseEntry)
        {
            double v;
            if (ls >> v && std::isfinite(v))
            {
                value = v;
                return true;
            }
            return false;
        }
    }
    return false;
}


Foam::List<Foam::scalarList> Foam::testMeasurements::responseTable
(
    const series& s,
    const fileName& runDir
) const
{
    dictionary d;
    d.name() = s.dict->name();
    d.add("response", runDir/s.response);
    const frictionDataTable t
    (
        d, "response",
        labelList({s.responseColumns.first(), s.responseColumns.second()})
    );
    return List<scalarList>({t.column(0), t.column(1)});
}


Foam::scalarField Foam::testMeasurements::modelValues
(
    const fileName& runDir,
    std::string& why,
    label& outside
) const
{
    outside = -1;
    scalarField model(nPoints_);
    label k = 0;
    forAll(series_, j)
    {
        const series& s = series_[j];
        const fileName table(runDir/s.response);
        if (!isFile(table))
        {
            why = "the run wrote no " + table;
            return scalarField();
        }
        if (!s.responseEntry.empty())
        {
            scalar v = 0;
            if (!responseScalar(s, runDir, v))
            {
                FatalIOErrorInFunction(*s.dict)
                    << "keyword 'responseEntry': no line '" << s.responseEntry
                    << " <value>' in " << table << exit(FatalIOError);
            }
            forAll(s.y, i)
            {
                model[k++] = v;
            }
            continue;
        }
        const List<scalarList> xy(responseTable(s, runDir));
        forAll(s.x, i)
        {
            if (!interpolate(xy[0], xy[1], s.x[i], model[k++]))
            {
                outside = j;
                why =
                    "series " + s.name + ": the measured x = "
                  + std::to_string(s.x[i]) + " is outside the simulated "
                  + "range [" + std::to_string(xy[0].empty() ? 0 : xy[0][0])
                  + ", " + std::to_string(xy[0].empty() ? 0 : xy[0].last())
                  + "] of " + table;
                return scalarField();
            }
        }
    }
    return model;
}


Foam::scalarField Foam::testMeasurements::measured() const
{
    scalarField y(nPoints_);
    label k = 0;
    for (const series& s : series_)
    {
        for (const scalar v : s.y)
        {
            y[k++] = v;
        }
    }
    return y;
}


Foam::scalarField Foam::testMeasurements::sigma() const
{
    scalarField sd(nPoints_);
    label k = 0;
    for (const series& s : series_)
    {
        forAll(s.y, i)
        {
            sd[k++] = s.sigma;
        }
    }
    return sd;
}


Foam::labelList Foam::testMeasurements::seriesOfPoint() const
{
    labelList which(nPoints_);
    label k = 0;
    forAll(series_, j)
    {
        forAll(series_[j].y, i)
        {
            which[k++] = j;
        }
    }
    return which;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Hardening curves with exact slopes (hardeningCurve, doc/theory.md
    [S8]): Swift's value and slope against the formula and central
    differences; a table's value against the Function1 it is read from,
    its segment slopes, the right segment at a table point, zero slope
    beyond the ends and before a first point above 0; constant: zero slope.
    Bad input ends in a FatalIOError naming the keyword: a spline or a
    repeating table (OpenFOAM v1912 reads a table's interpolationScheme and
    outOfBounds next to the entry), a Function1 without an exact slope (polynomial), a
    decreasing table.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "mechanicalLawTestTools.H"
#include "hardeningCurve.H"

using namespace Foam;

static dictionary dictOf(const std::string& s)
{
    IStringStream is(s);
    return dictionary(is);
}

// Does building the law from these entries stop with a FatalIOError whose
// message names 'yieldStress' and the given word?
static bool rejected(const std::string& entries, const std::string& word)
{
    const bool throwing = FatalIOError.throwExceptions();
    bool ok = false;
    try
    {
        mechanicalLawTest::law
        (
            "type vonMisesPlastic; rho 7900; E 193e9; nu 0.29; " + entries
        );
    }
    catch (const Foam::IOerror& e)
    {
        const std::string msg(e.message());
        ok =
            msg.find("yieldStress") != std::string::npos
         && msg.find(word) != std::string::npos;
        Info<< "    (message: " << e.message().c_str() << ")" << endl;
    }
    FatalIOError.throwExceptions(throwing);
    return ok;
}


int main()
{
    Info<< "Swift" << endl;
    {
        const hardeningCurve c
        (
            "yieldStress",
            dictOf("yieldStress { type swift; K 1270e6; eps0 0.03; n 0.45; }")
        );
        scalar errV = 0;
        scalar errH = 0;
        scalar errFD = 0;
        for (const scalar e : {1e-4, 0.01, 0.2, 1.0, 5.0})
        {
            scalar H;
            const scalar s = c.value(e, H);
            const scalar exact = 1270e6*Foam::pow(0.03 + e, 0.45);
            errV = max(errV, mag(s/exact - 1));
            errH = max(errH, mag(H/(0.45*exact/(0.03 + e)) - 1));
            const scalar h = 1e-6*(0.03 + e);
            const scalar fd = (c.value(e + h) - c.value(e - h))/(2*h);
            errFD = max(errFD, mag(H/fd - 1));
        }
        unitTest::checkBelow("swift: value = K (eps0 + epsP)^n", errV, 1e-15);
        unitTest::checkBelow("swift: slope = n sigma_y/(eps0 + epsP)", errH, 1e-15);
        // central differences with h = 1e-6 (eps0 + epsP): h^2 truncation
        // and 1e-16/1e-6 round-off
        unitTest::checkBelow("swift: slope vs central differences", errFD, 1e-8);
    }

    Info<< "Table" << endl;
    {
        const std::string entry =
            "yieldStress table ((0.01 300e6) (0.1 400e6) (0.5 600e6));";
        const dictionary d(dictOf(entry));
        const hardeningCurve c("yieldStress", d);
        autoPtr<Function1<scalar>> f(Function1<scalar>::New("yieldStress", d));

        scalar err = 0;
        for (const scalar e : {0.0, 0.01, 0.05, 0.1, 0.3, 0.5, 2.0})
        {
            err = max(err, mag(c.value(e) - f->value(e)));
        }
        unitTest::checkBelow("table: value = the Function1's [Pa]", err, 1e-6);

        scalar H;
        c.value(0.05, H);
        unitTest::checkRel("table: slope of the first segment", H, 100e6/0.09, 1e-14);
        c.value(0.1, H);
        unitTest::checkRel("table: at a point, slope of the segment to the right",
            H, 200e6/0.4, 1e-14);
        c.value(0.3, H);
        unitTest::checkRel("table: slope of the last segment", H, 200e6/0.4, 1e-14);
        const scalar beyond = c.value(2, H);
        unitTest::checkAbs("table: clamped beyond the last point: slope", H, 0, 0);
        unitTest::checkRel("table: clamped beyond the last point: value", beyond, 600e6, 1e-15);
        const scalar before = c.value(0, H);
        unitTest::checkAbs("table: before the first point: slope", H, 0, 0);
        unitTest::checkRel("table: before the first point: value", before, 300e6, 1e-15);
        unitTest::checkTrue("table: type", c.type() == "table");
    }

    Info<< "Constant" << endl;
    {
        const hardeningCurve c("yieldStress", dictOf("yieldStress 250e6;"));
        scalar H = 1;
        unitTest::checkRel("constant: value", c.value(0.3, H), 250e6, 0);
        unitTest::checkAbs("constant: slope", H, 0, 0);
    }

    Info<< "Bad input" << endl;
    {
        unitTest::checkTrue
        (
            "spline table rejected",
            rejected
            (
                "yieldStress table ((0 250e6) (0.1 400e6) (0.3 450e6) (1 500e6));"
                " interpolationScheme spline;",
                "interpolationScheme linear"
            )
        );
        unitTest::checkTrue
        (
            "repeating table rejected",
            rejected
            (
                "yieldStress table ((0 250e6) (1 500e6)); outOfBounds repeat;",
                "outOfBounds clamp"
            )
        );
        unitTest::checkTrue
        (
            "polynomial rejected (no exact slope)",
            rejected("yieldStress polynomial ((250e6 0) (100e6 1));", "polynomial")
        );
        unitTest::checkTrue
        (
            "decreasing table rejected",
            rejected("yieldStress table ((0 300e6) (0.1 200e6));", "decreases")
        );
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

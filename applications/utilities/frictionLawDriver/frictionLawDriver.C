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
    The friction laboratory: drives one contact point of any friction law,
    read from a dictionary, with no mesh, and reads laws off experiments
    (doc/theory.md sections 8.6 and 8.8). Modes:
      prescribed:     a slip-rate history, any Function1 of time (steps,
                      holds, reversals...);
      springSlider:   a block of mass per unit area M (may be 0) pulled
                      through a machine spring k whose end moves at V(t), a
                      Function1 of time (velocity steps, slide-hold-slide)
                      ([F22]);
      stability:      critical stiffness k_c(V) and frequency omega_c(V) of
                      steady sliding, with and without block mass ([F31]);
      identification: the relaxation law from measured F_ss, k_c, omega_c
                      ([F32]);
      frictionMap:    the boundary friction map of the lubricated law
                      ([F33]);
      fit:            Levenberg-Marquardt fit of law parameters to a
                      friction record, with confidence intervals ([F34]).
    Each writes a table and, if gnuplot is found, a PNG. SI units.

Usage
    frictionLawDriver [-dict frictionLawDriverDict]

    See applications/utilities/frictionLawDriver/frictionLawDriverDict and
    tutorials/frictionLawDriver.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IFstream.H"
#include "driverModes.H"
#include "strictDictionary.H"
#include "numberRange.H"
#include "HashTable.H"

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The driver dictionary (a number its reading would stop on with SIGFPE
//  refused first, [S19b])
dictionary readDriverDict(const fileName& dictFile)
{
    strictDictionary::checkNumberRange(dictFile);
    IFstream is(dictFile);
    if (!is.good())
    {
        FatalErrorInFunction
            << "cannot open driver dictionary " << dictFile
            << exit(FatalError);
    }
    return dictionary(is);
}


//- Strict keywords (strictDictionary.H): the driver's own, and those of
//  the sub-dictionary of each mode (the law checks its own)
void checkKeywords(const dictionary& dict)
{
    const HashTable<wordList> modeKeywords
    ({
        {"prescribed", {"slipRate", "slipRateCoeffs", "runInTime"}},
        {
            "springSlider",
            {
                "mass", "stiffness", "loadPointVelocity",
                "loadPointVelocityCoeffs", "statePerturbation", "runInTime"
            }
        },
        {"stability", {"loadPointVelocities", "nVelocities", "masses"}},
        {
            "identification",
            {
                "table", "columns", "normalStress", "mass", "VStar",
                "confidenceLevel", "friction", "frictionSlope",
                "lawDictionary"
            }
        },
        {
            "frictionMap",
            {
                "slipRates", "nSlipRates", "filmThicknesses",
                "contactPressures", "filmThicknessParameter",
                "filmMemoryDistance"
            }
        },
        {
            "fit",
            {
                "record", "columns", "drive", "stiffness", "mass",
                "runInTime", "subSteps", "runInSteps", "confidenceLevel",
                "parameters", "lawDictionary"
            }
        }
    });
    wordList known
    ({
        "FoamFile", "mode", "output", "law", "contactPressure", "deltaT",
        "endTime", "writeInterval", "plot", "shearYield"
    });
    known.append(modeKeywords.sortedToc());
    strictDictionary::check(dict, known, "frictionLawDriver");
    forAllConstIters(modeKeywords, iter)
    {
        if (dict.isDict(iter.key()))
        {
            strictDictionary::check
            (
                dict.subDict(iter.key()), iter.val(),
                "frictionLawDriver mode " + iter.key()
            );
        }
    }
}


//- The mode's run: modes that build their laws themselves (or need none),
//  then those that drive the dictionary's law
void runMode(const dictionary& dict, const word& mode, const fileName& output)
{
    if (mode == "identification")
    {
        driverModes::identification(dict, output);
        return;
    }
    if (mode == "frictionMap")
    {
        driverModes::frictionMap(dict, output);
        return;
    }
    if (mode == "fit")
    {
        driverModes::fit(dict, output);
        return;
    }
    autoPtr<frictionLaw> law = frictionLaw::New(dict.subDict("law"));
    if (mode == "prescribed")
    {
        driverModes::prescribed(dict, *law, output);
    }
    else if (mode == "springSlider")
    {
        driverModes::springSlider(dict, *law, output);
    }
    else if (mode == "stability")
    {
        driverModes::stability(dict, *law, output);
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'mode' must be prescribed, springSlider,"
            << " stability, identification, frictionMap or fit, got '"
            << mode << "'" << exit(FatalIOError);
    }
}

}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "The friction laboratory: drive a point-wise friction law (slip-rate"
        " history, spring-slider), its stability, identification, friction"
        " map and parameter fit; writes a table and a PNG plot"
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

    const dictionary dict
    (
        readDriverDict
        (
            args.getOrDefault<fileName>("dict", "frictionLawDriverDict")
        )
    );
    const word mode(dict.get<word>("mode"));
    const fileName output
    (
        dict.getOrDefault<fileName>("output", "frictionLawDriver.dat")
    );
    reportFiles::checkWritable(dict, "output", output);
    checkKeywords(dict);

    runMode(dict, mode, output);

    frictionLaw::reportIterationLimitHits();

    Info<< "End" << endl;
    return 0;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Application
    frictionFromTest

Group
    grpTriboFoamUtilities

Description
    Friction identified from a measured forming test (a ring compression
    test, a pear-shaped tube...) with the simulation in the loop
    (doc/theory.md [F41]): the named parameters of a friction law (mu, m or
    any keyword of any law) that bring a solver case's results nearest to
    the measured points in least squares, by Levenberg-Marquardt, with
    confidence intervals, stage after stage (a coarse mesh first, each
    stage starting from the last's result). Reads
    system/frictionFromTestDict:

        frictionLaw     { type coulomb; mu 0.1; }  // the law, start values
        parameters      (mu);            // keywords of the law to identify
        stages          ("model/coarse" "model/fine"); // cases, in turn
        lawFile         "constant/frictionLawDict";    // the cases' law
        postProcess     "ringPost .";    // run in a run's case after the
                                         // solver (optional)
        measurements
        {
            innerDiameter
            {
                file            "measured/ring.dat";
                response        "postProcessing/ring/history.dat";
                responseColumns (1 2);
                sigma           0.2;
            }
        }
        confidenceLevel 0.95;            // optional
        relativeStep    0.01;            // central differences, optional
        tolerance       1e-4;            // relative, optional
        maxEvaluations  40;              // per stage, optional
        nParallelRuns   2;               // optional: runs at a time

    Writes frictionFromTest/: fit.dat (measured points, the model at the
    last stage's start and at the fit), <series>.dat (the fitted model's whole curve),
    fittedLawDict, summary.dat ('name value'), fit.png (gnuplot), and each
    stage's run at its fit (<stage>/fit, for ParaView).

    -bootstrap N: N sets of synthetic measurements, the fitted model's
    values plus normal noise of each series' sigma, each fitted again from
    the fit: how often the intervals cover the fitted values tells whether
    they can be trusted for this test's design (bootstrap.dat).

Usage
    frictionFromTest [-case dir] [-dict file] [-keepRuns]
        [-bootstrap N] [-seed S]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IFstream.H"
#include "reportFiles.H"
#include "StringStream.H"
#include "OSspecific.H"
#include "Random.H"
#include "clockTime.H"
#include "strictDictionary.H"
#include "numberRange.H"
#include "testIdentification.H"

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

scalar positive(const dictionary& dict, const word& key, const scalar def)
{
    const scalar v = dict.getOrDefault<scalar>(key, def);
    if (!(v > 0) || !std::isfinite(v))
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': a number > 0 expected, got " << v
            << exit(FatalIOError);
    }
    return v;
}


testIdentification::settings readSettings(const dictionary& dict)
{
    testIdentification::settings s;
    s.confidence = dict.getOrDefault<scalar>("confidenceLevel", 0.95);
    if (!(s.confidence > 0 && s.confidence < 1))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'confidenceLevel': a level in (0, 1) expected, got "
            << s.confidence << exit(FatalIOError);
    }
    s.relativeStep = positive(dict, "relativeStep", s.relativeStep);
    s.tolerance = positive(dict, "tolerance", s.tolerance);
    s.maxEvaluations =
        dict.getOrDefault<label>("maxEvaluations", s.maxEvaluations);
    if (s.maxEvaluations < 2)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'maxEvaluations': at least 2 expected, got "
            << s.maxEvaluations << exit(FatalIOError);
    }
    return s;
}


void report
(
    const wordList& names,
    const testIdentification::result& r,
    const scalar confidence
)
{
    forAll(names, j)
    {
        Info<< "    " << names[j] << " = " << r.value[j] << " +- "
            << r.halfWidth[j] << " (" << label(std::round(100*confidence))
            << " % interval; start " << r.start[j] << ")" << nl;
    }
    Info<< "    rms (model - measured)/sigma " << r.rms << ", "
        << r.dof << " degrees of freedom, " << r.nEvaluations
        << " evaluations, stop: " << r.status << endl;
}


//- fit.dat: series, x, measured, model at the start, model at the fit
void writeFitTable
(
    const fileName& file,
    const testMeasurements& meas,
    const scalarField& start,
    const scalarField& fitted
)
{
    OFstream os(file);
    os.precision(10);
    os  << "# frictionFromTest: measured points, the model at the last"
        << " stage's start and at the fit" << nl
        << "# series x measured modelStart modelFit" << nl;
    label k = 0;
    for (const testMeasurements::series& s : meas.all())
    {
        forAll(s.x, i)
        {
            os  << s.name << ' ' << s.x[i] << ' ' << s.y[i] << ' '
                << start[k] << ' ' << fitted[k] << nl;
            ++k;
        }
    }
    reportFiles::checkWritten(os);
}


void plot(const fileName& dir, const testMeasurements& meas)
{
    const label n = meas.all().size();
    OStringStream os;
    // Six digits on y: a protrusion's 0.01 mm scatter at 12 mm needs five
    os  << "set format y '%.6g'" << nl
        << "set multiplot layout " << n << ",1" << nl;
    for (const testMeasurements::series& s : meas.all())
    {
        const std::string fit = "'" + dir/"fit.dat" + "'";
        // A scalar series: its measurements against their row, the model's
        // value at each row drawn with a point too (one measured value, as
        // the pear tube's protrusion, makes a line of no length). The
        // series name in column 1 is a string: gnuplot compares with 'eq'
        const std::string model =
            s.responseEntry.empty()
          ? "'" + dir/(s.name + ".dat") + "' u 1:2 w l lw 2"
          : fit + " u (strcol(1) eq '" + s.name + "' ? $2 : NaN):5"
            " w lp lw 2 pt 6 ps 2";
        os  << "set title 'frictionFromTest: " << s.name.c_str() << "'" << nl
            << "set xlabel '" << s.xLabel.c_str() << "'" << nl
            << "set ylabel '" << s.yLabel.c_str() << "'" << nl
            << "plot " << model.c_str() << " t 'model at the fit', "
            << fit.c_str() << " u (strcol(1) eq '" << s.name.c_str()
            << "' ? $2 : NaN):3 w p pt 7 ps 1.2 t 'measured', "
            << fit.c_str() << " u (strcol(1) eq '" << s.name.c_str()
            << "' ? $2 : NaN):4 w lp dt 2 t 'model at the stage start'" << nl;
    }
    os  << "unset multiplot" << nl;
    reportFiles::gnuplot(dir/"fit", os.str(), 900, 500*n);
}


//- The identification dictionary, its keywords checked
dictionary readIdentificationDict
(
    const fileName& dictFile,
    const fileName& casePath
)
{
    // [S19b] a number its reading would stop on with SIGFPE
    strictDictionary::checkNumberRange(dictFile);
    IFstream is(dictFile);
    if (!is.good())
    {
        FatalErrorInFunction
            << "cannot open the identification dictionary " << dictFile
            << " in " << casePath << exit(FatalError);
    }
    const dictionary dict(is);
    strictDictionary::check
    (
        dict,
        {
            "FoamFile", "frictionLaw", "parameters", "stages", "lawFile",
            "postProcess", "measurements", "confidenceLevel", "relativeStep",
            "tolerance", "maxEvaluations", "nParallelRuns"
        },
        "frictionFromTest"
    );
    return dict;
}


//- The model cases of the stages, coarse first: each must exist
fileNameList readStages(const dictionary& dict, const fileName& casePath)
{
    const fileNameList stages(dict.get<fileNameList>("stages"));
    if (stages.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'stages': at least one model case expected"
            << exit(FatalIOError);
    }
    for (const fileName& s : stages)
    {
        if (!isDir(fileName(s).expand()))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'stages': no case folder " << s << " (in "
                << casePath << ")" << exit(FatalIOError);
        }
    }
    return stages;
}


//- The start values, which the law must accept before anything runs
scalarList startValues(simulationModel& model, const dictionary& dict)
{
    const scalarList p0(model.start(dict));
    std::string why;
    if (!model.lawAccepts(p0, why))
    {
        FatalIOErrorInFunction(dict.subDict("frictionLaw"))
            << "the start values: " << why.c_str() << exit(FatalIOError);
    }
    return p0;
}


//- [F41] Each stage fitted from the last one's answer (coarse mesh first):
//  the last stage's result; p its values, lastStart its start
testIdentification::result fitStages
(
    simulationModel& model,
    const fileNameList& stages,
    const scalarField& y,
    const scalarField& sd,
    const testIdentification::settings& set,
    scalarList& p,
    scalarList& lastStart
)
{
    testIdentification::result res;
    forAll(stages, k)
    {
        model.setCase(fileName(stages[k]).expand());
        Info<< "Stage " << k + 1 << ": " << stages[k] << endl;
        testIdentification id(model, y, sd, set);
        lastStart = p;
        res = id.fit(p);
        report(model.names(), res, set.confidence);
        p = res.value;
        // The stage's run at its fit, for ParaView
        if (k + 1 < stages.size())
        {
            model.keep(p, "fit");
        }
        Info<< endl;
    }
    return res;
}


//- <series>.dat: the model's response curve of each curve series at the
//  fit (read from the run kept in fitDir)
void writeResponseCurves
(
    const fileName& outDir,
    const testMeasurements& meas,
    const fileName& fitDir
)
{
    for (const testMeasurements::series& s : meas.all())
    {
        if (!s.responseEntry.empty())
        {
            continue;
        }
        const List<scalarList> xy(meas.responseTable(s, fitDir));
        OFstream os(outDir/(s.name + ".dat"));
        os.precision(10);
        os  << "# the model at the fit: column " << s.responseColumns.first()
            << " and " << s.responseColumns.second() << " of "
            << s.response << nl;
        forAll(xy[0], i)
        {
            os  << xy[0][i] << ' ' << xy[1][i] << nl;
        }
        reportFiles::checkWritten(os);
    }
}


//- fittedLawDict: the law at the fit, its intervals as comments
void writeFittedLaw
(
    const fileName& file,
    const simulationModel& model,
    const testIdentification::result& res,
    const scalar confidence
)
{
    OFstream os(file);
    os.precision(10);
    os  << "// Identified by frictionFromTest (doc/theory.md [F41])" << nl;
    forAll(model.names(), j)
    {
        os  << "// " << model.names()[j] << " = " << res.value[j]
            << " +- " << res.halfWidth[j] << " ("
            << label(std::round(100*confidence))
            << " % interval; start " << res.start[j] << ")" << nl;
    }
    model.lawDict(res.value).write(os, false);
    reportFiles::checkWritten(os);
}


//- The bootstrap: nBoot synthetic sets, the model at the fit plus noise of
//  each point's sigma, fitted from the fit; bootstrap.dat; the number of
//  sets whose intervals cover the fit in every parameter
label bootstrap
(
    const fileName& file,
    simulationModel& model,
    const scalarField& fittedValues,
    const scalarField& sd,
    const testIdentification::settings& set,
    const testIdentification::result& res,
    const label nBoot,
    const label seed
)
{
    Random rnd(seed);
    OFstream os(file);
    os.precision(10);
    os  << "# set, per parameter: value halfWidth covered" << nl;
    Info<< "Bootstrap: " << nBoot << " sets, noise of sigma" << endl;
    label covered = 0;
    for (label b = 0; b < nBoot; ++b)
    {
        scalarField yb(fittedValues);
        forAll(yb, i)
        {
            yb[i] += sd[i]*rnd.GaussNormal<scalar>();
        }
        testIdentification id(model, yb, sd, set);
        const testIdentification::result rb = id.fit(res.value);
        bool all = true;
        os  << b + 1;
        forAll(rb.value, j)
        {
            const bool c = mag(rb.value[j] - res.value[j]) <= rb.halfWidth[j];
            all = all && c;
            os  << ' ' << rb.value[j] << ' ' << rb.halfWidth[j] << ' ' << c;
        }
        os  << nl;
        covered += all;
        Info<< "    set " << b + 1 << ":";
        forAll(rb.value, j)
        {
            Info<< ' ' << model.names()[j] << ' ' << rb.value[j]
                << " +- " << rb.halfWidth[j];
        }
        Info<< (all ? " covers" : " misses") << " the fit" << endl;
    }
    reportFiles::checkWritten(os);
    Info<< "Bootstrap: the intervals cover the fit in " << covered
        << " of " << nBoot << " sets" << nl << endl;
    return covered;
}


//- summary.dat: the values and half-widths, the cost, the bootstrap's
//  coverage
void writeSummary
(
    const fileName& file,
    const simulationModel& model,
    const testIdentification::result& res,
    const scalar wallTime,
    const label nBoot,
    const label covered
)
{
    OFstream os(file);
    os.precision(10);
    forAll(model.names(), j)
    {
        os  << model.names()[j] << ' ' << res.value[j] << nl
            << model.names()[j] << "HalfWidth " << res.halfWidth[j] << nl;
    }
    os  << "rms " << res.rms << nl
        << "evaluations " << res.nEvaluations << nl
        << "runs " << model.nRuns() << nl
        << "wallTime " << wallTime << nl;
    if (nBoot > 0)
    {
        os  << "bootstrapSets " << nBoot << nl
            << "bootstrapCovered " << covered << nl;
    }
    reportFiles::checkWritten(os);
}

}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Friction law parameters identified from a measured forming test,"
        " with the simulation in the loop (Levenberg-Marquardt, confidence"
        " intervals)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::noCheckProcessorDirectories();
    argList::addOption
    (
        "dict", "file", "identification dictionary"
        " (default: system/frictionFromTestDict)"
    );
    argList::addBoolOption("keepRuns", "keep every run's case");
    argList::addOption
    (
        "bootstrap", "N",
        "fit N synthetic sets (the fit plus noise of each series' sigma)"
    );
    argList::addOption("seed", "S", "seed of the bootstrap's noise (1)");

    argList args(argc, argv);
    if (!Foam::chDir(args.path()))
    {
        FatalErrorInFunction
            << "cannot change to the case " << args.path() << exit(FatalError);
    }
    const dictionary dict
    (
        readIdentificationDict
        (
            args.getOrDefault<fileName>("dict", "system/frictionFromTestDict"),
            args.path()
        )
    );
    const label nBoot = args.getOrDefault<label>("bootstrap", 0);
    if (nBoot < 0)
    {
        FatalErrorInFunction
            << "option -bootstrap " << nBoot << ": a number of sets >= 0"
            << " expected" << exit(FatalError);
    }

    const testMeasurements meas(dict.subDict("measurements"));
    const fileName outDir("frictionFromTest");
    rmDir(outDir, true);
    mkDir(outDir);
    simulationModel model(dict, meas, outDir, args.found("keepRuns"));
    const testIdentification::settings set(readSettings(dict));
    const fileNameList stages(readStages(dict, args.path()));
    const scalarList p0(startValues(model, dict));

    Info<< "frictionFromTest: " << model.names() << " of law "
        << dict.subDict("frictionLaw").get<word>("type") << " from "
        << meas.size() << " measured points in " << meas.all().size()
        << " series, " << stages.size() << " stage(s)" << nl << endl;

    clockTime clock;
    scalarList p(p0);
    scalarList lastStart(p0);
    const scalarField sd(meas.sigma());
    const testIdentification::result res =
        fitStages(model, stages, meas.measured(), sd, set, p, lastStart);

    // The last stage: the model at its start and at the fit (its runs are
    // cached), its curves
    const simulationModel::run start =
        model.evaluate(List<scalarList>(1, lastStart))[0];
    const simulationModel::run fitted = model.keep(p, "fit");
    writeFitTable(outDir/"fit.dat", meas, start.values, fitted.values);
    writeResponseCurves(outDir, meas, fitted.dir);
    writeFittedLaw(outDir/"fittedLawDict", model, res, set.confidence);

    const label covered =
        nBoot > 0
      ? bootstrap
        (
            outDir/"bootstrap.dat", model, fitted.values, sd, set, res, nBoot,
            args.getOrDefault<label>("seed", 1)
        )
      : 0;

    writeSummary
    (
        outDir/"summary.dat", model, res, clock.elapsedTime(), nBoot, covered
    );
    plot(outDir, meas);

    Info<< "frictionFromTest: " << model.nRuns() << " runs, "
        << clock.elapsedTime() << " s; results in " << outDir << nl
        << "End" << endl;
    return 0;
}


// ************************************************************************* //

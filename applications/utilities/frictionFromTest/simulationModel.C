/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

\*---------------------------------------------------------------------------*/

#include "simulationModel.H"
#include "lawParameters.H"
#include "quietMessages.H"
#include "IFstream.H"
#include "reportFiles.H"
#include "OSspecific.H"
#include "clockTime.H"
#include "error.H"
#include <unistd.h>
#include <cstdio>

// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * * //

std::string Foam::simulationModel::key(const scalarList& p)
{
    std::string k;
    char buf[32];
    for (const scalar v : p)
    {
        std::snprintf(buf, sizeof(buf), "%.15g ", v);
        k += buf;
    }
    return k;
}


bool Foam::simulationModel::lawAccepts
(
    const scalarList& p,
    std::string& why
) const
{
    const bool throwing = FatalError.throwExceptions();
    const bool throwingIO = FatalIOError.throwExceptions();
    bool ok = true;
    try
    {
        // The contact sets the penalties at run time (their automatic
        // values), the law's checks need some
        dictionary d(lawDict(p));
        for (const word k : {"KN", "KT"})
        {
            if (!d.found(k))
            {
                d.add(k, 1.0);
            }
        }
        quietMessages quiet;
        frictionLaw::New(d);
    }
    catch (const Foam::error& e)
    {
        ok = false;
        why = "the law refuses the parameters: " + e.message();
    }
    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(throwingIO);
    return ok;
}


void Foam::simulationModel::prepare(const run& r) const
{
    rmDir(r.dir, true);
    if (!mkDir(r.dir))
    {
        FatalErrorInFunction
            << "cannot make the run folder " << r.dir << exit(FatalError);
    }
    for (const word d : {"0", "constant", "system"})
    {
        if (isDir(case_/d) && !cp(case_/d, r.dir))
        {
            FatalErrorInFunction
                << "cannot copy " << case_/d << " to " << r.dir
                << " (the disk may be full)" << exit(FatalError);
        }
    }
    OFstream os(r.dir/lawFile_);
    os.precision(15);
    os  << "// The friction law of one run of frictionFromTest" << nl;
    lawDict(r.p).write(os, false);
    reportFiles::checkWritten(os);
}


void Foam::simulationModel::keepIfBest
(
    const run& r,
    const scalarField& y,
    const scalarField& sd
)
{
    if (keepRuns_ || r.values.empty())
    {
        return;
    }
    const scalar ssr = sum(sqr((r.values - y)/sd));
    if (best_.empty() || ssr < bestSsr_)
    {
        if (!best_.empty())
        {
            rmDir(best_, true);
        }
        best_ = r.dir;
        bestSsr_ = ssr;
    }
    else
    {
        rmDir(r.dir, true);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::simulationModel::simulationModel
(
    const dictionary& dict,
    const testMeasurements& measurements,
    const fileName& workDir,
    const bool keepRuns
)
:
    measurements_(measurements),
    lawDict_(dict.subDict("frictionLaw")),
    names_(lawParameters::names(dict, "parameters")),
    lawFile_
    (
        dict.getOrDefault<fileName>("lawFile", "constant/frictionLawDict")
    ),
    postProcess_(dict.getOrDefault<string>("postProcess", "")),
    nParallel_
    (
        dict.getOrDefault<label>
        (
            "nParallelRuns", std::min(2L, ::sysconf(_SC_NPROCESSORS_ONLN))
        )
    ),
    keepRuns_(keepRuns),
    workDir_(workDir),
    nRuns_(0),
    runTime_(0),
    bestSsr_(0)
{
    if (names_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'parameters': no parameter to identify"
            << exit(FatalIOError);
    }
    if (nParallel_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'nParallelRuns': at least 1 expected, got "
            << nParallel_ << exit(FatalIOError);
    }
    if (lawFile_.isAbsolute() || lawFile_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'lawFile': the file of the friction law relative to"
            << " the model's case (as constant/frictionLawDict) expected, got"
            << " '" << lawFile_ << "'" << exit(FatalIOError);
    }
    postProcess_.expand();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::simulationModel::setCase(const fileName& caseDir)
{
    const fileName controlDict(caseDir/"system"/"controlDict");
    IFstream is(controlDict);
    if (!is.good())
    {
        FatalErrorInFunction
            << "the model case " << caseDir << " has no " << controlDict
            << ": expected a case ready to run (mesh, 0, constant, system)"
            << exit(FatalError);
    }
    const dictionary cd(is);
    application_ = cd.get<word>("application");
    case_ = caseDir;
    stage_ = caseDir.name();
    cache_.clear();
    best_.clear();
}


Foam::scalarList Foam::simulationModel::start(const dictionary& dict) const
{
    return lawParameters::get(lawDict_, names_, dict, "parameters");
}


Foam::dictionary Foam::simulationModel::lawDict(const scalarList& p) const
{
    return lawParameters::with(lawDict_, names_, p);
}


Foam::List<Foam::simulationModel::run> Foam::simulationModel::evaluate
(
    const List<scalarList>& ps
)
{
    List<run> runs(ps.size());
    DynamicList<label> toRun;
    forAll(ps, i)
    {
        run& r = runs[i];
        r.p = ps[i];
        const std::string k = key(r.p);
        if (cache_.found(k))
        {
            r = cache_[k];
        }
        else if (lawAccepts(r.p, r.why))
        {
            r.dir = workDir_/stage_/("run" + Foam::name(++nRuns_));
            toRun.append(i);
        }
    }

    const scalarField y(measurements_.measured());
    const scalarField sd(measurements_.sigma());
    for (label b = 0; b < toRun.size(); b += nParallel_)
    {
        const label e = std::min(b + nParallel_, toRun.size());
        std::string cmd;
        for (label j = b; j < e; ++j)
        {
            const run& r = runs[toRun[j]];
            prepare(r);
            cmd +=
                "(cd '" + r.dir + "' && { " + application_ + " > log."
              + application_ + " 2>&1; rc=$?; echo $rc > exitCode; "
              + (
                    postProcess_.empty() ? std::string()
                  : "[ $rc -eq 0 ] && { " + postProcess_
                  + " > log.postProcess 2>&1; echo $? > postProcessExitCode; }; "
                )
              + "}) & ";
        }
        cmd += "wait";
        clockTime clock;
        Foam::system(cmd);
        const scalar wall = clock.elapsedTime();
        runTime_ += wall;
        for (label j = b; j < e; ++j)
        {
            run& r = runs[toRun[j]];
            r.wallTime = wall;
            label rc = -1, prc = 0;
            {
                IFstream is(r.dir/"exitCode");
                if (is.good()) { is >> rc; }
            }
            if (!postProcess_.empty() && rc == 0)
            {
                prc = -1;
                IFstream is(r.dir/"postProcessExitCode");
                if (is.good()) { is >> prc; }
            }
            if (rc != 0)
            {
                r.why =
                    application_ + " stopped (exit " + std::to_string(rc)
                  + "): see " + r.dir/("log." + application_);
            }
            else if (prc != 0)
            {
                r.why =
                    "the postProcess command failed (exit "
                  + std::to_string(prc) + "): see " + r.dir/"log.postProcess";
            }
            else
            {
                r.values = measurements_.modelValues(r.dir, r.why, r.outside);
            }
            keepIfBest(r, y, sd);
            cache_.set(key(r.p), r);
        }
    }

    for (const label i : toRun)
    {
        const run& r = runs[i];
        Info<< "    run " << r.dir.name() << " (" << stage_ << "):";
        forAll(names_, j)
        {
            Info<< ' ' << names_[j] << ' ' << r.p[j];
        }
        if (r.values.empty())
        {
            Info<< ": no values, " << r.why.c_str() << endl;
        }
        else
        {
            Info<< ": rms (model - measured)/sigma "
                << std::sqrt(average(sqr((r.values - y)/sd))) << ", "
                << r.wallTime << " s" << endl;
        }
    }
    forAll(runs, i)
    {
        if (runs[i].values.empty() && runs[i].dir.empty())
        {
            Info<< "    not run (" << stage_ << "):";
            forAll(names_, j)
            {
                Info<< ' ' << names_[j] << ' ' << runs[i].p[j];
            }
            Info<< ": " << runs[i].why.c_str() << endl;
        }
    }
    return runs;
}


Foam::simulationModel::run Foam::simulationModel::keep
(
    const scalarList& p,
    const word& name
)
{
    // The best run so far is kept on disk: the fit's, as a rule
    const std::string k = key(p);
    run r;
    if (cache_.found(k) && cache_[k].dir == best_ && isDir(best_))
    {
        r = cache_[k];
    }
    else
    {
        const bool keepRuns = keepRuns_;
        keepRuns_ = true;
        cache_.erase(k);
        r = evaluate(List<scalarList>({p}))[0];
        keepRuns_ = keepRuns;
    }
    const fileName dest(workDir_/stage_/name);
    if (!r.dir.empty() && isDir(r.dir))
    {
        rmDir(dest, true);
        Foam::mv(r.dir, dest);
        r.dir = dest;
        cache_.set(k, r);
    }
    best_.clear();
    return r;
}


// ************************************************************************* //

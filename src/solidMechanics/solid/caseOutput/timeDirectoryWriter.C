/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "timeDirectoryWriter.H"
#include "OFstream.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "Pstream.H"
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Time's precision of time names, and the largest it takes
struct timePrecision
:
    public Time
{
    using Time::precision_;
    using Time::maxPrecision_;
};


//- Start Time at a time directory, its name kept: the precision of time
//  names raised until the directory's value prints as its name.
//  A run whose steps were cut back writes names with more digits than
//  controlDict's timePrecision (Time raises it as it goes); Time's own
//  search at the start walks down from the largest precision and gives up
//  where two precisions print the same round-off digits (4.966394 prints
//  as 4.9663940000000002 at 17 and 18), and would read the fields from
//  4.96639, which does not exist. The step size stays controlDict's, as
//  Time's start leaves it.
static void startAt(Time& runTime, const instant& dir)
{
    const scalar deltaT = runTime.deltaTValue();
    const scalar t = runTime.timeToUserTime(dir.value());
    for
    (
        int p = timePrecision::precision_;
        p <= timePrecision::maxPrecision_;
        ++p
    )
    {
        if (Time::timeName(t, p) == dir.name())
        {
            timePrecision::precision_ = p;
            break;
        }
    }
    runTime.setTime(dir, runTime.timeIndex());
    runTime.setDeltaT(deltaT, false);
}


//- Print on the master, or on every processor with its number
static Ostream& report()
{
    if (Pstream::parRun())
    {
        return Pout;
    }
    return Info();
}

} // End namespace Foam


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::fileName Foam::timeDirectoryWriter::markerPath
(
    const Time& runTime,
    const word& timeName
)
{
    return runTime.path()/timeName/"uniform"/"solidState";
}


bool Foam::timeDirectoryWriter::complete
(
    const Time& runTime,
    const word& timeName
)
{
    return isFile(markerPath(runTime, timeName), false);
}


bool Foam::timeDirectoryWriter::endsComplete(const fileName& path)
{
    if (!isFile(path, false))
    {
        return isFile(path + ".gz", false);
    }
    std::ifstream is(path.c_str(), std::ios::binary);
    is.seekg(0, std::ios::end);
    const std::streamoff size = is.tellg();
    const std::streamoff n = std::min<std::streamoff>(size, 200);
    std::string tail(n, ' ');
    is.seekg(size - n);
    is.read(&tail[0], n);
    if (!is)
    {
        return false;
    }
    const std::string::size_type last = tail.find_last_not_of(" \t\r\n");
    const std::string divider("* //");
    return
        last != std::string::npos
     && last + 1 >= divider.size()
     && tail.compare(last + 1 - divider.size(), divider.size(), divider) == 0;
}


void Foam::timeDirectoryWriter::selectStartTime(Time& runTime)
{
    // [S19b] the time directories of this processor, constant left out
    DynamicList<instant> dirs;
    for (const instant& t : runTime.times())
    {
        if (t.name() != runTime.constant())
        {
            dirs.append(t);
        }
    }
    const word startFrom
    (
        runTime.controlDict().lookupOrDefault<word>("startFrom", "latestTime")
    );
    const scalar tol = 1e-12*max(mag(runTime.value()), scalar(1));
    auto indexOf = [&](const scalar t) -> label
    {
        forAll(dirs, i)
        {
            if (mag(dirs[i].value() - t) <= tol)
            {
                return i;
            }
        }
        return -1;
    };
    // the earliest directory holds the initial conditions
    auto completeAt = [&](const label i)
    {
        return i == 0 || complete(runTime, dirs[i].name());
    };

    const label starti = indexOf(runTime.value());
    bool present = starti >= 0;
    reduce(present, andOp<bool>());
    if (!present)
    {
        // Time reports a missing start directory itself
        return;
    }

    // the newest complete time up to the start, on every processor
    label chosen = starti;
    while (!completeAt(chosen))
    {
        --chosen;
    }
    scalar t = dirs[chosen].value();
    reduce(t, minOp<scalar>());
    chosen = indexOf(t);
    bool ok = chosen >= 0 && completeAt(chosen);
    reduce(ok, andOp<bool>());
    if (!ok)
    {
        FatalErrorInFunction
            << "No time directory up to the start time "
            << runTime.timeName() << " is complete (written with its "
            << "uniform/solidState) on every processor of " << runTime.path()
            << "; the earliest complete time, " << t << ", is missing or"
            << " incomplete on some processor" << nl << exit(FatalError);
    }

    if (chosen != starti || !returnReduce(completeAt(starti), andOp<bool>()))
    {
        const fileName startDir = runTime.timePath();
        if (startFrom != "latestTime")
        {
            FatalIOErrorInFunction(runTime.controlDict())
                << "The start time directory " << startDir << " (keywords"
                << " 'startFrom' " << startFrom << " and 'startTime' of "
                << runTime.controlDict().name() << ") is incomplete: it has"
                << " no uniform/solidState, written last when every field"
                << " is written (a run stopped while writing it). The newest"
                << " complete time before it is " << dirs[chosen].name()
                << "; start from it or use startFrom latestTime" << nl
                << exit(FatalIOError);
        }
        Info<< "Time directory " << runTime.timeName() << " is incomplete"
            << " (no uniform/solidState on "
            << (Pstream::parRun() ? "some processor" : word("disk"))
            << ": a run stopped while writing it): starting from the newest"
            << " complete time, " << dirs[chosen].name() << nl << endl;
    }
    if (runTime.timeName() != dirs[chosen].name())
    {
        startAt(runTime, dirs[chosen]);
    }

    // The incomplete directories after the start: kept, moved aside
    for (label i = chosen + 1; i < dirs.size(); ++i)
    {
        if (completeAt(i))
        {
            continue;
        }
        const fileName dir = runTime.path()/dirs[i].name();
        fileName aside = dir + ".incomplete";
        for (label n = 1; exists(aside, false); ++n)
        {
            aside = dir + ".incomplete" + Foam::name(n);
        }
        if (!mv(dir, aside))
        {
            FatalErrorInFunction
                << "Could not move the incomplete time directory " << dir
                << " aside to " << aside << nl << exit(FatalError);
        }
        report()
            << "Time directory " << dir << " is incomplete (no"
            << " uniform/solidState): moved aside to " << aside.name()
            << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::timeDirectoryWriter::timeDirectoryWriter(const Time& runTime)
:
    runTime_(runTime),
    faultKind_(),
    faultAfter_(-1),
    faultDir_(1),
    nDirs_(0),
    nWritten_(0),
    purge_
    (
        runTime.controlDict().lookupOrDefault<label>("purgeWrite", 0)
    ),
    written_()
{
    const std::string hook(getEnv("TRIBOFOAM_WRITE_FAULT"));
    if (!hook.empty())
    {
        std::istringstream is(hook);
        std::string kind;
        is >> kind >> faultAfter_;
        faultKind_ = kind;
        if (!(is >> faultDir_))
        {
            faultDir_ = 1;
        }
        if
        (
            (
                faultKind_ != "kill" && faultKind_ != "killIn"
             && faultKind_ != "fail"
            )
         || faultAfter_ < 0 || faultDir_ < 1
        )
        {
            FatalErrorInFunction
                << "Environment variable TRIBOFOAM_WRITE_FAULT is '"
                << hook.c_str() << "'; expected 'kill N M', 'killIn N M'"
                << " or 'fail N M'"
                << " with N >= 0, M >= 1 (a test hook: stop the writer after"
                << " N files of the M-th time directory written)" << nl
                << exit(FatalError);
        }
        Info<< "Test hook TRIBOFOAM_WRITE_FAULT: " << faultKind_
            << " after " << faultAfter_ << " files of time directory "
            << faultDir_ << " written" << endl;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::timeDirectoryWriter::collect
(
    const objectRegistry& db,
    const regIOobject& marker,
    DynamicList<const regIOobject*>& objects
) const
{
    for (const word& name : db.sortedToc())
    {
        const regIOobject* obj = *db.cfind(name);
        if (obj == &marker || obj->writeOpt() == IOobject::NO_WRITE)
        {
            continue;
        }
        if (isA<objectRegistry>(*obj))
        {
            collect(dynamic_cast<const objectRegistry&>(*obj), marker, objects);
        }
        else
        {
            objects.append(obj);
        }
    }
}


void Foam::timeDirectoryWriter::fail
(
    const fileName& path,
    const string& why
) const
{
    const fileName dir = runTime_.timePath();
    rmDir(dir, true);
    FatalErrorInFunction
        << "Writing " << path << " failed (" << why.c_str() << "): the disk"
        << " may be full or the directory not writable. The incomplete time"
        << " directory " << dir << " has been removed; a restart starts"
        << " from the last complete time"
        << nl << exit(FatalError);
}


void Foam::timeDirectoryWriter::cutShortInLastEntry(const fileName& path)
{
    // a run killed while writing the file: its last entry (before its last
    // ';') missing, so that it does not parse
    std::ifstream is(path.c_str(), std::ios::binary);
    std::string text
    (
        (std::istreambuf_iterator<char>(is)),
        std::istreambuf_iterator<char>()
    );
    is.close();
    std::ofstream os(path.c_str(), std::ios::binary | std::ios::trunc);
    const std::size_t cut = text.rfind(';');
    os.write(text.data(), cut == std::string::npos ? text.size()/2 : cut);
}


void Foam::timeDirectoryWriter::injectFault
(
    const std::function<bool()>& writer,
    const fileName& path
) const
{
    if (nDirs_ != faultDir_ || nWritten_ != faultAfter_)
    {
        return;
    }
    const fileName dir = runTime_.timePath();
    if (faultKind_ == "kill")
    {
        Info<< "TRIBOFOAM_WRITE_FAULT: killed after " << nWritten_
            << " files of " << dir << endl;
        ::kill(::getpid(), SIGKILL);
    }
    if (faultKind_ == "killIn")
    {
        // the file being written where the writer puts it (its temporary
        // name, if any)
        writer();
        cutShortInLastEntry(path);
        Info<< "TRIBOFOAM_WRITE_FAULT: killed in the write of " << path
            << " after " << nWritten_ << " files of " << dir << endl;
        ::kill(::getpid(), SIGKILL);
    }
    if (faultKind_ == "fail")
    {
        fail(path, "TRIBOFOAM_WRITE_FAULT: a simulated failure");
    }
}


void Foam::timeDirectoryWriter::writeChecked
(
    const std::function<bool()>& writer,
    const fileName& path
)
{
    injectFault(writer, path);
    if (!writer())
    {
        fail(path, "the stream reported an error");
    }
    if (!endsComplete(path))
    {
        fail(path, "the file read back is cut short");
    }
    ++nWritten_;
}


void Foam::timeDirectoryWriter::writeAside
(
    const regIOobject& obj,
    const fileName& file
)
{
    const fileName aside = file + ".writing";
    writeChecked
    (
        [&]()
        {
            mkDir(file.path());
            OFstream os(aside);
            bool ok = os.good() && obj.writeHeader(os);
            ok = ok && obj.writeData(os);
            IOobject::writeEndDivider(os);
            os.flush();
            return ok && os.good();
        },
        aside
    );
    if (!mv(aside, file))
    {
        fail(file, "renaming " + aside + " failed");
    }
}


void Foam::timeDirectoryWriter::writeFields(const regIOobject& marker)
{
    DynamicList<const regIOobject*> objects;
    collect(runTime_, marker, objects);
    const fileName dir = runTime_.timePath();
    for (const regIOobject* obj : objects)
    {
        // the path at this time (objectPath() names the last instance
        // until the object is written)
        writeChecked
        (
            [&]() { return obj->write(); },
            dir/obj->db().dbDir()/obj->local()/obj->name()
        );
    }
}


void Foam::timeDirectoryWriter::writeTimeDictionary()
{
    // After the fields (an incomplete directory mostly lacks it), written
    // aside like the mark: Time reads it from the latest directory before
    // the solver can step back from an incomplete one, and one cut short
    // (a run killed while writing it) would stop every restart
    IOdictionary timeDict
    (
        IOobject
        (
            "time",
            runTime_.timeName(),
            "uniform",
            runTime_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    timeDict.add
    (
        "value",
        Time::timeName
        (
            runTime_.timeToUserTime(runTime_.value()),
            timePrecision::maxPrecision_
        )
    );
    timeDict.add("name", string(runTime_.timeName()));
    timeDict.add("index", runTime_.timeIndex());
    timeDict.add("deltaT", runTime_.timeToUserTime(runTime_.deltaTValue()));
    timeDict.add("deltaT0", runTime_.timeToUserTime(runTime_.deltaT0Value()));
    writeAside(timeDict, runTime_.timePath()/"uniform"/"time");
}


void Foam::timeDirectoryWriter::purgeOldest()
{
    if (written_.empty() || written_.top() != runTime_.timeName())
    {
        written_.push(runTime_.timeName());
    }
    while (purge_ > 0 && written_.size() > label(purge_))
    {
        rmDir(runTime_.path()/written_.pop());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::timeDirectoryWriter::write(regIOobject& marker)
{
    const fileName markerFile = markerPath(runTime_, runTime_.timeName());
    nWritten_ = 0;
    ++nDirs_;

    // [S19b] a directory written again loses its mark first
    if (isFile(markerFile, false) && !rm(markerFile))
    {
        fail(markerFile, "the old mark could not be removed");
    }

    writeFields(marker);
    writeTimeDictionary();

    // the mark last, once every other file is complete
    marker.instance() = runTime_.timeName();
    writeAside(marker, markerFile);

    purgeOldest();
}


// ************************************************************************* //

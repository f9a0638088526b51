/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "caseLock.H"
#include "OSspecific.H"
#include "Pstream.H"
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <fstream>
#include <string>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The lock this process holds, removed at exit
std::string heldLock;

void releaseLock()
{
    if (!heldLock.empty())
    {
        ::unlink(heldLock.c_str());
        heldLock.clear();
    }
}


//- A parallel run that stops with an error on another processor is ended
//  by MPI with SIGTERM (after MPI_Abort): the lock goes with it, as at a
//  normal exit; then the default action
void releaseLockAndTerminate(int sig)
{
    if (!heldLock.empty())
    {
        ::unlink(heldLock.c_str());
    }
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

//- Create the lock file exclusively with "host pid"; false if it exists
bool createLock(const std::string& path, const std::string& content)
{
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0)
    {
        return false;
    }
    const ssize_t n = ::write(fd, content.data(), content.size());
    ::close(fd);
    return n == ssize_t(content.size());
}

//- Is the process pid of this host running the application?
bool running(const long pid, const std::string& application)
{
    if (pid <= 0 || (::kill(pid_t(pid), 0) != 0 && errno != EPERM))
    {
        return false;
    }
    // a killed run's process that its parent has not reaped yet (an MPI
    // rank while mpirun tears the job down) is a zombie: no longer a run
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string statLine;
    if (stat && std::getline(stat, statLine))
    {
        const std::string::size_type close = statLine.rfind(')');
        if
        (
            close != std::string::npos && close + 2 < statLine.size()
         && (statLine[close + 2] == 'Z' || statLine[close + 2] == 'X')
        )
        {
            return false;
        }
    }
    // a process id reused by another program is no run of the application
    std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
    std::string name;
    if (comm && std::getline(comm, name))
    {
        // comm holds at most 15 characters of the name
        return application.compare(0, name.size(), name) == 0;
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::fileName Foam::caseLock::lockFile
(
    const fileName& caseDir,
    const word& application
)
{
    return caseDir/application + ".lock";
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::caseLock::caseLock(const Time& runTime, const word& application)
{
    if (!Pstream::master())
    {
        return;
    }
    const fileName path(lockFile(runTime.globalPath(), application));
    const std::string host(hostName());
    const std::string content =
        host + ' ' + std::to_string(long(::getpid())) + '\n';

    for (int attempt = 0; attempt < 2; ++attempt)
    {
        if (createLock(path, content))
        {
            heldLock = path;
            std::atexit(releaseLock);
            std::signal(SIGTERM, releaseLockAndTerminate);
            return;
        }

        std::ifstream is(path.c_str());
        std::string lockHost;
        long pid = -1;
        is >> lockHost >> pid;
        if (!is && attempt == 0)
        {
            // being created this instant by another run, or empty: look
            // again once
            ::sleep(1);
            is.close();
            is.open(path.c_str());
            is >> lockHost >> pid;
        }

        if (lockHost.empty())
        {
            // a run writes "host pid" the instant it creates the lock: one
            // still empty 5 s after its last change was left by a run
            // killed as it started (or on a full disk), and no run holds it
            while
            (
                lockHost.empty() && exists(path, false)
             && std::time(nullptr) - lastModified(path, false) < 5
            )
            {
                ::sleep(1);
                is.close();
                is.clear();
                is.open(path.c_str());
                is >> lockHost >> pid;
            }
            if (lockHost.empty())
            {
                if (exists(path, false))
                {
                    Info<< "Lock file " << path << " is empty, unchanged"
                        << " for 5 s or more (a run killed as it started, or"
                        << " a full disk): taken over" << nl << endl;
                    ::unlink(path.c_str());
                }
                continue;
            }
        }
        if (lockHost != host)
        {
            FatalErrorInFunction
                << "The case " << runTime.globalPath() << " is locked by "
                << path << " (" << (lockHost.empty() ? "unreadable" :
                   "host " + lockHost + ", process " + std::to_string(pid))
                << "): another " << application << " may be running in it,"
                << " which cannot be checked from host " << host << ". Remove"
                << " the lock file if no run is using the case" << nl
                << exit(FatalError);
        }
        // a run that has just been stopped may take a moment to go: look
        // again for a few seconds before calling the case in use
        bool inUse = running(pid, application);
        for (int wait = 0; inUse && wait < 3; ++wait)
        {
            ::sleep(1);
            inUse = running(pid, application);
        }
        if (inUse)
        {
            FatalErrorInFunction
                << "The case " << runTime.globalPath() << " is in use: "
                << application << " process " << pid << " is running in it"
                << " (lock file " << path << "). One run per case folder: wait"
                << " for it to end or stop it; two runs would write the same"
                << " time directories" << nl << exit(FatalError);
        }
        Info<< "Lock file " << path << " of process " << pid << ", which no"
            << " longer runs (a run killed, crashed or ended by MPI_Abort):"
            << " taken over" << nl
            << endl;
        ::unlink(path.c_str());
    }
    FatalErrorInFunction
        << "Could not create the lock file " << path << " of the case "
        << runTime.globalPath() << ": " << std::strerror(errno)
        << " (is the case folder writable?)" << nl << exit(FatalError);
}


// ************************************************************************* //

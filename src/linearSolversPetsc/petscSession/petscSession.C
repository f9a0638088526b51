/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "petscSession.H"
#include "UPstream.H"
#include "error.H"
#include <cstdlib>
#include <fenv.h>

// * * * * * * * * * * * * * * * * Local state * * * * * * * * * * * * * * //

namespace
{

//- start() has run
bool started = false;

//- PETSc was initialised here (not by a library or program around us)
bool ownPetsc = false;

//- Finalisation has begun (guards the nested call PetscFinalize ->
//  MPI_Finalize -> MPI_COMM_SELF callback when PETSc started MPI)
bool finalising = false;

//- The first message of the last PETSc error
std::string lastError;


PetscErrorCode recordError
(
    MPI_Comm,
    int line,
    const char* fun,
    const char* file,
    PetscErrorCode n,
    PetscErrorType p,
    const char* mess,
    void*
)
{
    if (p == PETSC_ERROR_INITIAL)
    {
        const char* text = nullptr;
        PetscErrorMessage(n, &text, nullptr);
        lastError = std::string(mess ? mess : "")
            + " [" + (text ? text : "PETSc error") + ", in "
            + (fun ? fun : "?") + " at " + (file ? file : "?") + ":"
            + std::to_string(line) + "]";
    }
    return n;
}


void finalise()
{
    if (finalising || !ownPetsc)
    {
        return;
    }
    finalising = true;

    PetscBool done = PETSC_FALSE;
    PetscFinalized(&done);
    if (!done)
    {
        Foam::petscSession::fpeGuard guard;
        PetscFinalize();
    }
}


//- Delete callback of our attribute on MPI_COMM_SELF: runs first thing
//  in MPI_Finalize
int finaliseBeforeMpi(MPI_Comm, int, void*, void*)
{
    finalise();
    return MPI_SUCCESS;
}


//- For programs that exit without MPI_Finalize
void finaliseAtExit()
{
    finalise();

    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (initialised && !finalised)
    {
        MPI_Finalize();
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * fpeGuard  * * * * * * * * * * * * * * * //

Foam::petscSession::fpeGuard::fpeGuard()
:
    saved_(fegetexcept())
{
    if (saved_ > 0)
    {
        fedisableexcept(saved_);
    }
}


Foam::petscSession::fpeGuard::~fpeGuard()
{
    if (saved_ > 0)
    {
        // Flags raised (and handled) inside PETSc must not trap later
        feclearexcept(FE_ALL_EXCEPT);
        feenableexcept(saved_);
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

void Foam::petscSession::start()
{
    if (started)
    {
        if (finalising)
        {
            FatalErrorInFunction
                << "PETSc was already finalised: no PETSc solver can be"
                << " built after MPI_Finalize" << exit(FatalError);
        }
        return;
    }

    PetscBool initialised = PETSC_FALSE;
    PetscInitialized(&initialised);

    if (!initialised)
    {
        int mpiUp = 0;
        MPI_Initialized(&mpiUp);
        if (!mpiUp)
        {
            // Serial run: MPI started as OpenFOAM's, so that Pstream::exit
            // finalises it (a dummy Pstream leaves it to PETSc)
            UPstream::initNull();
        }
        PETSC_COMM_WORLD = MPI_COMM_WORLD;

        // PETSc keeps pointers to its arguments: static storage. No
        // signal handler of PETSc's: OpenFOAM's stay in place
        static char arg0[] = "triboFoam";
        static char arg1[] = "-no_signal_handler";
        static char* args[] = {arg0, arg1, nullptr};
        static char** argv = args;
        static int argc = 2;

        PetscErrorCode ierr = 0;
        {
            fpeGuard guard;
            ierr = PetscInitialize(&argc, &argv, nullptr, nullptr);
        }
        if (ierr)
        {
            FatalErrorInFunction
                << "PetscInitialize failed with error " << int(ierr)
                << " (check PETSC_OPTIONS and ~/.petscrc)"
                << exit(FatalError);
        }
        ownPetsc = true;

        int keyval = MPI_KEYVAL_INVALID;
        MPI_Comm_create_keyval
        (
            MPI_COMM_NULL_COPY_FN, finaliseBeforeMpi, &keyval, nullptr
        );
        MPI_Comm_set_attr(MPI_COMM_SELF, keyval, nullptr);
        std::atexit(finaliseAtExit);
    }

    PetscPushErrorHandler(recordError, nullptr);
    started = true;
}


bool Foam::petscSession::running()
{
    return started && !finalising;
}


std::string Foam::petscSession::message(const PetscErrorCode ierr)
{
    if (!ierr)
    {
        return std::string();
    }
    std::string m = lastError.empty()
        ? "PETSc error " + std::to_string(int(ierr)) : lastError;
    lastError.clear();
    return m;
}


// ************************************************************************* //

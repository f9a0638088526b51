/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The coded friction law (doc/theory.md [F40]): a shear strength written
    in the dictionary is compiled by OpenFOAM's dynamicCode into a law of
    the flowStressFriction family; it slides at the coded strength, its
    tangent (from the coded slopes) matches central finite differences,
    and a coded slope that is wrong fails that check (so the check can
    fail). The library is built under a scratch case folder, removed at
    the end. OpenFOAM refuses to build and load case code for an
    administrator (root): run as root, the test checks that refusal and
    says that the build was not tested.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "coded.H"
#include "OSspecific.H"

using namespace Foam;

int main()
{
    FatalIOError.throwExceptions();
    FatalError.throwExceptions();

    // dynamicCode builds under $FOAM_CASE/dynamicCode
    const fileName scratch(cwd()/"codedLaw.tmp");
    if (isDir(scratch))
    {
        rmDir(scratch);
    }
    mkDir(scratch);
    setEnv("FOAM_CASE", scratch, true);

    const scalar KN = 1e13;
    const scalar k = 2e8/std::sqrt(3.0);
    frictionInput in;
    in.n = vector(0, 0, 1);
    in.gT = vector(1e-4, 0, 0);
    in.dt = 1;
    in.shearYield = k;

    // tau = mu tN k/(k + mu tN): Coulomb at low pressure, k at high
    const std::string law =
        "type coded; name saturatingCoulomb; KN 1e13; KT 1e13;"
        " code #{ const scalar mu = 0.2;"
        " tau = mu*tN*k/(k + mu*tN);"
        " dtauDtN = mu*sqr(k/(k + mu*tN)); #};";

    // strict like every law, for an administrator too: a misspelled
    // keyword is refused before any compilation, with the keyword meant
    bool typoRefused = false;
    try
    {
        frictionTest::law
        (
            "type coded; name typoLaw; KN 1; KT 1; rateDependant true;"
            " code #{ tau = 0; #};"
        );
    }
    catch (const Foam::IOerror& e)
    {
        const std::string m(e.message());
        typoRefused =
            m.find("rateDependant") != std::string::npos
         && m.find("Did you mean 'rateDependent'") != std::string::npos;
    }
    unitTest::checkTrue
    (
        "misspelled keyword: FatalIOError naming it and the one meant",
        typoRefused
    );
    unitTest::checkTrue
    (
        "misspelled keyword: nothing compiled",
        !isDir(scratch/"dynamicCode"/"typoLaw")
    );

    if (isAdministrator())
    {
        bool refused = false;
        try
        {
            frictionTest::law(law);
        }
        catch (const Foam::IOerror& e)
        {
            refused =
                std::string(e.message()).find("administrator")
             != std::string::npos;
        }
        unitTest::checkTrue
        (
            "run as administrator: OpenFOAM refuses the case code", refused
        );
        Info<< "NOTE: run as an administrator, the build and the law were"
            << " not tested; run as an ordinary user for that" << endl;
        rmDir(scratch);
        return unitTest::exitCode();
    }

    autoPtr<frictionLaw> l;
    try
    {
        l = frictionTest::law(law);
    }
    catch (const Foam::error& e)
    {
        Info<< "coded law not built: " << e.message().c_str() << endl;
        unitTest::checkTrue("the coded law builds", false);
        return unitTest::exitCode();
    }
    unitTest::checkTrue("compiled law needs k", l->needsShearYield());
    unitTest::checkTrue
    (
        "compiled law has the given name",
        refCast<const frictionLaws::coded>(l()).redirect().type()
     == "saturatingCoulomb"
    );
    const frictionState old = l->initialState();
    for (const scalar tN : {1e6, 1e8, 1e9, 1e10})
    {
        in.gN = tN/KN;
        frictionResult r;
        l->update(old, in, r);
        unitTest::checkRel
        (
            "tN " + std::to_string(tN) + ": |tT| = coded tau",
            mag(r.tT), 0.2*tN*k/(k + 0.2*tN), 1e-12
        );
        unitTest::checkBelow
        (
            "tN " + std::to_string(tN) + ": tangent vs FD",
            frictionTest::tangentError(*l, old, in), 1e-6
        );
    }

    // the same code again: the library is reused, not rebuilt
    autoPtr<frictionLaw> again = frictionTest::law(law);
    unitTest::checkTrue("built once", again.valid());

    // a wrong slope (none) is caught by the tangent check
    autoPtr<frictionLaw> wrong = frictionTest::law
    (
        "type coded; name wrongSlope; KN 1e13; KT 1e13;"
        " code #{ tau = 0.2*tN*k/(k + 0.2*tN); #};"
    );
    in.gN = 1e8/KN;
    unitTest::checkTrue
    (
        "a missing slope fails the FD check (error above 1e-2)",
        frictionTest::tangentError(*wrong, old, in) > 1e-2
    );

    bool threw = false;
    try
    {
        frictionTest::law("type coded; name noCode; KN 1; KT 1;");
    }
    catch (const Foam::IOerror& e)
    {
        threw = std::string(e.message()).find("'code'") != std::string::npos;
    }
    unitTest::checkTrue("no code: FatalIOError naming 'code'", threw);

    rmDir(scratch);
    return unitTest::exitCode();
}

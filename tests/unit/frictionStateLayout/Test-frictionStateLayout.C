/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The state of every law, declared once in its frictionStateLayout
    (doc/theory.md [F2]) and serialised by the two functions the contact
    condition calls for restart (frictionStateLayout::write, read):
      - each law declares the variables it has (names and units);
      - a list of face states (sliding, sticking, open) written and read
        back gives every written variable bit for bit, and the next update
        from the read-back states equals the one from the originals (a
        restart continues the run);
      - a patch entry written before the layouts (all nine keywords, the
        relaxation law's phi under contactAge) is read by every law;
      - a state written by another law: the missing names are reported;
      - asking a law for a variable it does not have is an error that
        names its variables.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "frictionPointDriver.H"
#include "OStringStream.H"

using namespace Foam;

namespace
{

struct lawCase
{
    std::string name;
    std::string dict;
    //- The variables the law declares beyond the kinematic ones
    wordList own;
};

const wordList kinematic
({"totalSlip", "plasticSlip", "cumulatedSlip", "slipRate", "contactStatus"});

const std::string pen = "KN 1e12; KT 1e13; ";
const std::string lub =
    "type lubricatedRateState; " + pen + "M 0.1; D0 1e-6;"
    " creepVelocity 1e-9; muStatic 0.12; muDynamic 0.07;"
    " criticalVelocity 1e-3; filmViscosity 3e9; slipRateRange (1e-9 1e-3);"
    " lubrication { type stribeck; filmThickness 1e-6;"
    " referenceFilmThickness 1e-6; referenceVelocity 1e-3; n 1; }";

const std::vector<lawCase> cases =
{
    {"frictionless", "type frictionless; " + pen, {}},
    {"coulomb", "type coulomb; mu 0.3; " + pen, {}},
    {"curnier", "type curnier; criterion coulomb; f 0.3; QT 1e11; " + pen,
        {"tearSlip", "normalSlip"}},
    {"rateState ageing", "type rateState; stateLaw ageing; " + pen
      + "a 0.01; b 0.015; muStar 0.6; VStar 1e-6; L 1e-5;", {"contactAge"}},
    {"rateState relaxation", "type rateState; stateLaw relaxation; " + pen
      + "a 0.0349; b 0.0489; muStar 0.369; VStar 1e-6; relaxationTime 2.729;"
        " gamma 0.723;", {"normalisedContactAge"}},
    {"lubricatedRateState", lub, {"contactAge", "lubricationWeight"}}
};


//- Three face states: sliding, then sticking, then open (and fresh)
List<frictionState> someStates(const frictionLaw& law)
{
    frictionPointDriver drv(law, 1e6);
    List<frictionState> s(3);
    for (label i = 0; i < 50; ++i) drv.step(drv.slip() + 1e-7, 0.1);
    s[0] = drv.state();
    drv.step(drv.slip() - 1e-9, 0.1);
    s[1] = drv.state();
    s[2] = law.initialState();
    s[2].totalSlip = vector(1e-6, 2e-6, 0);
    s[2].plasticSlip = s[2].totalSlip;
    s[2].cumulatedSlip = 3e-6;
    return s;
}


//- The state entries as a patch dictionary, written as the contact does
dictionary written(const frictionStateLayout& layout, const UList<frictionState>& s)
{
    OStringStream os;
    os.precision(17);
    layout.write(os, s);
    return frictionTest::dict(os.str());
}


bool sameWritten
(
    const frictionStateLayout& layout,
    const frictionState& a,
    const frictionState& b
)
{
    bool same = true;
    for (const frictionStateEntry& e : layout.entries())
    {
        if (!e.write) continue;
        same = same &&
        (
            e.kind == frictionStateEntry::VECTOR
          ? layout.vectorValue(a, e.name) == layout.vectorValue(b, e.name)
          : layout.value(a, e.name) == layout.value(b, e.name)
        );
    }
    return same;
}

} // End anonymous namespace


int main()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // A patch entry as written before the laws declared their layouts:
    // every keyword for every law (phi of the relaxation law in contactAge).
    // Parsed for each read: reading a field takes its list out of the
    // dictionary, as the contact condition reads each keyword once
    const std::string oldFormat
    (
        "totalSlip nonuniform List<vector> 2((1e-6 0 0) (2e-6 0 0));"
        " plasticSlip nonuniform List<vector> 2((9e-7 0 0) (2e-6 0 0));"
        " tearSlip nonuniform List<vector> 2((1e-7 0 0) (0 0 0));"
        " normalSlip nonuniform List<scalar> 2(0 1e-8);"
        " cumulatedSlip nonuniform List<scalar> 2(5e-6 6e-6);"
        " contactAge nonuniform List<scalar> 2(2.5 0.5);"
        " lubricationWeight nonuniform List<scalar> 2(0.2 0);"
        " slipRate nonuniform List<scalar> 2(1e-6 0);"
        " contactStatus nonuniform List<scalar> 2(2 0);"
    );

    for (const lawCase& c : cases)
    {
        Info<< "Law " << c.name.c_str() << endl;
        autoPtr<frictionLaw> law = frictionTest::law(c.dict);
        const frictionStateLayout& layout = law->stateLayout();

        wordList names(layout.entries().size());
        forAll(names, i) names[i] = layout.entries()[i].name;
        wordList expected(kinematic);
        for (const word& w : c.own) expected.append(w);
        unitTest::checkTrue
        (
            c.name + ": declares the kinematic variables and its own",
            names == expected
        );

        // Round trip through the restart serialisation
        const List<frictionState> s = someStates(*law);
        const dictionary d = written(layout, s);
        List<frictionState> back(s.size(), law->initialState());
        const wordList missing = layout.read(d, back);
        bool same = missing.empty();
        forAll(s, i) same = same && sameWritten(layout, s[i], back[i]);
        unitTest::checkTrue
        (
            c.name + ": written variables read back bit for bit", same
        );

        // Restart: the next step from the read-back states is the same
        bool sameNext = true;
        forAll(s, i)
        {
            frictionInput in;
            in.gN = 1e6/law->KN();
            in.gT = s[i].totalSlip + vector(3e-8, 1e-8, 0);
            in.dt = 0.1;
            frictionResult r0, r1;
            law->update(s[i], in, r0);
            law->update(back[i], in, r1);
            sameNext = sameNext && r0.tT == r1.tT && r0.state == r1.state;
        }
        unitTest::checkTrue
        (
            c.name + ": update from the read-back states identical",
            sameNext
        );

        // A restart file of the previous version
        List<frictionState> old(2, law->initialState());
        const wordList missingOld =
            layout.read(frictionTest::dict(oldFormat), old);
        unitTest::checkTrue
        (
            c.name + ": reads a patch entry written before the layouts",
            missingOld.empty() && old[0].status == 2
         && old[0].plasticSlip == vector(9e-7, 0, 0)
         && old[1].cumulatedSlip == 6e-6
        );
        for (const word& w : c.own)
        {
            if (w == "contactAge" || w == "normalisedContactAge")
            {
                unitTest::checkAbs
                (
                    c.name + ": " + w + " from the old contactAge",
                    layout.value(old[0], w), 2.5, 0
                );
            }
        }
    }

    Info<< "State of another law" << endl;
    {
        autoPtr<frictionLaw> coulomb = frictionTest::law(cases[1].dict);
        autoPtr<frictionLaw> lubricated = frictionTest::law(lub);
        const List<frictionState> s = someStates(*coulomb);
        const dictionary d = written(coulomb->stateLayout(), s);
        List<frictionState> back(s.size(), lubricated->initialState());
        const wordList missing = lubricated->stateLayout().read(d, back);
        unitTest::checkTrue
        (
            "coulomb state read by the lubricated law: contactAge reported"
            " missing, fresh value kept",
            missing == wordList({"contactAge"})
         && lubricated->stateLayout().value(back[0], "contactAge")
         == lubricated->stateLayout().value
            (
                lubricated->initialState(), "contactAge"
            )
        );

        bool threw = false;
        try
        {
            coulomb->stateLayout().value(s[0], "contactAge");
        }
        catch (const Foam::error& e)
        {
            threw = std::string(e.message()).find("cumulatedSlip")
                != std::string::npos;
        }
        unitTest::checkTrue
        (
            "coulomb has no contactAge: error listing its variables", threw
        );
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

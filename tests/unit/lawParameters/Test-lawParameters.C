/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Named parameters of a friction law for the friction laboratory
    (lawParameters; frictionFromTest, frictionLawDriver fit and map, doc/theory.md
    [F41]). OpenFOAM's tokenizer splits an unquoted
    lubrication/filmThickness into three tokens; the names must come back
    whole, quoted or not, and reach the sub-dictionary's value exactly:
      - (mu0 lubrication/filmThickness "lubrication/n"): three names, the
        values 0.07, 1e-6 and 1 of the lubricated law of the pear tube's
        lubricant B; a value set on a path is read back bit for bit;
      - a parameter the law lacks (lubrication/etaZero, a misspelt
        sub-dictionary, a top-level mux): an error naming the keyword
        'parameters' and the name, listing the keywords of the
        sub-dictionary where the path stopped;
      - malformed lists (no parentheses, a doubled or trailing '/', a
        number): an error naming the keyword.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "lawParameters.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{

dictionary parse(const std::string& text)
{
    return unitTest::controls(text);
}

const dictionary lawB
(
    parse
    (
        "type lubricatedRateState; M 0.1; D0 1e-6; creepVelocity 1e-9;"
        " filmMemoryDistance 2e-4; mu0 0.07; filmViscosity 3e9;"
        " lubrication { type stribeck; filmThickness 1e-6;"
        " referenceFilmThickness 1e-6; referenceVelocity 1e-3; n 1; }"
    )
);

//- The message of the FatalIOError that f throws, "" if none
template<class F>
std::string errorOf(const F& f)
{
    try
    {
        f();
    }
    catch (const Foam::IOerror& e)
    {
        return e.message();
    }
    return "";
}

bool holdsAll(const std::string& msg, std::initializer_list<const char*> w)
{
    if (msg.empty())
    {
        return false;
    }
    for (const char* s : w)
    {
        if (msg.find(s) == std::string::npos)
        {
            Info<< "    (message lacks '" << s << "': " << msg.c_str() << ")"
                << endl;
            return false;
        }
    }
    return true;
}

} // End anonymous namespace


int main()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    Info<< "Names, unquoted and quoted paths" << endl;
    {
        const dictionary d
        (
            parse("parameters (mu0 lubrication/filmThickness \"lubrication/n\");")
        );
        const wordList n(lawParameters::names(d, "parameters"));
        unitTest::checkTrue
        (
            "three names: mu0, lubrication/filmThickness, lubrication/n",
            n.size() == 3 && n[0] == "mu0"
         && n[1] == "lubrication/filmThickness" && n[2] == "lubrication/n"
        );
        const scalarList v
        (
            lawParameters::get(lawB, n, d, "parameters")
        );
        unitTest::checkAbs("mu0", v[0], 0.07, 0);
        unitTest::checkAbs("lubrication/filmThickness", v[1], 1e-6, 0);
        unitTest::checkAbs("lubrication/n", v[2], 1, 0);

        const scalar h = 1.2345678901234567e-6;
        const dictionary w
        (
            lawParameters::with(lawB, wordList({n[1]}), scalarList({h}))
        );
        unitTest::checkAbs
        (
            "a value set on lubrication/filmThickness, read back exactly",
            w.subDict("lubrication").get<scalar>("filmThickness"), h, 0
        );
        unitTest::checkAbs
        (
            "and the law it was set in unchanged",
            lawB.subDict("lubrication").get<scalar>("filmThickness"), 1e-6, 0
        );
        unitTest::checkTrue
        (
            "name(): one unquoted path; the default without the entry",
            lawParameters::name
            (
                parse("filmThicknessParameter lubrication/filmThickness;"),
                "filmThicknessParameter", "x"
            ) == "lubrication/filmThickness"
         && lawParameters::name(dictionary(), "filmThicknessParameter", "y")
         == "y"
        );
    }

    Info<< "A parameter the law lacks" << endl;
    {
        auto missing = [](const char* list)
        {
            const dictionary d(parse(std::string("parameters ") + list + ";"));
            return errorOf
            (
                [&]()
                {
                    lawParameters::get
                    (
                        lawB, lawParameters::names(d, "parameters"), d,
                        "parameters"
                    );
                }
            );
        };
        unitTest::checkTrue
        (
            "lubrication/etaZero: names 'parameters', the path and what"
            " 'lubrication' holds",
            holdsAll
            (
                missing("(mu0 lubrication/etaZero)"),
                {
                    "'parameters'", "lubrication/etaZero",
                    "sub-dictionary 'lubrication'", "referenceVelocity"
                }
            )
        );
        unitTest::checkTrue
        (
            "lubricaton/filmThickness (misspelt sub-dictionary): the law's"
            " own keywords",
            holdsAll
            (
                missing("(lubricaton/filmThickness)"),
                {
                    "'parameters'", "lubricaton/filmThickness",
                    "filmViscosity", "lubrication"
                }
            )
        );
        unitTest::checkTrue
        (
            "mux: names it",
            holdsAll(missing("(mux)"), {"'parameters'", "'mux'"})
        );
        unitTest::checkTrue
        (
            "lubrication (a sub-dictionary, not a value): refused",
            holdsAll(missing("(lubrication)"), {"'parameters'"})
        );
    }

    Info<< "Malformed lists" << endl;
    for
    (
        const char* list
      : {"mu0", "(mu0 lubrication/ /n)", "(lubrication/)", "(0.07)",
         "(mu0) extra"}
    )
    {
        const dictionary d(parse(std::string("parameters ") + list + ";"));
        unitTest::checkTrue
        (
            std::string("parameters ") + list + ": refused naming the keyword",
            holdsAll
            (
                errorOf([&]() { lawParameters::names(d, "parameters"); }),
                {"'parameters'"}
            )
        );
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

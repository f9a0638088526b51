/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The strict keyword check (src/strictDictionary/strictDictionary.H):
      - the suggestion: a misspelt keyword (one or two letters wrong,
        swapped, missing or extra, or another case) finds the keyword
        meant; a word far from every known keyword finds none;
      - check() accepts a dictionary of known keywords and refuses an
        unknown one with a message naming the keyword, the suggestion and
        the file;
      - the file of an entry #include'd into a dictionary is that file,
        and nameAfterSource() names it in the dictionary's name;
      - with every directive of OpenFOAM v1912 (#include and its kin,
        #inputMode, #default ... #error, #remove, #includeFunc, #ifeq,
        #if, #eval, #calc, #codeStream) and a $variable written on one
        line inside the braces of a sub-dictionary, the entries' files
        are still found (the dictionary re-read raw does not break);
      - every friction law accepts its full dictionary (all optional
        keywords given) and refuses one unknown keyword added to it.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "strictDictionary.H"
#include "frictionLaw.H"
#include "IStringStream.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include <algorithm>

using namespace Foam;

namespace
{

//- The message of the FatalIOError check() throws ("" if none)
std::string refusal(const dictionary& dict, const wordList& known)
{
    try
    {
        strictDictionary::check(dict, known, "test");
    }
    catch (const Foam::IOerror& e)
    {
        return std::string(e.message()) + " file: " + e.ioFileName();
    }
    return "";
}


//- The message of the FatalIOError the law's constructor throws
std::string lawRefusal(const std::string& text)
{
    try
    {
        IStringStream is(text);
        dictionary d(is);
        frictionLaw::New(d);
    }
    catch (const Foam::IOerror& e)
    {
        return std::string(e.message());
    }
    return "";
}

bool has(const std::string& s, const std::string& part)
{
    return s.find(part) != std::string::npos;
}

} // End anonymous namespace


int main()
{
    FatalIOError.throwExceptions();
    FatalError.throwExceptions();

    Info<< "Suggestions" << endl;
    const wordList known
    ({
        "penaltyScale", "tangentialPenaltyScale", "searchDistance",
        "contactSmoothing", "frictionLaw", "obstacle", "value", "type", "mu",
        "KN"
    });
    const std::pair<word, word> near[] =
    {
        {"penaltyScal", "penaltyScale"},        // a letter missing
        {"penaltyScalee", "penaltyScale"},      // a letter more
        {"searchDistanse", "searchDistance"},   // a letter wrong
        {"contactSmoohting", "contactSmoothing"},  // two swapped
        {"FrictionLaw", "frictionLaw"},         // case
        {"obstacles", "obstacle"},
        {"KNN", "KN"},
        {"vlaue", "value"}
    };
    for (const auto& c : near)
    {
        unitTest::checkTrue
        (
            c.first + " -> " + c.second,
            strictDictionary::nearest(c.first, known) == c.second
        );
    }
    unitTest::checkTrue
    (
        "yieldStress -> no suggestion",
        strictDictionary::nearest("yieldStress", known).empty()
    );
    unitTest::checkTrue
    (
        "origin -> no suggestion",
        strictDictionary::nearest("origin", known).empty()
    );
    {
        const wordList k({"predictor", "predictorContact", "checkJacobian",
                          "checkJacobianStep"});
        unitTest::checkTrue
        (
            "predictorContacts -> predictorContact, not the prefix predictor",
            strictDictionary::nearest("predictorContacts", k)
         == "predictorContact"
        );
        unitTest::checkTrue
        (
            "checkJacobianSteps -> checkJacobianStep",
            strictDictionary::nearest("checkJacobianSteps", k)
         == "checkJacobianStep"
        );
    }
    unitTest::checkTrue
    (
        "sub -> no suggestion (two edits are too many for three letters)",
        strictDictionary::nearest("sub", known).empty()
    );

    Info<< "check()" << endl;
    {
        IStringStream is("type coulomb; mu 0.3; sub { a 1; }");
        dictionary d(is);
        unitTest::checkTrue
        (
            "known keywords (a sub-dictionary among them) accepted",
            refusal(d, wordList({"type", "mu", "sub"})).empty()
        );
        d.add("penaltyScal", 10);
        wordList withSub(known);
        withSub.append("sub");
        const std::string m = refusal(d, withSub);
        unitTest::checkTrue("unknown keyword refused", !m.empty());
        unitTest::checkTrue
        (
            "message names the keyword and the suggestion",
            has(m, "'penaltyScal'") && has(m, "Did you mean 'penaltyScale'")
        );
        d.add(keyType("(a|b)", keyType::REGEX), 1);
        d.remove("penaltyScal");
        unitTest::checkTrue
        (
            "a regular-expression keyword is left alone",
            refusal(d, wordList({"type", "mu", "sub"})).empty()
        );
    }

    Info<< "The file of an #include'd entry" << endl;
    {
        const fileName dir("strictDictionaryFiles");
        mkDir(dir);
        {
            OFstream os(dir/"lawDict");
            os  << "type coulomb;\nmu 0.3;\nmuStatc 0.4;\n";
        }
        {
            OFstream os(dir/"D");
            os  << "bottom\n{\n    type frictionalContact;\n"
                << "    frictionLaw\n    {\n        #include \"lawDict\"\n"
                << "    }\n}\n";
        }
        IFstream is(dir/"D");
        dictionary top(is);
        dictionary law(top.subDict("bottom").subDict("frictionLaw"));
        const fileName src(strictDictionary::sourceFile(law));
        unitTest::checkTrue
        (
            "sourceFile of the law's entries is lawDict (" + src + ")",
            src.name() == "lawDict"
        );
        strictDictionary::nameAfterSource(law);
        unitTest::checkTrue
        (
            "nameAfterSource names the #include'd file (" + law.name() + ")",
            has(law.name(), "lawDict") && has(law.name(), "frictionLaw")
        );
        const std::string m = refusal(law, wordList({"type", "mu"}));
        unitTest::checkTrue
        (
            "the refusal names lawDict, not D",
            has(m, "muStatc") && has(m, "lawDict")
        );

        // the same written on one line: 'frictionLaw { #include "lawDict" }'
        // (read raw, the directive must not take the closing brace)
        {
            OFstream os(dir/"D1");
            os  << "bottom\n{\n    type frictionalContact;\n"
                << "    frictionLaw { #include \"lawDict\" }\n"
                << "    // frictionLaw { #include \"lawDict\" } }\n"
                << "    note \"#include \\\"x\\\" }\";\n}\n";
        }
        IFstream is1(dir/"D1");
        dictionary top1(is1);
        dictionary law1(top1.subDict("bottom").subDict("frictionLaw"));
        const fileName src1(strictDictionary::sourceFile(law1));
        unitTest::checkTrue
        (
            "one-line #include: sourceFile is lawDict (" + src1 + ")",
            src1.name() == "lawDict"
        );
        const std::string m1 = refusal(law1, wordList({"type", "mu"}));
        unitTest::checkTrue
        (
            "one-line #include: the refusal names lawDict",
            has(m1, "muStatc") && has(m1, "file: " + dir/"lawDict")
        );
        const std::string m2 =
            refusal(top1.subDict("bottom"), wordList({"type", "frictionLaw"}));
        unitTest::checkTrue
        (
            "one-line #include: the patch's own refusal names D1, not lawDict",
            has(m2, "note") && has(m2, "D1") && !has(m2, "lawDict")
        );
        rmDir(dir);
    }

    Info<< "Every OpenFOAM directive written on one line inside braces"
        << endl;
    {
        // 'frictionLaw { <form> }' on one line of D: OpenFOAM's reading
        // gives the law lawDict's entries (muStatc among them) and 'extra'
        // written in D; the re-read raw (strictDictionary::rawText) must
        // not break, and must find muStatc in the file that holds it and
        // 'extra' in D. #calc and #codeStream compile code, which OpenFOAM
        // refuses to its administrator (the tests run as root): their
        // dictionaries are made by hand, as OpenFOAM reads them otherwise.
        const fileName dir(cwd()/"strictDictionaryDirectives");
        mkDir(dir/"site"/"etc");
        {
            OFstream os(dir/"lawDict");
            os  << "type coulomb;\nmu 0.3;\nmuStatc 0.4;\n";
        }
        {
            OFstream os(dir/"site"/"etc"/"etcLawDict");
            os  << "type coulomb;\nmu 0.3;\nmuStatc 0.4;\n";
        }
        // #includeEtc finds etcLawDict in $WM_PROJECT_SITE/etc
        setEnv("WM_PROJECT_SITE", dir/"site", true);

        struct form
        {
            std::string text;
            std::string muStatcFile;    // lawDict or etcLawDict
            bool readHere;              // OpenFOAM reads it as root
        };
        const form forms[] =
        {
            {"#inputMode merge #include \"lawDict\" extra 1;", "lawDict", true},
            {"#default extra 1; #include \"lawDict\"", "lawDict", true},
            {"#merge extra 1; #include \"lawDict\"", "lawDict", true},
            {"#overwrite extra 1; #include \"lawDict\"", "lawDict", true},
            {"#warn extra 1; #include \"lawDict\"", "lawDict", true},
            {"#error extra 1; #include \"lawDict\"", "lawDict", true},
            {"#default sub { a 1; } #include \"lawDict\" extra 1;",
             "lawDict", true},
            {"#remove mu #include \"lawDict\" extra 1;", "lawDict", true},
            {"#include \"lawDict\" #remove mu  extra 1;", "lawDict", true},
            {"#remove (a \"b.*\") #include \"lawDict\" extra 1;",
             "lawDict", true},
            {"#include lawDict extra 1;", "lawDict", true},
            {"#sinclude \"lawDict\" extra 1;", "lawDict", true},
            {"#includeIfPresent \"noSuchFile\" #include \"lawDict\" extra 1;",
             "lawDict", true},
            {"#sincludeEtc \"noSuchFile\" #include \"lawDict\" extra 1;",
             "lawDict", true},
            {"#includeEtc \"etcLawDict\" extra 1;", "etcLawDict", true},
            {"#includeFunc patchAverage(name=bottom,fields=(p))"
             " #include \"lawDict\" extra 1;", "lawDict", true},
            {"#ifeq a a #include \"lawDict\" #else #include \"noSuchFile\""
             " #endif extra 1;", "lawDict", true},
            {"#ifeq a b extra 2; #else #include \"lawDict\" #endif extra 1;",
             "lawDict", true},
            {"#ifeq $type frictionalContact #include \"lawDict\" #endif"
             " extra 1;", "lawDict", true},
            {"#if 1\n #include \"lawDict\" #else extra 2; #endif extra 1;",
             "lawDict", true},
            {"#if 0\n extra 2; #elif 1\n #include \"lawDict\" #endif extra 1;",
             "lawDict", true},
            {"$lawBase #include \"lawDict\" extra 1;", "lawDict", true},
            {"#include \"lawDict\" extra #eval{ 1+2 };", "lawDict", true},
            {"#include \"lawDict\" extra #eval \"1+2\";", "lawDict", true},
            {"#calc \"\\\"extra 1;\\\"\" #include \"lawDict\"", "lawDict",
             false},
            {"#codeStream { code #{ os << \"extra 1;\"; #}; }"
             " #include \"lawDict\"", "lawDict", false},
            {"#include \"lawDict\" extra #calc \"1+2\";", "lawDict", false}
        };
        label formi = 0;
        for (const form& f : forms)
        {
            const fileName D(dir/("D" + Foam::name(formi++)));
            {
                OFstream os(D);
                os  << "lawBase { note 2; }\nbottom\n{\n"
                    << "    type frictionalContact;\n"
                    << "    frictionLaw { " << f.text.c_str() << " }\n"
                    << "    after 1;\n}\n";
            }
            std::string line(f.text);
            std::replace(line.begin(), line.end(), '\n', ' ');
            std::string problem;
            try
            {
                dictionary law;
                if (f.readHere)
                {
                    IFstream is(D);
                    dictionary top(is);
                    law = top.subDict("bottom").subDict("frictionLaw");
                }
                else
                {
                    law.name() = D + ".bottom.frictionLaw";
                    law.add("type", "coulomb");
                    law.add("mu", 0.3);
                    law.add("muStatc", 0.4);
                    law.add("extra", 1);
                }
                if (!law.found("muStatc") || !law.found("extra"))
                {
                    problem = "OpenFOAM's reading lacks muStatc or extra";
                }
                const fileName srcMu(strictDictionary::sourceFile(law, "muStatc"));
                const fileName srcExtra(strictDictionary::sourceFile(law, "extra"));
                if (srcMu.name() != f.muStatcFile)
                {
                    problem += " muStatc from " + srcMu;
                }
                if (srcExtra != D)
                {
                    problem += " extra from " + srcExtra;
                }
                strictDictionary::nameAfterSource(law);
            }
            catch (const Foam::error& e)
            {
                problem += " error: " + std::string(e.message());
            }
            unitTest::checkTrue
            (
                "{ " + line + " }: " + (problem.empty() ? "ok" : problem),
                problem.empty()
            );
        }
        rmDir(dir);
    }

    Info<< "Friction laws: full dictionaries accepted, one more refused"
        << endl;
    const std::string base("KN 1e12; KT 1e12; ");
    const std::string laws[] =
    {
        "type coulomb; mu 0.3; muStatic 0.4;",
        "type frictionless;",
        "type curnier; criterion coulomb; f 0.3; C 0; QT 0; Q 0;"
        " referencePressure 1;",
        "type rateState; form standard; a 0.01; b 0.015; muStar 0.6;"
        " VStar 1e-6; creepVelocity 1e-12; initialSlipRate 1e-6;"
        " stateLaw ageing; L 1e-5;",
        "type rateState; a 0.01; b 0.015; muStar 0.6; VStar 1e-6;"
        " stateLaw relaxation; relaxationTime 1; gamma 1;",
        "type lubricatedRateState; M 0.1; D0 1e-6; creepVelocity 1e-9;"
        " muStatic 0.12; muDynamic 0.07; criticalVelocity 1e-3;"
        " filmViscosity 3e11; filmMemoryDistance 0; freshContactAge creep;"
        " slipRateRange (1e-9 1); contactPressureRange (1e6 1e9);"
        " lubrication { type constant; alpha 0.3; }",
        "type lubricatedRateState; M 0.1; D0 1e-6; creepVelocity 1e-9;"
        " muStatic 0.12; muDynamic 0.07; criticalVelocity 1e-3;"
        " filmViscosity 3e11; lubrication { type stribeck;"
        " filmThickness 1e-7; referenceFilmThickness 1e-6;"
        " referenceVelocity 1; n 1; }"
    };
    for (const std::string& l : laws)
    {
        const std::string name(l.substr(0, l.find(';')));
        const std::string ok = lawRefusal(base + l);
        unitTest::checkTrue(name + ": full dictionary accepted", ok.empty());
        if (!ok.empty())
        {
            Info<< "    " << ok.c_str() << endl;
        }
        const std::string m = lawRefusal(base + l + " unknownKeyword 1;");
        unitTest::checkTrue
        (
            name + ": unknownKeyword refused", has(m, "unknownKeyword")
        );
    }
    {
        const std::string m = lawRefusal
        (
            base + "type lubricatedRateState; M 0.1; D0 1e-6;"
            " creepVelocity 1e-9; muStatic 0.12; muDynamic 0.07;"
            " criticalVelocity 1e-3; filmViscosity 3e11;"
            " lubrication { type constant; alpha 0.3; alpah 0.3; }"
        );
        unitTest::checkTrue
        (
            "lubrication weight: 'alpah' refused, 'alpha' suggested",
            has(m, "alpah") && has(m, "Did you mean 'alpha'")
        );
    }

    return unitTest::exitCode();
}


// ************************************************************************* //

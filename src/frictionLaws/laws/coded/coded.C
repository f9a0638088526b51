/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "coded.H"
#include "dynamicCode.H"
#include "dynamicCodeContext.H"
#include "dlLibraryTable.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(coded, 0);
    addToRunTimeSelectionTable(frictionLaw, coded, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dlLibraryTable& Foam::frictionLaws::coded::libs() const
{
    // the laws have no Time: one table for every coded law of the run
    static dlLibraryTable table;
    return table;
}


void Foam::frictionLaws::coded::prepare
(
    dynamicCode& dynCode,
    const dynamicCodeContext& context
) const
{
    dynCode.setFilterVariable("typeName", name_);
    dynCode.addCompileFile("frictionLawTemplate.C");
    dynCode.addCopyFile("frictionLawTemplate.H");
    dynCode.setMakeOptions
    (
        "EXE_INC = \\\n"
        "    -I$(TRIBOFOAM_DIR)/src/frictionLaws/lnInclude \\\n"
      + context.options()
      + "\n\nLIB_LIBS = \\\n"
        "    -lOpenFOAM \\\n"
        "    -L$(FOAM_USER_LIBBIN) -lfrictionLaws \\\n"
      + context.libs()
    );
}


Foam::string Foam::frictionLaws::coded::description() const
{
    return "friction law " + name_ + " (type coded)";
}


void Foam::frictionLaws::coded::clearRedirect() const
{
    redirect_.clear();
}


const Foam::dictionary& Foam::frictionLaws::coded::codeDict() const
{
    return dict_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionLaws::coded::coded(const dictionary& dict)
:
    frictionLaw(dict),
    codedBase(),
    dict_(dict),
    name_(dict.get<word>("name"))
{
    // before the library is made: a misspelled keyword is refused at once,
    // not after a compilation (and the compiled law reads only these)
    checkKeywords
    (
        dict,
        {
            "name", "needsShearYield", "rateDependent",
            "code", "codeInclude", "codeOptions", "codeLibs", "localCode"
        }
    );
    if (!dict.found("code"))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'code': a coded friction law needs the code that"
            << " sets tau (and dtauDtN, dtauDv) from tN, k and v"
            << " (dictionary " << dict.name() << ")" << exit(FatalIOError);
    }
    if (name_ == typeName)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'name': the compiled law needs a name of its own,"
            << " not '" << name_ << "' (dictionary " << dict.name() << ")"
            << exit(FatalIOError);
    }

    // [F40] the templates are triboFoam's: OpenFOAM looks for them in
    // $FOAM_CODE_TEMPLATES (then its own etc), so point it there while
    // the library is made
    const word envName("FOAM_CODE_TEMPLATES");
    const std::string before(getEnv(envName));
    setEnv
    (
        envName,
        getEnv("TRIBOFOAM_DIR") + "/etc/codeTemplates/dynamicCode",
        true
    );
    setCodeContext(dict_);
    updateLibrary(name_);
    setEnv(envName, before, true);

    dictionary d(dict_);
    d.set("type", name_);
    redirect_ = frictionLaw::New(d);
    layout_ = redirect_->stateLayout();
}


// ************************************************************************* //

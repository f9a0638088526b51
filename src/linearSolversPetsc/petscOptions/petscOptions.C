/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "petscOptions.H"
#include "HashSet.H"
#include <algorithm>
#include <cctype>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * * Local helpers * * * * * * * * * * * * * * //

namespace
{

//- Options (full names, lower case) that this class has put into the
//  database: a solver built with the same prefix replaces them, while the
//  others came from PETSC_OPTIONS or a petscrc file
Foam::HashSet<std::string> setHere;

std::string lowerCase(std::string s)
{
    std::transform
    (
        s.begin(), s.end(), s.begin(),
        [](unsigned char c) { return std::tolower(c); }
    );
    return s;
}

bool inDatabase(const std::string& name)
{
    PetscBool found = PETSC_FALSE;
    PetscOptionsHasName(nullptr, nullptr, ("-" + name).c_str(), &found);
    return found;
}

//- The value of a one-token entry as PETSc reads it ("" = no value)
bool tokenText(const Foam::token& t, std::string& text)
{
    if (t.isWord())
    {
        text = t.wordToken();
    }
    else if (t.isString())
    {
        text = t.stringToken();
    }
    else if (t.isLabel())
    {
        text = std::to_string(t.labelToken());
    }
    else if (t.isNumber())
    {
        std::ostringstream os;
        os << std::setprecision(15) << t.number();
        text = os.str();
    }
    else if (t.isBool())
    {
        text = t.boolToken() ? "true" : "false";
    }
    else
    {
        return false;
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::petscOptions::petscOptions(const word& prefix, const dictionary& dict)
:
    prefix_(prefix)
{
    for (const char c : prefix_)
    {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'prefix' in dictionary " << dict.name()
                << " is '" << prefix_ << "': a PETSc options prefix has"
                << " letters, digits and underscores only"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::petscOptions::found(const std::string& option) const
{
    return inDatabase(prefix_ + option);
}


PetscErrorCode Foam::petscOptions::insert(const dictionary& options)
{
    // What an earlier solver of this prefix set is not this one's
    const std::string prefix = lowerCase(prefix_);
    for (const std::string& name : setHere.sortedToc())
    {
        if (name.compare(0, prefix.size(), prefix) == 0)
        {
            PetscCall(PetscOptionsClearValue(nullptr, ("-" + name).c_str()));
            setHere.erase(name);
        }
    }

    for (const entry& e : options)
    {
        std::string key = e.keyword();
        key.erase(0, key.find_first_not_of('-'));

        std::string value;
        const bool oneValue =
            e.isStream() && e.stream().size() == 1
         && tokenText(e.stream()[0], value);
        if (!oneValue)
        {
            FatalIOErrorInFunction(options)
                << "Entry '" << e.keyword() << "' of dictionary "
                << options.name() << ": one value expected (quote a value"
                << " with spaces or '/', use \"\" for an option without"
                << " value)" << exit(FatalIOError);
        }

        const std::string name = prefix_ + key;
        if (inDatabase(name))
        {
            Info<< "Linear solver petsc: -" << name.c_str()
                << " from PETSC_OPTIONS overrides " << e.keyword()
                << " of " << options.name() << endl;
        }
        else
        {
            PetscCall
            (
                PetscOptionsSetValue
                (
                    nullptr, ("-" + name).c_str(),
                    value.empty() ? nullptr : value.c_str()
                )
            );
            setHere.insert(lowerCase(name));
        }
        fromDict_.emplace_back(lowerCase(name), e.keyword());
    }
    return 0;
}


PetscErrorCode Foam::petscOptions::setDefault
(
    const std::string& option,
    const char* value
)
{
    const std::string name = lowerCase(prefix_ + option);
    if (std::find(defaults_.begin(), defaults_.end(), name) == defaults_.end())
    {
        defaults_.push_back(name);
    }
    if (!inDatabase(name))
    {
        PetscCall(PetscOptionsSetValue(nullptr, ("-" + name).c_str(), value));
        setHere.insert(name);
    }
    return 0;
}


PetscErrorCode Foam::petscOptions::unused
(
    std::string& dictionaryKeywords,
    std::string& otherOptions
) const
{
    PetscInt n = 0;
    char** names = nullptr;
    char** values = nullptr;
    PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));

    const std::string prefix = lowerCase(prefix_);
    for (PetscInt i = 0; i < n; ++i)
    {
        std::string name = lowerCase(names[i]);
        name.erase(0, name.find_first_not_of('-'));
        if
        (
            name.compare(0, prefix.size(), prefix) != 0
         || std::find(defaults_.begin(), defaults_.end(), name)
         != defaults_.end()
        )
        {
            continue;
        }
        auto it = std::find_if
        (
            fromDict_.begin(), fromDict_.end(),
            [&name](const std::pair<std::string, word>& o)
            {
                return o.first == name;
            }
        );
        if (it != fromDict_.end())
        {
            dictionaryKeywords += " " + it->second;
        }
        else
        {
            otherOptions += " -" + name;
        }
    }
    PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
    return 0;
}


// ************************************************************************* //

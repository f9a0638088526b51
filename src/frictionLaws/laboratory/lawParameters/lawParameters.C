/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "lawParameters.H"
#include "error.H"
#include "primitiveEntry.H"
#include "ITstream.H"
#include "OStringStream.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- The sub-dictionary holding the last component of path, or nullptr;
//  'reached' is the deepest sub-dictionary of the path that exists (for
//  the message listing what it holds) and 'where' its path
static const dictionary* holder
(
    const dictionary& lawDict,
    const word& path,
    word& key,
    const dictionary*& reached,
    std::string& where
)
{
    const dictionary* d = &lawDict;
    reached = d;
    std::string rest(path);
    std::size_t slash;
    while ((slash = rest.find('/')) != std::string::npos)
    {
        const word sub(rest.substr(0, slash), false);
        if (!d->isDict(sub))
        {
            return nullptr;
        }
        d = &d->subDict(sub);
        reached = d;
        where += (where.empty() ? "" : "/") + sub;
        rest = rest.substr(slash + 1);
    }
    key = word(rest, false);
    return d->found(key) && !d->isDict(key) ? d : nullptr;
}


//- The parameter name starting at token i of toks: a word, or words
//  joined by '/', or a string; i is left after it. Empty if none starts
//  there.
static std::string readName(const tokenList& toks, label& i)
{
    std::string name;
    if (i < toks.size() && toks[i].isString())
    {
        return toks[i++].stringToken();
    }
    while (i < toks.size() && toks[i].isWord())
    {
        name += toks[i++].wordToken();
        if
        (
            i + 1 < toks.size() && toks[i].isPunctuation()
         && toks[i].pToken() == token::DIVIDE && toks[i + 1].isWord()
        )
        {
            name += '/';
            ++i;
        }
        else
        {
            break;
        }
    }
    return name;
}


//- The tokens as written, for a message
static std::string written(const tokenList& toks)
{
    OStringStream os;
    forAll(toks, i)
    {
        os  << (i ? " " : "") << toks[i];
    }
    return os.str();
}


//- A name is keywords joined by single slashes, each a valid word
static bool validName(const std::string& name)
{
    if (name.empty() || name.front() == '/' || name.back() == '/')
    {
        return false;
    }
    for (std::size_t i = 0; i < name.size(); ++i)
    {
        const char c = name[i];
        if (c == '/' ? name[i + 1] == '/' : !word::valid(c))
        {
            return false;
        }
    }
    return true;
}

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::lawParameters::names
(
    const dictionary& dict,
    const word& key
)
{
    // The entry's tokens as they stand: an unquoted path is several
    const tokenList& toks = dict.lookup(key);
    DynamicList<word> out;
    bool closed = false;
    label i = 0;
    if
    (
        toks.size() && toks[0].isPunctuation()
     && toks[0].pToken() == token::BEGIN_LIST
    )
    {
        i = 1;
        while (i < toks.size())
        {
            if
            (
                toks[i].isPunctuation() && toks[i].pToken() == token::END_LIST
            )
            {
                closed = (i + 1 == toks.size());
                break;
            }
            const std::string n(readName(toks, i));
            if (!validName(n))
            {
                break;
            }
            out.append(word(n, false));
        }
    }
    if (!closed)
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': a list of parameter names expected,"
            << " each a keyword of the law or a path to one in its"
            << " sub-dictionaries, as (mu) or (mu lubrication/filmThickness);"
            << " got " << written(toks).c_str() << exit(FatalIOError);
    }
    return wordList(std::move(out));
}


Foam::word Foam::lawParameters::name
(
    const dictionary& dict,
    const word& key,
    const word& deflt
)
{
    if (!dict.found(key))
    {
        return deflt;
    }
    const tokenList& toks = dict.lookup(key);
    label i = 0;
    const std::string n(readName(toks, i));
    if (!validName(n) || i != toks.size())
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': one parameter name expected, a"
            << " keyword of the law or a path to one in its"
            << " sub-dictionaries (as lubrication/filmThickness); got "
            << written(toks).c_str() << exit(FatalIOError);
    }
    return word(n, false);
}


Foam::scalar Foam::lawParameters::get
(
    const dictionary& lawDict,
    const word& path,
    const dictionary& asker,
    const word& key
)
{
    word last;
    const dictionary* reached = nullptr;
    std::string where;
    const dictionary* d = holder(lawDict, path, last, reached, where);
    if (!d)
    {
        FatalIOErrorInFunction(asker)
            << "keyword '" << key << "': the friction law ("
            << lawDict.getOrDefault<word>("type", "?") << ") has no"
            << " parameter '" << path.c_str() << "' in its dictionary; the"
            << " keywords of "
            << (where.empty() ? "its dictionary" : ("its sub-dictionary '" + where + "'").c_str())
            << ": " << reached->toc() << exit(FatalIOError);
    }
    return d->get<scalar>(last);
}


void Foam::lawParameters::set
(
    dictionary& lawDict,
    const word& path,
    const scalar value
)
{
    word last;
    const dictionary* reached = nullptr;
    std::string where;
    const dictionary* d = holder(lawDict, path, last, reached, where);
    if (!d)
    {
        FatalErrorInFunction
            << "the friction law has no parameter '" << path << "'"
            << exit(FatalError);
    }
    // a token holds the double exactly (dictionary::set of a scalar goes
    // through a stream of 6 digits: an optimiser's steps would be lost)
    const_cast<dictionary*>(d)->set
    (
        new primitiveEntry(last, token(doubleScalar(value)))
    );
}


Foam::scalarList Foam::lawParameters::get
(
    const dictionary& lawDict,
    const wordList& paths,
    const dictionary& asker,
    const word& key
)
{
    scalarList values(paths.size());
    forAll(paths, i)
    {
        values[i] = get(lawDict, paths[i], asker, key);
    }
    return values;
}


Foam::dictionary Foam::lawParameters::with
(
    const dictionary& lawDict,
    const wordList& paths,
    const scalarList& values
)
{
    dictionary d(lawDict);
    forAll(paths, i)
    {
        set(d, paths[i], values[i]);
    }
    return d;
}


// ************************************************************************* //

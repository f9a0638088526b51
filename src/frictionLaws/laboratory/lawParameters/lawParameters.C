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

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- The sub-dictionary holding the last component of path, or nullptr
static const dictionary* holder
(
    const dictionary& lawDict,
    const word& path,
    word& key
)
{
    const dictionary* d = &lawDict;
    std::string rest(path);
    std::size_t slash;
    while ((slash = rest.find('/')) != std::string::npos)
    {
        const word sub(rest.substr(0, slash));
        if (!d->isDict(sub))
        {
            return nullptr;
        }
        d = &d->subDict(sub);
        rest = rest.substr(slash + 1);
    }
    key = rest;
    return d->found(key) && !d->isDict(key) ? d : nullptr;
}

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::lawParameters::get
(
    const dictionary& lawDict,
    const word& path,
    const dictionary& asker,
    const word& key
)
{
    word last;
    const dictionary* d = holder(lawDict, path, last);
    if (!d)
    {
        FatalIOErrorInFunction(asker)
            << "keyword '" << key << "': the friction law ("
            << lawDict.getOrDefault<word>("type", "?") << ") has no"
            << " parameter '" << path << "' in its dictionary; its"
            << " keywords: " << lawDict.toc() << exit(FatalIOError);
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
    const dictionary* d = holder(lawDict, path, last);
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

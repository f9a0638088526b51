/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionDataTable.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "DynamicList.H"
#include "error.H"
#include "ListOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionDataTable::frictionDataTable
(
    const dictionary& dict,
    const word& key,
    const labelList& cols
)
:
    file_(dict.get<fileName>(key).expand()),
    columns_(cols.size())
{
    IFstream is(file_);
    if (!is.good())
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << key << "': cannot open the data file "
            << file_ << exit(FatalIOError);
    }

    List<DynamicList<scalar>> data(cols.size());
    const label nNeeded = cols[findMax(cols)] + 1;
    label lineNo = 0;
    string line;
    while (is.good() && is.getLine(line).good())
    {
        ++lineNo;
        const auto hash = line.find('#');
        if (hash != std::string::npos)
        {
            line.erase(hash);
        }
        if (line.find_first_not_of(" \t\r") == std::string::npos)
        {
            continue;
        }

        // The numbers of the row, by OpenFOAM's tokeniser
        IStringStream row(line);
        DynamicList<scalar> values;
        token tok;
        while (!row.read(tok).bad() && tok.good())
        {
            if (!tok.isNumber())
            {
                FatalIOErrorInFunction(dict)
                    << "keyword '" << key << "': file " << file_
                    << ", line " << lineNo << ": '" << tok
                    << "' is not a number" << exit(FatalIOError);
            }
            values.append(tok.number());
        }
        if (values.size() < nNeeded)
        {
            FatalIOErrorInFunction(dict)
                << "keyword '" << key << "': file " << file_ << ", line "
                << lineNo << ": " << values.size() << " columns, column "
                << nNeeded - 1 << " (0-based) needed" << exit(FatalIOError);
        }
        forAll(cols, i)
        {
            data[i].append(values[cols[i]]);
        }
    }

    forAll(cols, i)
    {
        columns_[i].transfer(data[i]);
    }
}


// ************************************************************************* //

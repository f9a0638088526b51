/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "frictionStateLayout.H"
#include "dimensionSets.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionStateLayout::frictionStateLayout()
:
    entries_
    ({
        // name, kind, slot, dimensions, written, shown, older keyword
        {"totalSlip", frictionStateEntry::VECTOR, 0, dimLength.values(),
            true, false, word::null},
        {"plasticSlip", frictionStateEntry::VECTOR, 1, dimLength.values(),
            true, true, word::null},
        {"cumulatedSlip", frictionStateEntry::SCALAR, 0, dimLength.values(),
            true, true, word::null},
        {"slipRate", frictionStateEntry::SCALAR, 1, dimVelocity.values(),
            true, true, word::null},
        {"contactStatus", frictionStateEntry::STATUS, 0, dimless.values(),
            true, true, word::null}
    })
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionStateLayout::add
(
    const word& name,
    const frictionStateEntry::kindType kind,
    const label j,
    const dimensionSet& dims,
    const bool write,
    const bool show,
    const word& oldName
)
{
    const label n =
        kind == frictionStateEntry::VECTOR
      ? frictionState::nVectors
      : frictionState::nScalars;
    if (kind == frictionStateEntry::STATUS || j < 0 || j >= n || found(name))
    {
        FatalErrorInFunction
            << "state variable " << name << ": slot " << j << " outside [0, "
            << n << "), name declared twice or a second status"
            << abort(FatalError);
    }
    entries_.append
    (
        {name, kind, frictionState::firstLawSlot + j, dims.values(), write,
            show, oldName}
    );
}


bool Foam::frictionStateLayout::found(const word& name) const
{
    for (const frictionStateEntry& e : entries_)
    {
        if (e.name == name)
        {
            return true;
        }
    }
    return false;
}


const Foam::frictionStateEntry& Foam::frictionStateLayout::entry
(
    const word& name
) const
{
    for (const frictionStateEntry& e : entries_)
    {
        if (e.name == name)
        {
            return e;
        }
    }
    wordList names(entries_.size());
    forAll(entries_, i)
    {
        names[i] = entries_[i].name;
    }
    FatalErrorInFunction
        << "the law has no state variable '" << name << "'; its variables: "
        << names << exit(FatalError);
    return entries_[0];
}


Foam::word Foam::frictionStateLayout::column(const frictionStateEntry& e)
{
    // SI unit from the exponents of mass, length and time
    const char* sym[3] = {"kg", "m", "s"};
    const dimensionSet::dimensionType idx[3] =
        {dimensionSet::MASS, dimensionSet::LENGTH, dimensionSet::TIME};
    std::string unit;
    for (label i = 0; i < 3; ++i)
    {
        const scalar p = e.dimensions[idx[i]];
        if (p != 0)
        {
            unit += (unit.empty() ? "" : ".") + std::string(sym[i]);
            if (p != 1)
            {
                unit += "^" + std::string(Foam::name(p));
            }
        }
    }
    return e.name + "[" + (unit.empty() ? "-" : unit) + "]";
}


const Foam::frictionStateEntry& Foam::frictionStateLayout::entry
(
    const word& name,
    const bool vectorKind
) const
{
    const frictionStateEntry& e = entry(name);
    if ((e.kind == frictionStateEntry::VECTOR) != vectorKind)
    {
        FatalErrorInFunction
            << "state variable '" << name << "' is "
            << (vectorKind ? "not " : "") << "a vector" << exit(FatalError);
    }
    return e;
}


Foam::scalar Foam::frictionStateLayout::value
(
    const frictionState& s,
    const word& name
) const
{
    const frictionStateEntry& e = entry(name, false);
    return
        e.kind == frictionStateEntry::STATUS
      ? scalar(s.status)
      : s.scalarSlot(e.slot);
}


void Foam::frictionStateLayout::setValue
(
    frictionState& s,
    const word& name,
    const scalar v
) const
{
    const frictionStateEntry& e = entry(name, false);
    if (e.kind == frictionStateEntry::STATUS)
    {
        s.status = label(v + 0.5);
    }
    else
    {
        s.scalarSlot(e.slot) = v;
    }
}


const Foam::vector& Foam::frictionStateLayout::vectorValue
(
    const frictionState& s,
    const word& name
) const
{
    return s.vectorSlot(entry(name, true).slot);
}


void Foam::frictionStateLayout::setVectorValue
(
    frictionState& s,
    const word& name,
    const vector& v
) const
{
    s.vectorSlot(entry(name, true).slot) = v;
}


Foam::tmp<Foam::scalarField> Foam::frictionStateLayout::scalarValues
(
    const UList<frictionState>& states,
    const frictionStateEntry& e
) const
{
    tmp<scalarField> tf(new scalarField(states.size()));
    scalarField& f = tf.ref();
    forAll(states, i)
    {
        f[i] =
            e.kind == frictionStateEntry::STATUS
          ? scalar(states[i].status)
          : states[i].scalarSlot(e.slot);
    }
    return tf;
}


Foam::tmp<Foam::vectorField> Foam::frictionStateLayout::vectorValues
(
    const UList<frictionState>& states,
    const frictionStateEntry& e
) const
{
    tmp<vectorField> tf(new vectorField(states.size()));
    vectorField& f = tf.ref();
    forAll(states, i)
    {
        f[i] = states[i].vectorSlot(e.slot);
    }
    return tf;
}


void Foam::frictionStateLayout::write
(
    Ostream& os,
    const UList<frictionState>& states
) const
{
    for (const frictionStateEntry& e : entries_)
    {
        if (!e.write)
        {
            continue;
        }
        if (e.kind == frictionStateEntry::VECTOR)
        {
            vectorValues(states, e)().writeEntry(e.name, os);
        }
        else
        {
            scalarValues(states, e)().writeEntry(e.name, os);
        }
    }
}


Foam::wordList Foam::frictionStateLayout::keywords() const
{
    DynamicList<word> w;
    for (const frictionStateEntry& e : entries_)
    {
        if (e.write)
        {
            w.append(e.name);
            if (!e.oldName.empty())
            {
                w.append(e.oldName);
            }
        }
    }
    return std::move(w);
}


bool Foam::frictionStateLayout::foundIn(const dictionary& dict) const
{
    for (const frictionStateEntry& e : entries_)
    {
        if
        (
            e.write
         && (dict.found(e.name) || (!e.oldName.empty() && dict.found(e.oldName)))
        )
        {
            return true;
        }
    }
    return false;
}


Foam::wordList Foam::frictionStateLayout::read
(
    const dictionary& dict,
    UList<frictionState>& states
) const
{
    const label n = states.size();
    DynamicList<word> missing;
    for (const frictionStateEntry& e : entries_)
    {
        if (!e.write)
        {
            continue;
        }
        const word key =
            dict.found(e.name) ? e.name
          : !e.oldName.empty() && dict.found(e.oldName) ? e.oldName
          : word::null;
        if (key.empty())
        {
            missing.append(e.name);
        }
        else if (e.kind == frictionStateEntry::VECTOR)
        {
            const vectorField f(key, dict, n);
            forAll(states, i)
            {
                states[i].vectorSlot(e.slot) = f[i];
            }
        }
        else
        {
            const scalarField f(key, dict, n);
            forAll(states, i)
            {
                if (e.kind == frictionStateEntry::STATUS)
                {
                    states[i].status = label(f[i] + 0.5);
                }
                else
                {
                    states[i].scalarSlot(e.slot) = f[i];
                }
            }
        }
    }
    return wordList(missing);
}

// ************************************************************************* //

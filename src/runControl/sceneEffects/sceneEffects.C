/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

\*---------------------------------------------------------------------------*/

#include "sceneEffects.H"
#include "IOdictionary.H"
#include "Time.H"
#include "Switch.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::sceneEffects::collisionMode>
Foam::sceneEffects::collisionModeNames
({
    { collisionMode::off, "off" },
    { collisionMode::on, "on" },
    { collisionMode::automatic, "automatic" },
});


const Foam::wordList Foam::sceneEffects::names
({
    "fluid", "gravity", "collisions", "rotation", "friction",
    "frictionHistory", "periodicity", "fixedParticles"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sceneEffects::sceneEffects()
:
    source_("constant/sceneProperties (none: every effect from the inputs)")
{}


Foam::sceneEffects::sceneEffects(const dictionary& dict)
:
    source_(dict.name())
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (key == "FoamFile")
        {
            continue;
        }
        if (!names.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "unknown effect " << key << " in " << dict.name()
                << "; the effects are " << names << exit(FatalIOError);
        }
        const word value(e.stream());
        if (key == "collisions")
        {
            if (!collisionModeNames.found(value))
            {
                FatalIOErrorInFunction(dict)
                    << "collisions " << value << " in " << dict.name()
                    << " is not one of " << collisionModeNames
                    << exit(FatalIOError);
            }
            declared_.insert(key, value);
        }
        else
        {
            const Switch sw(value, true);
            if (!sw.valid())
            {
                FatalIOErrorInFunction(dict)
                    << key << " " << value << " in " << dict.name()
                    << " is not on or off (or yes/no, true/false)"
                    << exit(FatalIOError);
            }
            declared_.insert(key, sw ? "on" : "off");
        }
    }
}


Foam::sceneEffects Foam::sceneEffects::read(const Time& runTime)
{
    IOobject header
    (
        "sceneProperties",
        runTime.constant(),
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (!header.typeHeaderOk<IOdictionary>(true))
    {
        return sceneEffects();
    }
    return sceneEffects(IOdictionary(header));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::word& Foam::sceneEffects::valueOf(const word& key) const
{
    const auto iter = value_.cfind(key);
    if (!iter.found())
    {
        FatalErrorInFunction
            << "the effect " << key << " is asked for before it is settled"
            << abort(FatalError);
    }
    return *iter;
}


bool Foam::sceneEffects::settle
(
    const word& key,
    const bool inputsAsk,
    const string& origin
)
{
    const auto iter = declared_.cfind(key);
    if (iter.found())
    {
        value_.set(key, *iter);
        origin_.set(key, "declared");
    }
    else
    {
        value_.set(key, inputsAsk ? "on" : "off");
        origin_.set(key, origin);
    }
    return on(key);
}


Foam::sceneEffects::collisionMode Foam::sceneEffects::settleCollisions
(
    const collisionMode inputsAsk,
    const string& origin
)
{
    const auto iter = declared_.cfind("collisions");
    if (iter.found())
    {
        value_.set("collisions", *iter);
        origin_.set("collisions", "declared");
    }
    else
    {
        value_.set("collisions", collisionModeNames[inputsAsk]);
        origin_.set("collisions", origin);
    }
    return collisions();
}


void Foam::sceneEffects::contradiction
(
    const word& key,
    const string& why
) const
{
    FatalErrorInFunction
        << key << " " << declared_.lookup(key, "?") << " is declared in "
        << source_ << ", but " << why.c_str() << exit(FatalError);
}


void Foam::sceneEffects::report(Ostream& os) const
{
    os  << "Effects (" << source_ << "):" << nl;
    for (const word& key : names)
    {
        const auto iter = value_.cfind(key);
        if (!iter.found())
        {
            continue;
        }
        os  << "    " << key;
        for (label k = key.size(); k < 16; ++k)
        {
            os  << ' ';
        }
        os  << *iter << "  (" << origin_[key].c_str() << ")" << nl;
    }
}


// ************************************************************************* //

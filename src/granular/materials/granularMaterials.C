/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Description
    Named materials of a granular scene.

\*---------------------------------------------------------------------------*/

#include "granularMaterials.H"
#include "granularInput.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::granularMaterials::granularMaterials(const dictionary& materialsDict)
{
    const wordList toc(materialsDict.toc());
    if (toc.empty())
    {
        FatalIOErrorInFunction(materialsDict)
            << "no particle material given in " << materialsDict.name()
            << "; give at least one, e.g. glass { density 2500; }"
            << exit(FatalIOError);
    }
    for (const word& name : toc)
    {
        if (!materialsDict.isDict(name))
        {
            FatalIOErrorInFunction(materialsDict)
                << "material " << name << " is not a dictionary;"
                << " expected " << name << " { density <value>; }"
                << exit(FatalIOError);
        }
        const scalar rho = granularInput::positive
        (
            materialsDict.subDict(name),
            "density",
            "material " + name,
            dimDensity
        );
        index_.insert(name, names_.size());
        names_.append(name);
        densities_.append(rho);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::granularMaterials::addWallMaterial(const word& name)
{
    const label existing = find(name);
    if (existing >= 0)
    {
        return existing;
    }
    index_.insert(name, names_.size());
    names_.append(name);
    return names_.size() - 1;
}


Foam::label Foam::granularMaterials::particleMaterial
(
    const word& name,
    const string& owner,
    const dictionary& dict
) const
{
    const label i = find(name);
    if (i < 0 || isWall(i))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": material " << name
            << " is not a particle material; valid names: "
            << SubList<word>(names_, densities_.size())
            << exit(FatalIOError);
    }
    return i;
}


// ************************************************************************* //

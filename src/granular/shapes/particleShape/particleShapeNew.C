/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Class
\*---------------------------------------------------------------------------*/

#include "particleShape.H"
#include "HashTable.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::particleShape> Foam::particleShape::New
(
    const word& name,
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "particleShape",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<particleShape>(cstrIter()(name, dict));
}


Foam::wordList Foam::particleShape::keywords(const word& type)
{
    // Kept beside the selector: a type reads D (equivalent diameter) or
    // edge if it is a preset, vertices and scale if it is general, depth
    // if it is planar
    static const HashTable<wordList> byType
    ({
        {"sphere", wordList({"type", "D"})},
        {"tetrahedron", wordList({"type", "D", "edge"})},
        {"cube", wordList({"type", "D", "edge"})},
        {"octahedron", wordList({"type", "D", "edge"})},
        {"dodecahedron", wordList({"type", "D", "edge"})},
        {"icosahedron", wordList({"type", "D", "edge"})},
        {"convexPolyhedron", wordList({"type", "vertices", "scale"})},
        {"circle", wordList({"type", "D", "depth"})},
        {"convexPolygon", wordList({"type", "vertices", "scale", "depth"})},
        {"square", wordList({"type", "D", "edge", "depth"})},
        {"triangle", wordList({"type", "D", "edge", "depth"})}
    });
    return byType.lookup(type, wordList());
}


// ************************************************************************* //

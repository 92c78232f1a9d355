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

#include "platonicSolid.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "granularInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(platonicSolid, 0);

    // One class, selected under the name of each solid
    addNamedToRunTimeSelectionTable
    (
        particleShape, platonicSolid, dictionary, tetrahedron
    );
    addNamedToRunTimeSelectionTable
    (
        particleShape, platonicSolid, dictionary, cube
    );
    addNamedToRunTimeSelectionTable
    (
        particleShape, platonicSolid, dictionary, octahedron
    );
    addNamedToRunTimeSelectionTable
    (
        particleShape, platonicSolid, dictionary, dodecahedron
    );
    addNamedToRunTimeSelectionTable
    (
        particleShape, platonicSolid, dictionary, icosahedron
    );
}
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::particleShapes::platonicSolid::solids()
{
    static const wordList names
    ({
        "tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"
    });
    return names;
}


Foam::pointField Foam::particleShapes::platonicSolid::unitEdgeVertices
(
    const word& solid
)
{
    const scalar phi = 0.5*(1 + sqrt(5.0));
    DynamicList<point> v;
    scalar edge = 1;

    if (solid == "tetrahedron")
    {
        v.append({point(1, 1, 1), point(1, -1, -1),
                  point(-1, 1, -1), point(-1, -1, 1)});
        edge = 2*sqrt(2.0);
    }
    else if (solid == "cube")
    {
        for (const scalar x : {-1, 1})
            for (const scalar y : {-1, 1})
                for (const scalar z : {-1, 1})
                    v.append(point(x, y, z));
        edge = 2;
    }
    else if (solid == "octahedron")
    {
        for (const scalar s : {-1, 1})
        {
            v.append({point(s, 0, 0), point(0, s, 0), point(0, 0, s)});
        }
        edge = sqrt(2.0);
    }
    else if (solid == "dodecahedron")
    {
        for (const scalar x : {-1, 1})
            for (const scalar y : {-1, 1})
                for (const scalar z : {-1, 1})
                    v.append(point(x, y, z));
        for (const scalar s : {-1, 1})
        {
            for (const scalar t : {-1, 1})
            {
                v.append(point(0, s/phi, t*phi));
                v.append(point(s/phi, t*phi, 0));
                v.append(point(s*phi, 0, t/phi));
            }
        }
        edge = 2/phi;
    }
    else if (solid == "icosahedron")
    {
        for (const scalar s : {-1, 1})
        {
            for (const scalar t : {-1, 1})
            {
                v.append(point(0, s, t*phi));
                v.append(point(s, t*phi, 0));
                v.append(point(s*phi, 0, t));
            }
        }
        edge = 2;
    }
    else
    {
        FatalErrorInFunction
            << "Unknown Platonic solid " << solid << ". Valid: " << solids()
            << exit(FatalError);
    }

    pointField points(std::move(v));
    points /= edge;
    return points;
}


Foam::scalar Foam::particleShapes::platonicSolid::unitEdgeVolume
(
    const word& solid
)
{
    const scalar s5 = sqrt(5.0);
    if (solid == "tetrahedron") return 1/(6*sqrt(2.0));
    if (solid == "cube") return 1;
    if (solid == "octahedron") return sqrt(2.0)/3;
    if (solid == "dodecahedron") return (15 + 7*s5)/4;
    if (solid == "icosahedron") return 5*(3 + s5)/12;

    FatalErrorInFunction
        << "Unknown Platonic solid " << solid << ". Valid: " << solids()
        << exit(FatalError);
    return 0;
}


Foam::scalar Foam::particleShapes::platonicSolid::readEdge
(
    const word& name,
    const word& solid,
    const dictionary& dict
)
{
    const bool hasD = dict.found("D");
    const bool hasEdge = dict.found("edge");

    if (hasD == hasEdge)
    {
        FatalIOErrorInFunction(dict)
            << "shape " << name << " (" << solid << "): give exactly one of"
            << " D (volume-equivalent diameter) or edge (edge length); "
            << (hasD ? "both are" : "neither is") << " given"
            << exit(FatalIOError);
    }

    const scalar value = granularInput::positive
    (
        dict, hasD ? "D" : "edge", "shape " + name, dimLength
    );

    if (hasEdge)
    {
        return value;
    }

    const scalar V = constant::mathematical::pi*pow3(value)/6;
    return cbrt(V/unitEdgeVolume(solid));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::platonicSolid::platonicSolid
(
    const word& name,
    const word& solid,
    const scalar edge
)
:
    convexPolyhedron(name, edge*unitEdgeVertices(solid))
{}


Foam::particleShapes::platonicSolid::platonicSolid
(
    const word& name,
    const dictionary& dict
)
:
    platonicSolid
    (
        name,
        dict.get<word>("type"),
        readEdge(name, dict.get<word>("type"), dict)
    )
{}


// ************************************************************************* //

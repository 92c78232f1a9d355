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
    Convex polygons of 2D cases as prisms one cell deep.

\*---------------------------------------------------------------------------*/

#include "convexPolygon.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "granularInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(convexPolygon, 0);
    addToRunTimeSelectionTable(particleShape, convexPolygon, dictionary);
    // The presets, selected by their own names
    addNamedToRunTimeSelectionTable
    (
        particleShape, convexPolygon, dictionary, square
    );
    addNamedToRunTimeSelectionTable
    (
        particleShape, convexPolygon, dictionary, triangle
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::pointField Foam::particleShapes::convexPolygon::prism
(
    const UList<vector2D>& corners,
    const scalar depth
)
{
    pointField pts(2*corners.size());
    forAll(corners, i)
    {
        pts[2*i] = point(corners[i].x(), corners[i].y(), -0.5*depth);
        pts[2*i + 1] = point(corners[i].x(), corners[i].y(), 0.5*depth);
    }
    return pts;
}


Foam::List<Foam::vector2D> Foam::particleShapes::convexPolygon::readCorners
(
    const word& name,
    const dictionary& dict
)
{
    const word type(dict.get<word>("type"));
    const string owner("shape " + name);

    if (type == typeName)
    {
        List<vector2D> corners(dict.get<List<vector2D>>("vertices"));
        if (corners.size() < 3)
        {
            FatalIOErrorInFunction(dict)
                << owner.c_str() << ": " << corners.size()
                << " vertices; a polygon needs at least 3"
                << exit(FatalIOError);
        }
        scalar scale = 1;
        if (dict.found("scale"))
        {
            scale = granularInput::positive(dict, "scale", owner);
        }
        for (vector2D& c : corners)
        {
            c *= scale;
        }
        return corners;
    }

    // Presets: regular polygons of n sides, edge a, area n a^2/(4 tan(pi/n))
    const label n = type == "square" ? 4 : 3;
    const scalar pi = constant::mathematical::pi;
    const scalar areaPerEdge2 = n/(4*std::tan(pi/n));

    const bool hasD = dict.found("D");
    const bool hasEdge = dict.found("edge");
    if (hasD == hasEdge)
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << " (" << type << "): give either D"
            << " (area-equivalent diameter) or edge; "
            << (hasD ? "both are" : "neither is") << " given"
            << exit(FatalIOError);
    }
    scalar edge;
    if (hasEdge)
    {
        edge = granularInput::positive(dict, "edge", owner, dimLength);
    }
    else
    {
        const scalar D = granularInput::positive(dict, "D", owner, dimLength);
        edge = std::sqrt(pi*sqr(D)/4/areaPerEdge2);
    }

    // Corners on the circumscribed circle, one edge along x at the bottom
    const scalar R = edge/(2*std::sin(pi/n));
    List<vector2D> corners(n);
    for (label k = 0; k < n; ++k)
    {
        const scalar angle = -0.5*pi - pi/n + 2*pi*k/n;
        corners[k] = vector2D(R*std::cos(angle), R*std::sin(angle));
    }
    return corners;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::convexPolygon::convexPolygon
(
    const word& name,
    const UList<vector2D>& corners,
    const scalar depth
)
:
    convexPolyhedron(name, prism(corners, depth)),
    depth_(depth)
{}


Foam::particleShapes::convexPolygon::convexPolygon
(
    const word& name,
    const dictionary& dict
)
:
    convexPolygon
    (
        name,
        readCorners(name, dict),
        granularInput::positive(dict, "depth", "shape " + name, dimLength)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleShapes::convexPolygon::equivalentDiameter() const
{
    return std::sqrt(4*volume()/depth_/constant::mathematical::pi);
}


// ************************************************************************* //

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

#include "posedShape.H"
#include "sphere.H"
#include "circle.H"
#include "convexPolyhedron.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::posedShape::posedShape
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const char* what
)
:
    x_(x),
    R_(R),
    planar_(shape.planar()),
    radius_(-1),
    normals_(nullptr),
    offsets_(nullptr)
{
    if (const auto* s = isA<particleShapes::sphere>(shape))
    {
        radius_ = s->radius();
    }
    else if (const auto* c = isA<particleShapes::circle>(shape))
    {
        radius_ = c->radius();
    }
    else if (const auto* poly = isA<particleShapes::convexPolyhedron>(shape))
    {
        normals_ = &poly->faceNormals();
        offsets_ = &poly->faceOffsets();
    }
    else
    {
        FatalErrorInFunction
            << "shape " << shape.name() << " of type " << shape.type()
            << " has no " << what << " for the fictitious domain; known"
            << " types: sphere, circle and the convex polyhedra and polygons"
            << exit(FatalError);
    }
}


// ************************************************************************* //

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

#include "convexPolyhedron.H"
#include "convexHull.H"
#include "addToRunTimeSelectionTable.H"
#include "granularInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(convexPolyhedron, 0);
    addToRunTimeSelectionTable(particleShape, convexPolyhedron, dictionary);
}
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

void Foam::particleShapes::convexPolyhedron::massProperties
(
    const UList<point>& points,
    const faceList& faces,
    scalar& volume,
    point& centroid,
    symmTensor& secondMoment
)
{
    // Tetrahedra from a point inside the (convex) hull
    point inside(Zero);
    for (const point& p : points)
    {
        inside += p;
    }
    inside /= scalar(points.size());

    volume = 0;
    vector firstMoment(Zero);
    symmTensor C(Zero);

    for (const face& f : faces)
    {
        const vector a = points[f[0]] - inside;
        for (label k = 1; k + 1 < f.size(); ++k)
        {
            const vector b = points[f[k]] - inside;
            const vector c = points[f[k + 1]] - inside;
            const scalar det = a & (b ^ c);

            volume += det/6;
            firstMoment += (det/24)*(a + b + c);
            C += (det/120)*(sqr(a) + sqr(b) + sqr(c) + sqr(a + b + c));
        }
    }

    const vector c = firstMoment/volume;
    centroid = inside + c;
    secondMoment = C - volume*sqr(c);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::particleShapes::convexPolyhedron::build
(
    const UList<point>& vertices
)
{
    convexHull(name(), vertices, points_, faces_);

    point centroid;
    symmTensor C;
    massProperties(points_, faces_, volume_, centroid, C);

    points_ -= centroid;
    volumeInertia_ = tr(C)*symmTensor::I - C;
    boundingRadius_ = max(mag(points_));

    faceNormals_.setSize(faces_.size());
    faceOffsets_.setSize(faces_.size());
    forAll(faces_, facei)
    {
        faceNormals_[facei] = faces_[facei].unitNormal(points_);
        faceOffsets_[facei] = faceNormals_[facei] & points_[faces_[facei][0]];
    }

    // Distinct edge directions (parallel edges once), for separating axes
    DynamicList<vector> dirs;
    for (const face& f : faces_)
    {
        forAll(f, k)
        {
            const vector e = normalised(points_[f.nextLabel(k)] - points_[f[k]]);
            bool found = false;
            for (const vector& d : dirs)
            {
                if (mag(e ^ d) < 1e-9)
                {
                    found = true;
                    break;
                }
            }
            if (!found)
            {
                dirs.append(e);
            }
        }
    }
    edgeDirections_.transfer(dirs);

    // Distinct face normals up to sign (a cube's opposite faces once)
    DynamicList<vector> axes;
    for (const vector& n : faceNormals_)
    {
        bool found = false;
        for (const vector& a : axes)
        {
            if (mag(n ^ a) < 1e-9)
            {
                found = true;
                break;
            }
        }
        if (!found)
        {
            axes.append(n);
        }
    }
    faceAxes_.transfer(axes);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::convexPolyhedron::convexPolyhedron
(
    const word& name,
    const UList<point>& vertices
)
:
    particleShape(name),
    volume_(0),
    volumeInertia_(Zero),
    boundingRadius_(0)
{
    build(vertices);
}


Foam::particleShapes::convexPolyhedron::convexPolyhedron
(
    const word& name,
    const dictionary& dict
)
:
    particleShape(name),
    volume_(0),
    volumeInertia_(Zero),
    boundingRadius_(0)
{
    const scalar scale =
        dict.found("scale")
      ? granularInput::positive(dict, "scale", "shape " + name)
      : 1;

    build(scale*dict.get<pointField>("vertices"));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::particleShapes::convexPolyhedron::support
(
    const vector& dir
) const
{
    label best = 0;
    scalar bestDot = points_[0] & dir;
    for (label i = 1; i < points_.size(); ++i)
    {
        const scalar d = points_[i] & dir;
        if (d > bestDot)
        {
            bestDot = d;
            best = i;
        }
    }
    return points_[best];
}


// ************************************************************************* //

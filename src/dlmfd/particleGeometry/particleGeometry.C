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

#include "particleGeometry.H"
#include "sphere.H"
#include "circle.H"
#include "convexPolyhedron.H"
#include "edgeHashes.H"
#include "posedShape.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Points along segment a-b at spacing <= h, a included, b excluded
void segmentPoints
(
    const point& a,
    const point& b,
    const scalar h,
    DynamicList<point>& points
)
{
    const label n = max(label(1), label(std::ceil(mag(b - a)/h)));
    for (label k = 0; k < n; ++k)
    {
        points.append(a + (scalar(k)/n)*(b - a));
    }
}


//- Points of a grid of spacing h inside a convex planar polygon (body
//- frame corners c, unit normal n), at least h/2 from its edges
void facePoints
(
    const UList<point>& c,
    const vector& n,
    const scalar h,
    DynamicList<point>& points
)
{
    // In-plane axes
    const vector e1 = normalised(c[1] - c[0]);
    const vector e2 = n ^ e1;
    scalar lo1 = GREAT, hi1 = -GREAT, lo2 = GREAT, hi2 = -GREAT;
    for (const point& p : c)
    {
        lo1 = min(lo1, (p - c[0]) & e1);
        hi1 = max(hi1, (p - c[0]) & e1);
        lo2 = min(lo2, (p - c[0]) & e2);
        hi2 = max(hi2, (p - c[0]) & e2);
    }
    const label n1 = label(std::floor((hi1 - lo1)/h));
    const label n2 = label(std::floor((hi2 - lo2)/h));
    // Centre the grid in the face's box
    const scalar o1 = lo1 + 0.5*((hi1 - lo1) - n1*h);
    const scalar o2 = lo2 + 0.5*((hi2 - lo2) - n2*h);
    for (label i = 0; i <= n1; ++i)
    {
        for (label j = 0; j <= n2; ++j)
        {
            const point p = c[0] + (o1 + i*h)*e1 + (o2 + j*h)*e2;
            bool inside = true;
            forAll(c, k)
            {
                const point& a = c[k];
                const point& b = c[(k + 1) % c.size()];
                // Inward normal of edge a-b in the face plane
                const vector m = normalised(n ^ (b - a));
                if (((p - a) & m) < 0.5*h)
                {
                    inside = false;
                    break;
                }
            }
            if (inside)
            {
                points.append(p);
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::particleGeometry::contains
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const point& p
)
{
    return posedShape(shape, x, R, "inside test").contains(p);
}


Foam::scalar Foam::particleGeometry::depth
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const point& p,
    point& foot,
    vector& normal
)
{
    return posedShape(shape, x, R, "depth function").depth(p, foot, normal);
}


Foam::scalar Foam::particleGeometry::outsideDistanceBound
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const point& p
)
{
    return posedShape(shape, x, R, "depth function").outsideDistanceBound(p);
}


void Foam::particleGeometry::surfacePoints
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const scalar h,
    const scalar zPlane,
    DynamicList<point>& points
)
{
    using constant::mathematical::pi;

    if (const auto* s = isA<particleShapes::sphere>(shape))
    {
        const scalar r = s->radius();
        const label n = max(label(12), label(std::round(4*pi*sqr(r/h))));
        const scalar golden = pi*(3 - std::sqrt(5.0));
        for (label k = 0; k < n; ++k)
        {
            const scalar z = 1 - (2*k + 1)/scalar(n);
            const scalar rho = std::sqrt(max(scalar(0), 1 - z*z));
            const scalar phi = golden*k;
            points.append
            (
                x + (R & vector(r*rho*std::cos(phi), r*rho*std::sin(phi), r*z))
            );
        }
        return;
    }

    if (const auto* c = isA<particleShapes::circle>(shape))
    {
        const scalar r = c->radius();
        const label n = max(label(8), label(std::round(2*pi*r/h)));
        for (label k = 0; k < n; ++k)
        {
            const scalar phi = 2*pi*k/n;
            points.append
            (
                point
                (
                    x.x() + r*std::cos(phi),
                    x.y() + r*std::sin(phi),
                    zPlane
                )
            );
        }
        return;
    }

    if (const auto* poly = isA<particleShapes::convexPolyhedron>(shape))
    {
        const pointField& v = poly->points();
        const faceList& faces = poly->faces();
        const vectorField& normals = poly->faceNormals();

        if (shape.planar())
        {
            // The outline: each side face's two distinct corners in the
            // x-y plane make an edge of the polygon
            forAll(faces, f)
            {
                if (!posedShape::isSideFace(normals[f]))
                {
                    continue;
                }
                DynamicList<point> corners;
                for (const label vi : faces[f])
                {
                    point p = v[vi];
                    p.z() = 0;
                    bool seen = false;
                    for (const point& q : corners)
                    {
                        seen = seen || magSqr(q - p) < SMALL*sqr(h);
                    }
                    if (!seen)
                    {
                        corners.append(p);
                    }
                }
                if (corners.size() != 2)
                {
                    continue;
                }
                // Orient a-b along the outline (counter-clockwise about z)
                point a = corners[0], b = corners[1];
                if ((((b - a) ^ normals[f]) & vector(0, 0, 1)) > 0)
                {
                    std::swap(a, b);
                }
                DynamicList<point> body;
                segmentPoints(a, b, h, body);
                for (const point& p : body)
                {
                    point w = x + (R & p);
                    w.z() = zPlane;
                    points.append(w);
                }
            }
            return;
        }

        // Vertices once, edges without their ends, face interiors
        for (const point& p : v)
        {
            points.append(x + (R & p));
        }
        edgeHashSet edges;
        for (const face& f : faces)
        {
            forAll(f, k)
            {
                const edge e(f[k], f.nextLabel(k));
                if (!edges.insert(e))
                {
                    continue;
                }
                const point& a = v[e.first()];
                const point& b = v[e.second()];
                const label n = max(label(1), label(std::ceil(mag(b - a)/h)));
                for (label i = 1; i < n; ++i)
                {
                    points.append(x + (R & (a + (scalar(i)/n)*(b - a))));
                }
            }
        }
        forAll(faces, fi)
        {
            const pointField corners(faces[fi].points(v));
            DynamicList<point> body;
            facePoints(corners, normals[fi], h, body);
            for (const point& p : body)
            {
                points.append(x + (R & p));
            }
        }
        return;
    }

    FatalErrorInFunction
        << "shape " << shape.name() << " of type " << shape.type()
        << " has no surface points for the fictitious domain; known types:"
        << " sphere, circle and the convex polyhedra and polygons"
        << exit(FatalError);
}


// ************************************************************************* //

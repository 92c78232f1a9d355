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
    Foam::narrowPhase: the closed forms (a sphere against a polyhedron,
    shapes against planes) and the separating-axis tests of polygons and
    polyhedra. The choice of test by the pair's shape families:
    narrowPhaseDispatch.C; libccd's GJK/EPA: narrowPhaseGJK.C; two
    polyhedra's contact point from their touching features:
    narrowPhaseFeatures.C.

\*---------------------------------------------------------------------------*/

#include <cmath>

#include "narrowPhase.H"
#include "convexPolyhedron.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- The separating-axis test of two convex point sets: the least
    //- overlap of their projections over the axes tried, and the axis
    //- (pointing from j to i) that gives it
    struct separatingAxes
    {
        const UList<point>& wi;
        const UList<point>& wj;
        scalar best = GREAT;
        vector normal = Zero;

        separatingAxes(const UList<point>& pi, const UList<point>& pj)
        :
            wi(pi),
            wj(pj)
        {}

        //- Try the unit axis a; false if it separates the sets
        bool test(const vector& a)
        {
            scalar iMin = GREAT, iMax = -GREAT, jMin = GREAT, jMax = -GREAT;
            for (const point& x : wi)
            {
                const scalar s = x & a;
                iMin = min(iMin, s);
                iMax = max(iMax, s);
            }
            for (const point& x : wj)
            {
                const scalar s = x & a;
                jMin = min(jMin, s);
                jMax = max(jMax, s);
            }
            const scalar up = jMax - iMin;      // i leaves along +a
            const scalar down = iMax - jMin;    // i leaves along -a
            const scalar o = min(up, down);
            if (o < best)
            {
                best = o;
                normal = up < down ? a : -a;
            }
            return o > 0;
        }
    };
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::narrowPhase::spherePolyhedron
(
    const point& c,
    const scalar r,
    const posedShape& poly,
    contactGeometry& contact,
    const bool inPlane
)
{
    const auto& shape =
        static_cast<const particleShapes::convexPolyhedron&>(poly.shape);
    const pointField& pts = shape.points();

    // Sphere centre in the polyhedron's body frame; in the plane of a 2D
    // case, on the prism's mid-plane
    point cb = (c - poly.centre) & poly.R;
    if (inPlane)
    {
        cb.z() = 0;
    }
    // The end caps of a 2D prism take no part
    const auto skip = [&](const label facei)
    {
        return inPlane && mag(shape.faceNormals()[facei].z()) > 0.5;
    };

    // Largest signed distance to the face planes: <= 0 inside
    label outermost = -1;
    scalar sMax = -GREAT;
    forAll(shape.faces(), facei)
    {
        if (skip(facei))
        {
            continue;
        }
        const scalar s =
            (shape.faceNormals()[facei] & cb) - shape.faceOffsets()[facei];
        if (s > sMax)
        {
            sMax = s;
            outermost = facei;
        }
    }
    if (sMax > r)
    {
        return false;
    }

    point closest(Zero);
    vector nBody;
    scalar overlap;

    if (sMax <= 0)
    {
        // Centre inside: leave through the nearest face
        nBody = shape.faceNormals()[outermost];
        closest = cb - sMax*nBody;
        overlap = r - sMax;
    }
    else
    {
        // Closest point over the faces the centre is outside of
        scalar bestDist2 = GREAT;
        forAll(shape.faces(), facei)
        {
            const vector& nf = shape.faceNormals()[facei];
            const scalar s = (nf & cb) - shape.faceOffsets()[facei];
            if (s <= 0 || skip(facei))
            {
                continue;
            }
            const face& f = shape.faces()[facei];
            const point proj = cb - s*nf;

            // Inside the face polygon: every edge sees it on its left
            bool inside = true;
            forAll(f, i)
            {
                const point& a = pts[f[i]];
                const point& b = pts[f.nextLabel(i)];
                if ((((b - a) ^ (proj - a)) & nf) < 0)
                {
                    inside = false;
                    break;
                }
            }
            if (inside)
            {
                if (sqr(s) < bestDist2)
                {
                    bestDist2 = sqr(s);
                    closest = proj;
                }
                continue;
            }

            // Else the closest point of the polygon's edges
            forAll(f, i)
            {
                const point& a = pts[f[i]];
                const vector ab = pts[f.nextLabel(i)] - a;
                const scalar t =
                    max(scalar(0), min(scalar(1), ((cb - a) & ab)/magSqr(ab)));
                const point q = a + t*ab;
                const scalar d2 = magSqr(cb - q);
                if (d2 < bestDist2)
                {
                    bestDist2 = d2;
                    closest = q;
                }
            }
        }
        const scalar dist = sqrt(bestDist2);
        overlap = r - dist;
        if (overlap <= 0)
        {
            return false;
        }
        nBody = (cb - closest)/dist;
    }

    // Midway between the polyhedron's surface and the sphere's deepest point
    const vector n = poly.R & nBody;
    contact.set(poly.toWorld(closest) - 0.5*overlap*n, n, overlap);
    return true;
}


bool Foam::narrowPhase::supportPlane
(
    const posedShape& body,
    const point& p0,
    const vector& n,
    contactGeometry& contact
)
{
    const point deepest = body.support(-n);
    const scalar overlap = (p0 - deepest) & n;
    if (overlap <= 0)
    {
        return false;
    }

    contact.set(deepest + 0.5*overlap*n, n, overlap);
    return true;
}


bool Foam::narrowPhase::polyhedronPlane
(
    const posedShape& body,
    const point& p0,
    const vector& n,
    contactGeometry& contact
)
{
    if (!supportPlane(body, p0, n, contact))
    {
        return false;
    }
    const scalar overlap = contact.overlap;
    const auto& poly =
        static_cast<const particleShapes::convexPolyhedron&>(body.shape);

    // Depth-weighted mean of the vertices below the plane
    scalar sumDepth = 0;
    point weighted(Zero);
    for (const point& v : poly.points())
    {
        const point x = body.toWorld(v);
        const scalar depth = (p0 - x) & n;
        if (depth > 0)
        {
            sumDepth += depth;
            weighted += depth*x;
        }
    }
    const point onBody = weighted/sumDepth;
    contact.position = onBody + (((p0 - onBody) & n) - 0.5*overlap)*n;

    // Spread of the vertices within the overlap of the deepest one (a
    // face lying on the plane: all its corners)
    scalar r2 = 0;
    label nNear = 0;
    for (const point& v : poly.points())
    {
        const point x = body.toWorld(v);
        if (((p0 - x) & n) > -overlap)
        {
            const vector d = x - onBody;
            r2 += magSqr(d - (d & n)*n);
            ++nNear;
        }
    }
    contact.spread = nNear > 1 ? std::sqrt(r2/nNear) : 0;
    return true;
}


bool Foam::narrowPhase::polygonPolygon
(
    const posedShape& bi,
    const posedShape& bj,
    contactGeometry& contact
)
{
    const auto& pi =
        static_cast<const particleShapes::convexPolyhedron&>(bi.shape);
    const auto& pj =
        static_cast<const particleShapes::convexPolyhedron&>(bj.shape);

    // In-plane corners in the world (each corner appears twice, once per
    // end cap; harmless for projections)
    const auto corners = [](const posedShape& b, const pointField& pts)
    {
        pointField w(pts.size());
        forAll(pts, k)
        {
            w[k] = b.toWorld(pts[k]);
            w[k].z() = 0;
        }
        return w;
    };
    const pointField wi(corners(bi, pi.points()));
    const pointField wj(corners(bj, pj.points()));
    separatingAxes sat(wi, wj);

    // The side normals of both polygons, in the plane
    const auto sides = [&]
    (
        const posedShape& b,
        const particleShapes::convexPolyhedron& poly
    )
    {
        for (const vector& nb : poly.faceNormals())
        {
            if (mag(nb.z()) > 0.5)
            {
                continue;       // an end cap
            }
            vector a = b.R & nb;
            a.z() = 0;
            if (!sat.test(normalised(a)))
            {
                return false;
            }
        }
        return true;
    };
    if (!sides(bi, pi) || !sides(bj, pj))
    {
        return false;
    }

    contact.set(0.5*(bi.centre + bj.centre), sat.normal, sat.best);
    polyhedronContactPoint(bi, bj, contact);
    contact.position.z() = 0.5*(bi.centre.z() + bj.centre.z());
    return true;
}


bool Foam::narrowPhase::polyhedronPolyhedron
(
    const posedShape& bi,
    const posedShape& bj,
    contactGeometry& contact
)
{
    const auto& pi =
        static_cast<const particleShapes::convexPolyhedron&>(bi.shape);
    const auto& pj =
        static_cast<const particleShapes::convexPolyhedron&>(bj.shape);

    // Vertices relative to the midpoint of the centres, for round-off
    const point origin = 0.5*(bi.centre + bj.centre);
    const auto world = [&](const posedShape& b, const pointField& pts)
    {
        pointField w(pts.size());
        const vector c = b.centre - origin;
        forAll(pts, k)
        {
            w[k] = c + (b.R & pts[k]);
        }
        return w;
    };
    const pointField wi(world(bi, pi.points()));
    const pointField wj(world(bj, pj.points()));
    separatingAxes sat(wi, wj);

    // Face normals of both, then the cross products of their edge
    // directions: the least overlap over all of them is the penetration
    // depth, exactly (no bias toward face axes: that overestimated the
    // depth of a resting stack by 20 % and pumped energy into it)
    for (const vector& n : pi.faceAxes())
    {
        if (!sat.test(bi.R & n))
        {
            return false;
        }
    }
    for (const vector& n : pj.faceAxes())
    {
        if (!sat.test(bj.R & n))
        {
            return false;
        }
    }
    for (const vector& ei : pi.edgeDirections())
    {
        const vector wei = bi.R & ei;
        for (const vector& ej : pj.edgeDirections())
        {
            const vector a = wei ^ (bj.R & ej);
            const scalar magA = mag(a);
            if (magA < 1e-9)
            {
                continue;       // parallel edges: a face axis covers them
            }
            if (!sat.test(a/magA))
            {
                return false;
            }
        }
    }

    contact.set(origin, sat.normal, sat.best);
    polyhedronContactPoint(bi, bj, contact);
    return true;
}


// ************************************************************************* //

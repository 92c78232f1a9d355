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

#include <ccd/ccd.h>

#include "narrowPhase.H"
#include "sphere.H"
#include "convexPolyhedron.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- libccd's support callback on a posedShape
    void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out)
    {
        const posedShape& body = *static_cast<const posedShape*>(obj);
        const point s =
            body.support(vector(dir->v[0], dir->v[1], dir->v[2]));
        ccdVec3Set(out, s.x(), s.y(), s.z());
    }

    //- libccd's centre callback: the centroid, inside every convex shape
    void ccdCentre(const void* obj, ccd_vec3_t* out)
    {
        const posedShape& body = *static_cast<const posedShape*>(obj);
        ccdVec3Set(out, body.centre.x(), body.centre.y(), body.centre.z());
    }

    const particleShapes::sphere* asSphere(const particleShape& shape)
    {
        return dynamic_cast<const particleShapes::sphere*>(&shape);
    }
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::narrowPhase::sphereSphere
(
    const point& ci,
    const scalar ri,
    const point& cj,
    const scalar rj,
    contactGeometry& contact
)
{
    const vector d = ci - cj;
    const scalar dist = mag(d);
    const scalar overlap = ri + rj - dist;
    if (overlap <= 0)
    {
        return false;
    }

    // Concentric spheres have no normal: any direction will do
    contact.normal = dist > VSMALL ? d/dist : vector(1, 0, 0);
    contact.overlap = overlap;
    // Midway through the overlap lens
    contact.position = cj + (rj - 0.5*overlap)*contact.normal;
    return true;
}


bool Foam::narrowPhase::spherePlane
(
    const point& c,
    const scalar r,
    const point& p0,
    const vector& n,
    contactGeometry& contact
)
{
    const scalar overlap = r - ((c - p0) & n);
    if (overlap <= 0)
    {
        return false;
    }

    contact.normal = n;
    contact.overlap = overlap;
    contact.position = c - (r - 0.5*overlap)*n;
    return true;
}


bool Foam::narrowPhase::spherePolyhedron
(
    const point& c,
    const scalar r,
    const posedShape& poly,
    contactGeometry& contact
)
{
    const auto& shape =
        static_cast<const particleShapes::convexPolyhedron&>(poly.shape);
    const pointField& pts = shape.points();

    // Sphere centre in the polyhedron's body frame
    const point cb = (c - poly.centre) & poly.R;

    // Largest signed distance to the face planes: <= 0 inside
    label outermost = -1;
    scalar sMax = -GREAT;
    forAll(shape.faces(), facei)
    {
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

    point closest;
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
            if (s <= 0)
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

    contact.normal = poly.R & nBody;
    contact.overlap = overlap;
    // Midway between the polyhedron's surface and the sphere's deepest point
    contact.position = poly.toWorld(closest) - 0.5*overlap*contact.normal;
    return true;
}


bool Foam::narrowPhase::shapePlane
(
    const posedShape& body,
    const point& p0,
    const vector& n,
    contactGeometry& contact
)
{
    if (const particleShapes::sphere* s = asSphere(body.shape))
    {
        return spherePlane(body.centre, s->radius(), p0, n, contact);
    }

    const point deepest = body.support(-n);
    const scalar overlap = (p0 - deepest) & n;
    if (overlap <= 0)
    {
        return false;
    }

    contact.normal = n;
    contact.overlap = overlap;

    const auto* poly =
        dynamic_cast<const particleShapes::convexPolyhedron*>(&body.shape);
    if (!poly)
    {
        contact.position = deepest + 0.5*overlap*n;
        return true;
    }

    // Depth-weighted mean of the vertices below the plane
    scalar sumDepth = 0;
    point weighted(Zero);
    for (const point& v : poly->points())
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
    return true;
}


bool Foam::narrowPhase::shapeShapeGJK
(
    const posedShape& bi,
    const posedShape& bj,
    contactGeometry& contact
)
{
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccdSupport;
    ccd.support2 = ccdSupport;
    ccd.center1 = ccdCentre;
    ccd.center2 = ccdCentre;
    ccd.max_iterations = 1000;
    // Relative to the size of the pair: overlaps are 1e-3 D or less
    const scalar size = bi.shape.boundingRadius() + bj.shape.boundingRadius();
    ccd.epa_tolerance = 1e-12*size;
    ccd.dist_tolerance = 1e-12*size;

    // GJK + EPA: the minimal separating translation. MPR is faster but
    // measures the depth along the line of centres, which for a sphere
    // near a cube's edge was measured 0.1 edge off the true depth.
    ccd_real_t depth;
    ccd_vec3_t dir, pos;
    if (ccdGJKPenetration(&bi, &bj, &ccd, &depth, &dir, &pos) != 0)
    {
        return false;
    }
    if (!(depth > 0))
    {
        return false;
    }

    // libccd moves obj2 (j) along dir to separate: the normal from j to i
    // is -dir
    contact.normal = -normalised(vector(dir.v[0], dir.v[1], dir.v[2]));
    contact.overlap = depth;
    contact.position = point(pos.v[0], pos.v[1], pos.v[2]);
    return true;
}


bool Foam::narrowPhase::shapeShape
(
    const posedShape& bi,
    const posedShape& bj,
    contactGeometry& contact
)
{
    const particleShapes::sphere* si = asSphere(bi.shape);
    const particleShapes::sphere* sj = asSphere(bj.shape);
    if (si && sj)
    {
        return sphereSphere
        (
            bi.centre, si->radius(), bj.centre, sj->radius(), contact
        );
    }

    // Bounding spheres apart: no contact, whichever path would follow
    if
    (
        magSqr(bi.centre - bj.centre)
      > sqr(bi.shape.boundingRadius() + bj.shape.boundingRadius())
    )
    {
        return false;
    }

    const auto* pi =
        dynamic_cast<const particleShapes::convexPolyhedron*>(&bi.shape);
    const auto* pj =
        dynamic_cast<const particleShapes::convexPolyhedron*>(&bj.shape);
    if (si && pj)
    {
        return spherePolyhedron(bi.centre, si->radius(), bj, contact);
    }
    if (sj && pi)
    {
        if (!spherePolyhedron(bj.centre, sj->radius(), bi, contact))
        {
            return false;
        }
        contact.normal = -contact.normal;
        return true;
    }

    return shapeShapeGJK(bi, bj, contact);
}


// ************************************************************************* //

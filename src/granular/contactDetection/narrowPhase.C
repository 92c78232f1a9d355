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
#include <cfenv>
#include <cmath>

#include "narrowPhase.H"
#include "sphere.H"
#include "convexPolyhedron.H"
#include "circle.H"

#include <algorithm>

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


    //- A point of the contact plane with its heights along the normal
    struct featurePoint
    {
        scalar x, y;    //!< coordinates in the plane
        scalar h;       //!< height along the normal
    };

    //- 2D cross product of (a - o) and (b - o)
    scalar cross2(const featurePoint& o, const featurePoint& a, const featurePoint& b)
    {
        return (a.x - o.x)*(b.y - o.y) - (a.y - o.y)*(b.x - o.x);
    }

    //- Convex hull in the plane, counter-clockwise (monotone chain);
    //- collinear points give the two ends
    List<featurePoint> hull2D(List<featurePoint> pts, const scalar tol)
    {
        std::sort
        (
            pts.begin(), pts.end(),
            [](const featurePoint& a, const featurePoint& b)
            {
                return a.x < b.x || (a.x == b.x && a.y < b.y);
            }
        );
        const label n = pts.size();
        if (n < 3)
        {
            return pts;
        }
        List<featurePoint> h(2*n);
        label k = 0;
        for (label i = 0; i < n; ++i)
        {
            while (k >= 2 && cross2(h[k-2], h[k-1], pts[i]) <= tol) --k;
            h[k++] = pts[i];
        }
        for (label i = n - 2, t = k + 1; i >= 0; --i)
        {
            while (k >= t && cross2(h[k-2], h[k-1], pts[i]) <= tol) --k;
            h[k++] = pts[i];
        }
        h.setSize(max(k - 1, label(1)));
        return h;
    }

    //- Height over the plane of a feature, as a linear function fitted to
    //- its points (exact for a planar face)
    struct heightFit
    {
        scalar c0 = 0, cx = 0, cy = 0;

        explicit heightFit(const UList<featurePoint>& f)
        {
            const label n = f.size();
            scalar mx = 0, my = 0, mh = 0;
            for (const featurePoint& p : f) { mx += p.x; my += p.y; mh += p.h; }
            mx /= n; my /= n; mh /= n;
            scalar sxx = 0, sxy = 0, syy = 0, sxh = 0, syh = 0;
            for (const featurePoint& p : f)
            {
                const scalar dx = p.x - mx, dy = p.y - my, dh = p.h - mh;
                sxx += dx*dx; sxy += dx*dy; syy += dy*dy;
                sxh += dx*dh; syh += dy*dh;
            }
            const scalar det = sxx*syy - sxy*sxy;
            const scalar scale = sqr(sxx + syy);
            if (n >= 3 && det > 1e-12*scale)
            {
                cx = (sxh*syy - syh*sxy)/det;
                cy = (syh*sxx - sxh*sxy)/det;
            }
            else if (sxx + syy > 0)
            {
                // A segment: slope along it
                const scalar len2 = sxx + syy;
                cx = sxh/len2;
                cy = syh/len2;
            }
            c0 = mh - cx*mx - cy*my;
        }

        scalar operator()(const scalar x, const scalar y) const
        {
            return c0 + cx*x + cy*y;
        }
    };

    //- Sutherland-Hodgman: the part of subject inside the convex,
    //- counter-clockwise polygon clip
    List<featurePoint> clipPolygon
    (
        const List<featurePoint>& subject,
        const List<featurePoint>& clip
    )
    {
        List<featurePoint> out(subject);
        const label nc = clip.size();
        for (label e = 0; e < nc && out.size(); ++e)
        {
            const featurePoint& a = clip[e];
            const featurePoint& b = clip[(e + 1) % nc];
            const List<featurePoint> in(out);
            DynamicList<featurePoint> kept(in.size() + 2);
            const label ni = in.size();
            for (label i = 0; i < ni; ++i)
            {
                const featurePoint& p = in[i];
                const featurePoint& q = in[(i + 1) % ni];
                const scalar sp = cross2(a, b, p);
                const scalar sq = cross2(a, b, q);
                if (sp >= 0)
                {
                    kept.append(p);
                }
                if ((sp >= 0) != (sq >= 0) && ni > 1)
                {
                    const scalar t = sp/(sp - sq);
                    kept.append
                    (
                        featurePoint
                        {
                            p.x + t*(q.x - p.x), p.y + t*(q.y - p.y), 0
                        }
                    );
                }
            }
            out.transfer(kept);
        }
        return out;
    }

    //- The vertices of a polyhedron within tol of its extreme plane along
    //- dir (the feature that touches), in the plane basis (e1, e2, n)
    List<featurePoint> feature
    (
        const posedShape& body,
        const pointField& bodyPoints,
        const vector& dir,
        const vector& e1,
        const vector& e2,
        const vector& n,
        const scalar tol
    )
    {
        scalar top = -GREAT;
        pointField world(bodyPoints.size());
        forAll(bodyPoints, i)
        {
            world[i] = body.toWorld(bodyPoints[i]);
            top = max(top, world[i] & dir);
        }
        DynamicList<featurePoint> f;
        for (const point& w : world)
        {
            if ((w & dir) >= top - tol)
            {
                f.append(featurePoint{w & e1, w & e2, w & n});
            }
        }
        return List<featurePoint>(std::move(f));
    }


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

    const particleShapes::sphere* asSphere(const particleShape& shape)
    {
        return dynamic_cast<const particleShapes::sphere*>(&shape);
    }
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
    const auto* disc = dynamic_cast<const particleShapes::circle*>(&body.shape);
    if (disc && mag(n.z()) < 1e-9)
    {
        // A wall of the 2D plane: the rim's nearest point, on the mid-plane
        return spherePlane(body.centre, disc->radius(), p0, n, contact);
    }

    const point deepest = body.support(-n);
    const scalar overlap = (p0 - deepest) & n;
    if (overlap <= 0)
    {
        return false;
    }

    contact.set(deepest + 0.5*overlap*n, n, overlap);

    const auto* poly =
        dynamic_cast<const particleShapes::convexPolyhedron*>(&body.shape);
    if (!poly)
    {
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

    // Spread of the vertices within the overlap of the deepest one (a
    // face lying on the plane: all its corners)
    scalar r2 = 0;
    label nNear = 0;
    for (const point& v : poly->points())
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
    ccd.mpr_tolerance = 1e-12*size;

    // GJK + EPA: the minimal separating translation. MPR is faster but
    // measures the depth along the line of centres, which for a sphere
    // near a cube's edge was measured 0.1 edge off the true depth.
    ccd_real_t depth;
    ccd_vec3_t dir, pos;

    // libccd divides by zero on degenerate polytopes (touching faces):
    // run it with the floating-point traps of OpenFOAM (FOAM_SIGFPE) held,
    // then restore them; a non-finite answer falls back to MPR
    fenv_t env;
    feholdexcept(&env);
    // MPR decides whether they intersect: libccd's GJK was seen to call
    // two cubes with centres 0.22 edge apart separate (2 of 15000 random
    // placements). EPA then gives the minimal separating translation.
    int status = ccdMPRIntersect(&bi, &bj, &ccd) ? 0 : -1;
    if (status == 0)
    {
        status = ccdGJKPenetration(&bi, &bj, &ccd, &depth, &dir, &pos);
        if (status != 0)
        {
            // EPA failed on an intersecting pair: MPR's depth
            status = ccdMPRPenetration(&bi, &bj, &ccd, &depth, &dir, &pos);
        }
    }
    const auto finite = [&]()
    {
        return
            std::isfinite(depth)
         && std::isfinite(dir.v[0]) && std::isfinite(dir.v[1])
         && std::isfinite(dir.v[2]) && std::isfinite(pos.v[0])
         && std::isfinite(pos.v[1]) && std::isfinite(pos.v[2]);
    };
    if (status == 0 && !finite())
    {
        status = ccdMPRPenetration(&bi, &bj, &ccd, &depth, &dir, &pos);
        if (status == 0 && !finite())
        {
            status = -1;
        }
    }
    feclearexcept(FE_ALL_EXCEPT);
    fesetenv(&env);

    if (status != 0 || !(depth > 0))
    {
        return false;
    }

    // libccd moves obj2 (j) along dir to separate: the normal from j to i
    // is -dir
    contact.set
    (
        point(pos.v[0], pos.v[1], pos.v[2]),
        -normalised(vector(dir.v[0], dir.v[1], dir.v[2])),
        depth
    );
    return true;
}


void Foam::narrowPhase::polyhedronContactPoint
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

    const vector& n = contact.normal;
    // A basis of the contact plane
    const vector a = mag(n.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0);
    const vector e1 = normalised(a - (a & n)*n);
    const vector e2 = n ^ e1;

    // Features: vertices of i near its lowest plane along n, of j near its
    // highest; the tolerance takes in faces tilted by up to about
    // 1e-3 rad, which the depth weights below then push back flat
    const scalar size = pi.boundingRadius() + pj.boundingRadius();
    const scalar tol = contact.overlap + 1e-3*size;
    const List<featurePoint> fi = feature(bi, pi.points(), -n, e1, e2, n, tol);
    const List<featurePoint> fj = feature(bj, pj.points(), n, e1, e2, n, tol);

    const scalar areaTol = 1e-12*sqr(size);
    const List<featurePoint> hi = hull2D(fi, areaTol);
    const List<featurePoint> hj = hull2D(fj, areaTol);

    // The touching region in the plane
    List<featurePoint> region;
    if (hi.size() == 1 || hj.size() == 1)
    {
        // A vertex: it is the contact
        region = hi.size() == 1 ? hi : hj;
    }
    else if (hi.size() >= 3)
    {
        region = clipPolygon(hj, hi);
    }
    else if (hj.size() >= 3)
    {
        region = clipPolygon(hi, hj);
    }

    if (region.empty())
    {
        // Edge on edge (or features that do not overlap in the plane, by
        // round-off): the middle of the closest points of the two features
        const auto toWorld = [&](const featurePoint& p)
        {
            return p.x*e1 + p.y*e2 + p.h*n;
        };
        const auto ends = [&](const List<featurePoint>& h, point& a, point& b)
        {
            a = toWorld(h.first());
            b = toWorld(h.size() > 1 ? h[1] : h.first());
        };
        point a0, a1, b0, b1;
        ends(hi, a0, a1);
        ends(hj, b0, b1);
        // Closest points of segments [a0, a1] and [b0, b1]
        const vector d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
        const scalar aa = d1 & d1, ee = d2 & d2, ff = d2 & r;
        scalar s = 0, t = 0;
        if (aa > VSMALL && ee > VSMALL)
        {
            const scalar c = d1 & r, bb = d1 & d2;
            const scalar denom = aa*ee - bb*bb;
            s = denom > VSMALL*aa*ee
              ? max(scalar(0), min(scalar(1), (bb*ff - c*ee)/denom))
              : 0;
            t = (bb*s + ff)/ee;
            if (t < 0)
            {
                t = 0;
                s = max(scalar(0), min(scalar(1), -c/aa));
            }
            else if (t > 1)
            {
                t = 1;
                s = max(scalar(0), min(scalar(1), (bb - c)/aa));
            }
        }
        else if (ee > VSMALL)
        {
            t = max(scalar(0), min(scalar(1), ff/ee));
        }
        else if (aa > VSMALL)
        {
            s = max(scalar(0), min(scalar(1), -(d1 & r)/aa));
        }
        contact.position = 0.5*((a0 + s*d1) + (b0 + t*d2));
        contact.spread = 0;
        contact.nPoints = 0;
        return;
    }

    // Weighted by the local overlap (height of j's surface above i's), so
    // that a face pressed deeper on one side is pushed back flat
    const heightFit Hi(fi), Hj(fj);
    scalar sumW = 0;
    scalar x = 0, y = 0;
    contact.nPoints = 0;
    for (const featurePoint& p : region)
    {
        const scalar w = max(Hj(p.x, p.y) - Hi(p.x, p.y), scalar(0));
        sumW += w;
        x += w*p.x;
        y += w*p.y;
        if (w > 0 && contact.nPoints < contactGeometry::maxPoints)
        {
            contact.points[contact.nPoints] =
                p.x*e1 + p.y*e2 + 0.5*(Hi(p.x, p.y) + Hj(p.x, p.y))*n;
            contact.depths[contact.nPoints] = w;
            ++contact.nPoints;
        }
    }
    if (!(sumW > 0))
    {
        sumW = region.size();
        x = 0;
        y = 0;
        for (const featurePoint& p : region)
        {
            x += p.x;
            y += p.y;
        }
    }
    x /= sumW;
    y /= sumW;
    const scalar h = 0.5*(Hi(x, y) + Hj(x, y));
    contact.position = x*e1 + y*e2 + h*n;

    scalar r2 = 0;
    for (const featurePoint& p : region)
    {
        r2 += sqr(p.x - x) + sqr(p.y - y);
    }
    contact.spread = std::sqrt(r2/region.size());
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


bool Foam::narrowPhase::shapeShape
(
    const posedShape& bi,
    const posedShape& bj,
    contactGeometry& contact
)
{
    const auto* ci = dynamic_cast<const particleShapes::circle*>(&bi.shape);
    const auto* cj = dynamic_cast<const particleShapes::circle*>(&bj.shape);
    if (ci || cj)
    {
        // 2D: in the plane of the first body's centre
        if (ci && cj)
        {
            return sphereSphere
            (
                bi.centre, ci->radius(),
                point(bj.centre.x(), bj.centre.y(), bi.centre.z()),
                cj->radius(), contact
            );
        }
        if (ci && isA<particleShapes::convexPolyhedron>(bj.shape))
        {
            return spherePolyhedron
            (
                bi.centre, ci->radius(), bj, contact, true
            );
        }
        if (cj && isA<particleShapes::convexPolyhedron>(bi.shape))
        {
            if
            (
                !spherePolyhedron
                (
                    bj.centre, cj->radius(), bi, contact, true
                )
            )
            {
                return false;
            }
            contact.normal = -contact.normal;
            return true;
        }
    }

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

    if (pi && pj && bi.shape.planar() && bj.shape.planar())
    {
        return polygonPolygon(bi, bj, contact);
    }
    if (pi && pj)
    {
        return polyhedronPolyhedron(bi, bj, contact);
    }

    return shapeShapeGJK(bi, bj, contact);
}


// ************************************************************************* //

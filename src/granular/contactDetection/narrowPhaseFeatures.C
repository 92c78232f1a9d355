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
    Foam::narrowPhase::polyhedronContactPoint: the contact point and spread
    of two touching polyhedra from their touching features (the vertices
    near each one's extreme plane), clipped against each other in the
    contact plane.

\*---------------------------------------------------------------------------*/

#include <cmath>

#include "narrowPhase.H"
#include "convexPolyhedron.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

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
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

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


// ************************************************************************* //

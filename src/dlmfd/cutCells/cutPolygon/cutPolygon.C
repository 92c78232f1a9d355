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

#include "cutPolygon.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    scalar cross2(const vector2D& a, const vector2D& b)
    {
        return a.x()*b.y() - a.y()*b.x();
    }

    //- Add the triangle (0, P, Q), which lies inside the disk
    void addTriangle
    (
        const vector2D& P,
        const vector2D& Q,
        const scalar h,
        cutPolygon::diskSection& s
    )
    {
        const scalar c = cross2(P, Q);
        const scalar a = 0.5*c;
        s.area += a;
        s.moment += (a/3)*(P + Q);
        if (h != 0)
        {
            const scalar h2 = sqr(h);
            const scalar p = Foam::sqrt(h2 + magSqr(P));
            const scalar q = Foam::sqrt(h2 + magSqr(Q));
            // p q + P.Q without cancellation where P.Q < 0 (an angle beyond
            // a right angle at the centre): p^2 q^2 - (P.Q)^2 is
            // h^2 (h^2 + |P|^2 + |Q|^2) + (P x Q)^2
            const scalar PQ = (P & Q);
            const scalar pqPlusPQ =
                PQ >= 0
              ? p*q + PQ
              : (h2*(h2 + magSqr(P) + magSqr(Q)) + sqr(c))/(p*q - PQ);
            s.solidAngle +=
                2*sign(h)*Foam::atan2(c, pqPlusPQ + mag(h)*(p + q) + h2);
        }
    }

    //- Add the circular sector of radius r from the direction of P to that
    //  of Q (the shorter way), for an edge piece outside the circle
    void addSector
    (
        const vector2D& P,
        const vector2D& Q,
        const scalar r,
        const scalar h,
        cutPolygon::diskSection& s
    )
    {
        const scalar angle = Foam::atan2(cross2(P, Q), P & Q);
        if (angle == 0)
        {
            return;
        }
        const vector2D u = P/mag(P);
        const vector2D v = Q/mag(Q);
        s.area += 0.5*sqr(r)*angle;
        s.moment += (pow3(r)/3)*vector2D(v.y() - u.y(), u.x() - v.x());
        if (h != 0)
        {
            s.solidAngle +=
                angle*sign(h)*(1 - mag(h)/Foam::sqrt(sqr(h) + sqr(r)));
        }
    }
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::cutPolygon::clip
(
    const UList<point>& poly,
    const vector& n,
    const scalar d,
    const scalar tol,
    DynamicList<point>& kept
)
{
    kept.clear();
    const label np = poly.size();
    if (!np)
    {
        return;
    }
    scalar sP = (n & poly[0]) - d;
    for (label i = 0; i < np; ++i)
    {
        const point& P = poly[i];
        const point& Q = poly[(i + 1) % np];
        const scalar sQ = (n & Q) - d;
        if (sP <= tol)
        {
            kept.append(P);
        }
        if ((sP < 0 && sQ > tol) || (sP > tol && sQ < 0))
        {
            kept.append(P + (sP/(sP - sQ))*(Q - P));
        }
        sP = sQ;
    }
    if (kept.size() < 3)
    {
        kept.clear();
    }
}


void Foam::cutPolygon::areaAndCentroid
(
    const UList<point>& poly,
    vector& S,
    point& centroid
)
{
    S = Zero;
    centroid = Zero;
    const label np = poly.size();
    if (!np)
    {
        return;
    }
    const point& p0 = poly[0];
    vector weighted(Zero);
    for (label i = 1; i + 1 < np; ++i)
    {
        S += 0.5*((poly[i] - p0) ^ (poly[i + 1] - p0));
    }
    const scalar magS2 = magSqr(S);
    if (magS2 <= 0)
    {
        for (const point& p : poly)
        {
            centroid += p;
        }
        centroid /= np;
        return;
    }
    // Each fan triangle weighted by its area along the polygon's normal, so
    // that a polygon with collinear points has its exact centroid
    scalar total = 0;
    for (label i = 1; i + 1 < np; ++i)
    {
        const scalar w = (((poly[i] - p0) ^ (poly[i + 1] - p0)) & S);
        weighted += w*(poly[i] + poly[i + 1] - 2*p0);
        total += w;
    }
    centroid = p0 + weighted/(3*total);
}


Foam::cutPolygon::diskSection Foam::cutPolygon::cutByDisk
(
    const UList<vector2D>& poly,
    const scalar r,
    const scalar h
)
{
    diskSection s{0, vector2D::zero, 0};
    const label np = poly.size();
    const scalar r2 = sqr(r);
    // Whether an edge runs inside the circle, and whether the centre lies
    // inside the polygon (on the left of every edge, counter-clockwise)
    bool crosses = false;
    scalar twiceArea = 0;
    for (label i = 0; i < np; ++i)
    {
        twiceArea += cross2(poly[i], poly[(i + 1) % np]);
    }
    const scalar orient = (twiceArea < 0 ? -1 : 1);
    bool centreInside = np >= 3;
    for (label i = 0; i < np; ++i)
    {
        const vector2D& A = poly[i];
        const vector2D& B = poly[(i + 1) % np];
        centreInside = centreInside && orient*cross2(A, B) >= 0;
        const vector2D d = B - A;
        const scalar a = magSqr(d);
        if (a > 0)
        {
            const scalar b = (A & d);
            const scalar disc = sqr(b) - a*(magSqr(A) - r2);
            if (disc > 0)
            {
                const scalar root = Foam::sqrt(disc);
                crosses =
                    crosses || ((-b + root)/a > 0 && (-b - root)/a < 1);
            }
        }
    }
    if (!crosses)
    {
        // No edge inside the circle: the whole disk, or nothing (the
        // sectors would add up to either, less round-off)
        if (centreInside)
        {
            s.area = orient*constant::mathematical::pi*r2;
            if (h != 0)
            {
                s.solidAngle =
                    orient*constant::mathematical::twoPi*sign(h)
                   *(1 - mag(h)/Foam::sqrt(sqr(h) + r2));
            }
        }
        return s;
    }
    for (label i = 0; i < np; ++i)
    {
        const vector2D& A = poly[i];
        const vector2D& B = poly[(i + 1) % np];
        const vector2D d = B - A;
        const scalar a = magSqr(d);
        if (a <= 0)
        {
            continue;
        }
        // Where A + t d crosses the circle: a t^2 + 2 b t + c = 0
        const scalar b = (A & d);
        const scalar c = magSqr(A) - r2;
        const scalar disc = sqr(b) - a*c;
        if (disc <= 0)
        {
            addSector(A, B, r, h, s);
            continue;
        }
        const scalar root = Foam::sqrt(disc);
        const scalar t1 = min(max((-b - root)/a, scalar(0)), scalar(1));
        const scalar t2 = min(max((-b + root)/a, scalar(0)), scalar(1));
        const vector2D E = (t1 > 0 ? A + t1*d : A);
        const vector2D F = (t2 < 1 ? A + t2*d : B);
        if (t1 > 0)
        {
            addSector(A, E, r, h, s);
        }
        if (t2 > t1)
        {
            addTriangle(E, F, h, s);
        }
        if (t2 < 1)
        {
            addSector(F, B, r, h, s);
        }
    }
    return s;
}


// ************************************************************************* //

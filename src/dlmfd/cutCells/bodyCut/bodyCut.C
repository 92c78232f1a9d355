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

#include "bodyCut.H"
#include "cutPolygon.H"
#include "sphere.H"
#include "circle.H"
#include "convexPolyhedron.H"
#include "mathematicalConstants.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- A unit vector normal to n
    vector normalTo(const vector& n)
    {
        const vector a = cmptMag(n);
        const vector axis =
            (a.x() <= a.y() && a.x() <= a.z()) ? vector(1, 0, 0)
          : (a.y() <= a.z()) ? vector(0, 1, 0) : vector(0, 0, 1);
        return normalised(n ^ axis);
    }

    //- a before b in the order of their coordinates, x first
    //- a before b in the order of their coordinates, x first; coordinates
    //  within tol count as equal, so that the translated copy of a face
    //  (the other side of a cyclic, its points made apart and equal only
    //  to round-off) has its points in the same order
    bool before(const point& a, const point& b, const scalar tol)
    {
        for (direction i = 0; i < 3; ++i)
        {
            if (a[i] < b[i] - tol)
            {
                return true;
            }
            if (a[i] > b[i] + tol)
            {
                return false;
            }
        }
        return false;
    }

    //- 1e-9 of the span of a face's points: far above round-off, far below
    //  the distance between two of its points
    scalar orderTolerance(const pointField& pts, const face& f)
    {
        point lo(pts[f[0]]), hi(pts[f[0]]);
        for (const label pointi : f)
        {
            lo = min(lo, pts[pointi]);
            hi = max(hi, pts[pointi]);
        }
        return 1e-9*mag(hi - lo);
    }

    //- The part of a planar polygon (normal n) inside the disk of radius r
    //  about foot in its plane, seen from height h on the axis; its
    //  centroid, when it has area, in centroid
    cutPolygon::diskSection cutByDiskAt
    (
        const UList<point>& poly,
        const point& foot,
        const vector& n,
        const vector& e1,
        const scalar r,
        const scalar h,
        point& centroid
    )
    {
        const vector e2 = n ^ e1;
        List<vector2D> flat(poly.size());
        forAll(poly, i)
        {
            const vector d = poly[i] - foot;
            flat[i] = vector2D(d & e1, d & e2);
        }
        const cutPolygon::diskSection s = cutPolygon::cutByDisk(flat, r, h);
        if (s.area > 0)
        {
            const vector2D m = s.moment/s.area;
            centroid = foot + m.x()*e1 + m.y()*e2;
        }
        return s;
    }

    void extend(const UList<point>& ps, point& lo, point& hi)
    {
        for (const point& p : ps)
        {
            lo = min(lo, p);
            hi = max(hi, p);
        }
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::List<Foam::point> Foam::bodyCut::facePolygon
(
    const polyMesh& mesh,
    const label facei
)
{
    const face& f = mesh.faces()[facei];
    const pointField& pts = mesh.points();
    const label n = f.size();
    const scalar tol = orderTolerance(pts, f);
    label first = 0;
    for (label i = 1; i < n; ++i)
    {
        if (before(pts[f[i]], pts[f[first]], tol))
        {
            first = i;
        }
    }
    const label step =
        before(pts[f[(first + 1) % n]], pts[f[(first + n - 1) % n]], tol)
      ? 1 : n - 1;
    List<point> poly(n);
    forAll(poly, i)
    {
        poly[i] = pts[f[(first + i*step) % n]];
    }
    return poly;
}


Foam::labelList Foam::bodyCut::cellFacesInOrder
(
    const polyMesh& mesh,
    const label celli
)
{
    const cell& c = mesh.cells()[celli];
    List<List<point>> polys(c.size());
    forAll(c, i)
    {
        polys[i] = facePolygon(mesh, c[i]);
    }
    const scalar tol = orderTolerance(mesh.points(), mesh.faces()[c[0]]);
    labelList order(identity(c.size()));
    std::sort
    (
        order.begin(),
        order.end(),
        [&polys, tol](const label a, const label b)
        {
            const List<point>& pa = polys[a];
            const List<point>& pb = polys[b];
            for (label k = 0; k < min(pa.size(), pb.size()); ++k)
            {
                if (before(pa[k], pb[k], tol))
                {
                    return true;
                }
                if (before(pb[k], pa[k], tol))
                {
                    return false;
                }
            }
            return pa.size() < pb.size();
        }
    );
    labelList faces(c.size());
    forAll(order, i)
    {
        faces[i] = c[order[i]];
    }
    return faces;
}


Foam::point Foam::bodyCut::lowerCorner
(
    const polyMesh& mesh,
    const label celli
)
{
    point lo(point::max);
    for (const label facei : mesh.cells()[celli])
    {
        for (const label pointi : mesh.faces()[facei])
        {
            lo = min(lo, mesh.points()[pointi]);
        }
    }
    return lo;
}


Foam::scalar Foam::bodyCut::cellVolume(const polyMesh& mesh, const label celli)
{
    const point x0 = lowerCorner(mesh, celli);
    scalar sum = 0;
    for (const label facei : cellFacesInOrder(mesh, celli))
    {
        vector S;
        point cf;
        cutPolygon::areaAndCentroid(facePolygon(mesh, facei), S, cf);
        const scalar sgn =
            ((S & mesh.faceAreas()[facei]) > 0)
         == (mesh.faceOwner()[facei] == celli)
          ? 1 : -1;
        sum += sgn*((cf - x0) & S);
    }
    return sum/3;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyCut::bodyCut
(
    const particleShape& shape,
    const point& x,
    const tensor& R
)
:
    x_(x),
    planar_(shape.planar()),
    radius_(-1),
    boundingRadius_(shape.boundingRadius()),
    tol_(1e-12*(mag(x) + 2*shape.boundingRadius()))
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
        const vectorField& n = poly->faceNormals();
        const scalarField& d = poly->faceOffsets();
        DynamicList<vector> normals;
        DynamicList<scalar> offsets;
        forAll(n, f)
        {
            const vector nw = R & n[f];
            // A planar prism is bounded by its side faces only: the
            // fictitious domain treats it as infinite along z
            if (planar_ && mag(nw.z()) > 0.5)
            {
                continue;
            }
            normals.append(nw);
            offsets.append(d[f] + (nw & x));
        }
        normals_.transfer(normals);
        offsets_.transfer(offsets);
        const faceList& fs = poly->faces();
        DynamicList<List<point>> faces(fs.size());
        forAll(fs, f)
        {
            if (planar_ && mag((R & n[f]).z()) > 0.5)
            {
                continue;
            }
            List<point> world(fs[f].size());
            forAll(fs[f], i)
            {
                world[i] = x + (R & poly->points()[fs[f][i]]);
            }
            faces.append(world);
        }
        faces_.transfer(faces);
    }
    else
    {
        FatalErrorInFunction
            << "shape " << shape.name() << " of type " << shape.type()
            << " has no cut-cell geometry; known types: sphere, circle and"
            << " the convex polyhedra and polygons" << exit(FatalError);
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

bool Foam::bodyCut::mayMeet(const point& lo, const point& hi) const
{
    // The box's point nearest the centre, within the bounding radius?
    scalar d2 = 0;
    for (direction i = 0; i < (planar_ ? 2 : 3); ++i)
    {
        const scalar c = x_[i];
        const scalar gap = max(max(lo[i] - c, c - hi[i]), scalar(0));
        d2 += sqr(gap);
    }
    return d2 <= sqr(boundingRadius_ + tol_);
}


Foam::bodyCut::facePart Foam::bodyCut::polyhedronPart
(
    const UList<point>& poly
) const
{
    work0_ = poly;
    forAll(normals_, k)
    {
        cutPolygon::clip(work0_, normals_[k], offsets_[k], tol_, work1_);
        work0_.transfer(work1_);
        if (work0_.empty())
        {
            break;
        }
    }
    vector S;
    point c;
    cutPolygon::areaAndCentroid(work0_, S, c);
    return {mag(S), c};
}


Foam::bodyCut::facePart Foam::bodyCut::spherePart
(
    const UList<point>& poly,
    const vector& S,
    const point& centroid
) const
{
    const vector n = S/mag(S);
    const scalar h = ((centroid - x_) & n);
    if (mag(h) >= radius_)
    {
        return {0, centroid};
    }
    point c = centroid;
    const scalar area = cutByDiskAt
    (
        poly, x_ + h*n, n, normalTo(n), Foam::sqrt(sqr(radius_) - sqr(h)),
        0, c
    ).area;
    return {max(area, scalar(0)), c};
}


Foam::bodyCut::facePart Foam::bodyCut::circlePart
(
    const UList<point>& poly,
    const vector& S,
    const point& centroid
) const
{
    const vector n = S/mag(S);
    if (mag(n.z()) > 1 - 1e-9)
    {
        // A face normal to z: the disk about the centre's foot
        point c = centroid;
        const scalar area = cutByDiskAt
        (
            poly, point(x_.x(), x_.y(), centroid.z()), n, vector(1, 0, 0),
            radius_, 0, c
        ).area;
        return {max(area, scalar(0)), c};
    }
    if (mag(n.z()) < 1e-9)
    {
        // A face parallel to z: the strip the cylinder cuts from its plane
        const scalar h = ((centroid - x_) & n);
        if (mag(h) >= radius_)
        {
            return {0, centroid};
        }
        const vector t = normalised(vector(0, 0, 1) ^ n);
        const scalar w = Foam::sqrt(sqr(radius_) - sqr(h));
        cutPolygon::clip(poly, t, (t & x_) + w, tol_, work0_);
        cutPolygon::clip(work0_, -t, -(t & x_) + w, tol_, work1_);
        vector Sp;
        point c;
        cutPolygon::areaAndCentroid(work1_, Sp, c);
        return {mag(Sp), c};
    }
    FatalErrorInFunction
        << "a face with normal " << n << " is neither normal nor parallel"
        << " to z; a circle's (2D) mesh has faces of those two kinds only"
        << exit(FatalError);
    return {0, centroid};
}


Foam::bodyCut::cellPart Foam::bodyCut::polyhedronCell
(
    const polyMesh& mesh,
    const label celli
) const
{
    const point x0 = lowerCorner(mesh, celli);
    const labelList c = cellFacesInOrder(mesh, celli);
    List<vector> planeNormals(c.size());
    List<scalar> planeOffsets(c.size());
    scalar sum = 0;
    vector wallArea(Zero);
    vector wallMoment(Zero);
    scalar wallWeight = 0;
    // A planar prism's side faces span the cell along z
    scalar zLo = GREAT, zHi = -GREAT;
    if (planar_)
    {
        const point lo = lowerCorner(mesh, celli);
        zLo = lo.z();
        for (const label facei : c)
        {
            for (const label pointi : mesh.faces()[facei])
            {
                zHi = max(zHi, mesh.points()[pointi].z());
            }
        }
    }
    forAll(c, i)
    {
        const label facei = c[i];
        const List<point> poly = facePolygon(mesh, facei);
        vector S;
        point cf;
        cutPolygon::areaAndCentroid(poly, S, cf);
        // Out of the cell: the polygon's own normal, turned where it points
        // in (the face's neighbour, or the polygon's order reversed)
        const scalar sgn =
            ((S & mesh.faceAreas()[facei]) > 0)
         == (mesh.faceOwner()[facei] == celli)
          ? 1 : -1;
        planeNormals[i] = sgn*S/mag(S);
        planeOffsets[i] = (planeNormals[i] & cf);

        polyhedronPart(poly);
        // polyhedronPart left the clipped polygon in work0_
        vector Ss;
        point cs;
        cutPolygon::areaAndCentroid(work0_, Ss, cs);
        sum += sgn*((cs - x0) & Ss);
    }
    forAll(faces_, k)
    {
        const vector& nk = normals_[k];
        // A body face in the plane of a cell face with the same outward
        // normal is that cell face's solid part, counted above
        bool onCellFace = false;
        forAll(planeNormals, i)
        {
            if ((nk & planeNormals[i]) > 1 - 1e-9)
            {
                bool inPlane = true;
                for (const point& p : faces_[k])
                {
                    if (mag((planeNormals[i] & p) - planeOffsets[i]) > tol_)
                    {
                        inPlane = false;
                        break;
                    }
                }
                if (inPlane)
                {
                    onCellFace = true;
                    break;
                }
            }
        }
        if (onCellFace)
        {
            continue;
        }
        work0_ = faces_[k];
        if (planar_)
        {
            for (point& p : work0_)
            {
                p.z() = (p.z() > x_.z() ? zHi : zLo);
            }
        }
        forAll(planeNormals, i)
        {
            cutPolygon::clip
            (
                work0_, planeNormals[i], planeOffsets[i], tol_, work1_
            );
            work0_.transfer(work1_);
            if (work0_.empty())
            {
                break;
            }
        }
        vector Sk;
        point ck;
        cutPolygon::areaAndCentroid(work0_, Sk, ck);
        sum += ((ck - x0) & Sk);
        wallArea += Sk;
        wallMoment += mag(Sk)*(ck - x0);
        wallWeight += mag(Sk);
    }
    return
    {
        planar_ ? planarVolume(mesh, celli) : sum/3,
        wallArea,
        wallWeight > 0 ? x0 + wallMoment/wallWeight : x0
    };
}


Foam::scalar Foam::bodyCut::centreShare
(
    const UList<vector>& normals,
    const UList<scalar>& heights,
    const scalar tol
) const
{
    DynamicList<vector> through;
    forAll(heights, i)
    {
        if (heights[i] < -tol)
        {
            return 0;
        }
        if (heights[i] <= tol)
        {
            bool seen = false;
            for (const vector& n : through)
            {
                seen = seen || (n & normals[i]) > 1 - 1e-9;
            }
            if (!seen)
            {
                through.append(normals[i]);
            }
        }
    }
    // The interior dihedral angle between two planes of outward normals
    // a and b is pi less the angle between the normals
    auto dihedral = [](const vector& a, const vector& b)
    {
        return constant::mathematical::pi
          - Foam::acos(min(max(a & b, scalar(-1)), scalar(1)));
    };
    switch (through.size())
    {
        case 0: return 1;
        case 1: return 0.5;
        case 2:
            return dihedral(through[0], through[1])
               /constant::mathematical::twoPi;
        case 3:
            // A corner's solid angle is its dihedral angles' sum less pi
            return
            (
                dihedral(through[0], through[1])
              + dihedral(through[0], through[2])
              + dihedral(through[1], through[2])
              - constant::mathematical::pi
            )/(2*constant::mathematical::twoPi);
    }
    FatalErrorInFunction
        << "a sphere's centre " << x_ << " lies on " << through.size()
        << " planes of one cell; a hexahedral cell's corner has three"
        << exit(FatalError);
    return 0;
}


Foam::bodyCut::cellPart Foam::bodyCut::roundCell
(
    const polyMesh& mesh,
    const label celli
) const
{
    const labelList c = cellFacesInOrder(mesh, celli);
    const point x0 = lowerCorner(mesh, celli);
    List<vector> outward(c.size());
    List<scalar> heights(c.size());
    const scalar R3 = pow3(radius_);
    scalar sum = 0;
    // The solid parts' area vectors out of the cell, for the wall's closure
    vector solidOut(Zero);
    scalar zSum = 0;
    forAll(c, i)
    {
        const label facei = c[i];
        const List<point> poly = facePolygon(mesh, facei);
        vector S;
        point cf;
        cutPolygon::areaAndCentroid(poly, S, cf);
        zSum += cf.z();
        // Out of the cell: the polygon's own normal, turned where it points
        // in (the face's neighbour, or the polygon's order reversed)
        const scalar sgn =
            ((S & mesh.faceAreas()[facei]) > 0)
         == (mesh.faceOwner()[facei] == celli)
          ? 1 : -1;
        const vector n = S/mag(S);
        if (planar_)
        {
            solidOut += sgn*solidPart(poly).area*n;
            continue;
        }
        scalar h = ((cf - x_) & n);
        outward[i] = sgn*n;
        heights[i] = sgn*h;
        if (mag(h) >= radius_)
        {
            continue;
        }
        point lo = poly[0], hi = poly[0];
        extend(poly, lo, hi);
        if (!mayMeet(lo, hi))
        {
            continue;
        }
        // The plane through the centre (within tol_): no solid angle from
        // there, and h A = 0; centreShare carries the share
        const bool throughCentre = mag(h) <= tol_;
        point unused;
        const cutPolygon::diskSection s = cutByDiskAt
        (
            poly, x_ + h*n, n, normalTo(n),
            Foam::sqrt(sqr(radius_) - sqr(h)), throughCentre ? 0 : h, unused
        );
        solidOut += sgn*s.area*n;
        if (!throughCentre)
        {
            sum += sgn*(h*s.area - R3*s.solidAngle)/3;
        }
    }
    // The wall's centroid: the surface point along its mean normal (on a
    // sphere the pressure's moment about the centre is then zero, as it is
    // on the sphere itself)
    const vector wallArea = -solidOut;
    point wallCentroid = x0;
    if (magSqr(wallArea) > 0)
    {
        wallCentroid = x_ + radius_*wallArea/mag(wallArea);
        if (planar_)
        {
            wallCentroid.z() = zSum/c.size();
        }
    }
    const scalar volume =
        planar_
      ? planarVolume(mesh, celli)
      : sum
      + (2*constant::mathematical::twoPi/3)*R3
       *centreShare(outward, heights, tol_);
    return {volume, wallArea, wallCentroid};
}


Foam::scalar Foam::bodyCut::planarVolume
(
    const polyMesh& mesh,
    const label celli
) const
{
    // A prism along z one cell deep: the solid fraction of its face normal
    // to z
    for (const label facei : mesh.cells()[celli])
    {
        const vector& S = mesh.faceAreas()[facei];
        if (mag(S.z()) > 0.5*mag(S))
        {
            const List<point> poly = facePolygon(mesh, facei);
            vector Sc;
            point cf;
            cutPolygon::areaAndCentroid(poly, Sc, cf);
            return cellVolume(mesh, celli)*solidPart(poly).area/mag(Sc);
        }
    }
    FatalErrorInFunction
        << "cell " << celli << " has no face normal to z; a planar"
        << " shape's (2D) mesh is one cell deep along z"
        << exit(FatalError);
    return 0;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::bodyCut::contains(const point& p) const
{
    vector d = p - x_;
    if (planar_)
    {
        d.z() = 0;
    }
    if (radius_ >= 0)
    {
        return magSqr(d) < sqr(radius_);
    }
    forAll(normals_, k)
    {
        if ((normals_[k] & p) >= offsets_[k])
        {
            return false;
        }
    }
    return true;
}


Foam::bodyCut::facePart Foam::bodyCut::solidPart
(
    const UList<point>& poly
) const
{
    vector S;
    point centroid;
    cutPolygon::areaAndCentroid(poly, S, centroid);
    const scalar A = mag(S);
    if (A <= 0)
    {
        return {0, centroid};
    }
    point lo = poly[0], hi = poly[0];
    extend(poly, lo, hi);
    if (!mayMeet(lo, hi))
    {
        return {0, centroid};
    }
    if (radius_ < 0)
    {
        return polyhedronPart(poly);
    }
    bool inside = true;
    for (const point& p : poly)
    {
        inside = inside && contains(p);
    }
    if (inside)
    {
        return {A, centroid};
    }
    return planar_ ? circlePart(poly, S, centroid) : spherePart(poly, S, centroid);
}


Foam::bodyCut::facePart Foam::bodyCut::solidPartOfFace
(
    const polyMesh& mesh,
    const label facei
) const
{
    return solidPart(facePolygon(mesh, facei));
}


Foam::bodyCut::cellPart Foam::bodyCut::solidPartOfCell
(
    const polyMesh& mesh,
    const label celli
) const
{
    const cell& c = mesh.cells()[celli];
    point lo(point::max), hi(point::min);
    bool inside = true;
    for (const label facei : c)
    {
        for (const label pointi : mesh.faces()[facei])
        {
            const point& p = mesh.points()[pointi];
            lo = min(lo, p);
            hi = max(hi, p);
            inside = inside && contains(p);
        }
    }
    if (!mayMeet(lo, hi))
    {
        return {0, Zero, lo};
    }
    if (inside)
    {
        return {cellVolume(mesh, celli), Zero, lo};
    }
    return radius_ < 0 ? polyhedronCell(mesh, celli) : roundCell(mesh, celli);
}


// ************************************************************************* //

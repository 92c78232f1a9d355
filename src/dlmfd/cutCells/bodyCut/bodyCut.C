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
#include "pointOrder.H"
#include "sphere.H"
#include "circle.H"
#include "convexPolyhedron.H"
#include "mathematicalConstants.H"

#include <vector>


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

bool Foam::bodyCut::mayMeet(const boundBox& bb) const
{
    // The box's point nearest the centre, within the bounding radius?
    scalar d2 = 0;
    for (direction i = 0; i < (planar_ ? 2 : 3); ++i)
    {
        const scalar c = x_[i];
        const scalar gap =
            max(max(bb.min()[i] - c, c - bb.max()[i]), scalar(0));
        d2 += sqr(gap);
    }
    return d2 <= sqr(boundingRadius_ + tol_);
}


const Foam::DynamicList<Foam::point>& Foam::bodyCut::clipByBody
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
    return work0_;
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
        return {0, centroid, S};
    }
    point c = centroid;
    const scalar area = cutByDiskAt
    (
        poly, x_ + h*n, n, normalTo(n), Foam::sqrt(sqr(radius_) - sqr(h)),
        0, c
    ).area;
    return {max(area, scalar(0)), c, S};
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
        return {max(area, scalar(0)), c, S};
    }
    if (mag(n.z()) < 1e-9)
    {
        // A face parallel to z: the strip the cylinder cuts from its plane
        const scalar h = ((centroid - x_) & n);
        if (mag(h) >= radius_)
        {
            return {0, centroid, S};
        }
        const vector t = normalised(vector(0, 0, 1) ^ n);
        const scalar w = Foam::sqrt(sqr(radius_) - sqr(h));
        cutPolygon::clip(poly, t, (t & x_) + w, tol_, work0_);
        cutPolygon::clip(work0_, -t, -(t & x_) + w, tol_, work1_);
        vector Sp;
        point c;
        cutPolygon::areaAndCentroid(work1_, Sp, c);
        return {mag(Sp), c, S};
    }
    FatalErrorInFunction
        << "a face with normal " << n << " is neither normal nor parallel"
        << " to z; a circle's (2D) mesh has faces of those two kinds only"
        << exit(FatalError);
    return {0, centroid, S};
}


Foam::bodyCut::cellPart Foam::bodyCut::polyhedronCell
(
    const polyMesh& mesh,
    const label celli
) const
{
    point x0, hi;
    pointOrder::cellBounds(mesh, celli, x0, hi);
    const labelList c = pointOrder::cellFaces(mesh, celli);
    List<vector> planeNormals(c.size());
    List<scalar> planeOffsets(c.size());
    // The body's faces that lie in a cell face's plane with the same
    // outward normal: that cell face's solid part is their part, counted
    // once, with the cell face. Decided from the cell face's points, as its
    // clipping by the body plane was (within tol_: kept whole), so that
    // both agree
    std::vector<bool> onCellFace(faces_.size(), false);
    scalar sum = 0;
    forAll(c, i)
    {
        const label facei = c[i];
        const List<point> poly = pointOrder::facePolygon(mesh, facei);
        vector S;
        point cf;
        cutPolygon::areaAndCentroid(poly, S, cf);
        const scalar sgn = pointOrder::outwardSign(mesh, facei, celli, S);
        planeNormals[i] = sgn*S/mag(S);
        planeOffsets[i] = (planeNormals[i] & cf);

        forAll(faces_, k)
        {
            if ((normals_[k] & planeNormals[i]) > 1 - 1e-9)
            {
                bool inPlane = true;
                for (const point& p : poly)
                {
                    inPlane =
                        inPlane && mag((normals_[k] & p) - offsets_[k]) <= tol_;
                }
                if (inPlane)
                {
                    onCellFace[k] = true;
                }
            }
        }

        vector Ss;
        point cs;
        cutPolygon::areaAndCentroid(clipByBody(poly), Ss, cs);
        sum += sgn*((cs - x0) & Ss);
    }
    vector wallArea(Zero);
    vector wallMoment(Zero);
    scalar wallWeight = 0;
    forAll(faces_, k)
    {
        if (onCellFace[k])
        {
            continue;
        }
        work0_ = faces_[k];
        if (planar_)
        {
            // A planar prism's side faces span the cell along z
            for (point& p : work0_)
            {
                p.z() = (p.z() > x_.z() ? hi.z() : x0.z());
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
    const UList<scalar>& heights
) const
{
    DynamicList<vector> through;
    forAll(heights, i)
    {
        if (heights[i] < 0)
        {
            return 0;
        }
        if (heights[i] == 0)
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
    const labelList c = pointOrder::cellFaces(mesh, celli);
    point x0, hi;
    pointOrder::cellBounds(mesh, celli, x0, hi);
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
        const List<point> poly = pointOrder::facePolygon(mesh, facei);
        vector S;
        point cf;
        cutPolygon::areaAndCentroid(poly, S, cf);
        zSum += cf.z();
        const scalar sgn = pointOrder::outwardSign(mesh, facei, celli, S);
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
        if (!mayMeet(boundBox(poly, false)))
        {
            continue;
        }
        // A plane through the centre (h exactly 0): no solid angle from
        // there, and h A = 0; centreShare carries the share. Near it (h
        // tiny) the solid angle tends to the same share continuously
        point unused;
        const cutPolygon::diskSection s = cutByDiskAt
        (
            poly, x_ + h*n, n, normalTo(n),
            Foam::sqrt(sqr(radius_) - sqr(h)), h, unused
        );
        solidOut += sgn*s.area*n;
        sum += sgn*(h*s.area - R3*s.solidAngle)/3;
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
       *centreShare(outward, heights);
    return {volume, wallArea, wallCentroid};
}


Foam::scalar Foam::bodyCut::planarVolume
(
    const polyMesh& mesh,
    const label celli
) const
{
    // A prism along z one cell deep: the solid fraction of its first face
    // normal to z in point order (the same face on every decomposition)
    for (const label facei : pointOrder::cellFaces(mesh, celli))
    {
        const vector& S = mesh.faceAreas()[facei];
        if (mag(S.z()) > 0.5*mag(S))
        {
            const List<point> poly = pointOrder::facePolygon(mesh, facei);
            vector Sc;
            point cf;
            cutPolygon::areaAndCentroid(poly, Sc, cf);
            return pointOrder::cellVolume(mesh, celli)
               *solidPart(poly).area/mag(Sc);
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
    if (A <= 0 || !mayMeet(boundBox(poly, false)))
    {
        return {0, centroid, S};
    }
    if (radius_ < 0)
    {
        vector Sp;
        point c;
        cutPolygon::areaAndCentroid(clipByBody(poly), Sp, c);
        return {mag(Sp), c, S};
    }
    bool inside = true;
    for (const point& p : poly)
    {
        inside = inside && contains(p);
    }
    if (inside)
    {
        return {A, centroid, S};
    }
    facePart part =
        planar_ ? circlePart(poly, S, centroid) : spherePart(poly, S, centroid);
    part.faceArea = S;
    return part;
}


Foam::bodyCut::facePart Foam::bodyCut::solidPartOfFace
(
    const polyMesh& mesh,
    const label facei
) const
{
    return solidPart(pointOrder::facePolygon(mesh, facei));
}


Foam::bodyCut::cellPart Foam::bodyCut::solidPartOfCell
(
    const polyMesh& mesh,
    const label celli
) const
{
    const boundBox bb(mesh.points(), mesh.cellPoints()[celli], false);
    if (!mayMeet(bb))
    {
        return {0, Zero, bb.min()};
    }
    bool inside = true;
    for (const label pointi : mesh.cellPoints()[celli])
    {
        inside = inside && contains(mesh.points()[pointi]);
    }
    if (inside)
    {
        return {pointOrder::cellVolume(mesh, celli), Zero, bb.min()};
    }
    return radius_ < 0 ? polyhedronCell(mesh, celli) : roundCell(mesh, celli);
}


// ************************************************************************* //

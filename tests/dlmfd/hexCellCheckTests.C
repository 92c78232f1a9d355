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
    The mesh check of the coupling (hexCellCheck): hexahedra pass, and so
    do split hexahedra (a coarse cell beside eight cells of half its size,
    with hanging vertices on its faces, as refineHexMesh makes them);
    tetrahedra are refused, with the first of them named and what is
    supported said.

\*---------------------------------------------------------------------------*/

#include "foamTestCase.H"
#include "testInput.H"
#include "hexCellCheck.H"
#include "cellModel.H"
#include "cellShape.H"
#include "wallPolyPatch.H"
#include "labelVector.H"

#include <gtest/gtest.h>
#include <map>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- An axis-aligned box cell
struct box
{
    point lo, hi;
};

//- A mesh of axis-aligned boxes that tile a box, conforming or with hanging
//  vertices (a face is the overlap of two boxes' faces, its outline
//  carrying every mesh point on its edges), all boundary faces in one wall
//  patch
autoPtr<polyMesh> meshOfBoxes(const Time& runTime, const List<box>& boxes)
{
    // Points: every box corner, once
    std::map<std::tuple<scalar, scalar, scalar>, label> index;
    DynamicList<point> pts;
    const auto pointOf = [&](const point& p)
    {
        const auto key = std::make_tuple(p.x(), p.y(), p.z());
        auto it = index.find(key);
        if (it != index.end())
        {
            return it->second;
        }
        index[key] = pts.size();
        pts.append(p);
        return label(pts.size() - 1);
    };
    for (const box& b : boxes)
    {
        for (label m = 0; m < 8; ++m)
        {
            pointOf
            (
                point
                (
                    m & 1 ? b.hi.x() : b.lo.x(),
                    m & 2 ? b.hi.y() : b.lo.y(),
                    m & 4 ? b.hi.z() : b.lo.z()
                )
            );
        }
    }
    const point domainLo = min(pointField(pts)), domainHi = max(pointField(pts));

    // The outline of rectangle [lo, hi] in the plane normal to axis d at
    // lo[d], counter-clockwise about +n (sign = +1) or -n, with the mesh
    // points on its edges
    const auto outline = [&](const point& lo, const point& hi, direction d, int sign)
    {
        const direction a = (d + 1) % 3, b = (d + 2) % 3;
        List<point> corners(4, lo);
        corners[1][a] = hi[a];
        corners[2][a] = hi[a];
        corners[2][b] = hi[b];
        corners[3][b] = hi[b];
        if (sign < 0)
        {
            Swap(corners[1], corners[3]);
        }
        DynamicList<label> f;
        for (label e = 0; e < 4; ++e)
        {
            const point& p0 = corners[e];
            const point& p1 = corners[(e + 1) % 4];
            f.append(pointOf(p0));
            // Points strictly inside the edge, ordered from p0
            std::map<scalar, label> onEdge;
            forAll(pts, i)
            {
                const vector u = pts[i] - p0, v = p1 - p0;
                const scalar t = (u & v)/magSqr(v);
                if (t > 1e-9 && t < 1 - 1e-9 && mag(u - t*v) < 1e-9)
                {
                    onEdge[t] = i;
                }
            }
            for (const auto& tp : onEdge)
            {
                f.append(tp.second);
            }
        }
        return face(labelList(f));
    };

    // Internal faces (owner < neighbour, sorted), then boundary faces
    std::map<std::pair<label, label>, List<face>> internal;
    DynamicList<face> boundary;
    DynamicList<label> boundaryOwner;
    forAll(boxes, i)
    {
        const box& B = boxes[i];
        for (direction d = 0; d < 3; ++d)
        {
            for (const int sign : {-1, 1})
            {
                const scalar plane = sign > 0 ? B.hi[d] : B.lo[d];
                point lo = B.lo, hi = B.hi;
                lo[d] = plane;
                hi[d] = plane;
                if (plane == domainLo[d] || plane == domainHi[d])
                {
                    boundary.append(outline(lo, hi, d, sign));
                    boundaryOwner.append(i);
                    continue;
                }
                forAll(boxes, j)
                {
                    const box& N = boxes[j];
                    if (j <= i || (sign > 0 ? N.lo[d] : N.hi[d]) != plane)
                    {
                        continue;
                    }
                    point olo = max(lo, N.lo), ohi = min(hi, N.hi);
                    olo[d] = plane;
                    ohi[d] = plane;
                    const direction a = (d + 1) % 3, b = (d + 2) % 3;
                    if (ohi[a] > olo[a] && ohi[b] > olo[b])
                    {
                        internal[{i, j}].append(outline(olo, ohi, d, sign));
                    }
                }
            }
        }
    }
    DynamicList<face> faces;
    DynamicList<label> owner, neighbour;
    for (const auto& fs : internal)
    {
        for (const face& f : fs.second)
        {
            faces.append(f);
            owner.append(fs.first.first);
            neighbour.append(fs.first.second);
        }
    }
    const label nInternal = faces.size();
    faces.append(boundary);
    owner.append(boundaryOwner);

    autoPtr<polyMesh> mesh
    (
        new polyMesh
        (
            IOobject
            (
                "boxes", runTime.constant(), runTime,
                IOobject::NO_READ, IOobject::NO_WRITE
            ),
            pointField(pts),
            faceList(faces),
            labelList(owner),
            labelList(neighbour)
        )
    );
    List<polyPatch*> patches(1);
    patches[0] = new wallPolyPatch
    (
        "walls", boundary.size(), nInternal, 0, mesh->boundaryMesh(),
        wallPolyPatch::typeName
    );
    mesh->addPatches(patches);
    return mesh;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * * //

TEST(hexCellCheck, hexahedraOfABoxPass)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(4, 3, 2, vector(1, 2, 3));
    string why;
    EXPECT_EQ(hexCellCheck::countOthers(mesh, why), 0);
    EXPECT_TRUE(why.empty()) << why;
    EXPECT_NO_THROW(hexCellCheck::require(mesh, "DLM/FD"));
}


TEST(hexCellCheck, splitHexahedraWithHangingVerticesPass)
{
    // A coarse cell [0, 1]^3 beside eight cells of half its size filling
    // [1, 2] x [0, 1]^2: the coarse cell has 9 faces (its +x face split in
    // four) and four faces with a hanging vertex (5 vertices, 4 corners)
    test::foamTestCase tc;
    DynamicList<box> boxes;
    boxes.append(box{point(0, 0, 0), point(1, 1, 1)});
    for (label m = 0; m < 8; ++m)
    {
        const point lo(1 + 0.5*(m & 1), 0.5*((m >> 1) & 1), 0.5*((m >> 2) & 1));
        boxes.append(box{lo, lo + 0.5*vector::one});
    }
    autoPtr<polyMesh> mesh = meshOfBoxes(tc.runTime(), boxes);
    ASSERT_EQ(mesh->nCells(), 9);
    ASSERT_EQ(mesh->cells()[0].size(), 9);
    label fivePointFaces = 0;
    for (const label f : mesh->cells()[0])
    {
        fivePointFaces += mesh->faces()[f].size() == 5;
    }
    ASSERT_EQ(fivePointFaces, 4);
    ASSERT_NEAR(sum(mesh->cellVolumes()), 2, 1e-12);
    ASSERT_GT(min(mesh->cellVolumes()), 0);
    string why;
    EXPECT_EQ(hexCellCheck::countOthers(*mesh, why), 0) << why;
}


TEST(hexCellCheck, tetrahedraAreRefusedNamingTheFirstAndWhatIsSupported)
{
    // 2 x 2 x 2 cubes, each cut into six tetrahedra along its diagonal
    test::foamTestCase tc;
    const label n = 2;
    const auto pointI = [=](label i, label j, label k)
    {
        return i + (n + 1)*(j + (n + 1)*k);
    };
    pointField pts((n + 1)*(n + 1)*(n + 1));
    for (label k = 0; k <= n; ++k)
    {
        for (label j = 0; j <= n; ++j)
        {
            for (label i = 0; i <= n; ++i)
            {
                pts[pointI(i, j, k)] = point(i, j, k);
            }
        }
    }
    const cellModel& tet = cellModel::ref(cellModel::TET);
    const labelList axes[6] =
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    DynamicList<cellShape> shapes;
    for (label k = 0; k < n; ++k)
    {
        for (label j = 0; j < n; ++j)
        {
            for (label i = 0; i < n; ++i)
            {
                for (const labelList& order : axes)
                {
                    labelVector at(i, j, k);
                    labelList v(4);
                    v[0] = pointI(at.x(), at.y(), at.z());
                    for (label s = 0; s < 3; ++s)
                    {
                        ++at[order[s]];
                        v[s + 1] = pointI(at.x(), at.y(), at.z());
                    }
                    // Positive volume: (b - a) x (c - a) . (d - a) > 0
                    const point& a = pts[v[0]];
                    if ((((pts[v[1]] - a) ^ (pts[v[2]] - a)) & (pts[v[3]] - a)) < 0)
                    {
                        Swap(v[1], v[2]);
                    }
                    shapes.append(cellShape(tet, v));
                }
            }
        }
    }
    polyMesh mesh
    (
        IOobject
        (
            "tets", tc.runTime().constant(), tc.runTime(),
            IOobject::NO_READ, IOobject::NO_WRITE
        ),
        pointField(pts),
        cellShapeList(shapes),
        faceListList(),
        wordList(),
        wordList(),
        "walls",
        wallPolyPatch::typeName,
        wordList()
    );
    ASSERT_EQ(mesh.nCells(), 48);
    ASSERT_NEAR(sum(mesh.cellVolumes()), 8, 1e-12);

    string why;
    EXPECT_EQ(hexCellCheck::countOthers(mesh, why), 48);
    EXPECT_NE(why.find("cell 0 at"), std::string::npos) << why;
    EXPECT_NE(why.find("has 4 faces; face"), std::string::npos) << why;
    EXPECT_NE(why.find("has 3 corners"), std::string::npos) << why;

    const std::string msg = testInput::errorOf
    (
        [&]() { hexCellCheck::require(mesh, "DLM/FD"); }
    );
    EXPECT_NE(msg.find("48 of 48 cells"), std::string::npos) << msg;
    EXPECT_NE(msg.find("are not hexahedra"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Supported: hexahedra"), std::string::npos) << msg;
    EXPECT_NE(msg.find("split hexahedra (refineHexMesh"), std::string::npos) << msg;
}


// ************************************************************************* //

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

// CGAL first: OpenFOAM's headers define names CGAL's would clash with
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "convexHull.H"
#include "DynamicList.H"
#include "boundBox.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{
    typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
    typedef CGAL::Surface_mesh<Kernel::Point_3> HullMesh;

    //- A plane of merged hull triangles: unit normal, offset, vertices
    struct hullPlane
    {
        Foam::vector normal;
        Foam::scalar offset;
        std::vector<Foam::label> vertices;
    };
}


void Foam::convexHull
(
    const word& shapeName,
    const UList<point>& points,
    pointField& hullPoints,
    faceList& hullFaces,
    const scalar planarTolerance
)
{
    if (points.size() < 4)
    {
        FatalErrorInFunction
            << "shape " << shapeName << ": " << points.size()
            << " vertices; a convex polyhedron needs at least 4"
            << " that span a volume" << exit(FatalError);
    }

    std::vector<Kernel::Point_3> cgalPoints;
    cgalPoints.reserve(points.size());
    for (const point& p : points)
    {
        cgalPoints.emplace_back(p.x(), p.y(), p.z());
    }

    // Coplanar input gives a flat hull: no volume, no polyhedron
    if
    (
        CGAL::coplanar
        (
            cgalPoints[0], cgalPoints[1], cgalPoints[2], cgalPoints[3]
        )
     && std::all_of
        (
            cgalPoints.begin(), cgalPoints.end(),
            [&](const Kernel::Point_3& p)
            {
                return CGAL::coplanar
                (
                    cgalPoints[0], cgalPoints[1], cgalPoints[2], p
                );
            }
        )
    )
    {
        FatalErrorInFunction
            << "shape " << shapeName << ": all " << points.size()
            << " vertices lie in one plane; a convex polyhedron needs"
            << " volume (for a 2D shape use a polygon prism)"
            << exit(FatalError);
    }

    HullMesh mesh;
    CGAL::convex_hull_3(cgalPoints.begin(), cgalPoints.end(), mesh);

    // Hull vertices, numbered in CGAL's order
    pointField allHullPoints(mesh.number_of_vertices());
    std::map<HullMesh::Vertex_index, label> vertexLabel;
    {
        label i = 0;
        for (const auto v : mesh.vertices())
        {
            const Kernel::Point_3& p = mesh.point(v);
            allHullPoints[i] = point(p.x(), p.y(), p.z());
            vertexLabel[v] = i++;
        }
    }

    const scalar size = boundBox(allHullPoints, false).mag();

    // Group the triangles by plane
    std::vector<hullPlane> planes;
    for (const auto f : mesh.faces())
    {
        std::vector<label> tri;
        for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
        {
            tri.push_back(vertexLabel[v]);
        }

        const point& a = allHullPoints[tri[0]];
        vector n = (allHullPoints[tri[1]] - a)^(allHullPoints[tri[2]] - a);
        n /= mag(n);
        const scalar d = n & a;

        auto same = std::find_if
        (
            planes.begin(), planes.end(),
            [&](const hullPlane& pl)
            {
                return
                    (pl.normal & n) > 1 - planarTolerance
                 && mag(pl.offset - d) < planarTolerance*size;
            }
        );

        if (same == planes.end())
        {
            planes.push_back(hullPlane{n, d, tri});
        }
        else
        {
            same->vertices.insert(same->vertices.end(), tri.begin(), tri.end());
        }
    }

    // One polygon per plane, its vertices counter-clockwise about the
    // outward normal
    List<bool> used(allHullPoints.size(), false);
    faceList faces(planes.size());
    forAll(faces, facei)
    {
        hullPlane& pl = planes[facei];
        std::sort(pl.vertices.begin(), pl.vertices.end());
        pl.vertices.erase
        (
            std::unique(pl.vertices.begin(), pl.vertices.end()),
            pl.vertices.end()
        );

        point centre(Zero);
        for (const label v : pl.vertices)
        {
            centre += allHullPoints[v];
        }
        centre /= scalar(pl.vertices.size());

        const vector e1 = normalised(allHullPoints[pl.vertices[0]] - centre);
        const vector e2 = pl.normal ^ e1;
        std::sort
        (
            pl.vertices.begin(), pl.vertices.end(),
            [&](const label i, const label j)
            {
                const vector ri = allHullPoints[i] - centre;
                const vector rj = allHullPoints[j] - centre;
                return
                    std::atan2(ri & e2, ri & e1)
                  < std::atan2(rj & e2, rj & e1);
            }
        );

        faces[facei] = face(labelList(pl.vertices.begin(), pl.vertices.end()));
        for (const label v : pl.vertices)
        {
            used[v] = true;
        }
    }

    // Keep the vertices the faces use, renumbered
    labelList newLabel(allHullPoints.size(), -1);
    DynamicList<point> kept(allHullPoints.size());
    forAll(allHullPoints, i)
    {
        if (used[i])
        {
            newLabel[i] = kept.size();
            kept.append(allHullPoints[i]);
        }
    }
    for (face& f : faces)
    {
        for (label& v : f)
        {
            v = newLabel[v];
        }
    }

    hullPoints.transfer(kept);
    hullFaces.transfer(faces);
}


// ************************************************************************* //

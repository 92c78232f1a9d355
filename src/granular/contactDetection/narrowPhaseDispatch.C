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
    Foam::narrowPhase::shapeShape and shapePlane: the contact test of a
    pair chosen from a table indexed by the two shapes' families
    (particleShape::family), one entry per ordered pair; a pair whose first
    shape is of the "wrong" side calls its mirror and turns the normal.

    The tests themselves live in narrowPhase.H/.C (closed forms and
    separating axes) and narrowPhaseGJK.C (the general path).

\*---------------------------------------------------------------------------*/

#include "narrowPhase.H"
#include "sphere.H"
#include "circle.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;
    using namespace Foam::narrowPhase;

    typedef bool (*pairTest)
    (
        const posedShape&,
        const posedShape&,
        contactGeometry&
    );

    typedef bool (*planeTest)
    (
        const posedShape&,
        const point&,
        const vector&,
        contactGeometry&
    );

    scalar radiusOf(const posedShape& b)
    {
        return b.shape.family() == shapeFamily::circle
            ? static_cast<const particleShapes::circle&>(b.shape).radius()
            : static_cast<const particleShapes::sphere&>(b.shape).radius();
    }

    //- Bounding spheres apart: no contact, whichever test would follow.
    //- The closed forms of two round shapes and of a circle against a
    //- polygon need no such check
    bool apart(const posedShape& bi, const posedShape& bj)
    {
        return
            magSqr(bi.centre - bj.centre)
          > sqr(bi.shape.boundingRadius() + bj.shape.boundingRadius());
    }

    // Pair tests, first shape's family first

    bool sphereSphereTest
    (
        const posedShape& bi,
        const posedShape& bj,
        contactGeometry& c
    )
    {
        return sphereSphere
        (
            bi.centre, radiusOf(bi), bj.centre, radiusOf(bj), c
        );
    }

    //- Two circles of a 2D case: in the plane of the first one's centre
    bool circleCircleTest
    (
        const posedShape& bi,
        const posedShape& bj,
        contactGeometry& c
    )
    {
        return sphereSphere
        (
            bi.centre, radiusOf(bi),
            point(bj.centre.x(), bj.centre.y(), bi.centre.z()),
            radiusOf(bj), c
        );
    }

    //- A circle against a polygon (or a polyhedron) of a 2D case, in the
    //- polygon's plane
    bool circlePolyhedronTest
    (
        const posedShape& bi,
        const posedShape& bj,
        contactGeometry& c
    )
    {
        return spherePolyhedron(bi.centre, radiusOf(bi), bj, c, true);
    }

    bool spherePolyhedronTest
    (
        const posedShape& bi,
        const posedShape& bj,
        contactGeometry& c
    )
    {
        return
            !apart(bi, bj)
         && spherePolyhedron(bi.centre, radiusOf(bi), bj, c);
    }

    bool polyhedronPolyhedronTest
    (
        const posedShape& bi,
        const posedShape& bj,
        contactGeometry& c
    )
    {
        return !apart(bi, bj) && polyhedronPolyhedron(bi, bj, c);
    }

    bool polygonPolygonTest
    (
        const posedShape& bi,
        const posedShape& bj,
        contactGeometry& c
    )
    {
        return !apart(bi, bj) && polygonPolygon(bi, bj, c);
    }

    bool generalTest
    (
        const posedShape& bi,
        const posedShape& bj,
        contactGeometry& c
    )
    {
        return !apart(bi, bj) && shapeShapeGJK(bi, bj, c);
    }

    //- The test of (j, i), its normal turned to point from j to i
    template<pairTest test>
    bool mirrored
    (
        const posedShape& bi,
        const posedShape& bj,
        contactGeometry& c
    )
    {
        if (!test(bj, bi, c))
        {
            return false;
        }
        c.normal = -c.normal;
        return true;
    }

    // The table, rows and columns in the order of shapeFamily: sphere,
    // circle, polyhedron, polygon, general. A sphere meets a polygon as a
    // polyhedron (in 3D); a sphere and a circle never share a case, and
    // meet through GJK if they do
    const pairTest pairTests[nShapeFamilies][nShapeFamilies] =
    {
        // sphere
        {
            sphereSphereTest, generalTest, spherePolyhedronTest,
            spherePolyhedronTest, generalTest
        },
        // circle
        {
            generalTest, circleCircleTest, circlePolyhedronTest,
            circlePolyhedronTest, generalTest
        },
        // polyhedron
        {
            mirrored<spherePolyhedronTest>, mirrored<circlePolyhedronTest>,
            polyhedronPolyhedronTest, polyhedronPolyhedronTest, generalTest
        },
        // polygon
        {
            mirrored<spherePolyhedronTest>, mirrored<circlePolyhedronTest>,
            polyhedronPolyhedronTest, polygonPolygonTest, generalTest
        },
        // general
        {
            generalTest, generalTest, generalTest, generalTest, generalTest
        }
    };

    // Plane tests by family

    bool spherePlaneTest
    (
        const posedShape& b,
        const point& p0,
        const vector& n,
        contactGeometry& c
    )
    {
        return spherePlane(b.centre, radiusOf(b), p0, n, c);
    }

    //- A wall of the 2D plane meets the rim's nearest point, on the
    //- mid-plane; any other plane the disc's support point
    bool circlePlaneTest
    (
        const posedShape& b,
        const point& p0,
        const vector& n,
        contactGeometry& c
    )
    {
        if (mag(n.z()) < 1e-9)
        {
            return spherePlane(b.centre, radiusOf(b), p0, n, c);
        }
        return supportPlane(b, p0, n, c);
    }

    const planeTest planeTests[nShapeFamilies] =
    {
        spherePlaneTest,        // sphere
        circlePlaneTest,        // circle
        polyhedronPlane,        // polyhedron
        polyhedronPlane,        // polygon
        supportPlane            // general
    };
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::narrowPhase::shapeShape
(
    const posedShape& bi,
    const posedShape& bj,
    contactGeometry& contact
)
{
    return pairTests
        [static_cast<int>(bi.shape.family())]
        [static_cast<int>(bj.shape.family())](bi, bj, contact);
}


bool Foam::narrowPhase::shapePlane
(
    const posedShape& body,
    const point& p0,
    const vector& n,
    contactGeometry& contact
)
{
    return planeTests[static_cast<int>(body.shape.family())]
    (
        body, p0, n, contact
    );
}


// ************************************************************************* //

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
    A shape posed once (Foam::posedShape) answers the point queries of the
    fictitious-domain step as the geometry says, for a sphere, a rotated
    cube and a circle: the depth of a point is its distance to the surface
    computed independently (the sphere's radius less the distance to the
    centre; the cube's smallest gap to a face in its own frame; the
    circle's in the plane), the nearest surface point lies on the surface
    along the outward unit normal, a point is inside exactly where its
    depth is positive, and the outside bound never exceeds the true
    distance.

\*---------------------------------------------------------------------------*/

#include "posedShape.H"
#include "particleGeometry.H"
#include "platonicSolid.H"
#include "sphere.H"
#include "circle.H"
#include "quaternion.H"
#include "Random.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Points spread over a cube of half-width a about x
List<point> pointsAround(const point& x, const scalar a, const label n)
{
    Random rnd(1234);
    List<point> ps(n);
    for (point& p : ps)
    {
        p = x + a*(2*rnd.sample01<vector>() - vector::one);
    }
    return ps;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(posedShape, sphereDepthIsTheRadiusLessTheDistanceToTheCentre)
{
    const particleShapes::sphere ball("ball", 0.5);
    const point x(0.3, -0.2, 0.7);
    const posedShape S(ball, x, tensor::I);
    for (const point& p : pointsAround(x, 0.4, 500))
    {
        point foot;
        vector n;
        const scalar d = S.depth(p, foot, n);
        EXPECT_NEAR(d, 0.25 - mag(p - x), 1e-15);
        EXPECT_NEAR(mag(n), 1, 1e-14);
        EXPECT_NEAR(mag(foot - x), 0.25, 1e-14);
        EXPECT_LT(mag(foot - (p + d*n)), 1e-15);
        EXPECT_EQ(S.contains(p), d > 0);
        EXPECT_EQ(S.outsideDistanceBound(p), -d);
    }
}


TEST(posedShape, rotatedCubeDepthIsTheSmallestGapToAFace)
{
    // A cube of edge 0.4 turned about (1 2 3): in its own frame a point's
    // gap to the face along +-e_i is 0.2 - |b_i|
    const particleShapes::platonicSolid cube("cube", "cube", 0.4);
    const point x(1, 2, 3);
    const tensor R = quaternion(normalised(vector(1, 2, 3)), 0.7).R();
    const posedShape S(cube, x, R);
    label inside = 0;
    for (const point& p : pointsAround(x, 0.35, 2000))
    {
        const vector b = R.T() & (p - x);
        const scalar gap = 0.2 - cmptMax(cmptMag(b));
        point foot;
        vector n;
        const scalar d = S.depth(p, foot, n);
        EXPECT_EQ(S.contains(p), gap > 0);
        inside += S.contains(p);
        if (gap > 0)
        {
            // Inside: the depth is the distance to the surface
            EXPECT_NEAR(d, gap, 1e-14);
            EXPECT_NEAR(mag(n), 1, 1e-14);
            // The foot lies on a face: one body coordinate at +-0.2
            const vector bf = R.T() & (foot - x);
            EXPECT_NEAR(cmptMax(cmptMag(bf)), 0.2, 1e-14);
        }
        else
        {
            // Outside: a lower bound of the distance to the cube
            const vector over = cmptMag(b) - vector::uniform(0.2);
            const vector outside
            (
                max(over.x(), scalar(0)),
                max(over.y(), scalar(0)),
                max(over.z(), scalar(0))
            );
            EXPECT_LE(S.outsideDistanceBound(p), mag(outside) + 1e-14);
            EXPECT_GE(S.outsideDistanceBound(p), 0);
        }
        // The same as the free functions, which pose the shape per point
        point foot2;
        vector n2;
        EXPECT_EQ(particleGeometry::depth(cube, x, R, p, foot2, n2), d);
        EXPECT_EQ(foot2, foot);
        EXPECT_EQ(n2, n);
    }
    EXPECT_GT(inside, 100);
    EXPECT_LT(inside, 1900);
}


TEST(posedShape, circleIgnoresTheOutOfPlaneCoordinate)
{
    const particleShapes::circle disc("disc", 0.5, 0.01);
    const point x(0.1, 0.2, 0);
    const posedShape S(disc, x, tensor::I);
    for (const point& p : pointsAround(x, 0.4, 500))
    {
        const scalar planar = mag(vector(p.x() - x.x(), p.y() - x.y(), 0));
        point foot;
        vector n;
        EXPECT_NEAR(S.depth(p, foot, n), 0.25 - planar, 1e-15);
        EXPECT_EQ(n.z(), 0);
        EXPECT_EQ(foot.z(), p.z());
        EXPECT_EQ(S.contains(p), planar < 0.25);
    }
}


// ************************************************************************* //

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
    The 2D shapes (circle, convexPolygon, square, triangle: prisms one cell
    deep): mass properties against closed forms, area-equivalent diameters,
    circle-polygon and circle-circle contacts in the plane against closed
    forms, and motion that stays in the plane through collisions.

\*---------------------------------------------------------------------------*/

#include "circle.H"
#include "convexPolygon.H"
#include "narrowPhase.H"
#include "granularSystem.H"
#include "testInput.H"
#include "Random.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;
using Foam::testInput::parse;

namespace
{

    const scalar pi = constant::mathematical::pi;
}


TEST(planarShape, massPropertiesMatchClosedForms)
{
    // Exact to 1e-12 relative: a prism of depth h and in-plane polar moment
    const scalar h = 0.002;
    {
        particleShapes::circle c("c", 0.01, h);
        const scalar V = pi*sqr(0.005)*h;
        EXPECT_NEAR(c.volume(), V, 1e-12*V);
        EXPECT_NEAR(c.volumeInertia().zz(), V*sqr(0.005)/2, 1e-12*V*1e-4);
        EXPECT_NEAR(c.volumeInertia().xx(), V*(sqr(0.005)/4 + sqr(h)/12), 1e-12*V*1e-4);
        EXPECT_DOUBLE_EQ(c.equivalentDiameter(), 0.01);
        EXPECT_TRUE(c.planar());
    }
    {
        // Square of edge a: area a^2, J_zz = V a^2/6
        const scalar a = 0.008;
        particleShapes::convexPolygon sq("s", parse("type square; edge 0.008; depth 0.002;"));
        const scalar V = a*a*h;
        EXPECT_NEAR(sq.volume(), V, 1e-12*V);
        EXPECT_NEAR(sq.volumeInertia().zz(), V*a*a/6, 1e-12*V*a*a);
        EXPECT_NEAR(sq.equivalentDiameter(), std::sqrt(4*a*a/pi), 1e-12);
        EXPECT_TRUE(sq.planar());
    }
    {
        // Equilateral triangle of edge a: area sqrt(3)/4 a^2, J_zz = V a^2/12
        const scalar a = 0.01;
        particleShapes::convexPolygon tri("t", parse("type triangle; edge 0.01; depth 0.002;"));
        const scalar V = std::sqrt(3.0)/4*a*a*h;
        EXPECT_NEAR(tri.volume(), V, 1e-12*V);
        EXPECT_NEAR(tri.volumeInertia().zz(), V*a*a/12, 1e-12*V*a*a);
        // Sized by D instead: the same area as a circle of diameter D
        particleShapes::convexPolygon triD("t", parse("type triangle; D 0.01; depth 0.002;"));
        EXPECT_NEAR(triD.volume()/h, pi*0.25*1e-4, 1e-12*1e-4);
    }
    {
        // A right triangle given by its corners, moved to its centroid
        particleShapes::convexPolygon p
        (
            "p", parse("type convexPolygon; vertices ((0 0) (3 0) (0 4)); scale 0.001; depth 0.002;")
        );
        EXPECT_NEAR(p.volume(), 6e-6*h, 1e-18);
        // J_zz of a right triangle about its centroid: A (b^2 + c^2)/18
        EXPECT_NEAR(p.volumeInertia().zz(), 6e-6*h*(9e-6 + 16e-6)/18, 1e-12*6e-6*h*25e-6);
    }
}


TEST(planarShape, badPolygonInputIsReported)
{
    EXPECT_THROW
    (
        particleShapes::convexPolygon("bad", parse("type square; depth 0.001;")),
        Foam::error
    );
    EXPECT_THROW
    (
        particleShapes::convexPolygon("bad", parse("type convexPolygon; vertices ((0 0) (1 0)); depth 0.001;")),
        Foam::error
    );
    EXPECT_THROW
    (
        particleShapes::circle("bad", parse("D 0.01; depth -1;")),
        Foam::error
    );
}


TEST(planarShape, circlePolygonContactMatchesPointSquareDistance)
{
    // A circle against a square of edge a turned by theta about z, at random
    // in-plane positions near it: overlap = r - distance from the centre to
    // the square (outside), to 1e-12 a
    const scalar a = 0.01, r = 0.003, h = 0.002;
    particleShapes::convexPolygon sq("s", parse("type square; edge 0.01; depth 0.002;"));
    particleShapes::circle c("c", 2*r, h);
    Random rnd(7);
    label tested = 0;
    for (label k = 0; k < 2000; ++k)
    {
        const scalar theta = 2*pi*rnd.sample01<scalar>();
        const tensor R(quaternion(vector(0, 0, 1), theta).R());
        const point centre(0.001, -0.002, 0);
        const point local
        (
            (rnd.sample01<scalar>() - 0.5)*(a + 2*r),
            (rnd.sample01<scalar>() - 0.5)*(a + 2*r),
            0
        );
        // Distance from the local point to the axis-aligned square
        const scalar dx = max(mag(local.x()) - 0.5*a, scalar(0));
        const scalar dy = max(mag(local.y()) - 0.5*a, scalar(0));
        const scalar dist = std::sqrt(dx*dx + dy*dy);
        if (dist == 0)
        {
            continue;
        }
        const posedShape bs{sq, centre, R};
        const posedShape bc{c, centre + (R & local), tensor::I};
        contactGeometry g;
        const bool touching = narrowPhase::shapeShape(bc, bs, g);
        EXPECT_EQ(touching, dist < r);
        if (touching)
        {
            EXPECT_NEAR(g.overlap, r - dist, 1e-12*a);
            EXPECT_NEAR(g.normal.z(), 0, 1e-14);
            ++tested;
        }
    }
    EXPECT_GT(tested, 100);
}


TEST(planarShape, polygonPairOverlapMatchesClosedForm)
{
    // Two squares of edge a side by side, overlapping by delta, the pair
    // turned by a random angle about z and slid along the shared side: the
    // overlap is delta to 1e-12 a, the normal along the line of the sides,
    // and the contact point at the middle of the shared side
    const scalar a = 0.01;
    particleShapes::convexPolygon sq("s", parse("type square; edge 0.01; depth 0.002;"));
    Random rnd(3);
    for (label k = 0; k < 500; ++k)
    {
        const scalar theta = 2*pi*rnd.sample01<scalar>();
        const scalar delta = 1e-5*a + 1e-2*a*rnd.sample01<scalar>();
        const scalar slide = 0.8*a*(rnd.sample01<scalar>() - 0.5);
        const tensor R(quaternion(vector(0, 0, 1), theta).R());
        const point cj(0.002, 0.001, 0);
        const point ci = cj + (R & vector(a - delta, slide, 0));
        contactGeometry g;
        ASSERT_TRUE(narrowPhase::shapeShape({sq, ci, R}, {sq, cj, R}, g));
        EXPECT_NEAR(g.overlap, delta, 1e-12*a);
        EXPECT_NEAR(mag(g.normal - (R & vector(1, 0, 0))), 0, 1e-12);
        const point mid = cj + (R & vector(0.5*(a - delta), 0.5*slide, 0));
        EXPECT_NEAR(mag(g.position - mid), 0, 1e-9*a);
    }
}


TEST(planarShape, motionStaysInThePlaneThroughCollisions)
{
    // Circles, squares and triangles dropped in a 2D box with gravity along
    // -y: after 0.3 s of collisions every z, omega_x, omega_y and U_z is
    // exactly its initial value (zero), and nothing leaves the box
    const dictionary particleDict = parse
    (
        "shapes { disc { type circle; D 0.01; depth 0.002; }"
        " tile { type square; D 0.01; depth 0.002; }"
        " wedge { type triangle; D 0.01; depth 0.002; } }"
        " materials { glass { density 2500; } }"
    );
    const dictionary collisionDict = parse
    (
        "contactLaw hookeanSpringDashpot;"
        " domain { min (0 0 -0.001); max (0.06 0.1 0.001); }"
        " walls { floor { point (0 0 0); normal (0 1 0); material steel; }"
        " left { point (0 0 0); normal (1 0 0); material steel; }"
        " right { point (0.06 0 0); normal (-1 0 0); material steel; } }"
        " pairs { glass-glass { en 0.75; muc 0.5; kn 2e3; }"
        " glass-steel { en 0.75; muc 0.5; kn 2e3; } }"
    );
    granularSystem sys(particleDict, collisionDict);
    sys.setGravity(vector(0, -9.81, 0));
    const wordList shapes({"disc", "tile", "wedge"});
    label id = 0;
    for (label row = 0; row < 4; ++row)
    {
        for (label col = 0; col < 4; ++col)
        {
            sys.addParticle
            (
                id, shapes[id % 3], "glass",
                point(0.008 + 0.014*col + 0.001*row, 0.01 + 0.016*row, 0),
                quaternion(vector(0, 0, 1), 0.3*id)
            );
            ++id;
        }
    }
    sys.updated();
    label contacts = 0;
    for (label k = 0; k < 3000; ++k)
    {
        sys.evolve(1e-4);
        contacts += sys.stats().nContacts;
    }
    EXPECT_GT(contacts, 1000);
    for (label i = 0; i < sys.size(); ++i)
    {
        const rigidParticle& p = sys.particle(i);
        EXPECT_EQ(p.position().z(), 0) << i;
        EXPECT_EQ(p.velocity().z(), 0) << i;
        EXPECT_EQ(p.omegaBody().x(), 0) << i;
        EXPECT_EQ(p.omegaBody().y(), 0) << i;
        EXPECT_GT(p.position().x(), 0) << i;
        EXPECT_LT(p.position().x(), 0.06) << i;
        EXPECT_GT(p.position().y(), 0) << i;
    }
    std::cout << contacts << " contact evaluations, largest overlap "
        << sys.stats().maxOverlapRatio << " D in the last step" << nl;
}


// ************************************************************************* //

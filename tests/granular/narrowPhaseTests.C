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
Description
    Unit tests of the narrow phase of the granular library against closed
    forms on random poses: cube pairs (face on face, vertex into face)
    through libccd's GJK/EPA, a sphere against a rotated cube against the
    point-box distance, cubes against a plane against their lowest vertex,
    stacked cubes, and the contact point of a face lying on a plane; the
    dispatch by shape family: every ordered pair of families finds the
    same contact both ways, with the normal turned.

\*---------------------------------------------------------------------------*/

#include "narrowPhase.H"
#include "sphere.H"
#include "platonicSolid.H"
#include "circle.H"
#include "convexPolygon.H"
#include "testInput.H"
#include "Random.H"
#include "quaternion.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

tensor randomRotation(Random& rnd)
{
    const vector axis =
        normalised(rnd.sample01<vector>() - vector::uniform(0.5));
    return quaternion(axis, 2*constant::mathematical::pi*rnd.sample01<scalar>()).R();
}

//- A ball that declares no family of its own (a "general" shape): the
//- narrow phase can only meet it through GJK/EPA
class generalBall
:
    public particleShape
{
    scalar r_;

public:

    generalBall(const scalar r)
    :
        particleShape("ball"),
        r_(r)
    {}

    scalar volume() const
    {
        return 4.0/3.0*constant::mathematical::pi*pow3(r_);
    }

    symmTensor volumeInertia() const
    {
        return 0.4*volume()*sqr(r_)*symmTensor::I;
    }

    scalar boundingRadius() const
    {
        return r_;
    }

    vector support(const vector& dir) const
    {
        return r_*dir/mag(dir);
    }
};

} // End anonymous namespace


TEST(narrowPhase, everyPairOfFamiliesFindsTheSameContactBothWays)
{
    Random rnd(5);
    const particleShapes::sphere ball("sphere", 1.0);
    const particleShapes::platonicSolid cube("cube", "cube", 0.8);
    const generalBall general(0.5);
    const particleShapes::circle disc("circle", 1.0, 0.1);
    const particleShapes::convexPolygon square
    (
        "square", testInput::parse("type square; edge 0.8; depth 0.1;")
    );
    EXPECT_EQ(ball.family(), shapeFamily::sphere);
    EXPECT_EQ(cube.family(), shapeFamily::polyhedron);
    EXPECT_EQ(general.family(), shapeFamily::general);
    EXPECT_EQ(disc.family(), shapeFamily::circle);
    EXPECT_EQ(square.family(), shapeFamily::polygon);

    // The 3D families among themselves, the 2D ones among themselves (in
    // the plane z = 0, turned about z only)
    const std::vector<std::vector<const particleShape*>> cases
    {
        {&ball, &cube, &general},
        {&disc, &square}
    };
    for (const auto& shapes : cases)
    {
        const bool planar = shapes[0]->planar();
        for (const particleShape* a : shapes)
        {
            for (const particleShape* b : shapes)
            {
                for (label trial = 0; trial < 20; ++trial)
                {
                    vector dir = rnd.sample01<vector>() - vector::uniform(0.5);
                    if (planar)
                    {
                        dir.z() = 0;
                    }
                    dir.normalise();
                    const tensor Ra = planar
                      ? quaternion(vector(0, 0, 1), 6*rnd.sample01<scalar>()).R()
                      : randomRotation(rnd);
                    const tensor Rb = planar
                      ? quaternion(vector(0, 0, 1), 6*rnd.sample01<scalar>()).R()
                      : randomRotation(rnd);
                    const posedShape pa{*a, point::zero, Ra};
                    // Where along dir they first touch (by bisection),
                    // then a shallow overlap as in the granular step
                    // (libccd's EPA is not exact on round shapes in deep)
                    const scalar reach =
                        a->boundingRadius() + b->boundingRadius();
                    scalar lo = 0, hi = reach;
                    contactGeometry probe;
                    for (label k = 0; k < 60; ++k)
                    {
                        const scalar t = 0.5*(lo + hi);
                        const posedShape at{*b, t*dir, Rb};
                        (narrowPhase::shapeShape(pa, at, probe) ? lo : hi) = t;
                    }
                    const posedShape pb{*b, (lo - 1e-3*reach)*dir, Rb};
                    contactGeometry ab, ba;
                    const bool touchAB = narrowPhase::shapeShape(pa, pb, ab);
                    const bool touchBA = narrowPhase::shapeShape(pb, pa, ba);
                    const std::string pair =
                        a->name() + "-" + b->name() + " trial "
                      + std::to_string(trial);
                    ASSERT_TRUE(touchAB && touchBA) << pair;
                    // The closed forms and separating axes agree to
                    // round-off; EPA's polytope on a round surface to
                    // about 1e-3 of the overlap
                    const bool viaEPA =
                        a->family() == shapeFamily::general
                     || b->family() == shapeFamily::general;
                    const scalar tol = viaEPA ? 1e-3 : 1e-9;
                    EXPECT_NEAR(ab.overlap, ba.overlap, tol*ab.overlap)
                        << pair;
                    EXPECT_LT(ab.normal & ba.normal, -1 + tol) << pair;
                    // The normal points from the second body to the first
                    EXPECT_LT(ab.normal & dir, 0) << pair;
                }
            }
        }
    }

    // A sphere and the general ball of the same radius: GJK against the
    // closed form
    const particleShapes::sphere half("sphere", 1.0);
    const posedShape s{half, point::zero, tensor::I};
    const posedShape g{general, point(0.9, 0, 0), tensor::I};
    contactGeometry viaGJK, closed;
    ASSERT_TRUE(narrowPhase::shapeShape(s, g, viaGJK));
    ASSERT_TRUE
    (
        narrowPhase::sphereSphere(s.centre, 0.5, g.centre, 0.5, closed)
    );
    EXPECT_NEAR(viaGJK.overlap, closed.overlap, 1e-6);
    EXPECT_NEAR(viaGJK.normal & closed.normal, 1, 1e-6);
}


TEST(narrowPhase, cubePairsThroughGJKMatchClosedForms)
{
    Random rnd(11);
    const scalar a = 1;
    particleShapes::platonicSolid cube("cube", "cube", a);

    // Vertex of the upper cube pointing down: its body diagonal along -z
    const vector diag = normalised(vector(1, 1, 1));
    const vector down(0, 0, -1);
    const tensor vertexDown =
        quaternion(normalised(diag ^ down), Foam::acos(diag & down)).R();

    for (label trial = 0; trial < 200; ++trial)
    {
        // The whole pair turned and moved at random: depth is invariant
        const tensor Q = randomRotation(rnd);
        const point x0 = rnd.sample01<vector>();
        const scalar overlap = 1e-3*(rnd.sample01<scalar>() + 1e-3);
        const vector lateral
        (
            0.2*(rnd.sample01<scalar>() - 0.5),
            0.2*(rnd.sample01<scalar>() - 0.5),
            0
        );

        const posedShape lower{cube, x0, Q};

        // Face on face, the upper cube turned about the stack axis
        const tensor spin = quaternion
        (
            vector(0, 0, 1), 2*constant::mathematical::pi*rnd.sample01<scalar>()
        ).R();
        const posedShape faceUpper
        {
            cube, x0 + (Q & (point(0, 0, a - overlap) + lateral)), Q & spin
        };

        // Vertex into face
        const posedShape vertexUpper
        {
            cube,
            x0 + (Q & (point(0, 0, a/2 + Foam::sqrt(3.0)/2*a - overlap) + lateral)),
            Q & vertexDown
        };

        for (const posedShape* upper : {&faceUpper, &vertexUpper})
        {
            contactGeometry c;
            ASSERT_TRUE(narrowPhase::shapeShapeGJK(*upper, lower, c)) << trial;
            EXPECT_NEAR(c.overlap, overlap, 1e-10) << trial;
            EXPECT_GT(c.normal & (Q & vector(0, 0, 1)), 1 - 1e-10) << trial;
        }
    }
}


TEST(narrowPhase, sphereAgainstRotatedCubeMatchesPointBoxDistance)
{
    Random rnd(12);
    const scalar a = 1;     // cube edge
    const scalar r = 0.3;   // sphere radius
    particleShapes::platonicSolid cube("cube", "cube", a);
    particleShapes::sphere ball("ball", 2*r);
    scalar worst = 0, worstNormal = 0;
    label nContacts = 0;

    for (label trial = 0; trial < 2000; ++trial)
    {
        const tensor R = randomRotation(rnd);
        const point xc = rnd.sample01<vector>();

        // A sphere centre outside the cube, within r of its surface
        const vector local = (a + 2*r)*(rnd.sample01<vector>() - vector::uniform(0.5));
        const vector clamped
        (
            max(-a/2, min(a/2, local.x())),
            max(-a/2, min(a/2, local.y())),
            max(-a/2, min(a/2, local.z()))
        );
        const scalar dist = mag(local - clamped);
        if (dist < 1e-3 || dist > r - 1e-5)
        {
            continue;   // inside the cube, or not touching
        }
        ++nContacts;

        const posedShape bi{ball, xc + (R & local), randomRotation(rnd)};
        const posedShape bj{cube, xc, R};

        contactGeometry c;
        ASSERT_TRUE(narrowPhase::shapeShape(bi, bj, c)) << trial;
        worst = max(worst, mag(c.overlap - (r - dist)));

        // The normal points from the cube's closest point to the centre
        const vector nExact = R & vector(normalised(local - clamped));
        worstNormal = max(worstNormal, mag(c.normal - nExact));
    }

    EXPECT_GT(nContacts, 100);
    EXPECT_LT(worst, 1e-12) << "largest depth error (cube edge 1)";
    EXPECT_LT(worstNormal, 1e-9) << "largest normal error";
}


TEST(narrowPhase, sphereCentreInsideCubeLeavesByNearestFace)
{
    particleShapes::platonicSolid cube("cube", "cube", 1);
    particleShapes::sphere ball("ball", 0.2);
    const posedShape box{cube, point::zero, tensor::I};
    const posedShape inside{ball, point(0.1, 0.45, -0.2), tensor::I};

    contactGeometry c;
    ASSERT_TRUE(narrowPhase::shapeShape(inside, box, c));
    EXPECT_NEAR(c.overlap, 0.1 + 0.05, 1e-14);
    EXPECT_NEAR(c.normal.y(), 1, 1e-14);

    // The same pair the other way round: normal reversed
    contactGeometry r;
    ASSERT_TRUE(narrowPhase::shapeShape(box, inside, r));
    EXPECT_NEAR(r.normal.y(), -1, 1e-14);
    EXPECT_NEAR(r.overlap, c.overlap, 1e-14);
}


TEST(narrowPhase, rotatedCubeAgainstPlaneGivesLowestVertex)
{
    Random rnd(13);
    particleShapes::platonicSolid cube("cube", "cube", 1);
    const point p0(0, 0, 0);
    const vector n(0, 0, 1);

    for (label trial = 0; trial < 500; ++trial)
    {
        const tensor R = randomRotation(rnd);
        const point centre(0.3, -0.2, 0.5 + 0.4*rnd.sample01<scalar>());
        const posedShape body{cube, centre, R};

        scalar lowest = GREAT;
        for (const point& v : cube.points())
        {
            lowest = min(lowest, body.toWorld(v).z());
        }

        contactGeometry c;
        const bool touching = narrowPhase::shapePlane(body, p0, n, c);
        ASSERT_EQ(touching, lowest < 0) << trial;
        if (touching)
        {
            EXPECT_NEAR(c.overlap, -lowest, 1e-14);
            EXPECT_EQ(c.normal, n);
        }
    }
}


TEST(narrowPhase, faceOnPlanePushesAtItsCentre)
{
    particleShapes::platonicSolid cube("cube", "cube", 1);
    const posedShape body{cube, point(0.7, -1.3, 0.5 - 1e-4), tensor::I};

    contactGeometry c;
    ASSERT_TRUE
    (
        narrowPhase::shapePlane(body, point::zero, vector(0, 0, 1), c)
    );
    EXPECT_NEAR(c.overlap, 1e-4, 1e-15);
    EXPECT_NEAR(c.position.x(), 0.7, 1e-14);
    EXPECT_NEAR(c.position.y(), -1.3, 1e-14);
}


TEST(narrowPhase, stackedCubesOverlapAlongTheStack)
{
    Random rnd(14);
    particleShapes::platonicSolid cube("cube", "cube", 1);

    for (label trial = 0; trial < 100; ++trial)
    {
        const scalar overlap = 1e-3*rnd.sample01<scalar>() + 1e-6;
        const vector shift(0.4*rnd.sample01<scalar>(), -0.3*rnd.sample01<scalar>(), 0);
        const posedShape lower{cube, point::zero, tensor::I};
        const posedShape upper{cube, point(0, 0, 1 - overlap) + shift, tensor::I};

        contactGeometry c;
        ASSERT_TRUE(narrowPhase::shapeShape(upper, lower, c)) << trial;
        EXPECT_NEAR(c.overlap, overlap, 1e-9) << trial;
        EXPECT_GT(c.normal.z(), 1 - 1e-9) << trial;
    }
}


// ************************************************************************* //

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
    Unit tests of the particle shapes of the granular library: mass
    properties of the five Platonic solids against their closed forms to
    1e-10 relative, invariance under rotation and translation, merged
    planar faces, support functions, and the errors on bad input.

\*---------------------------------------------------------------------------*/

#include "particleShape.H"
#include "sphere.H"
#include "convexPolyhedron.H"
#include "platonicSolid.H"
#include "IStringStream.H"
#include "Random.H"
#include "quaternion.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

dictionary shapeDict(const std::string& text)
{
    IStringStream is(text);
    dictionary dict(is);
    dict.name() = "constant/granularProperties.shapes.test";
    return dict;
}

std::string ioErrorMessage(const std::string& text)
{
    try
    {
        particleShape::New("test", shapeDict(text));
    }
    catch (const IOerror& err)
    {
        return err.message();
    }
    catch (const error& err)
    {
        return err.message();
    }
    return "";
}

//- I/m about any centroidal axis for unit edge, and the vertex and face
//- counts of each Platonic solid
struct platonicData
{
    const char* name;
    scalar inertiaPerMass;
    label nVertices;
    label nFaces;
    label nFaceVertices;
};

const scalar s5 = Foam::sqrt(5.0);

const platonicData platonic[] =
{
    {"tetrahedron",  1.0/20,                 4,  4, 3},
    {"cube",         1.0/6,                  8,  6, 4},
    {"octahedron",   1.0/10,                 6,  8, 3},
    {"dodecahedron", (95 + 39*s5)/300,      20, 12, 5},
    {"icosahedron",  (3 + s5)/20,           12, 20, 3}
};

void expectRelNear(scalar actual, scalar expected, scalar rel, const char* what)
{
    EXPECT_NEAR(actual, expected, rel*mag(expected)) << what;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Platonic solids * * * * * * * * * * * * //

TEST(platonicSolid, massPropertiesMatchClosedForms)
{
    const scalar a = 0.37;

    for (const platonicData& p : platonic)
    {
        autoPtr<particleShape> shape = particleShape::New
        (
            p.name,
            shapeDict(std::string("type ") + p.name + "; edge 0.37;")
        );

        const scalar V = pow3(a)*particleShapes::platonicSolid::unitEdgeVolume(p.name);
        expectRelNear(shape->volume(), V, 1e-10, p.name);

        // Isotropic inertia: J = (I/m) a^2 V on the diagonal, 0 off it
        const scalar Jaxis = p.inertiaPerMass*sqr(a)*V;
        const symmTensor J = shape->volumeInertia();
        expectRelNear(J.xx(), Jaxis, 1e-10, p.name);
        expectRelNear(J.yy(), Jaxis, 1e-10, p.name);
        expectRelNear(J.zz(), Jaxis, 1e-10, p.name);
        EXPECT_LT(mag(J.xy()) + mag(J.xz()) + mag(J.yz()), 1e-10*Jaxis)
            << p.name;

        expectRelNear
        (
            shape->equivalentDiameter(), Foam::cbrt(6*V/pi), 1e-12, p.name
        );
    }
}


TEST(platonicSolid, cubeOfEdgeHasTheDiameterOfTheClosedForm)
{
    autoPtr<particleShape> cube =
        particleShape::New("c", shapeDict("type cube; edge 2;"));

    // D = a (6/pi)^(1/3)
    expectRelNear(cube->equivalentDiameter(), 2*Foam::cbrt(6/pi), 1e-12, "cube");
}


TEST(platonicSolid, sizedByDiameterHasThatDiameter)
{
    for (const platonicData& p : platonic)
    {
        autoPtr<particleShape> shape = particleShape::New
        (
            p.name,
            shapeDict(std::string("type ") + p.name + "; D 0.01;")
        );
        expectRelNear(shape->equivalentDiameter(), 0.01, 1e-12, p.name);
    }
}


TEST(platonicSolid, hullHasMergedPlanarFacesPointingOutwards)
{
    for (const platonicData& p : platonic)
    {
        particleShapes::platonicSolid shape(p.name, p.name, 1.0);

        EXPECT_EQ(shape.points().size(), p.nVertices) << p.name;
        ASSERT_EQ(shape.faces().size(), p.nFaces) << p.name;

        for (const face& f : shape.faces())
        {
            EXPECT_EQ(f.size(), p.nFaceVertices) << p.name;

            // Counter-clockwise from outside: area normal along the centre
            const vector n = f.areaNormal(shape.points());
            EXPECT_GT(n & f.centre(shape.points()), 0) << p.name;

            // Every edge of a Platonic solid with unit edge is 1 long
            forAll(f, i)
            {
                EXPECT_NEAR
                (
                    mag(shape.points()[f[i]] - shape.points()[f.nextLabel(i)]),
                    1.0,
                    1e-12
                ) << p.name;
            }
        }
    }
}


// * * * * * * * * * * * * * * * convexPolyhedron * * * * * * * * * * * * * //

TEST(convexPolyhedron, massPropertiesFollowRotationAndIgnoreInnerPoints)
{
    Random rnd(42);

    for (const platonicData& p : platonic)
    {
        const pointField unit =
            particleShapes::platonicSolid::unitEdgeVertices(p.name);
        particleShapes::convexPolyhedron reference(p.name, unit);

        // Random rotation and translation, plus points inside the hull
        const quaternion q
        (
            normalised(rnd.sample01<vector>() - vector::uniform(0.5)),
            2*pi*rnd.sample01<scalar>()
        );
        const tensor R = q.R();
        const vector shift(1.5, -3, 7);

        DynamicList<point> moved;
        for (const point& v : unit)
        {
            moved.append((R & v) + shift);
            moved.append((R & (0.3*v)) + shift);
        }
        particleShapes::convexPolyhedron shape(p.name, moved);

        expectRelNear(shape.volume(), reference.volume(), 1e-12, p.name);
        EXPECT_EQ(shape.points().size(), unit.size()) << p.name;

        // Body frame is the input frame moved to the centroid: J turns
        // with R; an isotropic J stays what it was
        const symmTensor J = shape.volumeInertia();
        const symmTensor Jref = reference.volumeInertia();
        expectRelNear(J.xx(), Jref.xx(), 1e-10, p.name);
        expectRelNear(J.yy(), Jref.yy(), 1e-10, p.name);
        expectRelNear(J.zz(), Jref.zz(), 1e-10, p.name);
    }
}


TEST(convexPolyhedron, boxMassPropertiesAndOffsetCentroid)
{
    // A 1 x 2 x 3 box with one corner at the origin
    autoPtr<particleShape> box = particleShape::New
    (
        "box",
        shapeDict
        (
            "type convexPolyhedron; vertices ((0 0 0) (1 0 0) (1 2 0) (0 2 0)"
            " (0 0 3) (1 0 3) (1 2 3) (0 2 3)); scale 2;"
        )
    );
    const scalar a = 2, b = 4, c = 6;
    const scalar V = a*b*c;
    expectRelNear(box->volume(), V, 1e-12, "box");

    const symmTensor J = box->volumeInertia();
    expectRelNear(J.xx(), V*(b*b + c*c)/12, 1e-12, "box Jxx");
    expectRelNear(J.yy(), V*(a*a + c*c)/12, 1e-12, "box Jyy");
    expectRelNear(J.zz(), V*(a*a + b*b)/12, 1e-12, "box Jzz");

    // Centroid moved to the origin: support is symmetric
    const vector s = box->support(vector(1, 1, 1));
    EXPECT_NEAR(s.x(), a/2, 1e-12);
    EXPECT_NEAR(s.y(), b/2, 1e-12);
    EXPECT_NEAR(s.z(), c/2, 1e-12);
    EXPECT_NEAR(box->boundingRadius(), 0.5*Foam::sqrt(a*a + b*b + c*c), 1e-12);
}


TEST(convexPolyhedron, supportIsTheFarthestVertex)
{
    particleShapes::platonicSolid ico("ico", "icosahedron", 1.0);
    Random rnd(7);

    for (label trial = 0; trial < 200; ++trial)
    {
        const vector d = rnd.sample01<vector>() - vector::uniform(0.5);
        const vector s = ico.support(d);
        for (const point& v : ico.points())
        {
            EXPECT_LE(v & d, (s & d) + 1e-14);
        }
    }
}


// * * * * * * * * * * * * * * * * * sphere * * * * * * * * * * * * * * * * //

TEST(sphere, massPropertiesAndSupport)
{
    autoPtr<particleShape> ball =
        particleShape::New("ball", shapeDict("type sphere; D 0.02;"));

    const scalar r = 0.01;
    const scalar V = 4.0/3.0*pi*pow3(r);
    expectRelNear(ball->volume(), V, 1e-14, "V");
    expectRelNear(ball->volumeInertia().xx(), 0.4*r*r*V, 1e-14, "J");
    expectRelNear(ball->equivalentDiameter(), 0.02, 1e-14, "D");

    const vector s = ball->support(vector(3, 0, 4));
    EXPECT_NEAR(s.x(), 0.006, 1e-15);
    EXPECT_NEAR(s.z(), 0.008, 1e-15);
}


// * * * * * * * * * * * * * * * * Bad input * * * * * * * * * * * * * * * //

TEST(particleShapeInput, typoListsEveryShape)
{
    const std::string msg = ioErrorMessage("type cubee; D 1;");
    for
    (
        const char* name
      : {"sphere", "convexPolyhedron", "tetrahedron", "cube", "octahedron",
         "dodecahedron", "icosahedron"}
    )
    {
        EXPECT_NE(msg.find(name), std::string::npos) << name << ": " << msg;
    }
    EXPECT_NE(msg.find("cubee"), std::string::npos) << msg;
}


TEST(particleShapeInput, bothOrNeitherSizeIsRejected)
{
    EXPECT_NE(ioErrorMessage("type cube; D 1; edge 1;").find("both"),
              std::string::npos);
    EXPECT_NE(ioErrorMessage("type cube;").find("neither"),
              std::string::npos);
}


TEST(particleShapeInput, nonPositiveSizesAreRejected)
{
    EXPECT_NE(ioErrorMessage("type sphere; D 0;").find("must be > 0"),
              std::string::npos);
    EXPECT_NE(ioErrorMessage("type cube; edge -1;").find("must be > 0"),
              std::string::npos);
}


TEST(particleShapeInput, flatVerticesAreRejected)
{
    const std::string msg = ioErrorMessage
    (
        "type convexPolyhedron; vertices ((0 0 0) (1 0 0) (0 1 0) (1 1 0));"
    );
    EXPECT_NE(msg.find("one plane"), std::string::npos) << msg;
}


// ************************************************************************* //

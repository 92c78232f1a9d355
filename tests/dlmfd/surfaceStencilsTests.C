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
    The fluidStencil's surface points and stencil weights without a mesh
    (Foam::surfaceStencils): the weights carry a linear field to the point
    exactly in 3D and 2D, a stencil that cannot fit one has none, the
    points are moved inwards by the retraction asked for, none are placed
    when they are off, and each value out of range is refused naming it.

\*---------------------------------------------------------------------------*/

#include "surfaceStencils.H"
#include "sphere.H"
#include "testInput.H"
#include "Random.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The value at p of sum_c w_c f(x_c) for a linear f
scalar carried
(
    const surfaceStencils& st,
    const point& p,
    const UList<point>& centres,
    const scalar h,
    const vector& G,
    bool& fitted
)
{
    scalarList w;
    fitted = st.weights(p, centres, h, w);
    if (!fitted)
    {
        return GREAT;
    }
    scalar u = 0;
    forAll(centres, i)
    {
        u += w[i]*(2.5 + (G & centres[i]));
    }
    return u;
}

} // End anonymous namespace


TEST(surfaceStencils, weightsCarryALinearFieldToThePointExactly)
{
    const scalar h = 0.01;
    const point p(0.3, 0.2, 0.1);
    const vector G(3, -1, 0.5);
    Random rnd(7);

    const surfaceStencils st3(testInput::parse(""), false, 0);
    List<point> centres(9);
    for (point& c : centres)
    {
        c = p + 1.2*h*(rnd.sample01<vector>() - 0.5*vector::one);
    }
    bool fitted = false;
    EXPECT_NEAR(carried(st3, p, centres, h, G, fitted), 2.5 + (G & p), 1e-12);
    EXPECT_TRUE(fitted);

    // 2D: centres in the plane, a field of x and y
    const surfaceStencils st2(testInput::parse(""), true, 0.1);
    List<point> planar(5);
    for (point& c : planar)
    {
        c = p + 1.2*h*(rnd.sample01<vector>() - 0.5*vector::one);
        c.z() = p.z();
    }
    const vector G2(G.x(), G.y(), 0);
    EXPECT_NEAR(carried(st2, p, planar, h, G2, fitted), 2.5 + (G2 & p), 1e-12);
    EXPECT_TRUE(fitted);
}


TEST(surfaceStencils, aStencilThatCannotFitALinearFieldHasNoWeights)
{
    const scalar h = 0.01;
    const point p(0, 0, 0);
    const surfaceStencils st(testInput::parse(""), false, 0);
    scalarList w;

    // Three cells for four coefficients
    EXPECT_FALSE(st.weights(p, List<point>({point(h, 0, 0), point(0, h, 0), point(0, 0, h)}), h, w));

    // Five cells on one plane: no gradient across it
    EXPECT_FALSE
    (
        st.weights
        (
            p,
            List<point>
            ({
                point(h, 0, 0), point(0, h, 0), point(-h, 0, 0),
                point(0, -h, 0), point(h, h, 0)
            }),
            h,
            w
        )
    );
}


TEST(surfaceStencils, pointsAreMovedInwardsByTheRetractionAndNoneWhenOff)
{
    const scalar D = 0.1;
    const scalar h = D/8;
    const particleShapes::sphere ball("ball", D);
    const point x(0.5, 0.5, 0.5);
    DynamicList<point> pts;

    const surfaceStencils onSurface(testInput::parse(""), false, 0);
    onSurface.points(ball, x, tensor::I, h, pts);
    ASSERT_GT(pts.size(), 100);
    for (const point& p : pts)
    {
        EXPECT_NEAR(mag(p - x), 0.5*D, 1e-12);
    }

    const surfaceStencils retracted
    (
        testInput::parse("surfacePointRetraction 0.3;"), false, 0
    );
    retracted.points(ball, x, tensor::I, h, pts);
    ASSERT_GT(pts.size(), 100);
    for (const point& p : pts)
    {
        EXPECT_NEAR(mag(p - x), 0.5*D - 0.3*h, 1e-12);
    }

    const surfaceStencils off(testInput::parse("surfacePoints off;"), false, 0);
    off.points(ball, x, tensor::I, h, pts);
    EXPECT_EQ(pts.size(), 0);
    EXPECT_FALSE(off.on());
}


TEST(surfaceStencils, valuesOutOfRangeAreRefusedNamingThem)
{
    const auto refused = [](const std::string& text)
    {
        return testInput::errorOf([&]
        {
            surfaceStencils st(testInput::parse(text), false, 0);
        });
    };
    std::string e = refused("surfacePointSpacing 0;");
    EXPECT_NE(e.find("surfacePointSpacing = 0"), std::string::npos) << e;
    EXPECT_NE(e.find("> 0"), std::string::npos) << e;
    e = refused("surfaceStencilRadius 0.9;");
    EXPECT_NE(e.find("surfaceStencilRadius = 0.9"), std::string::npos) << e;
    EXPECT_NE(e.find(">= 1"), std::string::npos) << e;
    e = refused("surfacePointRetraction 1;");
    EXPECT_NE(e.find("surfacePointRetraction = 1"), std::string::npos) << e;
    EXPECT_NE(e.find("0 <= it < 1"), std::string::npos) << e;
    EXPECT_EQ(refused("surfaceStencilRadius 2; surfacePointSpacing 0.5;"), "");
}


// ************************************************************************* //

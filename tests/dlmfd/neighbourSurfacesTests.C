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
    The neighbours' surfaces of the ghost cells' quadratic fit
    (Foam::neighbourSurfaces): a ray meets the nearest of two cubes at its
    face, to round-off, with that cube's rigid velocity there; a ray that
    passes beside them, or whose reach ends before them, meets nothing;
    the weight of a plane of points is the sum over a fine plane, and
    vanishes at and beyond the fit's radius.

\*---------------------------------------------------------------------------*/

#include "neighbourSurfaces.H"
#include "platonicSolid.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(neighbourSurfaces, rayMeetsTheNearestFaceWithItsRigidVelocity)
{
    // Cubes of edge 0.5 centred at x = 1 and x = 2 (faces at 0.75 and
    // 1.75), the nearer one moving at V = (0 0.2 0) and spinning about x
    const particleShapes::platonicSolid cube("cube", "cube", 0.5);
    neighbourSurfaces walls;
    const vector omega(0.3, 0, 0);
    walls.add(cube, point(2, 0, 0), tensor::I, Zero, Zero);
    walls.add(cube, point(1, 0, 0), tensor::I, vector(0, 0.2, 0), omega);
    ASSERT_EQ(walls.size(), 2);

    const point p(0, 0.1, 0.05);
    scalar t;
    vector u;
    ASSERT_TRUE(walls.firstAlong(p, vector(1, 0, 0), 2.5, 0.05, t, u));
    EXPECT_NEAR(t, 0.75, 1e-9);
    const vector expected = vector(0, 0.2, 0) + (omega ^ vector(-0.25, 0.1, 0.05));
    EXPECT_LT(mag(u - expected), 1e-12);

    // Beside the cubes, away from them, or short of them
    EXPECT_FALSE(walls.firstAlong(p + vector(0, 0.5, 0), vector(1, 0, 0), 2.5, 0.05, t, u));
    EXPECT_FALSE(walls.firstAlong(p, vector(-1, 0, 0), 2.5, 0.05, t, u));
    EXPECT_FALSE(walls.firstAlong(p, vector(1, 0, 0), 0.7, 0.05, t, u));
}


TEST(neighbourSurfaces, layerWeightIsTheSumOverAPlaneOfPoints)
{
    // The fit's weight (1 - r^2/R^2)^2 summed over a plane of points h
    // apart at distance t, with h small against R: the closed form to
    // 0.1 %; in 2D over a line; zero at and beyond R
    const scalar R = 2.5, h = 0.02;
    for (const scalar t : {0.3, 1.2, 2.1})
    {
        scalar plane = 0, line = 0;
        const label m = R/h + 1;
        for (label j = -m; j <= m; ++j)
        {
            const scalar rl = sqr(t) + sqr(j*h);
            if (rl < sqr(R))
            {
                line += sqr(1 - rl/sqr(R));
            }
            for (label k = -m; k <= m; ++k)
            {
                const scalar r2 = rl + sqr(k*h);
                if (r2 < sqr(R))
                {
                    plane += sqr(1 - r2/sqr(R));
                }
            }
        }
        EXPECT_NEAR(neighbourSurfaces::layerWeight(t, R, h, false), plane, 1e-3*plane) << t;
        EXPECT_NEAR(neighbourSurfaces::layerWeight(t, R, h, true), line, 1e-3*line) << t;
    }
    EXPECT_EQ(neighbourSurfaces::layerWeight(R, R, h, false), 0);
    EXPECT_EQ(neighbourSurfaces::layerWeight(1.1*R, R, h, true), 0);
}


// ************************************************************************* //

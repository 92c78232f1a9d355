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
    The periodic images of the cells (Foam::periodicImages): a ball near a
    corner of a box periodic in two directions meets the cells at four
    shifts and one periodic in none at one; only the shifts whose ball
    reaches this rank's cell centres are kept for a body; the shortest
    image of a separation; a negative period and a body longer than half
    a period are refused naming what is allowed.

\*---------------------------------------------------------------------------*/

#include "periodicImages.H"
#include "foamTestCase.H"
#include "testInput.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

bool holds(const List<vector>& shifts, const vector& s)
{
    for (const vector& t : shifts)
    {
        if (mag(t - s) < 1e-12)
        {
            return true;
        }
    }
    return false;
}

} // End anonymous namespace


TEST(periodicImages, aBallNearACornerMeetsTheCellsAtEachPeriodicShift)
{
    const boundBox box(point(0, 0, 0), point(1, 1, 1));
    const point x(0.05, 0.95, 0.5);

    // Periodic in x and y: the shifts s whose ball about x - s reaches
    // the box are zero, -1 period in x (the ball about x + (1 0 0) reaches
    // across the face x = 1), +1 period in y, and both
    const List<vector> s =
        periodicImages::shifts(box, vector(1, 1, 0), x, 0.1);
    EXPECT_EQ(s.size(), 4);
    EXPECT_EQ(s[0], vector::zero);
    EXPECT_TRUE(holds(s, vector(-1, 0, 0)));
    EXPECT_TRUE(holds(s, vector(0, 1, 0)));
    EXPECT_TRUE(holds(s, vector(-1, 1, 0)));

    // A ball in the middle, or no periodic direction: the zero shift only
    EXPECT_EQ(periodicImages::shifts(box, vector(1, 1, 0), point(0.5, 0.5, 0.5), 0.1).size(), 1);
    EXPECT_EQ(periodicImages::shifts(box, vector::zero, x, 0.1).size(), 1);
}


TEST(periodicImages, onlyShiftsReachingThisRanksCellsAreKept)
{
    test::foamTestCase tc;
    // The rank's cells span [0, 1] x [0, 1] x [0, 0.5] of a box periodic
    // in z with period 1 (the other half on another rank)
    const fvMesh& mesh = tc.makeBoxMesh(10, 10, 5, vector(1, 1, 0.5));
    const cellCentreSearch search(mesh);
    periodicImages images(search, boundBox(point(0, 0, 0), point(1, 1, 1)));
    images.setPeriod(vector(0, 0, 1));

    // A ball at z = 0.95 reaches this rank's cells only through the
    // shift +1 in z (its image at z = -0.05)
    const List<vector> near = images.reaching(point(0.5, 0.5, 0.95), 0.12);
    ASSERT_EQ(near.size(), 1);
    EXPECT_EQ(near[0], vector(0, 0, 1));

    // A ball at z = 0.75 reaches no cell of this rank
    EXPECT_EQ(images.reaching(point(0.5, 0.5, 0.75), 0.12).size(), 0);
}


TEST(periodicImages, theShortestImageOfASeparation)
{
    const vector period(1, 0, 2);
    const vector d = periodicImages::nearestImage(vector(0.8, 0.8, -1.5), period);
    EXPECT_NEAR(d.x(), -0.2, 1e-15);
    EXPECT_EQ(d.y(), 0.8);
    EXPECT_NEAR(d.z(), 0.5, 1e-15);
}


TEST(periodicImages, negativePeriodAndBodyLongerThanHalfAPeriodAreRefused)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(4, 4, 4, vector::one);
    const cellCentreSearch search(mesh);
    periodicImages images(search, mesh.bounds());

    std::string e = testInput::errorOf([&]
    {
        images.setPeriod(vector(1, -1, 0));
    });
    EXPECT_NE(e.find("must be > 0, or 0"), std::string::npos) << e;

    images.setPeriod(vector(1, 0, 0));
    EXPECT_EQ(testInput::errorOf([&]{ images.checkClearance(3, 0.49); }), "");
    e = testInput::errorOf([&]{ images.checkClearance(3, 0.5); });
    EXPECT_NE(e.find("particle 3"), std::string::npos) << e;
    EXPECT_NE(e.find("not below half the period 1"), std::string::npos) << e;
}


// ************************************************************************* //

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
    Unit tests of the contact search (Foam::verletList): the skin defaults
    to a tenth of the smallest diameter; a build lists the pairs within
    r_i + r_j + skin and, for the particles walls act on, the walls within
    r_i + skin; the list is kept until a particle has moved by more than
    half the skin; the reach query answers for a search distance beyond
    the skin without touching the list.

\*---------------------------------------------------------------------------*/

#include "verletList.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

// A 10 m box, walls at z = 0 (normal +z) and z = 10 (normal -z)
struct scene
{
    boundBox domain{point(0, 0, 0), point(10, 10, 10)};
    FixedList<bool, 3> periodic{false, false, false};
    List<planeWall> walls;
    scalarList r{0.5, 0.5, 0.5};

    scene()
    {
        walls.setSize(2);
        walls[0] = planeWall{"floor", point(0, 0, 0), vector(0, 0, 1), "wall"};
        walls[1] = planeWall{"lid", point(0, 0, 10), vector(0, 0, -1), "wall"};
    }
};

} // End anonymous namespace


TEST(verletList, skinDefaultsToATenthOfTheSmallestDiameter)
{
    scene s;
    verletList given;
    given.setSkin(0.3);
    given.reset(s.domain, s.periodic, 3, 0.5, 1.0);
    EXPECT_EQ(given.skin(), 0.3);

    verletList automatic;
    automatic.setSkin(-1);
    automatic.reset(s.domain, s.periodic, 3, 0.5, 0.8);
    EXPECT_DOUBLE_EQ(automatic.skin(), 0.08);
}


TEST(verletList, listsPairsAndWallsWithinTheSkinAndKeepsThemUntilHalfASkin)
{
    scene s;
    verletList list;
    list.setSkin(0.2);
    list.reset(s.domain, s.periodic, 3, 0.5, 1.0);
    EXPECT_TRUE(list.needsBuild(3));

    // 0 and 1 are 1.15 apart (within 0.5 + 0.5 + 0.2), 2 is far; 0 is
    // 0.65 above the floor (within 0.5 + 0.2), 1 too but walls do not
    // act on it
    pointField x({point(2, 2, 0.65), point(3.15, 2, 0.65), point(8, 8, 5)});
    list.build(x, s.r, s.walls, boolList({true, false, true}));
    EXPECT_FALSE(list.needsBuild(3));
    ASSERT_EQ(list.pairs().size(), 1);
    EXPECT_EQ(list.pairs()[0], labelPair(0, 1));
    EXPECT_TRUE(list.nearAWall(0));
    ASSERT_EQ(list.nearWalls(0).size(), 1);
    EXPECT_EQ(list.nearWalls(0)[0], 0);
    EXPECT_FALSE(list.nearAWall(1));
    EXPECT_FALSE(list.nearAWall(2));

    // Moving by less than half the skin keeps the list ...
    list.noteMoved(2, point(8.09, 8, 5));
    EXPECT_FALSE(list.needsBuild(3));
    // ... by more, it is built again at the next query
    list.noteMoved(2, point(8.11, 8, 5));
    EXPECT_TRUE(list.needsBuild(3));
    // and for another number of particles too
    list.build(x, s.r, s.walls, boolList({true, false, true}));
    EXPECT_FALSE(list.needsBuild(3));
    EXPECT_TRUE(list.needsBuild(4));
}


TEST(verletList, reachQueryLooksBeyondTheSkinWithoutTouchingTheList)
{
    scene s;
    verletList list;
    list.setSkin(0.1);
    list.reset(s.domain, s.periodic, 3, 0.5, 1.0);
    pointField x({point(2, 2, 5), point(3.5, 2, 5), point(8, 8, 5)});
    list.build(x, s.r, s.walls, boolList(3, true));
    EXPECT_EQ(list.pairs().size(), 0);

    // 0 and 1 are 0.5 apart at the surfaces
    EXPECT_FALSE(list.anyPairWithin(x, s.r, 0.4));
    EXPECT_TRUE(list.anyPairWithin(x, s.r, 0.6));
    EXPECT_EQ(list.pairs().size(), 0);
    EXPECT_FALSE(list.needsBuild(3));
}


// ************************************************************************* //

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
    Which body owns a cell (Foam::cellOwnership): a cell inside a body
    goes to it even when it is nearer another body whose stencil reaches
    it; inside two bodies, or near two, it goes to the closer centre,
    whatever order the claims come in; reset frees every claimed cell and
    only those.

\*---------------------------------------------------------------------------*/

#include "cellOwnership.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(cellOwnership, insideBeatsNearAndTheCloserCentreBreaksTies)
{
    struct claimOf { label c, b; scalar d2; bool inside; };
    // Cell 1: near body 0 (close), inside body 1 (far): inside wins.
    // Cell 2: inside both, body 1 closer. Cell 3: near both, body 0
    // closer. Cell 0: unclaimed.
    const List<claimOf> claims
    ({
        {1, 0, 0.1, false}, {1, 1, 4.0, true},
        {2, 0, 2.0, true}, {2, 1, 1.0, true},
        {3, 0, 0.5, false}, {3, 1, 0.7, false}
    });
    // The same owners whatever order the claims come in
    for (const bool reversed : {false, true})
    {
        cellOwnership owners(10);
        forAll(claims, k)
        {
            const claimOf& x = claims[reversed ? claims.size() - 1 - k : k];
            owners.claim(x.c, x.b, x.d2, x.inside);
        }
        EXPECT_EQ(owners.owner(1), 1);
        EXPECT_EQ(owners.owner(2), 1);
        EXPECT_EQ(owners.owner(3), 0);
        EXPECT_EQ(owners.owner(0), -1);
        EXPECT_TRUE(owners.inside(1));
        EXPECT_TRUE(owners.inside(2));
        EXPECT_FALSE(owners.inside(3));
    }
}


TEST(cellOwnership, resetFreesTheClaimedCells)
{
    cellOwnership owners(5);
    owners.claim(4, 2, 1.0, true);
    owners.claim(0, 1, 1.0, false);
    owners.reset();
    for (label c = 0; c < 5; ++c)
    {
        EXPECT_EQ(owners.owner(c), -1);
        EXPECT_FALSE(owners.inside(c));
    }
    // A claim after the reset is not compared with the old ones
    owners.claim(4, 3, 9.0, false);
    EXPECT_EQ(owners.owner(4), 3);
}


// ************************************************************************* //

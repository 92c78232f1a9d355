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
    Foam::bodyHolders: the sums over the ranks that hold a body are added
    in the order of Pstream's reduce over every rank (the schedule of 8
    ranks, built here as OpenFOAM builds it: 0 hears from 1, 2 and 4; 2
    from 3; 4 from 5 and 6; 6 from 7), so that they are the same bits.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "bodyHolders.H"

using namespace Foam;

namespace
{
    // The schedule of n ranks: its entries are filled when read
    // (UList<UPstream::commsStruct>::operator[]), as in a parallel run
    List<UPstream::commsStruct> schedule(const label n)
    {
        return List<UPstream::commsStruct>(n);
    }
}


TEST(bodyHolders, theScheduleOfEightRanksIsOpenFOAMsTree)
{
    const List<UPstream::commsStruct> comms(schedule(8));
    EXPECT_EQ(comms[0].below(), labelList({1, 2, 4}));
    EXPECT_EQ(comms[2].below(), labelList({3}));
    EXPECT_EQ(comms[4].below(), labelList({5, 6}));
    EXPECT_EQ(comms[6].below(), labelList({7}));
    EXPECT_EQ(comms[7].above(), 6);
}


TEST(bodyHolders, aSumOverHoldersIsTheReductionOfEveryRanksValue)
{
    const List<UPstream::commsStruct> comms(schedule(8));
    // Values whose sum depends on the order of the additions
    const scalarList all({0.3, 1e-16, 0.7, 1, 3e-16, 1e-16, 1e-16, 0.1});

    // Every rank: the tree's order
    const scalar whole =
        ((all[0] + all[1]) + (all[2] + all[3]))
      + ((all[4] + all[5]) + (all[6] + all[7]));
    EXPECT_EQ
    (
        bodyHolders::reductionOrderSum(comms, identity(8), all),
        whole
    );

    // Holders 3, 5, 6 (the others' values zero): 3 + (5 + 6), not
    // (3 + 5) + 6
    const labelList holders({3, 5, 6});
    const scalarList values({1, 1e-16, 1e-16});
    const scalar sum =
        bodyHolders::reductionOrderSum(comms, holders, values);
    scalarList withZeros(8, Zero);
    forAll(holders, k)
    {
        withZeros[holders[k]] = values[k];
    }
    EXPECT_EQ
    (
        sum,
        bodyHolders::reductionOrderSum(comms, identity(8), withZeros)
    );
    EXPECT_EQ(sum, values[0] + (values[1] + values[2]));
    EXPECT_NE(sum, (values[0] + values[1]) + values[2]);
}


TEST(bodyHolders, oneHolderIsItsOwnValueAndNoneIsZero)
{
    const List<UPstream::commsStruct> comms(schedule(4));
    EXPECT_EQ
    (
        bodyHolders::reductionOrderSum(comms, labelList({3}), scalarList({2.5})),
        2.5
    );
    EXPECT_EQ
    (
        bodyHolders::reductionOrderSum(comms, labelList(), scalarList()),
        0
    );
}


// ************************************************************************* //

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
    The exchanges of the fictitious-domain step (Foam::bodyExchange) in a
    serial run: a body with a share on the rank is solved there and one
    without is solved nowhere; the contributions reach the solver as they
    were sent and without a message; the results stay where they were
    solved. (On several ranks: tests/cases/dlmfdParallelMatchesSerial, whose
    bodies are solved on the rank holding most of each, with the counts of
    messages and bytes it logs.)

\*---------------------------------------------------------------------------*/

#include "bodyExchange.H"

#include <gtest/gtest.h>

using namespace Foam;


TEST(bodyExchange, aBodyIsSolvedWhereItHasAShareAndNowhereWithout)
{
    scalar seconds = 0;
    const labelList nHere({5, 0, 1});
    const labelList solver(bodyExchange::solvingRanks(nHere, seconds));
    EXPECT_EQ(solver, labelList({0, -1, 0}));
}


TEST(bodyExchange, serialContributionsArriveAsSentWithoutAMessage)
{
    scalar seconds = 0;
    exchangeTraffic received;
    List<DynamicList<bodyExchange::contribution>> outgoing(1);
    bodyExchange::contribution con;
    con.body = 3;
    con.centres = List<point>({point(1, 2, 3), point(4, 5, 6)});
    con.u = vectorField({vector(0.1, 0, 0), vector(0, 0.2, 0)});
    con.nInterior = 2;
    outgoing[0].append(con);
    const List<List<bodyExchange::contribution>> incoming
    (
        bodyExchange::toSolvers(outgoing, seconds, received)
    );
    ASSERT_EQ(incoming.size(), 1);
    ASSERT_EQ(incoming[0].size(), 1);
    EXPECT_EQ(incoming[0][0].body, 3);
    EXPECT_EQ(incoming[0][0].centres, con.centres);
    EXPECT_EQ(incoming[0][0].u, con.u);
    EXPECT_EQ(received.messages, 0);
    EXPECT_EQ(received.bytes, 0);

    List<bodyExchange::result> results(2);
    results[1].dV = vector(1, 2, 3);
    results[1].nInterior = 7;
    bodyExchange::sendResults
    (
        labelList({1}), labelList({1}), labelList({0}), bodyPlaces(), results,
        seconds, received
    );
    EXPECT_EQ(results[1].dV, vector(1, 2, 3));
    EXPECT_EQ(results[1].nInterior, 7);
    EXPECT_EQ(results[0].dV, vector::zero);
    EXPECT_EQ(received.messages, 0);
}


// ************************************************************************* //

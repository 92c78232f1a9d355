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
    The bins of a body's cells (Foam::pointBins): for query points inside,
    on the edge of and outside the points' box, the candidates forNear
    visits hold every point within the query radius (larger than a bin),
    each once; an empty set visits nothing; a bin width of zero is
    refused.

\*---------------------------------------------------------------------------*/

#include "pointBins.H"
#include "Random.H"
#include "DynamicList.H"
#include "testInput.H"

#include <gtest/gtest.h>
#include <algorithm>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(pointBins, nearPointsAreAllVisitedOnce)
{
    Random rnd(21);
    List<point> x(800);
    for (point& p : x)
    {
        // A shell, as a body's fluid cells are
        vector d = rnd.sample01<vector>() - vector::uniform(0.5);
        d /= mag(d) + VSMALL;
        p = (3 + 2*rnd.sample01<scalar>())*d;
    }
    const scalar width = 0.5, radius = 1.3;
    const pointBins bins(x, width);

    List<point> queries(200);
    for (point& q : queries)
    {
        q = 14*(rnd.sample01<vector>() - vector::uniform(0.5));
    }
    queries.append(point(5, 5, 5));      // a corner of the box
    queries.append(point(100, 0, 0));    // far outside
    for (const point& q : queries)
    {
        DynamicList<label> visited;
        bins.forNear(q, radius, [&](const label k) { visited.append(k); });
        labelList sorted(visited);
        std::sort(sorted.begin(), sorted.end());
        EXPECT_TRUE
        (
            std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()
        ) << "a point visited twice near query " << &q - queries.cdata();
        forAll(x, k)
        {
            if (mag(x[k] - q) <= radius)
            {
                EXPECT_TRUE(std::binary_search(sorted.begin(), sorted.end(), k))
                    << "point " << k << " missed near query "
                    << &q - queries.cdata();
            }
        }
    }
}


TEST(pointBins, emptySetVisitsNothingAndZeroWidthIsRefused)
{
    const pointBins none(List<point>(), 1.0);
    label n = 0;
    none.forNear(point::zero, 1.0, [&](const label) { ++n; });
    EXPECT_EQ(n, 0);

    const std::string e = testInput::errorOf([]
    {
        pointBins bad(List<point>(1, point::zero), 0);
    });
    EXPECT_NE(e.find("bin width 0"), std::string::npos) << e;
}


// ************************************************************************* //

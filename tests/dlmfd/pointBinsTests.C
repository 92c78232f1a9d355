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
    each once; the box of a ball's cap (the fits' half-ball) holds every
    point of the cap and is smaller than the ball's; bins of a given grid
    with unequal widths find the same points as a brute-force search; an
    empty set visits nothing; a bin width of zero and a point outside a
    given grid are refused.

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


TEST(pointBins, capBoxHoldsTheCapOfTheBallAndIsSmallerThanTheBall)
{
    Random rnd(22);
    const scalar r = 2.5, c = 0.5;
    for (label trial = 0; trial < 50; ++trial)
    {
        vector n = rnd.sample01<vector>() - vector::uniform(0.5);
        n /= mag(n);
        const point p = rnd.sample01<vector>();
        point lo, hi;
        pointBins::capBox(p, r, n, c, lo, hi);
        scalar volume = 1;
        for (direction d = 0; d < 3; ++d)
        {
            volume *= hi[d] - lo[d];
        }
        EXPECT_LT(volume, pow3(2*r)) << "trial " << trial;
        for (label k = 0; k < 2000; ++k)
        {
            const vector q = 2*r*(rnd.sample01<vector>() - vector::uniform(0.5));
            if (magSqr(q) >= sqr(r) || (n & q) < c)
            {
                continue;
            }
            const point x = p + q;
            for (direction d = 0; d < 3; ++d)
            {
                EXPECT_GE(x[d], lo[d]) << "trial " << trial;
                EXPECT_LE(x[d], hi[d]) << "trial " << trial;
            }
        }
    }
    // n along x: the cap runs from c to r along x, and across it as far
    // as the circle where the plane cuts the sphere
    point lo, hi;
    pointBins::capBox(point::zero, r, vector(1, 0, 0), c, lo, hi);
    EXPECT_NEAR(lo.x(), c, 1e-6);
    EXPECT_NEAR(hi.x(), r, 1e-6);
    EXPECT_NEAR(hi.y(), std::sqrt(sqr(r) - sqr(c)), 1e-6);
}


TEST(pointBins, givenGridWithUnequalWidthsFindsEveryPointInABox)
{
    Random rnd(7);
    const point origin(-1, 0, 2);
    const vector width(0.4, 0.25, 0.7);
    const labelVector nBins(5, 8, 3);
    List<point> x(600);
    for (point& p : x)
    {
        p = origin + cmptMultiply(rnd.sample01<vector>(), vector(2, 2, 2.1));
    }
    const pointBins bins(x, origin, width, nBins);
    for (label q = 0; q < 100; ++q)
    {
        const point lo = origin + cmptMultiply
        (
            rnd.sample01<vector>() - vector::uniform(0.3),
            vector(2, 2, 2.1)
        );
        const point hi = lo + 0.6*rnd.sample01<vector>();
        DynamicList<label> found;
        bins.forInBox(lo, hi, [&](const label k)
        {
            const point& p = x[k];
            if
            (
                p.x() >= lo.x() && p.y() >= lo.y() && p.z() >= lo.z()
             && p.x() <= hi.x() && p.y() <= hi.y() && p.z() <= hi.z()
            )
            {
                found.append(k);
            }
        });
        labelList sorted(found);
        std::sort(sorted.begin(), sorted.end());
        DynamicList<label> expected;
        forAll(x, k)
        {
            const point& p = x[k];
            if
            (
                p.x() >= lo.x() && p.y() >= lo.y() && p.z() >= lo.z()
             && p.x() <= hi.x() && p.y() <= hi.y() && p.z() <= hi.z()
            )
            {
                expected.append(k);
            }
        }
        EXPECT_EQ(sorted, labelList(expected)) << "box " << q;
    }

    const std::string e = testInput::errorOf([&]
    {
        List<point> outside(x);
        outside.append(point(5, 0.5, 2.5));
        pointBins bad(outside, origin, width, nBins);
    });
    EXPECT_NE(e.find("lies outside the bins' box"), std::string::npos) << e;
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

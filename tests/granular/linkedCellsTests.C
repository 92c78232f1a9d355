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
    Unit tests of the linked-cell broad phase: on random particles, with
    and without periodic directions (also periodic directions only one or
    two cells wide, and centres outside a walled extent), it finds exactly
    the pairs that the brute-force O(N^2) search finds; a grid over a
    region of the domain (a rank's box and its reach) finds exactly those
    pairs too for the particles within the region, across the periodic
    boundaries, with fewer cells than the whole domain's grid.

\*---------------------------------------------------------------------------*/

#include "linkedCells.H"
#include "Random.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace Foam;

namespace
{

std::set<std::pair<label, label>> bruteForce
(
    const linkedCells& cells,
    const UList<point>& x,
    const UList<scalar>& r,
    const scalar skin
)
{
    std::set<std::pair<label, label>> pairs;
    forAll(x, i)
    {
        for (label j = i + 1; j < x.size(); ++j)
        {
            if (magSqr(cells.separation(x[i], x[j])) < sqr(r[i] + r[j] + skin))
            {
                pairs.insert({i, j});
            }
        }
    }
    return pairs;
}

} // End anonymous namespace


TEST(linkedCells, findsExactlyTheBruteForcePairs)
{
    struct setUp
    {
        vector span;
        FixedList<bool, 3> periodic;
    };
    const setUp cases[] =
    {
        {vector(20, 20, 20), {false, false, false}},
        {vector(20, 20, 20), {true, false, false}},
        {vector(20, 20, 20), {true, true, true}},
        {vector(20, 3.5, 20), {true, true, true}},     // one cell along y
        {vector(20, 5, 6), {false, true, true}}        // two cells along y
    };

    Random rnd(2024);
    const scalar skin = 0.1;

    for (const setUp& c : cases)
    {
        const boundBox domain(point(-1, 2, 0), point(-1, 2, 0) + c.span);
        const label n = 1500;
        pointField x(n);
        scalarField r(n);
        forAll(x, i)
        {
            r[i] = 0.5 + 0.5*rnd.sample01<scalar>();
            // Up to 1 outside the extent, to bin centres past a wall
            x[i] = domain.min() - vector::uniform(1)
              + cmptMultiply(c.span + vector::uniform(2), rnd.sample01<vector>());
        }

        const linkedCells cells(domain, c.periodic, 2*max(r) + skin);
        DynamicList<labelPair> found;
        cells.findPairs(x, r, skin, found);

        std::set<std::pair<label, label>> fromCells;
        for (const labelPair& p : found)
        {
            ASSERT_LT(p.first(), p.second());
            const bool inserted = fromCells.insert({p.first(), p.second()}).second;
            EXPECT_TRUE(inserted)
                << "pair found twice: " << p.first() << " " << p.second();
        }

        const auto expected = bruteForce(cells, x, r, skin);
        EXPECT_GT(expected.size(), 100u);
        EXPECT_EQ(fromCells, expected)
            << "span " << c.span.x() << " " << c.span.y() << " " << c.span.z()
            << ", periodic " << c.periodic[0] << c.periodic[1]
            << c.periodic[2] << ", cells " << cells.nCells().x() << " "
            << cells.nCells().y() << " " << cells.nCells().z();
    }
}


TEST(linkedCells, aGridOverARegionFindsThePairsOfItsParticles)
{
    // A rank's box of a domain cut 4 x 4 x 1, periodic in x and y, walls
    // in z; boxes at the periodic corner and inside, the region the box
    // grown by a reach; the particles within the region's reach of the
    // box (as a rank holds them: owned and ghosts), some across the
    // periodic boundaries, a few past the walls
    const vector span(24, 24, 10);
    const boundBox domain(point(-2, 1, 0), point(-2, 1, 0) + span);
    const FixedList<bool, 3> periodic{true, true, false};
    const scalar skin = 0.1, reach = 2;
    Random rnd(41);

    const label nAll = 20000;
    pointField xAll(nAll);
    scalarField rAll(nAll);
    forAll(xAll, i)
    {
        rAll[i] = 0.25 + 0.25*rnd.sample01<scalar>();
        xAll[i] = domain.min() - vector(0, 0, 0.3)
          + cmptMultiply(span + vector(0, 0, 0.6), rnd.sample01<vector>());
    }
    const scalar width = 2*max(rAll) + skin;
    const linkedCells whole(domain, periodic, width);

    const vector boxSpan(span.x()/4, span.y()/4, span.z());
    for (const labelVector& ijk : {labelVector(0, 0, 0), labelVector(2, 1, 0), labelVector(3, 3, 0)})
    {
        const point lo =
            domain.min() + cmptMultiply(boxSpan, vector(ijk.x(), ijk.y(), ijk.z()));
        const boundBox box(lo, lo + boxSpan);
        const boundBox region
        (
            box.min() - vector::uniform(reach), box.max() + vector::uniform(reach)
        );
        const linkedCells local(domain, periodic, width, region);

        // The particles a rank holds: within the reach of its box, by the
        // minimum image
        DynamicList<point> x;
        DynamicList<scalar> r;
        forAll(xAll, i)
        {
            const vector d = whole.separation(xAll[i], box.centre());
            bool within = true;
            for (direction k = 0; k < 3; ++k)
            {
                within = within && mag(d[k]) <= 0.5*boxSpan[k] + reach;
            }
            if (within)
            {
                x.append(xAll[i]);
                r.append(rAll[i]);
            }
        }

        DynamicList<labelPair> fromLocal, fromWhole;
        local.findPairs(x, r, skin, fromLocal);
        whole.findPairs(x, r, skin, fromWhole);
        EXPECT_GT(fromWhole.size(), 200);
        EXPECT_EQ(fromLocal, fromWhole)
            << "box " << ijk.x() << " " << ijk.y() << ": " << fromLocal.size()
            << " pairs from the region's grid, " << fromWhole.size()
            << " from the whole domain's";
        // Every pair of the brute force among them
        std::set<std::pair<label, label>> missed = bruteForce(whole, x, r, skin);
        for (const labelPair& p : fromLocal)
        {
            missed.erase({p.first(), p.second()});
        }
        EXPECT_TRUE(missed.empty()) << missed.size() << " pairs missed";

        // Fewer cells: the region's, not the domain's (the periodic x and
        // y not wrapped: the region is shorter than half the period)
        EXPECT_LT(cmptProduct(local.nCells()), cmptProduct(whole.nCells())/4)
            << "cells " << local.nCells().x() << " " << local.nCells().y()
            << " " << local.nCells().z();
    }
}


// ************************************************************************* //

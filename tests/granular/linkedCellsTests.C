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
    the pairs that the brute-force O(N^2) search finds.

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


// ************************************************************************* //

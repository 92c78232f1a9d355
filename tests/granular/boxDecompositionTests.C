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
    Tests of Foam::boxDecomposition: the rank of a point and the ranks
    within reach of it, against a brute force over every box and every
    periodic image.

\*---------------------------------------------------------------------------*/

#include "boxDecomposition.H"
#include "Random.H"

#include <gtest/gtest.h>
#include <string>

using namespace Foam;

namespace
{

//- Distance from x to box b, the nearest of x's periodic images
scalar bruteDistance
(
    const boundBox& domain,
    const FixedList<bool, 3>& periodic,
    const boundBox& b,
    const point& x
)
{
    const vector L = domain.span();
    scalar best = GREAT;
    for (label i = -2; i <= 2; ++i)
    for (label j = -2; j <= 2; ++j)
    for (label k = -2; k <= 2; ++k)
    {
        const labelVector s(i, j, k);
        bool allowed = true;
        point y = x;
        for (direction d = 0; d < 3; ++d)
        {
            allowed = allowed && (periodic[d] || s[d] == 0);
            y[d] += s[d]*L[d];
        }
        if (!allowed)
        {
            continue;
        }
        best = min(best, mag(y - b.nearest(y)));
    }
    return best;
}

//- A point for a message
std::string where(const point& x)
{
    return
        std::to_string(x.x()) + ' ' + std::to_string(x.y()) + ' '
      + std::to_string(x.z());
}

//- Whether each rank is among ranks (those boxes.ranksWithin gave for x
//- and reach) as the brute force says, the ranks at the reach to
//- round-off left out; how many were checked
label expectTheBruteForce
(
    const boxDecomposition& boxes,
    const boundBox& domain,
    const FixedList<bool, 3>& periodic,
    const point& x,
    const scalar reach,
    const UList<label>& ranks
)
{
    label checked = 0;
    for (label r = 0; r < boxes.size(); ++r)
    {
        const scalar d = bruteDistance(domain, periodic, boxes.box(r), x);
        if (mag(d - reach) < 1e-12)
        {
            continue;
        }
        EXPECT_EQ(ranks.found(r), d < reach)
            << "rank " << r << " at " << d << " from " << where(x)
            << ", reach " << reach;
        ++checked;
    }
    return checked;
}

} // End anonymous namespace


TEST(boxDecomposition, ranksWithinReachAreThoseOfTheBruteForce)
{
    // Boxes narrower than the reach along y, a periodic x and z, points
    // near faces, edges and corners and outside the domain along the
    // periodic directions
    const boundBox domain(point(-1, 0, 0.5), point(3, 1, 2.5));
    for (const bool px : {false, true})
    for (const bool pz : {false, true})
    {
        const FixedList<bool, 3> periodic({px, false, pz});
        const labelVector n(4, 5, 3);
        const boxDecomposition boxes(domain, periodic, n);
        ASSERT_EQ(boxes.size(), 60);
        Random rnd(17);
        DynamicList<label> ranks;
        label checked = 0, far = 0;
        for (label sample = 0; sample < 3000; ++sample)
        {
            point x =
                domain.min()
              + cmptMultiply(rnd.sample01<vector>(), domain.span());
            // Outside along the periodic directions, by up to a period
            if (px && sample % 3 == 0)
            {
                x.x() += (sample % 2 ? 1 : -1)*domain.span().x();
            }
            if (pz && sample % 5 == 0)
            {
                x.z() -= 0.999*domain.span().z();
            }
            const scalar reach = 0.05 + 0.6*rnd.sample01<scalar>();
            const label own = boxes.rankOf(x);
            ASSERT_GE(own, 0) << where(x);
            boxes.ranksWithin(x, reach, ranks);
            EXPECT_TRUE(ranks.found(own)) << where(x);
            for (label a = 1; a < ranks.size(); ++a)
            {
                EXPECT_LT(ranks[a - 1], ranks[a]);
            }
            checked +=
                expectTheBruteForce(boxes, domain, periodic, x, reach, ranks);
            for (const label r : ranks)
            {
                far += r != own && mag(boxes.box(r).centre() - x) > 0.6;
            }
            // The point's own box holds it (its image in the domain)
            EXPECT_LT
            (
                bruteDistance(domain, periodic, boxes.box(own), x), 1e-12
            );
        }
        EXPECT_EQ(checked, 3000*60);
        // Boxes beyond the face neighbours were met (corners, and the
        // narrow boxes along y)
        EXPECT_GT(far, 100);
    }
}


TEST(boxDecomposition, pointsOnBoxFacesBelongToTheUpperBoxAndTheDomainEndToTheLast)
{
    const boundBox domain(point(0, 0, 0), point(4, 2, 1));
    const boxDecomposition boxes
    (
        domain, FixedList<bool, 3>({false, true, false}), labelVector(4, 2, 1)
    );
    EXPECT_EQ(boxes.rankOf(point(1, 0.5, 0.5)), 1);
    EXPECT_EQ(boxes.rankOf(point(0.9999999, 0.5, 0.5)), 0);
    EXPECT_EQ(boxes.rankOf(point(4, 0.5, 0.5)), 3);
    EXPECT_EQ(boxes.rankOf(point(0, 0, 0)), 0);
    EXPECT_EQ(boxes.rankOf(point(0.5, 1, 0.5)), 4);
    // Periodic in y: y = 2 is y = 0, -0.5 is 1.5
    EXPECT_EQ(boxes.rankOf(point(0.5, 2, 0.5)), 0);
    EXPECT_EQ(boxes.rankOf(point(0.5, -0.5, 0.5)), 4);
    // Outside along x or z, which are not periodic
    EXPECT_EQ(boxes.rankOf(point(-0.01, 0.5, 0.5)), -1);
    EXPECT_EQ(boxes.rankOf(point(0.5, 0.5, 1.01)), -1);
    DynamicList<label> ranks(1, label(7));
    boxes.ranksWithin(point(4.5, 0.5, 0.5), 1, ranks);
    EXPECT_TRUE(ranks.empty());
}


TEST(boxDecomposition, noBoxesOrAFlatDomainIsRefused)
{
    const FixedList<bool, 3> open({false, false, false});
    const boundBox domain(point(0, 0, 0), point(1, 1, 1));
    EXPECT_THROW
    (
        boxDecomposition(domain, open, labelVector(2, 0, 1)), Foam::error
    );
    EXPECT_THROW
    (
        boxDecomposition
        (
            boundBox(point(0, 0, 0), point(1, 0, 1)), open,
            labelVector(1, 1, 1)
        ),
        Foam::error
    );
}


TEST(boxDecomposition, neighboursAreSymmetricAndHoldEveryRankWithinReachOfTheBox)
{
    // The ranks a rank exchanges with: every rank that ranksWithin names
    // for a point of its box (sampled, corners and faces included) within
    // the reach, the relation symmetric, the rank itself never among them
    const boundBox domain(point(0, 0, 0), point(0.3, 0.2, 0.1));
    Random rnd(7);
    label nChecks = 0;
    for (const labelVector n : {labelVector(6, 1, 1), labelVector(3, 4, 2)})
    for (const bool px : {false, true})
    for (const scalar reach : {0.01, 0.04, 0.12})
    {
        const FixedList<bool, 3> periodic({px, true, false});
        const boxDecomposition boxes(domain, periodic, n);
        List<DynamicList<label>> nbrs(boxes.size());
        for (label r = 0; r < boxes.size(); ++r)
        {
            boxes.neighbours(r, reach, nbrs[r]);
            EXPECT_FALSE(nbrs[r].found(r)) << "rank " << r;
        }
        DynamicList<label> within;
        for (label r = 0; r < boxes.size(); ++r)
        {
            for (const label q : nbrs[r])
            {
                EXPECT_TRUE(nbrs[q].found(r)) << r << " names " << q;
            }
            const boundBox b = boxes.box(r);
            for (label k = 0; k < 200; ++k)
            {
                // Inside the box, a third of them on a face or a corner
                point x;
                for (direction d = 0; d < 3; ++d)
                {
                    const scalar u = rnd.sample01<scalar>();
                    x[d] =
                        k % 3 == 0
                      ? (u < 0.5 ? b.min()[d] : b.max()[d] - 1e-12)
                      : b.min()[d] + u*(b.max()[d] - b.min()[d]);
                }
                if (boxes.rankOf(x) != r)
                {
                    continue;
                }
                boxes.ranksWithin(x, reach, within);
                for (const label q : within)
                {
                    ++nChecks;
                    EXPECT_TRUE(q == r || nbrs[r].found(q))
                        << "rank " << r << " point " << x.x() << ' '
                        << x.y() << ' ' << x.z() << " reach "
                        << reach << ": rank " << q << " is not a neighbour";
                }
            }
        }
    }
    std::cout << nChecks << " ranks within reach checked" << nl;
    EXPECT_GT(nChecks, 10000);
}


TEST(boxDecomposition, boxesCutAtGivenPlanesGiveTheRanksOfTheBruteForce)
{
    // Unequal boxes (a mesh decomposition's), periodic along x or not:
    // each point's rank is the box that holds it (its image in the
    // domain), the ranks within reach those of the brute force
    const boundBox domain(point(0, -1, 0), point(2, 1, 1));
    FixedList<scalarList, 3> planes;
    planes[0] = scalarList({0, 0.3, 0.35, 1.2, 2});
    planes[1] = scalarList({-1, 0.5, 1});
    planes[2] = scalarList({0, 1});
    for (const bool px : {false, true})
    {
        const FixedList<bool, 3> periodic({px, true, false});
        const boxDecomposition boxes(domain, periodic, planes);
        ASSERT_EQ(boxes.size(), 8);
        EXPECT_EQ(boxes.n(), labelVector(4, 2, 1));
        EXPECT_EQ(boxes.box(5), boundBox(point(0.3, 0.5, 0), point(0.35, 1, 1)));
        Random rnd(23);
        DynamicList<label> ranks;
        label checked = 0;
        for (label sample = 0; sample < 2000; ++sample)
        {
            point x =
                domain.min()
              + cmptMultiply(rnd.sample01<vector>(), domain.span());
            if (px && sample % 4 == 0)
            {
                x.x() -= domain.span().x();
            }
            const label own = boxes.rankOf(x);
            ASSERT_GE(own, 0) << where(x);
            EXPECT_LT
            (
                bruteDistance(domain, periodic, boxes.box(own), x), 1e-12
            ) << where(x);
            const scalar reach = 0.02 + 0.4*rnd.sample01<scalar>();
            boxes.ranksWithin(x, reach, ranks);
            checked +=
                expectTheBruteForce(boxes, domain, periodic, x, reach, ranks);
        }
        EXPECT_GT(checked, 15000);
        // A plane belongs to the box above it
        EXPECT_EQ(boxes.rankOf(point(0.35, -1, 0.5)), 2);
        EXPECT_EQ(boxes.rankOf(point(2, 0.7, 0.5)), px ? 4 : 7);
    }
    // Planes that do not ascend from the domain's start to its end
    FixedList<scalarList, 3> bad(planes);
    bad[0] = scalarList({0, 0.5, 0.5, 2});
    EXPECT_THROW
    (
        boxDecomposition(domain, FixedList<bool, 3>(false), bad), Foam::error
    );
    bad[0] = scalarList({0, 0.5, 1.9});
    EXPECT_THROW
    (
        boxDecomposition(domain, FixedList<bool, 3>(false), bad), Foam::error
    );
}


TEST(boxDecomposition, theGridOfAMeshDecompositionIsFoundAndOthersAreNot)
{
    // A simple decomposition's ranks (x fastest) over unequal slabs, their
    // faces off by round-off: the grid, its boxes the ranks' own
    const boundBox domain(point(0, 0, 0), point(4, 2, 2));
    const FixedList<bool, 3> periodic({true, false, true});
    const scalarList xs({0, 1.25, 2, 3.1, 4}), ys({0, 1, 2}), zs({0, 0.9, 2});
    List<boundBox> rankBoxes;
    for (label k = 0; k < 2; ++k)
    for (label j = 0; j < 2; ++j)
    for (label i = 0; i < 4; ++i)
    {
        rankBoxes.append
        (
            boundBox
            (
                point(xs[i], ys[j], zs[k] + 1e-12),
                point(xs[i + 1] - 1e-12, ys[j + 1], zs[k + 1])
            )
        );
    }
    const autoPtr<boxDecomposition> grid
    (
        boxDecomposition::fromRankBoxes(domain, periodic, rankBoxes)
    );
    ASSERT_TRUE(grid.valid());
    EXPECT_EQ(grid->n(), labelVector(4, 2, 2));
    forAll(rankBoxes, r)
    {
        EXPECT_LT(mag(grid->box(r).min() - rankBoxes[r].min()), 1e-11) << r;
        EXPECT_LT(mag(grid->box(r).max() - rankBoxes[r].max()), 1e-11) << r;
        EXPECT_EQ(grid->rankOf(rankBoxes[r].centre()), r);
    }

    // Not found: the ranks numbered z fastest, a box missing, two ranks
    // that are not a grid (one box cut across the other's plane), a box
    // outside the domain
    List<boundBox> swapped(rankBoxes);
    std::swap(swapped[1], swapped[8]);
    EXPECT_FALSE
    (
        boxDecomposition::fromRankBoxes(domain, periodic, swapped).valid()
    );
    List<boundBox> fewer(SubList<boundBox>(rankBoxes, 15));
    EXPECT_FALSE
    (
        boxDecomposition::fromRankBoxes(domain, periodic, fewer).valid()
    );
    const List<boundBox> notGrid
    ({
        boundBox(point(0, 0, 0), point(1, 2, 2)),
        boundBox(point(1, 0, 0), point(4, 1, 2)),
        boundBox(point(1, 1, 0), point(4, 2, 2)),
        boundBox(point(0, 0, 0), point(1, 1, 2))
    });
    EXPECT_FALSE
    (
        boxDecomposition::fromRankBoxes(domain, periodic, notGrid).valid()
    );
    List<boundBox> outside(rankBoxes);
    outside[15].max().x() = 4.5;
    EXPECT_FALSE
    (
        boxDecomposition::fromRankBoxes(domain, periodic, outside).valid()
    );
}


TEST(boxDecomposition, theLeastAreaFactorsTakeTheFirstOfEqualsAndOneBoxAcrossAFlatDomain)
{
    // A cube on 16 ranks: 2 x 2 x 4, 2 x 4 x 2 and 4 x 2 x 2 cut as much;
    // the first found (x fewest) is taken
    EXPECT_EQ
    (
        boxDecomposition::leastAreaBoxes(vector(1, 1, 1), 16),
        labelVector(2, 2, 4)
    );
    EXPECT_EQ
    (
        boxDecomposition::leastAreaBoxes(vector(16, 2, 2), 8),
        labelVector(8, 1, 1)
    );
    // One cell deep along z: never cut there
    EXPECT_EQ
    (
        boxDecomposition::leastAreaBoxes(vector(4, 4, 0.01), 4),
        labelVector(2, 2, 1)
    );
}


// ************************************************************************* //

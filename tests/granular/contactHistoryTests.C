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
    Unit tests of the contacts' tangential histories (Foam::contactHistory):
    a contact computed in every sub-step accumulates its history as the law
    alone does; one left out of a sub-step loses it and starts again from
    zero; the entries come out sorted by (i, j), walls (j < 0) included;
    a law without history leaves none.

\*---------------------------------------------------------------------------*/

#include "contactHistory.H"
#include "IStringStream.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

autoPtr<contactLaw> law(const word& name, const std::string& text)
{
    IStringStream is(text);
    dictionary dict(is);
    dict.name() = "constant/collisionProperties.pairs.a-a";
    return contactLaw::New(name, dict, materialPair{"a-a", 2500, 2500});
}

contactGeometry touching(const scalar overlap)
{
    contactGeometry c;
    c.position = Zero;
    c.normal = vector(0, 0, 1);
    c.overlap = overlap;
    return c;
}

} // End anonymous namespace


TEST(contactHistory, keepsTheHistoryOfContactsThatStayAndDropsTheOthers)
{
    autoPtr<contactLaw> friction = law
    (
        "hookeanStaticFriction", "kn 1e4; en 1; muc 0.5; gammat 0; ks 2e3;"
    );
    const scalar M = 1e-3, dt = 1e-5;
    const vector creep(1e-3, 0, 0);
    const contactGeometry c = touching(1e-4);

    // The law alone over 3 sub-steps, and through the histories
    vector h(Zero), Flaw(Zero);
    for (label k = 0; k < 3; ++k)
    {
        Flaw = friction->force(c.overlap, c.normal, creep, M, dt, h);
    }
    contactHistory histories;
    vector F(Zero);
    for (label k = 0; k < 3; ++k)
    {
        F = histories.force(*friction, c, creep, M, dt, 0, 1);
        histories.force(*friction, c, creep, M, dt, 2, -1);  // wall 0
        histories.endSubStep();
    }
    EXPECT_EQ(F, Flaw);

    // Pair (0 1) not computed in a sub-step: it ends; the wall contact
    // stays
    histories.force(*friction, c, creep, M, dt, 2, -1);
    histories.endSubStep();
    List<std::pair<labelPair, vector>> open = histories.entries();
    ASSERT_EQ(open.size(), 1);
    EXPECT_EQ(open[0].first, labelPair(2, -1));

    // When (0 1) touches again, it starts from zero
    vector fresh(Zero);
    const vector F0 = friction->force(c.overlap, c.normal, creep, M, dt, fresh);
    EXPECT_EQ(histories.force(*friction, c, creep, M, dt, 0, 1), F0);
}


TEST(contactHistory, entriesAreSortedAndLawsWithoutHistoryLeaveNone)
{
    contactHistory histories;
    histories.set(3, 1, vector(1, 0, 0));
    histories.set(0, -2, vector(2, 0, 0));
    histories.set(0, 5, vector(3, 0, 0));
    const List<std::pair<labelPair, vector>> e = histories.entries();
    ASSERT_EQ(e.size(), 3);
    // Keys order by i, then by j as an unsigned 32-bit number (walls last)
    EXPECT_EQ(e[0].first, labelPair(0, 5));
    EXPECT_EQ(e[1].first, labelPair(0, -2));
    EXPECT_EQ(e[2].first, labelPair(3, 1));
    EXPECT_EQ(e[1].second, vector(2, 0, 0));

    histories.clear();
    autoPtr<contactLaw> plain = law("hookeanSpringDashpot", "kn 1e4; en 0.9; muc 0.3;");
    histories.force(*plain, touching(1e-4), vector(1, 0, 0), 1e-3, 1e-5, 0, 1);
    histories.endSubStep();
    EXPECT_TRUE(histories.empty());
}


// ************************************************************************* //

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
    The scene's settings of constant/collisionProperties
    (Foam::collisionSettings): defaults where nothing is given, the values
    given kept, and each value out of range refused naming the keyword,
    the value and what is allowed.

\*---------------------------------------------------------------------------*/

#include "collisionSettings.H"
#include "testInput.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

const std::string box = "domain { min (0 0 0); max (1 2 3); }";

} // End anonymous namespace


TEST(collisionSettings, defaultsWhereNothingIsGiven)
{
    const collisionSettings s(testInput::parse(box));
    EXPECT_EQ(s.subStepsPerContact(), 20);
    EXPECT_EQ(s.overlapLimit(), 0.05);
    EXPECT_LT(s.skin(), 0);
    EXPECT_EQ(s.domain().min(), point(0, 0, 0));
    EXPECT_EQ(s.domain().max(), point(1, 2, 3));
    EXPECT_FALSE(s.anyPeriodic());
}


TEST(collisionSettings, givenValuesAreKept)
{
    const collisionSettings s
    (
        testInput::parse
        (
            "subStepsPerContact 40; overlapLimit 0.02; skin 0.001;"
            " domain { min (0 0 0); max (1 1 1); periodic (true false true); }"
        )
    );
    EXPECT_EQ(s.subStepsPerContact(), 40);
    EXPECT_EQ(s.overlapLimit(), 0.02);
    EXPECT_EQ(s.skin(), 0.001);
    EXPECT_TRUE(s.periodic()[0]);
    EXPECT_FALSE(s.periodic()[1]);
    EXPECT_TRUE(s.periodic()[2]);
    EXPECT_TRUE(s.anyPeriodic());
}


TEST(collisionSettings, valuesOutOfRangeAreRefusedNamingThem)
{
    const auto refused = [](const std::string& text)
    {
        return testInput::errorOf([&]
        {
            collisionSettings s(testInput::parse(text));
        });
    };
    std::string e = refused("subStepsPerContact 0; " + box);
    EXPECT_NE(e.find("subStepsPerContact = 0"), std::string::npos) << e;
    EXPECT_NE(e.find(">= 1"), std::string::npos) << e;

    e = refused("overlapLimit 1.5; " + box);
    EXPECT_NE(e.find("overlapLimit = 1.5"), std::string::npos) << e;
    EXPECT_NE(e.find("0 < overlapLimit < 1"), std::string::npos) << e;

    e = refused("skin -0.1; " + box);
    EXPECT_NE(e.find("skin = -0.1"), std::string::npos) << e;
    EXPECT_NE(e.find(">= 0"), std::string::npos) << e;

    e = refused("domain { min (0 0 0); max (1 0 1); }");
    EXPECT_NE(e.find("must exceed min"), std::string::npos) << e;

    e = refused("domain { min (0 0 0); max (1 1 1); periodc (true true true); }");
    EXPECT_NE(e.find("periodc"), std::string::npos) << e;
}


TEST(collisionSettings, subCyclingIsAllUnlessInReachIsAsked)
{
    EXPECT_FALSE(collisionSettings(testInput::parse(box)).subCycleInReach());
    EXPECT_FALSE
    (
        collisionSettings(testInput::parse("subCycling all; " + box))
       .subCycleInReach()
    );
    EXPECT_TRUE
    (
        collisionSettings(testInput::parse("subCycling inReach; " + box))
       .subCycleInReach()
    );
    const std::string e = testInput::errorOf([&]
    {
        collisionSettings s(testInput::parse("subCycling near; " + box));
    });
    EXPECT_NE(e.find("subCycling near"), std::string::npos) << e;
    EXPECT_NE(e.find("inReach"), std::string::npos) << e;
    EXPECT_NE(e.find("all"), std::string::npos) << e;
}


TEST(collisionSettings, particleDistributionIsMasterUnlessOwnedIsAsked)
{
    EXPECT_FALSE
    (
        collisionSettings(testInput::parse(box)).ownedDistribution()
    );
    EXPECT_TRUE
    (
        collisionSettings
        (
            testInput::parse("particleDistribution owned; " + box)
        ).ownedDistribution()
    );
    const std::string e = testInput::errorOf([&]
    {
        collisionSettings s
        (
            testInput::parse("particleDistribution own; " + box)
        );
    });
    EXPECT_NE(e.find("particleDistribution own"), std::string::npos) << e;
    EXPECT_NE(e.find("master"), std::string::npos) << e;
    EXPECT_NE(e.find("owned"), std::string::npos) << e;
}


// ************************************************************************* //

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
    Misspelt keywords (Foam::knownKeywords): refused in a sub-dictionary
    whatever they are, refused at a file's top level when they are within
    a few edits of a known keyword, taken as variables otherwise; the
    entries an #include brings are not counted; the collision dictionary
    refuses a misspelt optional keyword.

\*---------------------------------------------------------------------------*/

#include "knownKeywords.H"
#include "granularSystem.H"
#include "testInput.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IFstream.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::testInput;

namespace
{

const wordList known({"fluidDensity", "fictitiousDomain"});
const wordList inner({"surfacePointSpacing", "tolerance"});

} // End anonymous namespace


TEST(knownKeywords, editDistanceCountsInsertionsDeletionsAndSubstitutions)
{
    EXPECT_EQ(knownKeywords::distance("surfacePointSpacing", "surfacePointSpacing"), 0);
    EXPECT_EQ(knownKeywords::distance("surfacePointSpcing", "surfacePointSpacing"), 1);
    EXPECT_EQ(knownKeywords::distance("subStepPerContact", "subStepsPerContact"), 1);
    EXPECT_EQ(knownKeywords::distance("tolerence", "tolerance"), 1);
    EXPECT_EQ(knownKeywords::distance("", "abc"), 3);
}


TEST(knownKeywords, anUnknownKeywordInASubDictionaryIsRefusedNamingTheNearest)
{
    const dictionary d(parse("fictitiousDomain { surfacePointSpcing 1; }"));
    knownKeywords::require(d, known);
    const std::string msg = errorOf
    (
        [&]{ knownKeywords::require(d, inner, "fictitiousDomain"); }
    );
    EXPECT_NE(msg.find("unknown keyword surfacePointSpcing in fictitiousDomain"), std::string::npos) << msg;
    EXPECT_NE(msg.find("a misspelling of surfacePointSpacing?"), std::string::npos) << msg;
    // Far from every known one, still refused inside a sub-dictionary
    const dictionary e(parse("fictitiousDomain { Ga 70; }"));
    EXPECT_FALSE(errorOf([&]{ knownKeywords::require(e, inner, "fictitiousDomain"); }).empty());
}


TEST(knownKeywords, atTheTopLevelANearMissIsRefusedAndAFarKeywordIsAVariable)
{
    const dictionary nearMiss(parse("fluidDensty 1000;"));
    const std::string msg = errorOf([&]{ knownKeywords::require(nearMiss, known); });
    EXPECT_NE(msg.find("a misspelling of fluidDensity?"), std::string::npos) << msg;

    const dictionary variables(parse("Ga 70; particleDensity 2; fluidDensity $particleDensity;"));
    EXPECT_TRUE(errorOf([&]{ knownKeywords::require(variables, known); }).empty());
}


TEST(knownKeywords, entriesOfAnIncludedFileAreNotCounted)
{
    const fileName dir("/tmp/dlmfdKnownKeywords." + Foam::name(Foam::pid()));
    mkDir(dir);
    {
        OFstream os(dir/"scales");
        os  << "rhoF 1000;\nsurfacePointSpcin 2;\n";
    }
    {
        OFstream os(dir/"props");
        os  << "#include \"scales\"\nfluidDensity $rhoF;\n"
            << "fictitiousDomain { tolerance 1e-9; }\n";
    }
    IFstream is(dir/"props");
    const dictionary d(is);
    // The included near-miss is in the expanded dictionary, not in the file
    ASSERT_TRUE(d.found("surfacePointSpcin"));
    EXPECT_TRUE(errorOf([&]{ knownKeywords::require(d, known, word::null, dir/"props"); }).empty());
    EXPECT_TRUE(errorOf([&]{ knownKeywords::require(d, inner, "fictitiousDomain", dir/"props"); }).empty());

    // A misspelling in the file itself is named with its line
    {
        OFstream os(dir/"props");
        os  << "#include \"scales\"\nfluidDensity $rhoF;\n"
            << "fictitiousDomain\n{\n    tolerence 1e-9;\n}\n";
    }
    IFstream is2(dir/"props");
    const dictionary d2(is2);
    const std::string msg = errorOf
    (
        [&]{ knownKeywords::require(d2, inner, "fictitiousDomain", dir/"props"); }
    );
    EXPECT_NE(msg.find("unknown keyword tolerence in fictitiousDomain"), std::string::npos) << msg;
    EXPECT_NE(msg.find(", line 5 (a misspelling of tolerance?)"), std::string::npos) << msg;
    rmDir(dir);
}


TEST(knownKeywords, aMisspeltCollisionKeywordIsRefused)
{
    const std::string msg = errorOf
    (
        [&]
        {
            granularSystem
            (
                parse("shapes { ball { type sphere; D 0.01; } } materials { glass { density 2500; } }"),
                parse
                (
                    "contactLaw none; subStepPerContact 40;"
                    " domain { min (0 0 0); max (1 1 1); periodic (false false false); }"
                )
            );
        }
    );
    EXPECT_NE(msg.find("unknown keyword subStepPerContact"), std::string::npos) << msg;
    EXPECT_NE(msg.find("a misspelling of subStepsPerContact?"), std::string::npos) << msg;
}


// ************************************************************************* //

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
    Bad input to the granular system, one kind per test, each checking that
    the message names what is wrong (keyword, value, what is allowed, the
    particle and its position, the file's line): the particle file
    (malformed entries, duplicate ids, unknown motions, shapes and
    materials, orientations that are no rotation), the starting state
    (particles overlapping each other, across a periodic boundary or a
    wall, outside the domain, planar particles tilted out of their plane),
    the collision dictionary (sub-steps, skin, domain, overlap limit, wall
    normal), the particle dictionary (missing keyword, wrong type, wrong
    dimensions, non-positive density) and the checks of a running state
    (an exploding contact and a value that is not finite, named with the
    time).

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "testInput.H"
#include "OFstream.H"
#include "OSspecific.H"

#include <gtest/gtest.h>
#include <fstream>
#include <limits>
#include <sstream>

using namespace Foam;
using namespace Foam::testInput;

namespace
{

const std::string shapesAndMaterials =
    "shapes { ball { type sphere; D 0.01; } box { type cube; edge 0.008; }"
    " disc { type circle; D 0.01; depth 0.002; } }"
    " materials { glass { density 2500; } }";

const std::string coeffs =
    "en 0.9; muc 0.3; maxOverlapRatio 1e-3; impactVelocity 0.5;"
    " referenceDiameter 0.01;";

//- The collision dictionary: a box of 0.2 m, a floor at z = 0, and extra
//- entries (which override the defaults by coming last)
std::string collision
(
    const std::string& extra = "",
    const std::string& periodic = "(false false false)"
)
{
    return
        "contactLaw hookeanSpringDashpot; domain { min (-0.1 -0.1 0);"
        " max (0.1 0.1 0.2); periodic " + periodic + "; }"
        " walls { floor { point (0 0 0); normal (0 0 1); material steel; } }"
        " pairs { glass-glass {" + coeffs + "} glass-steel {" + coeffs + "} } "
      + extra;
}

autoPtr<granularSystem> makeSystem
(
    const std::string& collisionText = collision(),
    const std::string& particleText = shapesAndMaterials
)
{
    return autoPtr<granularSystem>::New
    (
        parse(particleText), parse(collisionText)
    );
}

//- The message of reading a particle file of the given particles
std::string readError
(
    const std::string& particles,
    const std::string& collisionText = collision()
)
{
    // From a file, as a run reads it: the messages give its lines
    const fileName dir("/tmp/dlmfdBadInput." + Foam::name(Foam::pid()));
    mkDir(dir);
    const fileName file(dir/"particles");
    {
        OFstream os(file);
        os  << particles.c_str() << nl;
    }
    autoPtr<granularSystem> sys = makeSystem(collisionText);
    const std::string msg = errorOf([&]{ sys->readParticles(file); });
    rmDir(dir);
    return msg;
}

void expectHas(const std::string& msg, const std::vector<std::string>& parts)
{
    EXPECT_FALSE(msg.empty()) << "no error raised";
    for (const std::string& part : parts)
    {
        EXPECT_NE(msg.find(part), std::string::npos)
            << "lacks '" << part << "': " << msg;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Particle file * * * * * * * * * * * * * * * //

TEST(badInput, particleFileGoodStateIsAccepted)
{
    EXPECT_EQ
    (
        readError
        (
            "particles (\n"
            "(0 ball glass free (0 0 0.01) (1 0 0 0))\n"
            "(1 ball glass free (0.02 0 0.01) (1 0 0 0) (0 0 -1))\n);"
        ),
        ""
    );
}


TEST(badInput, particleFileMalformedEntryNamesItsLine)
{
    expectHas
    (
        readError
        (
            "particles (\n"
            "(0 ball glass free (0 0 0.01) (1 0 0 0))\n"
            "(1 ball glass free (0.02 0 0.01) (1 0 0 0) oops)\n);"
        ),
        {"/particles", "line 3", "particle 1", "expected ')' or a vector"}
    );
}


TEST(badInput, particleFileDuplicateIdIsRefused)
{
    expectHas
    (
        readError
        (
            "particles (\n"
            "(4 ball glass free (0 0 0.01) (1 0 0 0))\n"
            "(4 ball glass free (0.05 0 0.01) (1 0 0 0))\n);"
        ),
        {"line 3", "particle id 4 is given twice"}
    );
}


TEST(badInput, particleFileUnknownMotionListsTheMotions)
{
    expectHas
    (
        readError("particles (\n(0 ball glass flying (0 0 0.01) (1 0 0 0))\n);"),
        {"line 2", "motion flying", "fixed", "free", "prescribed"}
    );
}


TEST(badInput, particleFileUnknownShapeListsTheShapes)
{
    expectHas
    (
        readError("particles (\n(0 bal glass free (0 0 0.01) (1 0 0 0))\n);"),
        {"bal", "ball", "box", "disc"}
    );
}


TEST(badInput, particleFileUnknownMaterialListsTheMaterials)
{
    expectHas
    (
        readError("particles (\n(0 ball glas free (0 0 0.01) (1 0 0 0))\n);"),
        {"glas", "glass"}
    );
}


TEST(badInput, particleFileOrientationThatIsNoRotationIsRefused)
{
    expectHas
    (
        readError("particles (\n(0 ball glass free (0 0 0.01) (0 0 0 0))\n);"),
        {"line 2", "particle 0", "is not a rotation", "(1 0 0 0)"}
    );
}


TEST(badInput, particleFileContactOfAMissingParticleIsRefused)
{
    expectHas
    (
        readError
        (
            "particles (\n(0 ball glass free (0 0 0.01) (1 0 0 0))\n);\n"
            "contacts ( ((0 7) (0 0 0)) );"
        ),
        {"contact (0 7)", "not in the file"}
    );
    // A counted list would be allocated before it is read: refused
    expectHas
    (
        readError
        (
            "particles (\n(0 ball glass free (0 0 0.01) (1 0 0 0))\n);\n"
            "contacts 999999999 ( ((0 7) (0 0 0)) );"
        ),
        {"reading contacts", "999999999"}
    );
    // A malformed contact
    expectHas
    (
        readError
        (
            "particles (\n(0 ball glass free (0 0 0.01) (1 0 0 0))\n);\n"
            "contacts ( (0 1 (0 0 0)) );"
        ),
        {"contact pair", "line 4"}
    );
}


TEST(badInput, particleFileThatIsNotTextNamesItsLine)
{
    expectHas
    (
        readError("particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n\x01);"),
        {"particles\" line 3", "character code 1 is not ASCII text"}
    );
    // Any text in comments
    EXPECT_EQ
    (
        readError
        (
            "// r\xc3\xa9sum\xc3\xa9 \x01\nparticles (\n/* \xe2\x80\x94 */"
            "(0 ball glass free (0 0 0.05) (1 0 0 0))\n);"
        ),
        ""
    );
}


TEST(badInput, quotedKeywordIsRefused)
{
    // OpenFOAM would end the program on "invalid fileName" for a quoted
    // keyword with a space, and take minutes to match a pathological one
    // against each lookup (both found by tests/fuzz)
    for
    (
        const char* key
      : {"\"  \"", "\"(Fi)I 0k|[E-xSt5Sc6y-]+++++++++++++++++++++++++++++\""}
    )
    {
        expectHas
        (
            readError
            (
                "\n" + std::string(key)
              + " 0;\nparticles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n);"
            ),
            {"particles\" line 2: keyword", "is a pattern (a quoted keyword)"}
        );
    }
}


TEST(badInput, repeatedKeywordIsRefusedWithBothLines)
{
    // OpenFOAM takes the later one; a particle file written twice into
    // (or a copy and paste) would lose particles without a word. A
    // repeated keyword also made libOpenFOAM v1912 read freed memory
    // (tests/fuzz: "s;s;", a repeated FoamFile header)
    expectHas
    (
        readError
        (
            "particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n);\n"
            "particles (\n(1 ball glass free (0 0 0.08) (1 0 0 0))\n);"
        ),
        {"particles\" line 4", "keyword particles is given twice",
         "first at line 1"}
    );
    expectHas
    (
        readError
        (
            "FoamFile { version 2.0; version 2.0; }\n"
            "particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n);"
        ),
        {"line 1", "keyword version is given twice"}
    );
}


TEST(badInput, unknownKeywordListsTheKeywords)
{
    // A misspelt contacts would drop the contact history silently
    expectHas
    (
        readError
        (
            "particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n);\n"
            "contacs ();"
        ),
        {"line 4", "keyword contacs is not one of", "FoamFile",
         "particles", "contacts"}
    );
}


TEST(badInput, entryStructureErrorsNameTheirLines)
{
    const std::string p =
        "particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n)";
    // No ';' at the end
    expectHas(readError(p), {"keyword particles (line 1)", "ends before its ';'"});
    // An unclosed bracket
    expectHas
    (
        readError("particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0)\n);"),
        {"ends before its ';'", "'(' of line 1 is not closed"}
    );
    // A bracket that closes the wrong one
    expectHas
    (
        readError("particles (\n(0 ball glass free (0 0 0.05] (1 0 0 0))\n);"),
        {"line 2", "']' does not close '('"}
    );
    // A keyword without a value
    expectHas(readError("contacts;\n" + p + ";"), {"line 1", "contacts has no value"});
    // A header that is not a sub-dictionary, or holds one
    expectHas(readError("FoamFile 2;\n" + p + ";"), {"expected '{' after FoamFile"});
    expectHas
    (
        readError("FoamFile { a { b 1; } }\n" + p + ";"),
        {"FoamFile entry a is a sub-dictionary"}
    );
    expectHas(readError("FoamFile { version 2.0;\n" + p + ";"), {"ends before its '}'"});
    // A value where a keyword belongs
    expectHas(readError("12;\n" + p + ";"), {"line 1", "expected a keyword"});
}


TEST(badInput, directivesAndVariablesAreRefused)
{
    const std::string p =
        "particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n);";
    expectHas
    (
        readError("#include \"other\"\n" + p),
        {"line 1", "directive #include is not taken"}
    );
    expectHas
    (
        readError("particles (\n(0 ball glass free (0 0 $z) (1 0 0 0))\n);"),
        {"line 2", "is not taken in a particle file"}
    );
    expectHas(readError("$p;\n" + p), {"line 1", "variable $p is not taken"});
    expectHas
    (
        readError("particles #{ (0 ball) #};\n"),
        {"line 1", "is not taken in a particle file"}
    );
}


TEST(badInput, typedListIsRefusedWithItsLine)
{
    // OpenFOAM's tokenizer reads List<word> as a typed list, and leaks a
    // malformed one when its error is caught (tests/fuzz ran out of memory)
    expectHas
    (
        readError
        (
            "particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n);\n"
            "contacts List<word> 403(a b;"
        ),
        {"particles\" line 4: character '<' is not taken"}
    );
}


TEST(badInput, malformedHeadersFoundByFuzzingAreRefused)
{
    // Inputs on which libOpenFOAM's dictionary parser read freed memory
    // (tests/fuzz/regressions): each ends in an error naming its line
    for
    (
        const char* finding
      : {"heapUseAfterFree-dictionaryRemoveFoamFile",
         "heapUseAfterFree-dictionaryParse", "heapUseAfterFree-minimal",
         "outOfMemory-typedListLeak"}
    )
    {
        const fileName file
        (
            fileName(DLMFD_TEST_SOURCE_DIR)/"fuzz"/"regressions"/finding
        );
        std::ifstream ifs(file, std::ios::binary);
        ASSERT_TRUE(ifs.good()) << file;
        std::ostringstream text;
        text << ifs.rdbuf();
        SCOPED_TRACE(finding);
        expectHas(readError(text.str()), {"particles\" line"});
    }
}


// * * * * * * * * * * * * * * * Starting state  * * * * * * * * * * * * * * //

TEST(badInput, overlappingParticlesAreNamedWithPositions)
{
    // 0 and 1 overlap by 0.2 D; 1 and 2 touch within the limit (0.01 D)
    expectHas
    (
        readError
        (
            "particles (\n"
            "(0 ball glass free (0 0 0.05) (1 0 0 0))\n"
            "(1 ball glass free (0.008 0 0.05) (1 0 0 0))\n"
            "(2 ball glass free (0.0179 0 0.05) (1 0 0 0))\n);"
        ),
        {
            "/particles", "1 problem(s)", "particle 0 at (0 0 0.05)",
            "particle 1 at (0.008 0 0.05)", "overlap by 0.2 D",
            "overlapLimit = 0.05"
        }
    );
}


TEST(badInput, overlapAcrossAPeriodicBoundaryIsFound)
{
    // x periodic over 0.2 m: 0.0995 and -0.0995 are 0.001 m apart
    expectHas
    (
        readError
        (
            "particles (\n"
            "(0 ball glass free (0.0995 0 0.05) (1 0 0 0))\n"
            "(1 ball glass free (-0.0995 0 0.05) (1 0 0 0))\n);",
            collision("", "(true false false)")
        ),
        {"particle 0 at (0.0995 0 0.05)", "particle 1", "overlap by 0.9 D"}
    );
}


TEST(badInput, overlappingCubesAreFound)
{
    expectHas
    (
        readError
        (
            "particles (\n"
            "(0 box glass free (0 0 0.05) (1 0 0 0))\n"
            "(1 box glass free (0.006 0 0.05) (1 0 0 0))\n);"
        ),
        {"particle 0", "particle 1", "overlap by"}
    );
}


TEST(badInput, particleThroughAWallIsNamed)
{
    expectHas
    (
        readError("particles (\n(3 ball glass free (0 0 0.002) (1 0 0 0))\n);"),
        {"particle 3 at (0 0 0.002)", "wall floor", "overlap by 0.3 D"}
    );
}


TEST(badInput, particleOutsideTheDomainIsNamed)
{
    expectHas
    (
        readError("particles (\n(5 ball glass free (0 0.3 0.05) (1 0 0 0))\n);"),
        {"particle 5 at (0 0.3 0.05)", "outside the domain along y"}
    );
}


TEST(badInput, particleOutsideAPeriodicDirectionIsWrappedNotRefused)
{
    EXPECT_EQ
    (
        readError
        (
            "particles (\n(5 ball glass free (0.3 0 0.05) (1 0 0 0))\n);",
            collision("", "(true false false)")
        ),
        ""
    );
}


TEST(badInput, tiltedPlanarParticleIsRefused)
{
    expectHas
    (
        readError
        (
            "particles (\n"
            "(2 disc glass free (0 0 0.05) (0.9659258 0.2588190 0 0))\n);"
        ),
        {"particle 2 (planar shape disc)", "out of the x-y plane", "about z"}
    );
}


TEST(badInput, numberBeyondDoubleRangeIsReportedWithItsLine)
{
    expectHas
    (
        readError
        (
            "particles (\n(1 ball glass free (0 0 0.05) (1 0 0 0) (1e400 0 0))\n);"
        ),
        {"particles\" line 2: cannot read 1e400", "beyond double range"}
    );
}


// * * * * * * * * * * * * * * * Dictionaries  * * * * * * * * * * * * * * * //

TEST(badInput, subStepsPerContactBelowOneIsRefused)
{
    expectHas
    (
        errorOf([]{ makeSystem(collision("subStepsPerContact 0;")); }),
        {"subStepsPerContact = 0", ">= 1"}
    );
}


TEST(badInput, negativeSkinIsRefused)
{
    expectHas
    (
        errorOf([]{ makeSystem(collision("skin -0.001;")); }),
        {"skin = -0.001", ">= 0"}
    );
}


TEST(badInput, overlapLimitOutOfRangeIsRefused)
{
    for (const char* v : {"0", "1.5", "-0.1"})
    {
        expectHas
        (
            errorOf
            (
                [&]{ makeSystem(collision("overlapLimit " + std::string(v) + ";")); }
            ),
            {"overlapLimit = " + std::string(v), "0 < overlapLimit < 1"}
        );
    }
}


TEST(badInput, emptyDomainIsRefused)
{
    expectHas
    (
        errorOf
        (
            []{
                makeSystem
                (
                    "contactLaw none; domain { min (0 0 0); max (1 0 1); }"
                );
            }
        ),
        {"domain: max (1 0 1) must exceed min (0 0 0)"}
    );
}


TEST(badInput, wallWithoutANormalIsRefused)
{
    expectHas
    (
        errorOf
        (
            []{
                makeSystem
                (
                    "contactLaw none; domain { min (0 0 0); max (1 1 1); }"
                    " walls { lid { point (0 0 1); normal (0 0 0);"
                    " material steel; } }"
                );
            }
        ),
        {"lid", "normal"}
    );
}


TEST(badInput, missingKeywordIsNamed)
{
    // A pair without its restitution coefficient
    expectHas
    (
        errorOf
        (
            []{
                makeSystem
                (
                    "contactLaw hookeanSpringDashpot;"
                    " domain { min (0 0 0); max (1 1 1); }"
                    " pairs { glass-glass { muc 0.3; kn 1e4; } }"
                );
            }
        ),
        {"en", "not found"}
    );
}


TEST(badInput, wrongTypeIsNamed)
{
    expectHas
    (
        errorOf
        (
            []{
                makeSystem
                (
                    collision(),
                    "shapes { ball { type sphere; D small; } }"
                    " materials { glass { density 2500; } }"
                );
            }
        ),
        {"shape ball", "D = small is not a number"}
    );
}


TEST(badInput, wrongDimensionsAreNamed)
{
    expectHas
    (
        errorOf
        (
            []{
                makeSystem
                (
                    collision(),
                    "shapes { ball { type sphere; D 0.01; } }"
                    " materials { glass { density [0 1 0 0 0 0 0] 2500; } }"
                );
            }
        ),
        {"dimensions"}
    );
}


TEST(badInput, nonPositiveDensityIsRefused)
{
    expectHas
    (
        errorOf
        (
            []{
                makeSystem
                (
                    collision(),
                    "shapes { ball { type sphere; D 0.01; } }"
                    " materials { glass { density -2500; } }"
                );
            }
        ),
        {"glass", "density = -2500", "> 0"}
    );
}


// * * * * * * * * * * * * * * * Running state * * * * * * * * * * * * * * * //

TEST(badInput, explodingContactStopsNamingThePairAndTheTime)
{
    // Spheres closing at 200 m/s on a law made for 0.5 m/s: the overlap
    // grows far beyond the limit within the step
    autoPtr<granularSystem> sys = makeSystem();
    sys->readParticles
    (
        parse
        (
            "particles (\n"
            "(10 ball glass free (0 0 0.05) (1 0 0 0) (100 0 0))\n"
            "(11 ball glass free (0.0101 0 0.05) (1 0 0 0) (-100 0 0))\n);"
        ),
        "case/0/particles"
    );
    sys->evolve(2e-5);
    EXPECT_GT(sys->stats().maxOverlapRatio, sys->overlapLimit());
    expectHas
    (
        errorOf([&]{ sys->checkHealth(0.25); }),
        {
            "time 0.25", "particle 10 at", "particle 11 at",
            "beyond overlapLimit = 0.05 D", "exploded",
            "last write time holds the last good state"
        }
    );
}


TEST(badInput, valueThatIsNoLongerFiniteStopsNamingTheParticleAndTheTime)
{
    autoPtr<granularSystem> sys = makeSystem();
    sys->readParticles
    (
        parse
        (
            "particles (\n(0 ball glass free (0 0 0.05) (1 0 0 0))\n"
            "(7 ball glass free (0.05 0 0.05) (1 0 0 0))\n);"
        ),
        "case/0/particles"
    );
    EXPECT_EQ(errorOf([&]{ sys->checkHealth(0.5); }), "");

    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    sys->setExternalForce(1, vector(nan, 0, 0));
    sys->evolve(1e-4);
    expectHas
    (
        errorOf([&]{ sys->checkHealth(0.5001); }),
        {"time 0.5001", "particle 7 (ball)", "no longer finite"}
    );
}


// ************************************************************************* //

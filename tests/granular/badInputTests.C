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
    Bad particle files given to the granular system, one kind per test,
    each checking that the message names what is wrong (keyword, value,
    what is allowed, the particle, the file's line): malformed entries,
    duplicate ids, unknown motions, shapes and materials, orientations that
    are no rotation, text that is no particle file, and what the entry
    reader refuses (quoted and repeated keywords, directives, typed lists,
    the headers found by fuzzing). The starting state, the dictionaries and
    the running state: badInputStateTests.C; what both share:
    badInputHelpers.H.

\*---------------------------------------------------------------------------*/

#include "badInputHelpers.H"

#include <gtest/gtest.h>
#include <fstream>
#include <limits>
#include <sstream>

using namespace Foam;
using namespace Foam::testInput;

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


// ************************************************************************* //

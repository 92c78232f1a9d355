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
    Bad input to the granular system beyond the particle file
    (badInputTests.C), one kind per test, each checking that the message
    names what is wrong (keyword, value, what is allowed, the particle and
    its position): the starting state (particles overlapping each other,
    across a periodic boundary or a wall, outside the domain, planar
    particles tilted out of their plane), the collision dictionary
    (sub-steps, skin, domain, overlap limit, wall normal), the particle
    dictionary (missing keyword, wrong type, wrong dimensions, non-positive
    density) and the checks of a running state (an exploding contact and a
    value that is not finite, named with the time).

\*---------------------------------------------------------------------------*/

#include "badInputHelpers.H"

#include <gtest/gtest.h>
#include <fstream>
#include <limits>
#include <sstream>

using namespace Foam;
using namespace Foam::testInput;

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

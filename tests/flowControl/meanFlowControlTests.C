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
    Unit tests of the meanFlowControl family (src/flowControl): run-time
    selection and its error on a typo, coefficient checks, and the
    bulk-velocity controller against its closed form.

\*---------------------------------------------------------------------------*/

#include "foamTestCase.H"
#include "meanFlowControl.H"
#include "IStringStream.H"
#include "volFields.H"
#include "Random.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- A dictionary parsed from text, named like the case file it stands for
dictionary properties(const std::string& text)
{
    IStringStream is(text);
    dictionary dict(is);
    dict.name() = "constant/flowControlProperties";
    return dict;
}

//- The message of the IOerror that fn throws, or "" if it throws none
template<class Fn>
std::string ioErrorMessage(Fn fn)
{
    try
    {
        fn();
    }
    catch (const IOerror& err)
    {
        return err.message();
    }
    return "";
}

//- The message of the IOerror that selecting from the properties text
//- throws, or "" if the selection succeeds
std::string selectionError(const fvMesh& mesh, const std::string& text)
{
    return ioErrorMessage([&]()
    {
        meanFlowControl::New(mesh, properties(text));
    });
}


//- A zero velocity field on the mesh and a 1/A field of value rAU
struct flowFields
{
    volVectorField U;
    volScalarField rAU;

    flowFields(const fvMesh& mesh, const scalar rAUvalue)
    :
        U
        (
            IOobject("U", mesh.time().timeName(), mesh),
            mesh,
            dimensionedVector("U", dimVelocity, Zero)
        ),
        rAU
        (
            IOobject("rAU", mesh.time().timeName(), mesh),
            mesh,
            dimensionedScalar("rAU", dimTime, rAUvalue)
        )
    {}
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Selection * * * * * * * * * * * * * * * //

TEST(meanFlowControlSelection, typoListsEveryValidName)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));

    const std::string msg =
        selectionError(mesh, "meanFlowControl fixedPresureGradient;");

    EXPECT_NE(msg.find("fixedPresureGradient"), std::string::npos) << msg;
    for
    (
        const char* name
      : {"none", "fixedPressureGradient", "fixedBulkVelocity"}
    )
    {
        EXPECT_NE(msg.find(name), std::string::npos)
            << "valid name " << name << " not listed in: " << msg;
    }
}


TEST(meanFlowControlSelection, missingKeywordNamesIt)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));

    const std::string msg = selectionError(mesh, "model none;");

    EXPECT_NE(msg.find("meanFlowControl"), std::string::npos) << msg;
}


TEST(meanFlowControlSelection, noneKeepsZeroGradient)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));
    flowFields f(mesh, 0.5);
    f.U.primitiveFieldRef() = vector(1, 2, 3);

    autoPtr<meanFlowControl> control =
        meanFlowControl::New(mesh, properties("meanFlowControl none;"));
    control->correct(f.U, f.rAU);

    EXPECT_EQ(control->type(), "none");
    EXPECT_EQ(control->gradP().value(), vector::zero);
    EXPECT_EQ(f.U[0], vector(1, 2, 3));
}


// * * * * * * * * * * * * * * fixedPressureGradient * * * * * * * * * * * * //

TEST(fixedPressureGradient, readsGradientWithDimensions)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));

    autoPtr<meanFlowControl> control = meanFlowControl::New
    (
        mesh,
        properties
        (
            "meanFlowControl fixedPressureGradient;"
            "fixedPressureGradient { gradP [0 1 -2 0 0 0 0] (1 -2 3); }"
        )
    );

    EXPECT_EQ(control->gradP().value(), vector(1, -2, 3));
    EXPECT_EQ(control->gradP().dimensions(), dimVelocity/dimTime);
}


TEST(fixedPressureGradient, wrongDimensionsAreRejected)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));

    const std::string msg = selectionError
    (
        mesh,
        "meanFlowControl fixedPressureGradient;"
        "fixedPressureGradient { gradP [0 1 -1 0 0 0 0] (1 0 0); }"
    );

    EXPECT_NE(msg, "") << "a velocity given as gradP was accepted";
}


TEST(fixedPressureGradient, missingSubDictionaryNamesKeyword)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));

    const std::string msg =
        selectionError(mesh, "meanFlowControl fixedPressureGradient;");

    EXPECT_NE(msg.find("gradP"), std::string::npos) << msg;
}


// * * * * * * * * * * * * * * * fixedBulkVelocity * * * * * * * * * * * * * //

TEST(fixedBulkVelocity, meetsTargetAfterOneCorrectionWithUniformRAU)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(3, 4, 5, vector(1, 2, 3));
    flowFields f(mesh, 0.25);

    Random rnd(1234);
    forAll(f.U, celli)
    {
        f.U[celli] = rnd.sample01<vector>() - vector(0.5, 0.5, 0.5);
    }
    const vector Ubulk0 = meanFlowControl::bulkVelocity(f.U);

    autoPtr<meanFlowControl> control = meanFlowControl::New
    (
        mesh,
        properties
        (
            "meanFlowControl fixedBulkVelocity;"
            "fixedBulkVelocity { direction (0 0 2); Ubar 0.7; }"
        )
    );
    control->correct(f.U, f.rAU);

    const vector Ubulk = meanFlowControl::bulkVelocity(f.U);
    EXPECT_NEAR(Ubulk.z(), 0.7, 1e-12);
    // Other directions untouched
    EXPECT_NEAR(Ubulk.x(), Ubulk0.x(), 1e-12);
    EXPECT_NEAR(Ubulk.y(), Ubulk0.y(), 1e-12);
    // dG = (Ubar - <U>.d)/rAU along d
    EXPECT_NEAR(control->gradP().value().z(), (0.7 - Ubulk0.z())/0.25, 1e-10);
    EXPECT_EQ(control->gradP().value().x(), 0);
}


TEST(fixedBulkVelocity, zeroMeanFluxConvergesWithNonUniformRAU)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(4, 4, 4, vector(1, 1, 1));
    flowFields f(mesh, 1);

    Random rnd(99);
    forAll(f.U, celli)
    {
        f.U[celli] = vector(0, 0, 1 + rnd.sample01<scalar>());
        f.rAU[celli] = 0.5 + rnd.sample01<scalar>();
    }

    autoPtr<meanFlowControl> control = meanFlowControl::New
    (
        mesh,
        properties
        (
            "meanFlowControl fixedBulkVelocity;"
            "fixedBulkVelocity { direction (0 0 -1); Ubar [0 1 -1 0 0 0 0] 0; }"
        )
    );

    // One correction per time step: a fixed-point iteration whose error
    // shrinks by the spread of rAU around its mean
    for (label step = 0; step < 40; ++step)
    {
        ++tc.runTime();
        control->correct(f.U, f.rAU);
    }

    EXPECT_NEAR(meanFlowControl::bulkVelocity(f.U).z(), 0, 1e-10);
}


TEST(fixedBulkVelocity, correctorsOfOneStepDoNotAccumulate)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));
    flowFields f(mesh, 0.5);

    autoPtr<meanFlowControl> control = meanFlowControl::New
    (
        mesh,
        properties
        (
            "meanFlowControl fixedBulkVelocity;"
            "fixedBulkVelocity { direction (1 0 0); Ubar 1; }"
        )
    );

    // Every corrector rebuilds U from the same momentum matrix: the same
    // U before each correct() must give the same gradient, not twice it
    ++tc.runTime();
    f.U.primitiveFieldRef() = vector(0.2, 0, 0);
    control->correct(f.U, f.rAU);
    const vector first = control->gradP().value();
    f.U.primitiveFieldRef() = vector(0.2, 0, 0);
    control->correct(f.U, f.rAU);

    EXPECT_NEAR(first.x(), (1 - 0.2)/0.5, 1e-12);
    EXPECT_NEAR(control->gradP().value().x(), first.x(), 1e-12);
}


TEST(fixedBulkVelocity, zeroDirectionIsRejected)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));

    const std::string msg = selectionError
    (
        mesh,
        "meanFlowControl fixedBulkVelocity;"
        "fixedBulkVelocity { direction (0 0 0); Ubar 0; }"
    );

    EXPECT_NE(msg.find("direction"), std::string::npos) << msg;
}


TEST(fixedBulkVelocity, relaxationOutOfRangeIsRejected)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(2, 2, 2, vector(1, 1, 1));

    for (const char* value : {"0", "1.5", "-1"})
    {
        const std::string msg = selectionError
        (
            mesh,
            std::string("meanFlowControl fixedBulkVelocity;")
            + "fixedBulkVelocity { direction (1 0 0); Ubar 0;"
            + " relaxation " + value + "; }"
        );

        EXPECT_NE(msg.find("relaxation"), std::string::npos)
            << "relaxation " << value << ": " << msg;
        EXPECT_NE(msg.find("0 < relaxation <= 1"), std::string::npos) << msg;
    }
}


// ************************************************************************* //

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
    The fluid step's penalty (fluidStepPenalty): off unless asked for, its
    settings checked as read; it holds the cells whose centres lie inside a
    body (those of a periodic image too) and what it gives the fluid there
    is K (u_b - u) V dt, scaled by the time scheme's share.

\*---------------------------------------------------------------------------*/

#include "foamTestCase.H"
#include "testInput.H"
#include "fluidStepPenalty.H"
#include "sphere.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

dictionary fdDict(const std::string& text)
{
    return testInput::parse(text);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(fluidStepPenalty, isOffUnlessAskedFor)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(4, 4, 4, vector::one);
    const cellCentreSearch search(mesh);
    using treatment = fictitiousDomain::surfaceTreatment;

    const fluidStepPenalty off
    (
        mesh, fdDict(""), treatment::ghostCells, search
    );
    EXPECT_FALSE(off.on());

    const fluidStepPenalty multipliers
    (
        mesh, fdDict("fluidStepForce multipliers;"), treatment::fluidStencil,
        search
    );
    EXPECT_FALSE(multipliers.on());

    const fluidStepPenalty on
    (
        mesh, fdDict("fluidStepForce penalty;"), treatment::ghostCells, search
    );
    EXPECT_TRUE(on.on());
    EXPECT_EQ(on.factor(), 100);
}


TEST(fluidStepPenalty, refusesWhatItCannotDo)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(4, 4, 4, vector::one);
    const cellCentreSearch search(mesh);
    using treatment = fictitiousDomain::surfaceTreatment;

    std::string e = testInput::errorOf([&]
    {
        fluidStepPenalty p
        (
            mesh, fdDict("fluidStepForce implicit;"), treatment::ghostCells,
            search
        );
    });
    EXPECT_NE(e.find("fluidStepForce implicit"), std::string::npos) << e;
    EXPECT_NE(e.find("multipliers"), std::string::npos) << e;
    EXPECT_NE(e.find("penalty"), std::string::npos) << e;

    e = testInput::errorOf([&]
    {
        fluidStepPenalty p
        (
            mesh, fdDict("fluidStepForce penalty; penaltyFactor 0;"),
            treatment::ghostCells, search
        );
    });
    EXPECT_NE(e.find("penaltyFactor 0"), std::string::npos) << e;
    EXPECT_NE(e.find("> 0"), std::string::npos) << e;

    e = testInput::errorOf([&]
    {
        fluidStepPenalty p
        (
            mesh, fdDict("fluidStepForce penalty;"), treatment::fluidStencil,
            search
        );
    });
    EXPECT_NE(e.find("ghostCells"), std::string::npos) << e;
    EXPECT_NE(e.find("fluidStencil"), std::string::npos) << e;
}


TEST(fluidStepPenalty, givesTheFluidInsideTheBodyItsMomentumScaledByTheTimeScheme)
{
    // A sphere of D 0.5 moving at V in fluid at rest: the penalty's momentum
    // is (factor/dt) (V - 0) V_c dt / c summed over the cells whose centres
    // lie inside, c = dt times fvm::ddt's diagonal (1 Euler, 1.5 backward);
    // a sphere across the periodic boundary holds its cells' images
    for (const word ddt : {"Euler", "backward"})
    try
    {
        test::foamTestCase tc;
        const fvMesh& mesh = tc.makeBoxMesh(16, 16, 16, vector::one);
        const cellCentreSearch search(mesh);
        volVectorField U
        (
            IOobject("U", mesh.time().timeName(), mesh),
            mesh,
            dimensionedVector(dimVelocity, Zero),
            "calculated"
        );
        volVectorField deviation(U);
        const scalar dt = 0.01;

        particleShapes::sphere ball("ball", 0.5);
        const List<point> centres
        ({
            point(0.5, 0.5, 0.5), point(0.02, 0.5, 0.97)
        });
        for (const point& centre : centres)
        {
            List<fictitiousDomain::body> bodies(1);
            bodies[0].shape = &ball;
            bodies[0].centre = centre;
            bodies[0].V = vector(0.2, 0, -0.1);

            fluidStepPenalty penalty
            (
                mesh, fdDict("fluidStepForce penalty; penaltyFactor 50;"),
                fictitiousDomain::surfaceTreatment::ghostCells, search
            );
            const vector period(vector::one);
            const scalar c = ddt == "Euler" ? 1 : 1.5;
            tmp<fvVectorMatrix> m =
                penalty.matrix(U, bodies, deviation, period, dt, c);

            // The cells held: those whose centre (or its image) is inside
            scalar held = 0;
            vector heldMoment(Zero);
            forAll(mesh.C(), k)
            {
                vector arm = mesh.C()[k] - centre;
                for (direction d = 0; d < 3; ++d)
                {
                    arm[d] -= std::round(arm[d]);
                }
                if (mag(arm) < 0.25)
                {
                    held += mesh.V()[k];
                    heldMoment += mesh.V()[k]*arm;
                }
            }
            // The matrix's diagonal: K V_c in exactly those cells
            EXPECT_NEAR(sum(m().diag()), 50/dt*held, 1e-9*50/dt*held);

            List<vector> momentum, moment;
            penalty.momentum(U, 1, dt, momentum, moment);
            const vector expected = 50/dt*dt/c*held*bodies[0].V;
            EXPECT_LT(mag(momentum[0] - expected), 1e-12) << ddt;
            // Its moment about the centre, from each held cell's image
            const vector expectedMoment =
                heldMoment ^ (50/dt*dt/c*bodies[0].V);
            EXPECT_LT(mag(moment[0] - expectedMoment), 1e-12);
        }
    }
    catch (const Foam::error& e)
    {
        ADD_FAILURE() << ddt << ": " << e.message();
    }
}


// ************************************************************************* //

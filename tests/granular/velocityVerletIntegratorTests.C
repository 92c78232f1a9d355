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
    The granular time integration without contacts
    (Foam::velocityVerletIntegrator): a constant force is integrated
    exactly over sub-steps, fusing a sub-step's second half kick into the
    next one's first pass gives the bits of separate passes, positions wrap
    into the periodic box only along periodic directions, fixed particles
    are left alone, and the number of sub-steps of a step.

\*---------------------------------------------------------------------------*/

#include "velocityVerletIntegrator.H"
#include "sphere.H"
#include "testInput.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

const scalar D = 0.01;

//- n sub-steps of Deltat/n, as granularSystem::evolve runs them without
//- contacts
void evolve
(
    const velocityVerletIntegrator& integrator,
    std::vector<rigidParticle>& particles,
    const scalar Deltat,
    const label n,
    scalar& E
)
{
    const scalar dt = Deltat/n;
    for (label k = 0; k < n; ++k)
    {
        integrator.openSubStep(particles, dt, k > 0, nullptr);
        if (k == n - 1)
        {
            E = integrator.closeStep(particles, dt);
        }
    }
}

//- The force sum a step starts from: that of the previous step's last
//- sub-step (gravity and the external forces here, no contact)
void holdForces
(
    const velocityVerletIntegrator& integrator,
    std::vector<rigidParticle>& particles
)
{
    for (const label i : integrator.moving())
    {
        rigidParticle& p = particles[i];
        p.clearForces();
        p.addForce(p.mass()*integrator.gravity());
        if (integrator.externalForcesOn())
        {
            p.addForce(integrator.externalForce(i));
        }
    }
}

} // End anonymous namespace


TEST(velocityVerletIntegrator, constantForceIsIntegratedExactlyOverSubSteps)
{
    const collisionSettings settings
    (
        testInput::parse("domain { min (-1 -1 -1); max (1 1 1); }")
    );
    velocityVerletIntegrator integrator(settings);
    const particleShapes::sphere ball("ball", D);
    std::vector<rigidParticle> particles;
    particles.emplace_back(ball, 2500, point(0, 0, 0));
    particles[0].setVelocity(vector(0.1, 0, 0.2));
    integrator.setParticles(labelList({0}), 1);
    const vector g(0, 0, -9.81);
    integrator.setGravity(g);
    const vector F(2e-3, 0, 0);
    integrator.setExternalForce(0, F, Zero);

    const scalar t = 0.05;
    scalar E = 0;
    holdForces(integrator, particles);
    evolve(integrator, particles, t, 7, E);

    const scalar m = particles[0].mass();
    const vector a = g + F/m;
    const vector U = vector(0.1, 0, 0.2) + a*t;
    const point x = vector(0.1, 0, 0.2)*t + 0.5*a*t*t;
    EXPECT_LT(mag(particles[0].position() - x), 1e-15);
    EXPECT_LT(mag(particles[0].velocity() - U), 1e-15);
    EXPECT_NEAR(E, 0.5*m*magSqr(U), 1e-12*0.5*m*magSqr(U));

    // Cleared external forces are no longer applied
    integrator.clearExternalForces();
    EXPECT_FALSE(integrator.externalForcesOn());
    holdForces(integrator, particles);
    evolve(integrator, particles, t, 3, E);
    EXPECT_LT(mag(particles[0].velocity() - (U + g*t)), 1e-14);
}


TEST(velocityVerletIntegrator, fusedHalfKickGivesTheBitsOfSeparatePasses)
{
    const collisionSettings settings
    (
        testInput::parse("domain { min (-1 -1 -1); max (1 1 1); }")
    );
    velocityVerletIntegrator integrator(settings);
    const particleShapes::sphere ball("ball", D);
    std::vector<rigidParticle> fused, separate;
    for (label i = 0; i < 10; ++i)
    {
        const point x(0.01*i, 0.003*i, -0.002*i);
        fused.emplace_back(ball, 2500, x);
        separate.emplace_back(ball, 2500, x);
        fused.back().setVelocity(vector(0.01*i, -0.1, 0.02));
        separate.back().setVelocity(vector(0.01*i, -0.1, 0.02));
    }
    integrator.setParticles(labelList(identity(10)), 10);
    integrator.setGravity(vector(0, 0, -9.81));

    const scalar dt = 1e-4;
    scalar E = 0;
    holdForces(integrator, fused);
    holdForces(integrator, separate);
    evolve(integrator, fused, 5*dt, 5, E);
    for (label k = 0; k < 5; ++k)
    {
        integrator.openSubStep(separate, dt, false, nullptr);
        integrator.closeStep(separate, dt);
    }
    for (label i = 0; i < 10; ++i)
    {
        EXPECT_EQ(fused[i].position(), separate[i].position()) << i;
        EXPECT_EQ(fused[i].velocity(), separate[i].velocity()) << i;
    }
}


TEST(velocityVerletIntegrator, positionsWrapOnlyAlongPeriodicDirections)
{
    const collisionSettings settings
    (
        testInput::parse
        (
            "domain { min (0 0 0); max (1 1 1); periodic (true false false); }"
        )
    );
    velocityVerletIntegrator integrator(settings);
    const particleShapes::sphere ball("ball", D);
    std::vector<rigidParticle> particles;
    particles.emplace_back(ball, 2500, point(0.95, 0.95, 0.5));
    particles[0].setVelocity(vector(1, 1, 0));
    integrator.setParticles(labelList({0}), 1);

    scalar E = 0;
    evolve(integrator, particles, 0.1, 1, E);
    // x leaves through the periodic face and comes back at the other side;
    // y is not periodic and leaves the box
    EXPECT_NEAR(particles[0].position().x(), 0.05, 1e-12);
    EXPECT_NEAR(particles[0].position().y(), 1.05, 1e-12);
    EXPECT_EQ(particles[0].position().z(), 0.5);
}


TEST(velocityVerletIntegrator, fixedParticlesAreLeftAlone)
{
    const collisionSettings settings
    (
        testInput::parse("domain { min (-1 -1 -1); max (1 1 1); }")
    );
    velocityVerletIntegrator integrator(settings);
    const particleShapes::sphere ball("ball", D);
    std::vector<rigidParticle> particles;
    particles.emplace_back(ball, 2500, point(0, 0, 0));
    particles.emplace_back(ball, 2500, point(0.5, 0, 0));
    integrator.setParticles(labelList({1}), 2);
    integrator.setGravity(vector(0, 0, -9.81));

    scalar E = 0;
    holdForces(integrator, particles);
    evolve(integrator, particles, 0.1, 4, E);
    EXPECT_EQ(particles[0].position(), point(0, 0, 0));
    EXPECT_EQ(particles[0].velocity(), vector::zero);
    EXPECT_LT(particles[1].position().z(), 0);
    EXPECT_NEAR(E, 0.5*particles[1].mass()*sqr(0.981), 1e-12);
}


TEST(velocityVerletIntegrator, aStepOfExactlyNSubStepsHasN)
{
    EXPECT_EQ(velocityVerletIntegrator::nSubSteps(1e-3, 1e-4), 10);
    EXPECT_EQ(velocityVerletIntegrator::nSubSteps(0.3, 0.1), 3);
    EXPECT_EQ(velocityVerletIntegrator::nSubSteps(1.05e-3, 1e-4), 11);
    EXPECT_EQ(velocityVerletIntegrator::nSubSteps(1e-5, 1e-4), 1);
    EXPECT_EQ(velocityVerletIntegrator::nSubSteps(1e-3, VGREAT), 1);
}


// ************************************************************************* //

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
    The forces of one contact on the particles it joins
    (Foam::contactResolution): equal and opposite with the reduced mass of
    two free particles; a fixed partner gets none and the free one feels
    the law with its own mass; a pair of which neither moves is left
    alone; a face pressed flat (equal corner overlaps) gives the law
    itself and no torque, a tilted one a torque that rights it; a wall
    contact is the law at the particle's own mass; the periodic image's
    shift moves the partner's point of action.

\*---------------------------------------------------------------------------*/

#include "contactResolution.H"
#include "sphere.H"
#include "IStringStream.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

autoPtr<contactLaw> springDashpot()
{
    IStringStream is("kn 1e4; en 0.9; muc 0.3;");
    dictionary dict(is);
    dict.name() = "constant/collisionProperties.pairs.a-a";
    return contactLaw::New
    (
        "hookeanSpringDashpot", dict, materialPair{"a-a", 2500, 2500}
    );
}

//- A point contact at the origin, normal +z (from j to i)
contactGeometry pointContact(const scalar overlap)
{
    contactGeometry c;
    c.set(point::zero, vector(0, 0, 1), overlap);
    return c;
}

const scalar D = 0.01, dt = 1e-6, delta = 1e-5;

} // End anonymous namespace


TEST(contactResolution, twoFreeParticlesGetEqualOppositeForcesOfTheReducedMass)
{
    autoPtr<contactLaw> law = springDashpot();
    particleShapes::sphere ball("ball", D);
    rigidParticle pi(ball, 2500, point(0, 0, 0.5*D));
    rigidParticle pj(ball, 2500, point(0, 0, -0.5*D));
    pi.setVelocity(vector(0, 0, -0.1));
    pj.setVelocity(vector(0, 0, 0.1));
    contactHistory history;
    const contactGeometry c = pointContact(delta);
    ASSERT_TRUE
    (
        contactResolution::pair(law(), c, pi, pj, Zero, dt, history, 0, 1)
    );
    EXPECT_EQ(pi.force(), -pj.force());
    EXPECT_GT(pi.force().z(), 0);

    // The law itself at the reduced mass and the predicted approach speed
    vector Ui, omegai, Uj, omegaj, unused(Zero);
    pi.predictedVelocities(dt, Ui, omegai);
    pj.predictedVelocities(dt, Uj, omegaj);
    const vector F = law->force
    (
        delta, c.normal, Ui - Uj, 0.5*pi.mass(), dt, unused
    );
    EXPECT_LT(mag(pi.force() - F), 1e-12*mag(F));
    EXPECT_LT(mag(pi.torque()), 1e-20);
}


TEST(contactResolution, fixedPartnerGetsNoForceAndTheOtherFeelsItsOwnMass)
{
    autoPtr<contactLaw> law = springDashpot();
    particleShapes::sphere ball("ball", D);
    rigidParticle pi(ball, 2500, point(0, 0, 0.5*D));
    rigidParticle pj(ball, 2500, point(0, 0, -0.5*D));
    pj.setMotion(rigidParticle::motionKind::fixed);
    pi.setVelocity(vector(0, 0, -0.1));
    contactHistory history;
    const contactGeometry c = pointContact(delta);
    contactResolution::pair(law(), c, pi, pj, Zero, dt, history, 0, 1);
    EXPECT_EQ(mag(pj.force()), 0);

    vector Ui, omegai, unused(Zero);
    pi.predictedVelocities(dt, Ui, omegai);
    const vector F =
        law->force(delta, c.normal, Ui, pi.mass(), dt, unused);
    EXPECT_LT(mag(pi.force() - F), 1e-12*mag(F));

    // Neither moves: nothing is done
    pi.clearForces();
    pi.setMotion(rigidParticle::motionKind::fixed);
    EXPECT_FALSE
    (
        contactResolution::pair(law(), c, pi, pj, Zero, dt, history, 0, 1)
    );
    EXPECT_EQ(mag(pi.force()), 0);
}


TEST(contactResolution, faceContactGivesTheLawAndTiltGivesARightingTorque)
{
    autoPtr<contactLaw> law = springDashpot();
    particleShapes::sphere ball("ball", D);  // the shape does not matter
    rigidParticle pi(ball, 2500, point(0, 0, 0.5*D));
    rigidParticle pj(ball, 2500, point(0, 0, -0.5*D));
    pj.setMotion(rigidParticle::motionKind::fixed);
    contactHistory history;

    // Four corners of a square face at equal overlap
    contactGeometry c = pointContact(delta);
    c.nPoints = 4;
    const scalar a = 0.25*D;
    c.points[0] = point(a, a, 0);
    c.points[1] = point(-a, a, 0);
    c.points[2] = point(-a, -a, 0);
    c.points[3] = point(a, -a, 0);
    for (label k = 0; k < 4; ++k)
    {
        c.depths[k] = delta;
    }
    c.spread = a*std::sqrt(2.0);
    contactResolution::pair(law(), c, pi, pj, Zero, dt, history, 0, 1);
    vector Ui, omegai, unused(Zero);
    pi.predictedVelocities(dt, Ui, omegai);
    const vector F =
        law->force(delta, c.normal, Ui, pi.mass(), dt, unused);
    EXPECT_LT(mag(pi.force() - F), 1e-12*mag(F));
    EXPECT_LT(mag(pi.torque()), 1e-12*mag(F)*D);

    // Deeper on the +x side: the force there is larger and turns the
    // particle about -y (lifting its +x side, +z force at +x: r x F
    // along -y)
    pi.clearForces();
    c.depths[0] = c.depths[3] = 2*delta;
    contactResolution::pair(law(), c, pi, pj, Zero, dt, history, 0, 1);
    EXPECT_LT(pi.torque().y(), 0);
    EXPECT_LT(mag(pi.torque().x()), 1e-12*mag(F)*D);
}


TEST(contactResolution, periodicImageShiftMovesThePartnersPointOfAction)
{
    autoPtr<contactLaw> law = springDashpot();
    particleShapes::sphere ball("ball", D);
    // pj sits one period L away along x; its image touches pi from below
    const scalar L = 0.1;
    rigidParticle pi(ball, 2500, point(0, 0, 0.5*D));
    rigidParticle pj(ball, 2500, point(L + 0.2*D, 0, -0.5*D));
    contactHistory history;
    contactGeometry c = pointContact(delta);
    c.position = point(0.1*D, 0, 0);
    contactResolution::pair
    (
        law(), c, pi, pj, vector(-L, 0, 0), dt, history, 0, 1
    );
    EXPECT_EQ(pi.force(), -pj.force());
    // Torques about each centre from the point where the force acts on it
    const vector Ti = (c.position - pi.position()) ^ pi.force();
    const vector Tj =
        (c.position + vector(L, 0, 0) - pj.position()) ^ pj.force();
    EXPECT_LT(mag(pi.torque() - Ti), 1e-12*mag(Ti) + 1e-30);
    EXPECT_LT(mag(pj.torque() - Tj), 1e-12*mag(Tj) + 1e-30);
}


TEST(contactResolution, wallContactIsTheLawAtTheParticlesMass)
{
    autoPtr<contactLaw> law = springDashpot();
    particleShapes::sphere ball("ball", D);
    rigidParticle pi(ball, 2500, point(0, 0, 0.5*D));
    pi.setVelocity(vector(0.02, 0, -0.1));
    contactHistory history;
    const contactGeometry c = pointContact(delta);
    contactResolution::wall(law(), c, pi, dt, history, 0, 2);
    vector Ui, omegai, unused(Zero);
    pi.predictedVelocities(dt, Ui, omegai);
    const vector F =
        law->force(delta, c.normal, Ui, pi.mass(), dt, unused);
    EXPECT_LT(mag(pi.force() - F), 1e-12*mag(F));
    EXPECT_GT(pi.force().z(), 0);
}


// ************************************************************************* //

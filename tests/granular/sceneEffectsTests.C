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
    The effects a scene declares (sceneEffects) and what the granular
    system does with them: bad declarations are refused with the valid
    names, declarations the inputs contradict are refused naming both,
    undeclared effects follow the inputs, and each effect switches its work
    off: automatic collisions skip the sub-steps and the narrow phase while
    no pair is near and match collisions on through a collision, rotation
    off keeps omega at zero, friction off leaves no tangential force, fixed
    particles take no sub-step work.

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "testInput.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::testInput;

namespace
{

//- Glass spheres of D = 1 cm (and a cube of the same volume) with a law,
//- a floor at z = 0 and the declared effects
autoPtr<granularSystem> makeScene
(
    const std::string& effects,
    const std::string& law = "hookeanSpringDashpot",
    const std::string& periodic = "(false false false)"
)
{
    const dictionary particleDict = parse
    (
        "shapes { ball { type sphere; D 0.01; } box { type cube; edge 0.008; } }"
        " materials { glass { density 2500; } }"
    );
    const std::string coeffs =
        "en 0.9; muc 0.3; maxOverlapRatio 1e-3; impactVelocity 0.5;"
        " referenceDiameter 0.01;"
      + std::string(law == "hookeanStaticFriction" ? " ks 1e4;" : "");
    const dictionary collisionDict = parse
    (
        "contactLaw " + law + "; domain { min (-0.1 -0.1 -0.1);"
        " max (0.1 0.1 0.1); periodic " + periodic + "; }"
        " walls { floor { point (0 0 0); normal (0 0 1); material steel; } }"
        " pairs { glass-glass {" + coeffs + "} glass-steel {" + coeffs + "} }"
    );
    return autoPtr<granularSystem>::New
    (
        particleDict, collisionDict, sceneEffects(parse(effects))
    );
}

} // End anonymous namespace


TEST(sceneEffects, unknownEffectIsRefusedListingTheEffects)
{
    const std::string msg =
        errorOf([]{ sceneEffects(parse("colisions on;")); });
    std::cout << msg << nl;
    EXPECT_NE(msg.find("colisions"), std::string::npos);
    EXPECT_NE(msg.find("collisions"), std::string::npos);
    EXPECT_NE(msg.find("frictionHistory"), std::string::npos);
}


TEST(sceneEffects, unknownCollisionModeListsTheModes)
{
    const std::string msg =
        errorOf([]{ sceneEffects(parse("collisions sometimes;")); });
    std::cout << msg << nl;
    EXPECT_NE(msg.find("sometimes"), std::string::npos);
    EXPECT_NE(msg.find("automatic"), std::string::npos);
    EXPECT_NE
    (
        errorOf([]{ sceneEffects(parse("rotation maybe;")); }).find("on or off"),
        std::string::npos
    );
}


TEST(sceneEffects, undeclaredEffectsFollowTheInputs)
{
    auto sys = makeScene("", "hookeanStaticFriction", "(false false true)");
    const sceneEffects& e = sys->effects();
    EXPECT_TRUE(e.collisions() == sceneEffects::collisionMode::on);
    EXPECT_TRUE(e.on("friction"));
    EXPECT_TRUE(e.on("frictionHistory"));
    EXPECT_TRUE(e.on("periodicity"));
    EXPECT_TRUE(e.on("rotation"));

    auto dry = makeScene("", "none");
    EXPECT_TRUE(dry->effects().collisions() == sceneEffects::collisionMode::off);
    EXPECT_FALSE(dry->effects().on("friction"));
    EXPECT_FALSE(dry->effects().on("periodicity"));
}


TEST(sceneEffects, declarationsTheInputsContradictAreRefused)
{
    // Each message names the declaration and what contradicts it
    const auto check = [](const std::string& decl, const std::string& law,
                          const std::string& periodic, const std::string& word)
    {
        const std::string msg =
            errorOf([&]{ makeScene(decl, law, periodic); });
        std::cout << decl << " -> " << msg << nl;
        EXPECT_NE(msg.find(word), std::string::npos) << decl;
    };
    check("collisions on;", "none", "(false false false)", "contactLaw none");
    check("collisions automatic;", "none", "(false false false)", "contactLaw none");
    check("frictionHistory on;", "hookeanSpringDashpot", "(false false false)",
          "hookeanStaticFriction");
    check("frictionHistory off;", "hookeanStaticFriction", "(false false false)",
          "keeps a tangential history");
    check("friction off;", "hookeanStaticFriction", "(false false false)",
          "friction law with history");
    check("periodicity off;", "hookeanSpringDashpot", "(true false false)",
          "periodic (true false false)");
    check("periodicity on;", "hookeanSpringDashpot", "(false false false)",
          "periodic none");
}


TEST(sceneEffects, fixedParticleDeclaredAbsentIsReportedWithItsId)
{
    auto sys = makeScene("fixedParticles off;");
    sys->addParticle(7, "ball", "glass", point(0, 0, 0.02));
    sys->addParticle(42, "ball", "glass", point(0.03, 0, 0.02));
    sys->particle(1).setMotion(rigidParticle::motionKind::fixed);
    const std::string msg = errorOf([&]{ sys->updated(); });
    std::cout << msg << nl;
    EXPECT_NE(msg.find("particle 42"), std::string::npos);
    EXPECT_NE(msg.find("fixed"), std::string::npos);
}


TEST(sceneEffects, automaticCollisionsSkipTheSubStepsWhileNoPairIsNear)
{
    // Two spheres 4 D apart falling far above the floor: automatic takes
    // one step per evolve with no contact work; the trajectory is that of
    // collisions on (constant force: velocity Verlet is exact) to
    // round-off
    point x[2] = {Zero, Zero};
    for (const std::string mode : {"on", "automatic"})
    {
        auto sys = makeScene("collisions " + mode + ";");
        sys->setGravity(vector(0, 0, -9.81));
        sys->addParticle(0, "ball", "glass", point(0, 0, 0.08));
        sys->addParticle(1, "ball", "glass", point(0.04, 0, 0.08));
        sys->updated();
        sys->particle(0).setVelocity(vector(0.1, 0, 0));
        // A first evolve of a nanosecond: the first half kick of a run
        // has no force yet (weight included), and over a whole step of
        // automatic that would weigh 1e-4 m in the comparison
        sys->evolve(1e-9);
        label nSub = 0, skipped = 0;
        for (int k = 0; k < 20; ++k)
        {
            nSub += sys->evolve(1e-3);
            skipped += sys->stats().contactsSkipped;
        }
        std::cout << mode << ": " << nSub << " sub-steps, " << skipped
            << " steps without contact work" << nl;
        if (mode == "automatic")
        {
            EXPECT_EQ(nSub, 20);
            EXPECT_EQ(skipped, 20);
            const scalar d = mag(sys->particle(0).position() - x[0]);
            std::cout << "position difference " << d << " m" << nl;
            EXPECT_LT(d, 1e-14);
        }
        else
        {
            EXPECT_GT(nSub, 100);
            EXPECT_EQ(skipped, 0);
            x[0] = sys->particle(0).position();
        }
    }
}


TEST(sceneEffects, automaticCollisionsMatchCollisionsOnThroughACollision)
{
    // A head-on collision at 0.5 m/s from 3 D apart, no gravity: automatic
    // skips the approach and sub-cycles the contact; the rebound speeds
    // agree with collisions on to 1e-9 relative
    vector U[2] = {Zero, Zero};
    for (const std::string mode : {"on", "automatic"})
    {
        auto sys = makeScene("collisions " + mode + ";");
        // Off the sub-step grid: spheres that touch exactly at a sub-step's
        // end would start the contact (its dashpot) by round-off alone
        sys->addParticle(0, "ball", "glass", point(-0.0150123, 0, 0.05));
        sys->addParticle(1, "ball", "glass", point(0.0150123, 0, 0.05));
        sys->updated();
        sys->particle(0).setVelocity(vector(0.25, 0, 0));
        sys->particle(1).setVelocity(vector(-0.25, 0, 0));
        label skipped = 0, contacts = 0;
        for (int k = 0; k < 160; ++k)
        {
            sys->evolve(5e-4);
            skipped += sys->stats().contactsSkipped;
            contacts += sys->stats().nContacts > 0;
        }
        Info<< mode.c_str() << ": " << skipped << " of 160 steps without"
            << " contact work, " << contacts << " with a contact; U = "
            << sys->particle(0).velocity() << nl;
        EXPECT_GT(contacts, 0);
        if (mode == "automatic")
        {
            EXPECT_GT(skipped, 100);
            EXPECT_LT
            (
                mag(sys->particle(0).velocity() - U[0])/mag(U[0]), 1e-9
            );
            EXPECT_LT
            (
                mag(sys->particle(1).velocity() - U[1])/mag(U[1]), 1e-9
            );
        }
        else
        {
            U[0] = sys->particle(0).velocity();
            U[1] = sys->particle(1).velocity();
            // e_n = 0.9 of the law
            EXPECT_NEAR(U[1].x(), 0.9*0.25, 0.01*0.25);
        }
    }
}


TEST(sceneEffects, rotationOffKeepsOmegaZero)
{
    // A tilted cube dropped on its edge spins with rotation on; with
    // rotation off its angular velocity stays exactly zero and it bounces
    const quaternion tilt(vector(1, 0, 0), 0.3);
    for (const std::string mode : {"on", "off"})
    {
        auto sys = makeScene("rotation " + mode + ";");
        sys->setGravity(vector(0, 0, -9.81));
        sys->addParticle(0, "box", "glass", point(0, 0, 0.0075), tilt);
        sys->updated();
        sys->particle(0).setVelocity(vector(0, 0, -0.3));
        scalar maxOmega = 0;
        for (int k = 0; k < 100; ++k)
        {
            sys->evolve(1e-4);
            maxOmega = max(maxOmega, mag(sys->particle(0).omega()));
        }
        std::cout << "rotation " << mode << ": max |omega| " << maxOmega
            << " 1/s" << nl;
        if (mode == "on")
        {
            EXPECT_GT(maxOmega, 1);
        }
        else
        {
            EXPECT_EQ(maxOmega, 0);
        }
    }
}


TEST(sceneEffects, frictionOffLeavesNoTangentialForce)
{
    // A sphere sliding on the floor at 0.5 m/s: friction slows it and
    // spins it up; without friction it keeps its speed and does not turn
    for (const std::string mode : {"on", "off"})
    {
        auto sys = makeScene("friction " + mode + ";");
        sys->setGravity(vector(0, 0, -9.81));
        sys->addParticle(0, "ball", "glass", point(0, 0, 0.005));
        sys->updated();
        sys->particle(0).setVelocity(vector(0.5, 0, 0));
        for (int k = 0; k < 200; ++k)
        {
            sys->evolve(1e-4);
        }
        const rigidParticle& p = sys->particle(0);
        Info<< "friction " << mode.c_str() << ": U " << p.velocity()
            << " omega " << p.omega() << nl;
        if (mode == "on")
        {
            EXPECT_LT(p.velocity().x(), 0.49);
        }
        else
        {
            EXPECT_NEAR(p.velocity().x(), 0.5, 1e-12);
            EXPECT_LT(mag(p.omega()), 1e-9);
        }
    }
}


TEST(sceneEffects, fixedParticlesTakeNoSubStepWork)
{
    // A bed of fixed spheres alone: no sub-step at all. A free sphere
    // dropped on one of them bounces off it; the fixed one neither moves
    // nor carries a force
    auto sys = makeScene("fixedParticles on;");
    sys->setGravity(vector(0, 0, -9.81));
    for (label i = 0; i < 10; ++i)
    {
        sys->addParticle(i, "ball", "glass", point(-0.05 + 0.011*i, 0, 0.005));
    }
    sys->updated();
    for (label i = 0; i < 10; ++i)
    {
        sys->particle(i).setMotion(rigidParticle::motionKind::fixed);
    }
    sys->updated();
    EXPECT_EQ(sys->evolve(1e-3), 0);

    sys->addParticle(10, "ball", "glass", point(-0.05, 0, 0.0155));
    sys->updated();
    sys->particle(10).setVelocity(vector(0, 0, -0.2));
    scalar maxUp = 0;
    for (int k = 0; k < 100; ++k)
    {
        EXPECT_GT(sys->evolve(1e-4), 0);
        maxUp = max(maxUp, sys->particle(10).velocity().z());
    }
    std::cout << "largest upward speed after the impact " << maxUp
        << " m/s" << nl;
    EXPECT_GT(maxUp, 0.1);
    EXPECT_EQ(mag(sys->particle(0).position() - point(-0.05, 0, 0.005)), 0);
    EXPECT_EQ(mag(sys->particle(0).velocity()), 0);
}


// ************************************************************************* //

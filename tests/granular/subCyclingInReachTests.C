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
    subCycling inReach (collisionProperties): every particle takes the
    contact sub-steps, but the contact work (broad and narrow phase, laws)
    is done only for the particles that can touch something over the step.
    A colliding pair among particles far apart: the contacts of the pair
    only, and every trajectory the same bits as with subCycling all; a
    particle that a contact flings farther than its allowed travel makes
    the step start again with every particle's contacts (the same bits).

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "testInput.H"

#include <gtest/gtest.h>

using namespace Foam;
using Foam::testInput::parse;

namespace
{

//- Glass spheres and cubes (D, edge 0.01 m), a floor far below, gravity
autoPtr<granularSystem> makeSystem(const word& subCycling)
{
    const dictionary particleDict = parse
    (
        "shapes { ball { type sphere; D 0.01; } cube { type cube; edge 0.01; } }"
        " materials { glass { density 2500; } }"
    );
    const dictionary collisionDict = parse
    (
        "contactLaw hookeanSpringDashpot; subStepsPerContact 20;"
        " subCycling " + subCycling + ";"
        " domain { min (-1 -1 -1); max (1 1 1); }"
        " walls { floor { point (0 0 -0.9); normal (0 0 1); material steel; } }"
        " pairs { glass-glass { en 0.7; muc 0.4; kn 2e3; }"
        " glass-steel { en 0.7; muc 0.4; kn 2e3; } }"
    );
    auto sys = autoPtr<granularSystem>::New(particleDict, collisionDict);
    sys->setGravity(vector(0, 0, -9.81));
    return sys;
}

//- Far from one another and from the pair: spheres and cubes, turning
void addFarParticles(granularSystem& sys, const label first)
{
    for (label k = 0; k < 6; ++k)
    {
        sys.addParticle(first + k, k % 2 ? "cube" : "ball", "glass",
            point(-0.3 + 0.1*k, 0.2, 0.1*(k % 3)),
            quaternion(vector(1, 1, 0)/std::sqrt(2.0), 0.3*k));
    }
}

void setFarMotion(granularSystem& sys, const label first)
{
    for (label k = 0; k < 6; ++k)
    {
        sys.particle(first + k).setVelocity(vector(0.1, -0.05*k, 0.02));
        sys.particle(first + k).setOmega(vector(5*k, -3, 2));
    }
}

} // End anonymous namespace


TEST(subCyclingInReach, contactWorkOfThePairOnlyAndTrajectoriesUnchanged)
{
    auto make = [](const word& mode)
    {
        auto sys = makeSystem(mode);
        sys->addParticle(0, "ball", "glass", point(-0.006, 0, 0));
        sys->addParticle(1, "ball", "glass", point(0.006, 0, 0));
        addFarParticles(sys(), 2);
        sys->updated();
        sys->particle(0).setVelocity(vector(0.5, 0, 0));
        sys->particle(1).setVelocity(vector(-0.5, 0, 0));
        setFarMotion(sys(), 2);
        return sys;
    };
    auto all = make("all");
    auto inReach = make("inReach");
    const scalar Deltat = 20*all->maxSubStep();

    label stepsInReach = 0, contacts = 0;
    for (label k = 0; k < 100; ++k)
    {
        EXPECT_EQ(all->evolve(Deltat), 20);
        EXPECT_EQ(inReach->evolve(Deltat), 20);
        const granularSystem::statistics& s = inReach->stats();
        EXPECT_EQ(s.nFallbacks, 0) << "step " << k;
        EXPECT_EQ(s.nContacts, all->stats().nContacts) << "step " << k;
        EXPECT_EQ(all->stats().nInReach, -1);
        contacts += s.nContacts;
        // The pair while it can touch, else nobody
        EXPECT_TRUE(s.nInReach == 2 || s.nInReach == 0) << s.nInReach;
        stepsInReach += s.nInReach == 2;
        // Every particle takes the same sub-steps: the same bits
        for (label i = 0; i < all->size(); ++i)
        {
            const rigidParticle& a = all->particle(i);
            const rigidParticle& b = inReach->particle(i);
            EXPECT_EQ(a.position(), b.position()) << "particle " << i;
            EXPECT_EQ(a.velocity(), b.velocity()) << "particle " << i;
            EXPECT_EQ(a.omega(), b.omega()) << "particle " << i;
            EXPECT_EQ(a.orientation().w(), b.orientation().w()) << "particle " << i;
        }
    }
    EXPECT_GT(contacts, 0);
    // In reach from the start, through the contact, then apart
    EXPECT_GT(stepsInReach, 0);
    EXPECT_LT(stepsInReach, 100);
    EXPECT_EQ(all->kineticEnergy(), inReach->kineticEnergy());

    // The rebound: the pair separates at the restitution's speed
    const scalar vRel =
        mag(inReach->particle(1).velocity() - inReach->particle(0).velocity());
    EXPECT_NEAR(vRel, 0.7*1.0, 0.02) << vRel;
}


TEST(subCyclingInReach, particleFlungBeyondItsAllowedTravelRedoesTheStep)
{
    // Two spheres at rest overlapping by 3 % of D, the others at rest too:
    // the contact throws the two apart far faster than their reach at
    // rest (weight alone) said, so the step is redone with every
    // particle's contact work
    auto make = [](const word& mode)
    {
        auto sys = makeSystem(mode);
        sys->addParticle(0, "ball", "glass", point(-0.00485, 0, 0));
        sys->addParticle(1, "ball", "glass", point(0.00485, 0, 0));
        addFarParticles(sys(), 2);
        sys->updated();
        return sys;
    };
    auto all = make("all");
    auto inReach = make("inReach");
    const scalar Deltat = 20*all->maxSubStep();
    all->evolve(Deltat);
    inReach->evolve(Deltat);
    EXPECT_EQ(inReach->stats().nFallbacks, 1);
    EXPECT_EQ(inReach->stats().nInReach, -1);
    EXPECT_EQ(inReach->stats().nContacts, all->stats().nContacts);
    for (label i = 0; i < all->size(); ++i)
    {
        EXPECT_EQ(all->particle(i).position(), inReach->particle(i).position()) << i;
        EXPECT_EQ(all->particle(i).velocity(), inReach->particle(i).velocity()) << i;
        EXPECT_EQ(all->particle(i).omega(), inReach->particle(i).omega()) << i;
    }
    EXPECT_EQ(all->kineticEnergy(), inReach->kineticEnergy());
}


// ************************************************************************* //

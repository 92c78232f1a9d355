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
    The granular predictor of the coupling turns a body as the granular
    step will (issue 20, finding e: it moved the centre but kept the
    orientation of the step's start, so the constraint of a spinning cube
    was imposed where the cube had been).

\*---------------------------------------------------------------------------*/

#include "dlmfdCoupling.H"
#include "rigidParticle.H"
#include "platonicSolid.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(dlmfdCoupling, predictorTurnsTheBodyAsTheGranularStepDoes)
{
    particleShapes::platonicSolid cube("cube", "cube", 0.01);
    const quaternion q0(normalised(vector(1, 2, 3)), 0.7);
    const vector omega(3, -1, 2);
    const scalar dt = 0.02;
    rigidParticle p(cube, 2000, point(0.1, 0.2, 0.3), q0);
    p.setOmega(omega);

    const tensor predicted =
        dlmfdCoupling::predictedRotation(p.R(), omega, dt);

    // No torque: the granular step turns it at constant omega
    p.kickDrift(dt);
    EXPECT_LT(mag(predicted - p.R()), 1e-12);
    // and the turn is not negligible (what the old predictor dropped)
    EXPECT_GT(mag(q0.R() - p.R()), 0.05);
    EXPECT_EQ(dlmfdCoupling::predictedRotation(q0.R(), Zero, dt), q0.R());
}


TEST(particleDistribution, strategiesAreTheRunTimeSelectedMasterAndOwned)
{
    // What particleDistribution in constant/collisionProperties may name:
    // a new strategy is a new model of the table, the coupling unchanged
    const wordList names
    (
        particleDistribution::couplingConstructorTablePtr_->sortedToc()
    );
    EXPECT_EQ(names, wordList({"master", "owned"}));
}


// ************************************************************************* //

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
    The mesh-free momentum balance of a rigid body and the cells it moves
    (Foam::rigidMomentumBalance), on random clouds of cells: the body and
    its cells keep the momentum and the moment they had before the
    constraint (m = 0.5, 1, 1.01, 3); a flow that already moves rigidly
    with the body needs no change; modes left out keep their predicted
    values while the others still balance; cells moving affinely in the
    body's velocities enter the balance as the rigid ones do when their
    P, Q, E describe the rigid motion; a body with nothing to push on and
    no excess mass is singular.

\*---------------------------------------------------------------------------*/

#include "rigidMomentumBalance.H"
#include "Random.H"
#include "scalarField.H"
#include "vectorList.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A cloud of cells about a body's centre: positions, volumes and the
//- velocities the fluid step gave them
struct cloud
{
    List<vector> r;
    scalarField V;
    List<vector> u;

    cloud(Random& rnd, const label n)
    :
        r(n),
        V(n),
        u(n)
    {
        for (label i = 0; i < n; ++i)
        {
            r[i] = rnd.sample01<vector>() - vector::uniform(0.5);
            V[i] = 1e-3*(0.5 + rnd.sample01<scalar>());
            u[i] = rnd.sample01<vector>() - vector::uniform(0.5);
        }
    }

    scalar volume() const
    {
        return sum(V);
    }
};

const labelList allModes{0, 1, 2, 3, 4, 5};

} // End anonymous namespace


TEST(rigidMomentumBalance, bodyAndCellsKeepTheirMomentum)
{
    Random rnd(3);
    for (const scalar m : {0.5, 1.0, 1.01, 3.0})
    {
        const cloud c(rnd, 40);
        // The body is the cloud: its excess mass and inertia from the
        // cells' own volume distribution
        const scalar mvp = (m - 1)*c.volume();
        tensor J(Zero);
        forAll(c.r, i)
        {
            J += c.V[i]*(magSqr(c.r[i])*tensor::I - c.r[i]*c.r[i]);
        }
        const tensor mJ = (m - 1)*J;
        const vector Vstar(0.1, -0.2, 0.3), omegaStar(-1, 0.5, 2);
        rigidMomentumBalance balance(mvp, mJ, Vstar, omegaStar, Zero, Zero);
        vector P0 = mvp*Vstar, L0 = mJ & omegaStar;
        forAll(c.r, i)
        {
            balance.addRigidCell(c.r[i], c.V[i], c.u[i]);
            P0 += c.V[i]*c.u[i];
            L0 += c.V[i]*(c.r[i] ^ c.u[i]);
        }
        vector V = Vstar, omega = omegaStar;
        ASSERT_TRUE(balance.solve(allModes, V, omega)) << "m = " << m;
        vector P1 = mvp*V, L1 = mJ & omega;
        forAll(c.r, i)
        {
            const vector ui = V + (omega ^ c.r[i]);
            P1 += c.V[i]*ui;
            L1 += c.V[i]*(c.r[i] ^ ui);
        }
        EXPECT_LT(mag(P1 - P0), 1e-14) << "m = " << m;
        EXPECT_LT(mag(L1 - L0), 1e-14) << "m = " << m;
    }
}


TEST(rigidMomentumBalance, rigidFlowNeedsNoChange)
{
    Random rnd(4);
    const cloud c(rnd, 30);
    const vector V0(0.3, 0.1, -0.4), omega0(0.2, -0.7, 1.1);
    rigidMomentumBalance balance
    (
        2*c.volume(), 0.1*tensor::I, V0, omega0, Zero, Zero
    );
    forAll(c.r, i)
    {
        balance.addRigidCell(c.r[i], c.V[i], V0 + (omega0 ^ c.r[i]));
    }
    vector V = V0, omega = omega0;
    ASSERT_TRUE(balance.solve(allModes, V, omega));
    EXPECT_LT(mag(V - V0), 1e-13);
    EXPECT_LT(mag(omega - omega0), 1e-12);
}


TEST(rigidMomentumBalance, modesLeftOutKeepTheirPredictedValues)
{
    Random rnd(5);
    const cloud c(rnd, 30);
    const scalar mvp = 1.5*c.volume();
    const vector Vstar(0.1, 0.2, 0.3), omegaStar(0.4, 0.5, 0.6);
    rigidMomentumBalance balance
    (
        mvp, 0.2*tensor::I, Vstar, omegaStar, Zero, Zero
    );
    forAll(c.r, i)
    {
        balance.addRigidCell(c.r[i], c.V[i], c.u[i]);
    }
    // 2D: x and y, the rotation about z
    vector V = Vstar, omega = omegaStar;
    ASSERT_TRUE(balance.solve(labelList{0, 1, 5}, V, omega));
    EXPECT_EQ(V.z(), Vstar.z());
    EXPECT_EQ(omega.x(), omegaStar.x());
    EXPECT_EQ(omega.y(), omegaStar.y());
    // x and y momentum and the z moment still balance
    vector P0 = mvp*Vstar, P1 = mvp*V;
    scalar Lz0 = 0.2*omegaStar.z(), Lz1 = 0.2*omega.z();
    forAll(c.r, i)
    {
        const vector ui = V + (omega ^ c.r[i]);
        P0 += c.V[i]*c.u[i];
        P1 += c.V[i]*ui;
        Lz0 += c.V[i]*(c.r[i] ^ c.u[i]).z();
        Lz1 += c.V[i]*(c.r[i] ^ ui).z();
    }
    EXPECT_NEAR(P1.x(), P0.x(), 1e-14);
    EXPECT_NEAR(P1.y(), P0.y(), 1e-14);
    EXPECT_NEAR(Lz1, Lz0, 1e-14);

    // A fixed body: nothing solved, nothing changed
    vector Vf = Vstar, omegaf = omegaStar;
    ASSERT_TRUE(balance.solve(labelList(), Vf, omegaf));
    EXPECT_EQ(Vf, Vstar);
    EXPECT_EQ(omegaf, omegaStar);
}


TEST(rigidMomentumBalance, affineCellsDescribingRigidMotionActAsRigidOnes)
{
    Random rnd(6);
    const cloud c(rnd, 25);
    const vector Vstar(0, 0, -0.5), omegaStar(0.3, 0, 0);
    const tensor mJ(0.05*tensor::I);
    rigidMomentumBalance rigid(c.volume(), mJ, Vstar, omegaStar, Zero, Zero);
    rigidMomentumBalance affine(c.volume(), mJ, Vstar, omegaStar, Zero, Zero);
    forAll(c.r, i)
    {
        rigid.addRigidCell(c.r[i], c.V[i], c.u[i]);
        // u = V + Omega x r = I V - [r]x Omega
        affine.addAffineCell
        (
            c.r[i], c.V[i], tensor::I, -rigidMomentumBalance::cross(c.r[i]),
            Zero, c.u[i]
        );
    }
    vector V1 = Vstar, o1 = omegaStar, V2 = Vstar, o2 = omegaStar;
    ASSERT_TRUE(rigid.solve(allModes, V1, o1));
    ASSERT_TRUE(affine.solve(allModes, V2, o2));
    EXPECT_LT(mag(V1 - V2), 1e-12);
    EXPECT_LT(mag(o1 - o2), 1e-12);
}


TEST(rigidMomentumBalance, nothingToPushOnIsSingular)
{
    // m = 1 and no cell: no mass, no inertia
    rigidMomentumBalance balance
    (
        0, tensor::zero, vector(1, 0, 0), Zero, Zero, Zero
    );
    vector V(1, 0, 0), omega(Zero);
    EXPECT_FALSE(balance.solve(allModes, V, omega));
}


// ************************************************************************* //

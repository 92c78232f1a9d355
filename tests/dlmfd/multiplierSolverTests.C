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
    The mesh-free rigid-body constraint of the fluid-stencil fictitious
    domain (Foam::multiplierSolver), on random clouds of cells with
    collocation points interpolating them: the points end at the rigid
    motion of a fixed body; a free body and its cells keep their momentum
    (m = 0.5, 1, 3) and, with points at cell centres, their moment; a
    flow that already moves rigidly needs no force; in 2D nothing leaves
    the plane; a CG that cannot converge, and a body with no excess mass
    and no point to push on, are fatal errors that name the particle.

\*---------------------------------------------------------------------------*/

#include "multiplierSolver.H"
#include "Random.H"
#include "error.H"
#include "testInput.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A body's cells about its centre (at the origin) with random velocities
//- and volumes, and nPoints collocation points: the first nAtCells at
//- cell centres (weight 1 on that cell, as the interior points), the rest
//- at random places interpolating 8 random cells with positive weights
//- that sum to one (as the surface points' stencils)
collocationSet randomSet
(
    Random& rnd,
    const label nCells,
    const label nAtCells,
    const label nStencil
)
{
    collocationSet s;
    s.centres.setSize(nCells);
    s.invVolume.setSize(nCells);
    s.u.setSize(nCells);
    for (label c = 0; c < nCells; ++c)
    {
        s.centres[c] = rnd.sample01<vector>() - vector::uniform(0.5);
        s.invVolume[c] = 1/(1e-3*(0.5 + rnd.sample01<scalar>()));
        s.u[c] = rnd.sample01<vector>() - vector::uniform(0.5);
    }
    DynamicList<label> start, cell;
    DynamicList<scalar> weight;
    DynamicList<point> points;
    for (label k = 0; k < nAtCells; ++k)
    {
        start.append(cell.size());
        cell.append(k);
        weight.append(1);
        points.append(s.centres[k]);
    }
    for (label k = 0; k < nStencil; ++k)
    {
        start.append(cell.size());
        // 8 distinct cells among those not used by the interior points
        labelList picked;
        while (picked.size() < 8)
        {
            const label c =
                nAtCells + rnd.position<label>(0, nCells - nAtCells - 1);
            if (!picked.found(c))
            {
                picked.append(c);
            }
        }
        scalarList w(8);
        for (scalar& x : w)
        {
            x = 0.1 + rnd.sample01<scalar>();
        }
        const scalar total = sum(w);
        point p(Zero);
        forAll(picked, i)
        {
            cell.append(picked[i]);
            weight.append(w[i]/total);
            p += w[i]/total*s.centres[picked[i]];
        }
        points.append(p);
    }
    start.append(cell.size());
    s.points.transfer(points);
    s.nInterior = nAtCells;
    s.rowStart.transfer(start);
    s.rowCell.transfer(cell);
    s.rowWeight.transfer(weight);
    return s;
}


//- The velocity the points' interpolation gives at point k
vector atPoint(const collocationSet& s, const label k)
{
    vector sum(Zero);
    for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
    {
        sum += s.rowWeight[e]*s.u[s.rowCell[e]];
    }
    return sum;
}


//- A body about the origin whose volume and inertia are those of the
//- cells
multiplierSolver::rigidBody cloudBody(const collocationSet& s, const scalar m)
{
    multiplierSolver::rigidBody B;
    B.V = vector(0.1, -0.2, 0.3);
    B.omega = vector(-1, 0.5, 2);
    B.excessDensity = m - 1;
    forAll(s.centres, c)
    {
        const scalar V = 1/s.invVolume[c];
        const vector& r = s.centres[c];
        B.volume += V;
        B.volumeInertia += V*(magSqr(r)*tensor::I - r*r);
    }
    return B;
}

} // End anonymous namespace


TEST(multiplierSolver, fixedBodyPointsEndAtItsRigidMotion)
{
    Random rnd(11);
    collocationSet s(randomSet(rnd, 80, 10, 12));
    multiplierSolver::rigidBody B(cloudBody(s, 2));
    B.free = false;
    const multiplierSolver solver(1e-12, 1000, false);
    vectorField f;
    multiplierSolver::outcome out;
    solver.solve(0, B, s, 0.01, f, out);

    EXPECT_EQ(mag(out.dV), 0);
    EXPECT_EQ(mag(out.dOmega), 0);
    EXPECT_GT(out.iterations, 0);
    forAll(s.points, k)
    {
        const vector rigid = B.V + (B.omega ^ s.points[k]);
        EXPECT_LT(mag(atPoint(s, k) - rigid), 1e-10) << "point " << k;
    }
    EXPECT_LT(out.constraintError, 1e-10);
}


TEST(multiplierSolver, freeBodyAndItsCellsKeepTheirMomentum)
{
    for (const scalar m : {0.5, 1.0, 3.0})
    {
        Random rnd(12);
        // Points at cell centres only: the moment of the multipliers about
        // the centre is then the cells' moment change
        collocationSet s(randomSet(rnd, 60, 20, 0));
        const multiplierSolver::rigidBody B(cloudBody(s, m));
        const vectorField u0(s.u);
        const scalar dt = 0.02;
        const multiplierSolver solver(1e-13, 1000, false);
        vectorField f;
        multiplierSolver::outcome out;
        solver.solve(3, B, s, dt, f, out);

        vector dP(Zero), dL(Zero);
        forAll(s.u, c)
        {
            const scalar V = 1/s.invVolume[c];
            dP += V*(s.u[c] - u0[c]);
            dL += V*(s.centres[c] ^ (s.u[c] - u0[c]));
            // The force density is what moved the cells
            EXPECT_LT(mag(s.u[c] - u0[c] - dt*f[c]), 1e-14);
        }
        // The cells gain dt sum(lambda), the body loses it
        EXPECT_LT(mag(dP - dt*out.sumLambda), 1e-14) << "m = " << m;
        EXPECT_LT(mag(dL - dt*out.sumMoment), 1e-14) << "m = " << m;
        const vector bodyP = B.excessDensity*B.volume*out.dV;
        const vector bodyL = B.excessDensity*(B.volumeInertia & out.dOmega);
        EXPECT_LT(mag(bodyP + dP), 1e-10*B.volume) << "m = " << m;
        EXPECT_LT(mag(bodyL + dL), 1e-10*B.volume) << "m = " << m;

        // And the points move with the body's new velocities
        const vector V = B.V + out.dV, omega = B.omega + out.dOmega;
        forAll(s.points, k)
        {
            EXPECT_LT(mag(atPoint(s, k) - (V + (omega ^ s.points[k]))), 1e-9)
                << "m = " << m << ", point " << k;
        }
    }
}


TEST(multiplierSolver, freeBodyWithSurfaceStencilsKeepsItsMomentum)
{
    Random rnd(13);
    collocationSet s(randomSet(rnd, 90, 12, 14));
    const multiplierSolver::rigidBody B(cloudBody(s, 1.5));
    const vectorField u0(s.u);
    const multiplierSolver solver(1e-13, 1000, false);
    vectorField f;
    multiplierSolver::outcome out;
    solver.solve(0, B, s, 0.01, f, out);

    // The weights sum to one: each multiplier puts its whole force on cells
    vector dP(Zero);
    forAll(s.u, c)
    {
        dP += (s.u[c] - u0[c])/s.invVolume[c];
    }
    EXPECT_LT(mag(dP + 0.5*B.volume*out.dV), 1e-10*B.volume);
    EXPECT_LT(out.constraintError, 1e-9);
}


TEST(multiplierSolver, rigidFlowNeedsNoForce)
{
    Random rnd(14);
    collocationSet s(randomSet(rnd, 50, 20, 0));
    const multiplierSolver::rigidBody B(cloudBody(s, 2));
    forAll(s.u, c)
    {
        s.u[c] = B.V + (B.omega ^ s.centres[c]);
    }
    const multiplierSolver solver(1e-10, 1000, false);
    vectorField f;
    multiplierSolver::outcome out;
    solver.solve(0, B, s, 0.01, f, out);
    EXPECT_LT(mag(out.dV), 1e-12);
    EXPECT_LT(mag(out.dOmega), 1e-12);
    EXPECT_LT(max(mag(f)), 1e-9);
}


TEST(multiplierSolver, twoDKeepsEverythingInThePlane)
{
    Random rnd(15);
    collocationSet s(randomSet(rnd, 60, 10, 10));
    const vectorField u0(s.u);
    multiplierSolver::rigidBody B(cloudBody(s, 2));
    B.V.z() = 0;
    B.omega.x() = 0;
    B.omega.y() = 0;
    const multiplierSolver solver(1e-12, 1000, true);
    vectorField f;
    multiplierSolver::outcome out;
    solver.solve(0, B, s, 0.01, f, out);
    EXPECT_EQ(out.dV.z(), 0);
    EXPECT_EQ(out.dOmega.x(), 0);
    EXPECT_EQ(out.dOmega.y(), 0);
    forAll(f, c)
    {
        EXPECT_EQ(f[c].z(), 0) << "cell " << c;
        EXPECT_EQ(s.u[c].z(), u0[c].z()) << "cell " << c;
    }
    forAll(s.points, k)
    {
        vector miss =
            atPoint(s, k) - (B.V + out.dV + ((B.omega + out.dOmega) ^ s.points[k]));
        miss.z() = 0;
        EXPECT_LT(mag(miss), 1e-9) << "point " << k;
    }
}


TEST(multiplierSolver, unconvergedSolveAndSingularBodyAreFatal)
{
    Random rnd(16);
    {
        collocationSet s(randomSet(rnd, 80, 10, 12));
        multiplierSolver::rigidBody B(cloudBody(s, 2));
        B.free = false;
        const multiplierSolver solver(1e-14, 1, false);
        vectorField f;
        multiplierSolver::outcome out;
        const std::string what = testInput::errorOf([&]
        {
            solver.solve(7, B, s, 0.01, f, out);
        });
        EXPECT_NE(what.find("particle 7"), std::string::npos) << what;
        EXPECT_NE(what.find("maxIterations"), std::string::npos) << what;
    }
    {
        // m = 1 and no point: nothing to push on, no excess mass
        collocationSet s(randomSet(rnd, 20, 0, 0));
        const multiplierSolver::rigidBody B(cloudBody(s, 1));
        const multiplierSolver solver(1e-10, 100, false);
        vectorField f;
        multiplierSolver::outcome out;
        const std::string what = testInput::errorOf([&]
        {
            solver.solve(9, B, s, 0.01, f, out);
        });
        EXPECT_NE(what.find("particle 9"), std::string::npos) << what;
        EXPECT_NE(what.find("singular"), std::string::npos) << what;
    }
}


// ************************************************************************* //

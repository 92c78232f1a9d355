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
    The fictitious-domain step on a box mesh of 24^3 cells: after the step
    the fluid at every collocation point moves with the body (to the CG
    tolerance); the step exchanges momentum and angular momentum between
    fluid and particle without creating any (the least-squares weights
    reproduce constants and linear fields, so the multipliers' force and
    moment reach the fluid whole); light (m = 0.5), neutral (m = 1) and
    heavy particles alike; a fluid already moving rigidly needs no force;
    a cell two particles claim goes to the closer centre.

\*---------------------------------------------------------------------------*/

#include "foamTestCase.H"
#include "fictitiousDomain.H"
#include "platonicSolid.H"
#include "sphere.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A smooth, non-rigid velocity field
vector swirl(const point& x)
{
    using constant::mathematical::twoPi;
    return vector
    (
        0.1*std::sin(twoPi*x.y()) + 0.02,
        0.05*std::cos(twoPi*x.z()),
        0.08*std::sin(twoPi*x.x())*std::cos(twoPi*x.y())
    );
}


tmp<volVectorField> makeU(const fvMesh& mesh)
{
    tmp<volVectorField> tU
    (
        new volVectorField
        (
            IOobject("U", mesh.time().timeName(), mesh),
            mesh,
            dimensionedVector(dimVelocity, Zero),
            "calculated"
        )
    );
    forAll(mesh.C(), c)
    {
        tU.ref()[c] = swirl(mesh.C()[c]);
    }
    return tU;
}


//- Momentum and angular momentum (about the origin) of the fluid, plus
//- those of the particles' excess mass (m - 1), all over rho_f
void totals
(
    const fvMesh& mesh,
    const volVectorField& U,
    const volVectorField& deviation,
    const UList<fictitiousDomain::body>& bodies,
    const UList<vector>& V,
    const UList<vector>& omega,
    vector& P,
    vector& L
)
{
    P = Zero;
    L = Zero;
    // Less the ghost cells' deviations from the rigid motion, which the
    // bodies do not count as theirs
    forAll(U, c)
    {
        const vector u = U[c] - deviation[c];
        P += mesh.V()[c]*u;
        L += mesh.V()[c]*(mesh.C()[c] ^ u);
    }
    forAll(bodies, b)
    {
        const fictitiousDomain::body& B = bodies[b];
        const scalar mv = B.excessDensity*B.shape->volume();
        const tensor J = B.R & B.shape->volumeInertia() & B.R.T();
        P += mv*V[b];
        L += mv*(B.centre ^ V[b]) + B.excessDensity*(J & omega[b]);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(fictitiousDomain, constraintHoldsAndMomentumIsKeptForAnyDensityRatio)
{
    const word treatment("ghostCells");
    for (const scalar m : {0.5, 1.0, 1.01, 3.0})
    {
        test::foamTestCase tc;
        const fvMesh& mesh = tc.makeBoxMesh(24, 24, 24, vector::one);
        tmp<volVectorField> tU = makeU(mesh);
        volVectorField& U = tU.ref();

        particleShapes::sphere ball("ball", 0.3);
        particleShapes::platonicSolid cube("cube", "cube", 0.25);
        List<fictitiousDomain::body> bodies(2);
        bodies[0].shape = &ball;
        bodies[0].centre = point(0.3, 0.5, 0.45);
        bodies[0].V = vector(0.01, -0.02, 0.03);
        bodies[0].omega = vector(0.5, 0, -0.2);
        bodies[1].shape = &cube;
        bodies[1].centre = point(0.72, 0.5, 0.55);
        bodies[1].R = quaternion(normalised(vector(1, 2, 3)), 0.7).R();
        bodies[1].omega = vector(0, 0.4, 0);
        for (auto& b : bodies)
        {
            b.excessDensity = m - 1;
        }

        dictionary dict;
        dict.add("surfaceTreatment", treatment);
        fictitiousDomain fd(mesh, dict);

        vector P0, L0;
        totals
        (
            mesh, U, fd.deviation(), bodies, vectorField({bodies[0].V, bodies[1].V}),
            vectorField({bodies[0].omega, bodies[1].omega}), P0, L0
        );
        const List<fictitiousDomain::result>& res = fd.solve(U, bodies, 0.01);

        vectorField V(2), omega(2);
        forAll(bodies, b)
        {
            V[b] = bodies[b].V + res[b].dV;
            omega[b] = bodies[b].omega + res[b].dOmega;
            // Ghost cells: the cells within a cell of the surface count
            // as its points, not as interior points
            EXPECT_GT(res[b].nInterior + (treatment == "ghostCells" ? res[b].nSurface : 0), 100)
                << treatment << " m " << m;
            // Surface points imposed, and those left out for want of a
            // stencil counted (about 40 % of them with the default
            // 1.2-cell stencil; the two together cover the surface)
            EXPECT_GT(res[b].nSurface, 50) << "m " << m;
            EXPECT_GT(res[b].nSurface + res[b].nSurfaceDropped, 100)
                << "m " << m;
            EXPECT_LT(res[b].constraintError, 1e-9) << "m " << m << " body " << b;
        }
        vector P1, L1;
        totals(mesh, U, fd.deviation(), bodies, V, omega, P1, L1);
        std::cout << "m " << m << ": momentum change " << mag(P1 - P0)
            << ", angular momentum change " << mag(L1 - L0)
            << " (of " << mag(P0) << ", " << mag(L0) << "); sphere |dV| "
            << mag(res[0].dV) << nl;
        EXPECT_LT(mag(P1 - P0), 1e-12*mag(P0)) << treatment << " m " << m;
        EXPECT_LT(mag(L1 - L0), 1e-12*mag(L0)) << treatment << " m " << m;
    }
}


TEST(fictitiousDomain, rigidFluidNeedsNoForceAndFixedBodiesStayFixed)
{
    const word treatment("ghostCells");
    {
    SCOPED_TRACE(treatment);
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(20, 20, 20, vector::one);
    const vector V0(0.02, 0.01, -0.03), omega0(0.3, -0.1, 0.2);
    const point X(0.5, 0.5, 0.5);
    volVectorField U
    (
        IOobject("U", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        "calculated"
    );
    forAll(U, c)
    {
        U[c] = V0 + (omega0 ^ (mesh.C()[c] - X));
    }
    particleShapes::sphere ball("ball", 0.4);
    List<fictitiousDomain::body> bodies(1);
    bodies[0].shape = &ball;
    bodies[0].centre = X;
    bodies[0].V = V0;
    bodies[0].omega = omega0;
    bodies[0].excessDensity = 1;

    dictionary dict;
    dict.add("surfaceTreatment", treatment);
    fictitiousDomain fd(mesh, dict);
    fictitiousDomain::result r;
    try
    {
        r = fd.solve(U, bodies, 0.01)[0];
    }
    catch (const Foam::error& e)
    {
        FAIL() << e.message();
    }
    EXPECT_LT(mag(r.sumLambda), 1e-12);
    EXPECT_LT(mag(r.dV), 1e-12);
    EXPECT_LT(mag(r.dOmega), 1e-12);

    // Fixed: the fluid is brought to rest inside (ghost cells: to their
    // deviation from rest), the body keeps its speed
    bodies[0].free = false;
    bodies[0].V = Zero;
    bodies[0].omega = Zero;
    const fictitiousDomain::result f = fd.solve(U, bodies, 0.01)[0];
    EXPECT_EQ(f.dV, vector::zero);
    EXPECT_EQ(f.dOmega, vector::zero);
    EXPECT_LT(f.constraintError, 1e-9);
    forAll(f.interiorCells, i)
    {
        const vector dev =
            f.interiorDeviation.size() ? f.interiorDeviation[i] : Zero;
        EXPECT_LT(mag(U[f.interiorCells[i]] - dev), 1e-9) << i;
    }
    }
}


TEST(fictitiousDomain, bodiesListedInAnotherOrderWithTheirGlobalIndicesGiveTheSameBits)
{
    // The same three bodies (two spheres 1.2 cells apart, whose ghost
    // cells meet, and a tilted cube), listed in the scene's order and in
    // another order with their global indices, over two steps (the second
    // reads the first's ghost owners and deviations): the same fields to
    // the bit, the owner field holding global indices, and each body's
    // result the same whatever its place
    particleShapes::sphere ball("ball", 0.3);
    particleShapes::platonicSolid cube("cube", "cube", 0.25);
    List<fictitiousDomain::body> scene(3);
    for (auto& b : scene)
    {
        b.excessDensity = 1;
        b.V = vector(0.01, -0.02, 0.03);
        b.omega = vector(0.5, 0, -0.2);
    }
    scene[0].shape = &ball;
    scene[0].centre = point(0.26, 0.31, 0.5);
    scene[1].shape = &ball;
    scene[1].centre = point(0.61, 0.32, 0.48);
    scene[2].shape = &cube;
    scene[2].centre = point(0.5, 0.73, 0.55);
    scene[2].R = quaternion(normalised(vector(1, 2, 3)), 0.7).R();
    const labelList order({2, 0, 1});

    const word treatment("ghostCells");
    {
        SCOPED_TRACE(treatment);
        dictionary dict;
        dict.add("surfaceTreatment", treatment);

        test::foamTestCase tcA, tcB;
        const fvMesh& meshA = tcA.makeBoxMesh(24, 24, 24, vector::one);
        const fvMesh& meshB = tcB.makeBoxMesh(24, 24, 24, vector::one);
        tmp<volVectorField> tUA = makeU(meshA);
        tmp<volVectorField> tUB = makeU(meshB);
        fictitiousDomain fdA(meshA, dict), fdB(meshB, dict);

        List<fictitiousDomain::body> inOrder(scene), reordered(3);
        forAll(order, b)
        {
            reordered[b] = scene[order[b]];
            reordered[b].index = order[b];
        }
        for (label step = 0; step < 2; ++step)
        {
            const List<fictitiousDomain::result> resA
            (
                fdA.solve(tUA.ref(), inOrder, 0.01)
            );
            const List<fictitiousDomain::result> resB
            (
                fdB.solve(tUB.ref(), reordered, 0.01)
            );
            forAll(order, b)
            {
                const fictitiousDomain::result& a = resA[order[b]];
                const fictitiousDomain::result& r = resB[b];
                EXPECT_EQ(a.dV, r.dV) << "step " << step << " body " << b;
                EXPECT_EQ(a.dOmega, r.dOmega) << "step " << step;
                EXPECT_EQ(a.sumLambda, r.sumLambda) << "step " << step;
                EXPECT_EQ(a.interiorCells, r.interiorCells);
            }
            EXPECT_EQ(tUA().primitiveField(), tUB().primitiveField())
                << "step " << step;
            EXPECT_EQ
            (
                fdA.source().primitiveField(), fdB.source().primitiveField()
            ) << "step " << step;
            EXPECT_EQ
            (
                fdA.ghostOwner().primitiveField(),
                fdB.ghostOwner().primitiveField()
            ) << "step " << step;
            EXPECT_EQ
            (
                fdA.deviation().primitiveField(),
                fdB.deviation().primitiveField()
            ) << "step " << step;
            // The bodies move on a little
            for (auto* list : {&inOrder, &reordered})
            {
                for (auto& b : *list)
                {
                    b.centre += vector(0.013, 0.007, -0.011);
                }
            }
        }
        if (treatment == "ghostCells")
        {
            // Every global index of the scene owns cells
            const scalarField& o = fdA.ghostOwner().primitiveField();
            EXPECT_EQ(max(o), 2);
            labelHashSet owners;
            for (const scalar x : o)
            {
                owners.insert(label(x));
            }
            EXPECT_EQ(owners.size(), 4);
        }
    }
}


TEST(fictitiousDomain, cellClaimedByTwoParticlesGoesToTheCloserCentre)
{
    // Two spheres overlapping (as in a contact): no cell serves both, and
    // each shared cell goes to the closer centre
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(24, 24, 24, vector::one);
    tmp<volVectorField> tU = makeU(mesh);
    particleShapes::sphere ball("ball", 0.3);
    List<fictitiousDomain::body> bodies(2);
    for (auto& b : bodies)
    {
        b.shape = &ball;
        b.excessDensity = 1;
    }
    bodies[0].centre = point(0.38, 0.5, 0.5);
    bodies[1].centre = point(0.62, 0.5, 0.5);

    dictionary dict;
    fictitiousDomain fd(mesh, dict);
    const List<fictitiousDomain::result>& res = fd.solve(tU.ref(), bodies, 0.01);

    labelHashSet first(res[0].interiorCells);
    label inBoth = 0;
    for (const label c : res[1].interiorCells)
    {
        inBoth += first.found(c);
    }
    EXPECT_EQ(inBoth, 0);
    label checked = 0;
    forAll(res, b)
    {
        for (const label c : res[b].interiorCells)
        {
            const point& x = mesh.C()[c];
            const scalar d0 = mag(x - bodies[0].centre);
            const scalar d1 = mag(x - bodies[1].centre);
            if (d0 < 0.15 && d1 < 0.15)
            {
                ++checked;
                EXPECT_LE(b == 0 ? d0 : d1, b == 0 ? d1 : d0) << c;
            }
        }
        EXPECT_LT(res[b].constraintError, 1e-9) << b;
    }
    EXPECT_GT(checked, 4);
}


// ************************************************************************* //


TEST(fictitiousDomain, bodyAcrossPeriodicBoundariesActsAsInAnOpenBox)
{
    // A cube straddling the corner of a periodic unit box (24^3 cells) and
    // the same cube in the middle of a box of twice the size (48^3 cells,
    // the same cells repeated, not periodic), in the same periodic velocity
    // field: the same points, the same multipliers, the same velocity
    // changes, and in the periodic box the fluid's momentum plus the
    // body's is kept
    particleShapes::platonicSolid cube("cube", "cube", 0.25);
    fictitiousDomain::body B;
    B.shape = &cube;
    B.R = quaternion(normalised(vector(1, 2, 3)), 0.7).R();
    B.V = vector(0.01, -0.02, 0.03);
    B.omega = vector(0.5, 0, -0.2);
    B.excessDensity = 1;
    const point corner(0.02, 0.97, 0.05);
    const word treatment("ghostCells");
    {
    SCOPED_TRACE(treatment);
    dictionary dict;
    dict.add("surfaceTreatment", treatment);

    fictitiousDomain::result open;
    {
        test::foamTestCase tc;
        const fvMesh& mesh = tc.makeBoxMesh(48, 48, 48, 2*vector::one);
        tmp<volVectorField> tU = makeU(mesh);
        List<fictitiousDomain::body> bodies(1, B);
        bodies[0].centre = corner + vector(1, 0, 1);
        fictitiousDomain fd(mesh, dict);
        open = fd.solve(tU.ref(), bodies, 0.01)[0];
    }

    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(24, 24, 24, vector::one);
    tmp<volVectorField> tU = makeU(mesh);
    List<fictitiousDomain::body> bodies(1, B);
    bodies[0].centre = corner;
    fictitiousDomain fd(mesh, dict);
    fd.setPeriodicity(vector::one);
    vector P0(Zero);
    forAll(mesh.C(), c)
    {
        P0 += mesh.V()[c]*tU()[c];
    }
    P0 += B.excessDensity*cube.volume()*B.V;
    const fictitiousDomain::result r = fd.solve(tU.ref(), bodies, 0.01)[0];
    vector P1(Zero);
    forAll(mesh.C(), c)
    {
        P1 += mesh.V()[c]*(tU()[c] - fd.deviation()[c]);
    }
    P1 += B.excessDensity*cube.volume()*(B.V + r.dV);

    Info<< "periodic corner: " << r.nInterior << " interior, "
        << r.nSurface << " surface points (open box " << open.nInterior
        << ", " << open.nSurface << "); dV " << r.dV << " against "
        << open.dV << "; momentum change " << mag(P1 - P0) << endl;
    EXPECT_GT(r.nInterior + r.nSurface, 200);
    EXPECT_EQ(r.nInterior, open.nInterior);
    EXPECT_EQ(r.nSurface, open.nSurface);
    EXPECT_EQ(r.nSurfaceDropped, open.nSurfaceDropped);
    EXPECT_LT(mag(r.dV - open.dV), 1e-9*mag(open.dV));
    EXPECT_LT(mag(r.dOmega - open.dOmega), 1e-9*mag(open.dOmega));
    EXPECT_LT(mag(r.sumLambda - open.sumLambda), 1e-9*mag(open.sumLambda));
    EXPECT_LT(mag(r.sumMoment - open.sumMoment), 1e-9*mag(open.sumMoment));
    EXPECT_LT(r.constraintError, 1e-9);
    EXPECT_LT(mag(P1 - P0), 1e-12*mag(P0));

    // Cells of the body on the far sides of the box carry their centres
    // where they sit relative to it
    label shifted = 0;
    forAll(r.interiorCells, i)
    {
        const vector s = r.interiorCentres[i] - mesh.C()[r.interiorCells[i]];
        EXPECT_LT(mag(s - vector(round(s.x()), round(s.y()), round(s.z()))), 1e-12);
        shifted += mag(s) > 0.5;
    }
    EXPECT_GT(shifted, 10);
    }
}


TEST(fictitiousDomain, bodyLongerThanHalfThePeriodIsRefused)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(12, 12, 12, vector::one);
    tmp<volVectorField> tU = makeU(mesh);
    particleShapes::sphere ball("ball", 0.9);
    List<fictitiousDomain::body> bodies(1);
    bodies[0].shape = &ball;
    bodies[0].centre = point(0.5, 0.5, 0.5);
    bodies[0].excessDensity = 1;
    dictionary dict;
    fictitiousDomain fd(mesh, dict);
    fd.setPeriodicity(vector(1, 0, 0));
    try
    {
        fd.solve(tU.ref(), bodies, 0.01);
        FAIL() << "a body wider than half the period was accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg = e.message();
        EXPECT_NE(msg.find("particle 0"), std::string::npos) << msg;
        EXPECT_NE(msg.find("half the period"), std::string::npos) << msg;
    }
}

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
    The wall links of the default coupling (Foam::wallLinks, ghostShear
    link): the slope weights are the derivative at the face of the parabola
    (or line) through the wall and the cells along the link; a link meets a
    sphere's and a rotated cube's surface where the closed form puts it,
    with the wall's rigid velocity there; what the fluid gains at the links
    in a step, which the bodies pay, is the links' terms of the momentum
    equation's matrix applied to the velocity (the same numbers, to
    round-off), and a fixed body in a stream takes it as drag, with no
    torque where the flow is symmetric about it.

\*---------------------------------------------------------------------------*/

#include "foamTestCase.H"
#include "wallLinks.H"
#include "fictitiousDomain.H"
#include "platonicSolid.H"
#include "sphere.H"
#include "cellCentreSearch.H"
#include "periodicImages.H"
#include "quaternion.H"

#include <gtest/gtest.h>
#include <random>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

tmp<volVectorField> velocity(const fvMesh& mesh, const vector& U0, const scalar shear)
{
    // U0 plus a shear along y of the x component
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
    forAll(tU(), c)
    {
        tU.ref()[c] = U0 + vector(shear*(mesh.C()[c].y() - 0.5), 0, 0);
    }
    tU.ref().correctBoundaryConditions();
    return tU;
}


tmp<volScalarField> viscosity(const fvMesh& mesh, const scalar nu)
{
    return tmp<volScalarField>
    (
        new volScalarField
        (
            IOobject("nu", mesh.time().timeName(), mesh),
            mesh,
            dimensionedScalar("nu", dimViscosity, nu)
        )
    );
}


//- Row by row, the matrix's coefficients applied to u less its source:
//- what its terms add to the left-hand side of each cell's equation
vectorField rowResiduals(const fvVectorMatrix& m, const vectorField& u)
{
    const fvMesh& mesh = m.psi().mesh();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    vectorField r(m.diag()*u - m.source());
    if (m.hasUpper())
    {
        forAll(nei, f)
        {
            r[own[f]] += m.upper()[f]*u[nei[f]];
        }
    }
    if (m.hasLower())
    {
        forAll(nei, f)
        {
            r[nei[f]] += m.lower()[f]*u[own[f]];
        }
    }
    return r;
}

//- One fixed body (shape, centre, rotation) in a 24^3 unit box with the
//- velocity U0 plus a shear along y: its wall links after one
//- fictitious-domain step (which marks the body's cells), the links'
//- matrix, and what pay() gives for a step dt (Euler, no history)
struct fixedBodyLinks
{
    test::foamTestCase tc;
    const fvMesh& mesh;
    tmp<volVectorField> tU;
    tmp<volScalarField> tnu;
    List<fictitiousDomain::body> bodies;
    autoPtr<fictitiousDomain> fd;
    autoPtr<wallLinks> links;
    tmp<fvVectorMatrix> tm;
    List<vector> momentum, moment;

    fixedBodyLinks
    (
        const particleShape& shape,
        const point& centre,
        const tensor& R,
        const vector& U0,
        const scalar shear,
        const scalar dt
    )
    :
        mesh(tc.makeBoxMesh(24, 24, 24, vector::one)),
        tU(velocity(mesh, U0, shear)),
        tnu(viscosity(mesh, 0.01)),
        bodies(1),
        momentum(1, Zero),
        moment(1, Zero)
    {
        bodies[0].shape = &shape;
        bodies[0].centre = centre;
        bodies[0].R = R;
        bodies[0].free = false;
        bodies[0].index = 0;
        fd.reset(new fictitiousDomain(mesh, dictionary()));
        volVectorField Ustep(tU());
        fd->solve(Ustep, bodies, dt);
        links.reset(new wallLinks(mesh, true));
        links->update(fd->ghostOwner(), bodies, fd->images());
        tm = links->matrix(tU(), tnu());
        links->pay(tU(), dt, 1, momentum, moment);
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(wallLinks, slopeWeightsGiveTheSlopeAtTheFaceOfTheParabolaThroughTheWallAndTwoCells)
{
    // u(y) = 0.3 - 1.7 y + 2.9 y^2 along the line from the wall (y = 0)
    // through c (y = d) to the third point (y = d + hE); the face at d - a
    const auto u = [](const scalar y) { return 0.3 - 1.7*y + 2.9*y*y; };
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int k = 0; k < 500; ++k)
    {
        const scalar h = 0.01 + unit(gen);
        const scalar d = h*(1e-3 + unit(gen));        // the wall's distance from c
        const scalar hE = h*(0.5 + unit(gen));        // the third point beyond c
        const scalar a = h*(0.2 + 0.6*unit(gen));     // the face's distance from c
        const FixedList<scalar, 3> w = wallLinks::slopeWeights(d, hE, a);
        const scalar slope = w[0]*u(0) + w[1]*u(d) + w[2]*u(d + hE);
        const scalar exact = -1.7 + 2*2.9*(d - a);
        EXPECT_NEAR(slope, exact, 1e-9*(1 + mag(exact))) << "d " << d << " hE " << hE << " a " << a;
        // A constant has no slope
        EXPECT_NEAR(w[0] + w[1] + w[2], 0, 1e-9*(mag(w[0]) + mag(w[1]) + mag(w[2])));
    }
    // Without a third point the line through the wall and c: exact for a
    // linear profile, the third weight zero
    const auto line = [](const scalar y) { return 0.3 - 1.7*y; };
    const FixedList<scalar, 3> w = wallLinks::slopeWeights(0.4, 0, 0.5);
    EXPECT_EQ(w[2], 0);
    EXPECT_NEAR(w[0]*line(0) + w[1]*line(0.4), -1.7, 1e-12);
}


TEST(wallLinks, aLinkMeetsTheSurfaceWhereTheClosedFormPutsItWithTheWallsRigidVelocity)
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(8, 8, 8, vector::one);
    const cellCentreSearch search(mesh);
    const periodicImages images(search, mesh.bounds());

    const point X(0.5, 0.45, 0.55);
    const vector V(0.1, -0.2, 0.05), omega(1, 2, -0.5);
    std::mt19937 gen(5);
    std::normal_distribution<double> normal(0, 1);

    // A sphere of radius 0.2: from 1.7 r out to 0.3 r in along any
    // direction the surface is 0.7/1.4 of the way
    particleShapes::sphere ball("ball", 0.4);
    wallLinks::body B;
    B.shape = &ball;
    B.centre = X;
    B.V = V;
    B.omega = omega;
    const scalar r = 0.2;
    for (int k = 0; k < 50; ++k)
    {
        const vector n = normalised(vector(normal(gen), normal(gen), normal(gen)));
        vector uWall, arm;
        const scalar t = wallLinks::crossing(B, images, X + 1.7*r*n, X + 0.3*r*n, uWall, arm);
        EXPECT_NEAR(t, 0.5, 1e-10);
        EXPECT_LT(mag(arm - r*n), 1e-10);
        EXPECT_LT(mag(uWall - (V + (omega ^ (r*n)))), 1e-9);
    }

    // A cube of edge 0.3, rotated: a link along its body x axis from 0.24
    // out to the centre's plane meets the face x = 0.15 at 0.09/0.24 of
    // the way, off the axis as it started
    particleShapes::platonicSolid cube("cube", "cube", 0.3);
    B.shape = &cube;
    B.R = quaternion(normalised(vector(1, 2, 3)), 0.7).R();
    const vector off(0, 0.05, -0.03);
    vector uWall, arm;
    const scalar t = wallLinks::crossing
    (
        B, images, X + (B.R & (vector(0.24, 0, 0) + off)), X + (B.R & off), uWall, arm
    );
    EXPECT_NEAR(t, 0.09/0.24, 1e-10);
    EXPECT_LT(mag(arm - (B.R & (vector(0.15, 0, 0) + off))), 1e-10);
    EXPECT_LT(mag(uWall - (V + (omega ^ arm))), 1e-12);

    // A fluid end on the surface keeps a sliver of the link: no division
    // by zero
    const scalar t0 = wallLinks::crossing
    (
        B, images, X + (B.R & (vector(0.15, 0, 0) + off)), X + (B.R & off), uWall, arm
    );
    EXPECT_GE(t0, 1e-6);
    EXPECT_LT(t0, 1e-5);
}


TEST(wallLinks, whatTheFluidGainsAtTheLinksIsTheMatrixsLinkTermsAndTheBodyPaysItAsDrag)
{
    // A fixed sphere and a fixed rotated cube in a sheared stream along x
    // on a 24^3 box: the gain that pay() returns for the bodies over a step
    // dt (Euler, no history) is minus dt times the sum over the cells of
    // what the links' matrix adds to their rows, to round-off
    const scalar dt = 0.01;
    particleShapes::sphere ball("ball", 0.35);
    particleShapes::platonicSolid cube("cube", "cube", 0.3);
    for (const bool isCube : {false, true})
    {
        SCOPED_TRACE(isCube ? "cube" : "sphere");
        const fixedBodyLinks b
        (
            isCube ? static_cast<const particleShape&>(cube) : ball,
            point(0.51, 0.48, 0.5),
            isCube ? quaternion(normalised(vector(1, 2, 3)), 0.7).R() : tensor::I,
            vector(0.2, 0.01, -0.03), 0.5, dt
        );
        ASSERT_GT(b.links->size(), 100);
        const vector fromMatrix = -dt*sum(rowResiduals(b.tm(), b.tU().primitiveField()));
        Info<< (isCube ? "cube" : "sphere") << ": " << b.links->size() << " links, the fluid gained "
            << b.momentum[0] << " (from the matrix " << fromMatrix << "), moment " << b.moment[0]
            << endl;
        EXPECT_LT(mag(b.momentum[0] - fromMatrix), 1e-12*mag(fromMatrix));
        // The fluid streaming along +x loses momentum to the body at rest:
        // the body, paying the fluid's gain, is pushed downstream
        EXPECT_LT(b.momentum[0].x(), 0);
        EXPECT_GT(mag(b.momentum[0].x()), 3*mag(b.momentum[0].y()));
    }

    // A sphere centred between the cells of a symmetric mesh in a uniform
    // stream: no torque at the links (the flow and the links are symmetric
    // about the stream's axis through it)
    const fixedBodyLinks b(ball, point(0.5, 0.5, 0.5), tensor::I, vector(0.2, 0, 0), 0, dt);
    EXPECT_LT(b.momentum[0].x(), 0);
    EXPECT_LT(mag(b.momentum[0].y()) + mag(b.momentum[0].z()), 1e-12*mag(b.momentum[0].x()));
    EXPECT_LT(mag(b.moment[0]), 1e-12*mag(b.momentum[0])*0.175);
}


// ************************************************************************* //

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
    The ghost-cell surface treatment of the fictitious-domain step
    (surfaceTreatment ghostCells): a shear flow along a face is carried
    through the wall where the face is (ghostShear mirrored), or given to
    the viscous fluxes of the faces between the ghost and the fluid cells
    only, the ghost cells moving rigidly (ghostShear viscous); with
    ghostFitOrder 2 a profile that bends, and a gap's profile that
    vanishes at the neighbour's face, are carried through the wall as
    parabolas; every cell within a cell of the surface has fluid to fit,
    whatever the resolution (no point is left out); no fluid cell is
    forced, in a two-cell gap between two cubes neither; with
    ghostCutCells, only those the surface cuts (centres less than half a
    cell out).

\*---------------------------------------------------------------------------*/

#include "foamTestCase.H"
#include "testInput.H"
#include "fictitiousDomain.H"
#include "particleGeometry.H"
#include "platonicSolid.H"
#include "sphere.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A point as text, for the failure messages
std::string str(const vector& v)
{
    return "(" + std::to_string(v.x()) + " " + std::to_string(v.y()) + " "
        + std::to_string(v.z()) + ")";
}


dictionary ghostCells()
{
    dictionary dict;
    dict.add("surfaceTreatment", word("ghostCells"));
    return dict;
}


//- Solve the bodies with ghostShear mirrored, whose ghost cells carry the
//- fitted profile in their velocities, and the fit order given
fictitiousDomain::result solveMirrored
(
    const fvMesh& mesh,
    volVectorField& U,
    const UList<fictitiousDomain::body>& bodies,
    const label fitOrder
)
{
    dictionary dict(ghostCells());
    dict.add("ghostShear", word("mirrored"));
    dict.add("ghostFitOrder", fitOrder);
    fictitiousDomain fd(mesh, dict);
    return fd.solve(U, bodies, 0.01)[0];
}


tmp<volVectorField> zeroU(const fvMesh& mesh)
{
    return tmp<volVectorField>
    (
        new volVectorField
        (
            IOobject("U", mesh.time().timeName(), mesh),
            mesh,
            dimensionedVector(dimVelocity, Zero),
            "calculated"
        )
    );
}

//- Two cubes of edge 0.3 face to face along x, two cells apart (their faces
//- 0.01 cell off the cell faces), in a unit box of 24^3 cells, and a
//- swirling flow there
struct twoCubesInAGap
{
    static constexpr scalar h = 1.0/24;
    static constexpr scalar edge = 0.3;
    test::foamTestCase tc;
    const fvMesh& mesh;
    tmp<volVectorField> tU;
    particleShapes::platonicSolid cube;
    List<fictitiousDomain::body> bodies;

    twoCubesInAGap()
    :
        mesh(tc.makeBoxMesh(24, 24, 24, vector::one)),
        tU(zeroU(mesh)),
        cube("cube", "cube", edge),
        bodies(2)
    {
        using constant::mathematical::twoPi;
        forAll(tU(), c)
        {
            const point& x = mesh.C()[c];
            tU.ref()[c] = vector
            (
                0.1*std::sin(twoPi*x.y()),
                0.05*std::cos(twoPi*x.z()) + 0.03,
                0.08*std::sin(twoPi*x.x())
            );
        }
        for (auto& b : bodies)
        {
            b.shape = &cube;
            b.excessDensity = 1;
        }
        bodies[0].centre = point(0.5 - h - edge/2 + 0.01*h, 0.5, 0.5);
        bodies[1].centre = point(0.5 + h + edge/2 + 0.01*h, 0.5, 0.5);
    }

    //- Is x in the gap between the faces (away from their edges)?
    static bool inGap(const point& x, const scalar margin)
    {
        return mag(x.x() - 0.5) < h && mag(x.y() - 0.5) < edge/2 - margin
            && mag(x.z() - 0.5) < edge/2 - margin;
    }
};

//- A fixed cube of edge 0.4 whose +x face sits at x = xf = 0.717, a third
//- of a cell from the cell faces at h = 1/24, and fluid in a shear
//- U_y = a (x - xf) everywhere
struct faceShear
{
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(24, 24, 24, vector::one);
    tmp<volVectorField> tU = zeroU(mesh);
    volVectorField& U = tU.ref();
    const scalar a = 0.7, edge = 0.4;
    const point X{0.517, 0.5, 0.5};
    const scalar xf = X.x() + edge/2;
    particleShapes::platonicSolid cube{"cube", "cube", edge};
    List<fictitiousDomain::body> bodies{1};

    faceShear()
    {
        forAll(U, c)
        {
            U[c] = vector(0, a*(mesh.C()[c].x() - xf), 0);
        }
        bodies[0].shape = &cube;
        bodies[0].centre = X;
        bodies[0].free = false;
        bodies[0].excessDensity = 1;
    }

    //- Is x under the middle of the face, within a cell of it or beyond?
    bool underFace(const point& x) const
    {
        const scalar h = 1.0/24;
        return x.x() > xf - h && mag(x.y() - X.y()) < edge/2 - 3*h
            && mag(x.z() - X.z()) < edge/2 - 3*h;
    }

    //- The body's cells of a result under the middle of the face
    labelList cellsUnderFace(const fictitiousDomain::result& r) const
    {
        DynamicList<label> under;
        for (const label g : r.interiorCells)
        {
            if (underFace(mesh.C()[g]))
            {
                under.append(g);
            }
        }
        return labelList(std::move(under));
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(ghostCells, linearShearAlongAFaceIsExtrapolatedThroughTheWall)
{
    // A fixed cube of edge 0.4 whose +x face sits at x = 0.717, a third of a
    // cell from the cell faces (h = 1/24); fluid in a shear U_y = a (x - xf)
    // on that side. The ghost cells under the middle of that face take the
    // same linear profile on the other side of the wall: U_y = a (x - xf) < 0
    faceShear s;
    const fictitiousDomain::result r = solveMirrored(s.mesh, s.U, s.bodies, 1);

    const labelList under(s.cellsUnderFace(r));
    for (const label g : under)
    {
        const point& x = s.mesh.C()[g];
        EXPECT_NEAR(s.U[g].y(), s.a*(x.x() - s.xf), 1e-12) << str(x);
        EXPECT_LT(s.U[g].y(), 0) << str(x);
    }
    EXPECT_GE(label(under.size()), 9);
    EXPECT_EQ(r.nSurfaceDropped, 0);
}


TEST(ghostCells, viscousShearMovesNoMassButGivesTheFluidTheWallShear)
{
    // The shear of the test above with ghostShear viscous:
    // the ghost cells under the face move rigidly (no velocity along the
    // shell, so no mass flux through the body), and the face between each
    // of them and its fluid neighbour carries the viscous flux of the
    // mirrored velocity a (x_g - xf): the fluid cell gains
    // nu a (x_g - xf)/h^2 per unit volume, the ghost cell loses as much,
    // and the sources sum to zero over the mesh
    faceShear s;
    const scalar nu = 0.1, h = 1.0/24;
    dictionary dict(ghostCells());
    dict.add("ghostShear", word("viscous"));
    fictitiousDomain fd(s.mesh, dict);
    ASSERT_TRUE(fd.hasWallShearSource());
    const fictitiousDomain::result r = fd.solve(s.U, s.bodies, 0.01)[0];
    const volScalarField nuField
    (
        IOobject("nu", s.mesh.time().timeName(), s.mesh),
        s.mesh,
        dimensionedScalar("nu", dimViscosity, nu)
    );
    const tmp<volVectorField> tsrc = fd.wallShearSource(nuField);
    const volVectorField& src = tsrc();

    const labelList under(s.cellsUnderFace(r));
    for (const label g : under)
    {
        const point& x = s.mesh.C()[g];
        EXPECT_NEAR(s.U[g].y(), 0, 1e-12) << str(x);
        const scalar expected = nu*s.a*(x.x() - s.xf)/sqr(h);
        EXPECT_LT(expected, 0);
        EXPECT_NEAR(src[g].y(), -expected, 1e-9*mag(expected)) << str(x);
        // Its fluid neighbour across the face
        const label c = s.mesh.findCell(x + vector(h, 0, 0));
        ASSERT_GE(c, 0);
        EXPECT_NEAR(src[c].y(), expected, 1e-9*mag(expected)) << str(x);
    }
    EXPECT_GE(label(under.size()), 9);
    EXPECT_LT(mag(gSum(s.mesh.V()*src.primitiveField())), 1e-14);
}


TEST(ghostCells, curvedProfileIsCarriedThroughTheWallWithTheQuadraticFit)
{
    // The face of the tests above with a profile that bends, U_y = a s +
    // c s^2 (s = x - xf), as in a gap between two walls or a boundary
    // layer thinner than the fit. With ghostFitOrder 2 the ghost cells
    // under the face take the parabola continued through the wall, a (-d)
    // + c d^2 (d = xf - x), to 2 % (the fit's regularisation); the linear
    // fit (ghostFitOrder 1) reads a wall slope 10 % or more too low
    faceShear s;
    const scalar c = -2;
    forAll(s.U, k)
    {
        const scalar sk = s.mesh.C()[k].x() - s.xf;
        s.U[k] = vector(0, s.a*sk + c*sqr(sk), 0);
    }
    const volVectorField U0(s.U);
    for (const label order : {2, 1})
    {
        volVectorField U(U0);
        const fictitiousDomain::result r =
            solveMirrored(s.mesh, U, s.bodies, order);
        const labelList under(s.cellsUnderFace(r));
        for (const label g : under)
        {
            const point& x = s.mesh.C()[g];
            const scalar d = s.xf - x.x();
            const scalar exact = -s.a*d + c*sqr(d);
            if (order == 2)
            {
                EXPECT_NEAR(U[g].y(), exact, 2e-2*mag(exact)) << str(x);
            }
            else
            {
                EXPECT_GT(U[g].y(), 0.9*exact) << str(x);
            }
        }
        EXPECT_GE(label(under.size()), 9);
    }
}


TEST(ghostCells, gapProfileVanishesAtBothWallsWithTheQuadraticFit)
{
    // Two fixed cubes two cells apart, a plane Poiseuille profile across
    // the gap, U_y = 4 U0 s (g - s)/g^2 (s from the first cube's face).
    // Below the gap the first cube's fit has one layer of fluid cells
    // beyond its cut cells; with ghostFitOrder 2 it also takes the second
    // cube's face as a datum, so its ghost cells carry the parabola through
    // the wall, 4 U0 (-d) (g + d)/g^2; the linear fit through the one
    // layer gives a quarter of the wall slope
    twoCubesInAGap gap;
    const scalar h = twoCubesInAGap::h, g = 2*h, U0 = 0.3;
    const scalar face = gap.bodies[0].centre.x() + twoCubesInAGap::edge/2;
    const auto profile = [&](const scalar x)
    {
        const scalar s = x - face;
        return 4*U0*s*(g - s)/sqr(g);
    };
    for (auto& b : gap.bodies)
    {
        b.free = false;
    }
    for (const label order : {2, 1})
    {
        volVectorField U(gap.tU());
        forAll(U, c)
        {
            const scalar x = gap.mesh.C()[c].x();
            U[c] = vector(0, x > face && x < face + g ? profile(x) : 0, 0);
        }
        const fictitiousDomain::result r =
            solveMirrored(gap.mesh, U, gap.bodies, order);
        label checked = 0;
        for (const label c : r.interiorCells)
        {
            const point& x = gap.mesh.C()[c];
            if
            (
                x.x() < face - h || mag(x.y() - 0.5) > 0.6*h
             || mag(x.z() - 0.5) > 0.6*h
            )
            {
                continue;
            }
            ++checked;
            const scalar exact = profile(x.x());
            if (order == 2)
            {
                EXPECT_NEAR(U[c].y(), exact, 2e-2*mag(exact)) << str(x);
            }
            else
            {
                EXPECT_GT(U[c].y(), 0.5*exact) << str(x);
            }
        }
        EXPECT_EQ(checked, 4);
    }
}


TEST(ghostCells, everySurfaceCellHasFluidToFitAtAnyResolution)
{
    // A sphere and a cube of the same volume, D = 0.5, at D/dx = 4, 6, 8
    // and 12, both rotated and off the grid: no ghost cell is without
    // fluid cells to fit, none is left out
    for (const label N : {8, 12, 16, 24})
    {
        test::foamTestCase tc;
        const fvMesh& mesh = tc.makeBoxMesh(N, N, N, vector::one);
        tmp<volVectorField> tU = zeroU(mesh);
        forAll(tU(), c)
        {
            tU.ref()[c] = vector(0.1, 0, 0);
        }
        const scalar D = 0.5;
        particleShapes::sphere ball("ball", D);
        particleShapes::platonicSolid cube
        (
            "cube", "cube", std::cbrt(constant::mathematical::pi/6)*D
        );
        for (const particleShape* shape : {static_cast<const particleShape*>(&ball), static_cast<const particleShape*>(&cube)})
        {
            List<fictitiousDomain::body> bodies(1);
            bodies[0].shape = shape;
            bodies[0].centre = point(0.503, 0.488, 0.511);
            bodies[0].R = quaternion(normalised(vector(1, 2, 3)), 0.7).R();
            bodies[0].excessDensity = 1;
            dictionary dict(ghostCells());
            fictitiousDomain fd(mesh, dict);
            const fictitiousDomain::result r = fd.solve(tU.ref(), bodies, 0.01)[0];
            Info<< shape->type() << " at D/dx " << D*N << ": "
                << r.nInterior << " interior, " << r.nSurface
                << " ghost cells, " << r.nSurfaceDropped << " without fluid"
                << endl;
            EXPECT_GT(r.nSurface, 0) << N;
            EXPECT_EQ(r.nSurfaceDropped, 0) << N << " " << shape->type();
        }
    }
}


TEST(ghostCells, withoutCutCellForcingNoFluidCellIsForcedNotEvenInATwoCellGap)
{
    // With ghostCutCells none no fluid cell is forced at all, those of a
    // two-cell gap between two cubes included; the cubes' own cells take
    // the whole force
    twoCubesInAGap g;
    volVectorField& U = g.tU.ref();
    const vectorField before(U.primitiveField());
    dictionary dict(ghostCells());
    dict.add("ghostCutCells", word("none"));
    fictitiousDomain fd(g.mesh, dict);
    const List<fictitiousDomain::result>& res = fd.solve(U, g.bodies, 0.01);
    label outside = 0, inGap = 0;
    forAll(U, c)
    {
        const point& x = g.mesh.C()[c];
        bool inside = false;
        for (const auto& b : g.bodies)
        {
            inside = inside || particleGeometry::contains(g.cube, b.centre, b.R, x);
        }
        if (inside)
        {
            continue;
        }
        ++outside;
        inGap += twoCubesInAGap::inGap(x, 0);
        EXPECT_EQ(mag(fd.source()[c]), 0) << str(x);
        EXPECT_EQ(mag(U[c] - before[c]), 0) << str(x);
    }
    EXPECT_GT(inGap, 20);
    EXPECT_GT(outside, 10000);
    for (const auto& r : res)
    {
        EXPECT_GT(mag(r.sumLambda), 0);
    }
}


TEST(ghostCells, withCutCellsOnlyCutFluidCellsAreForcedEvenInATwoCellGap)
{
    // ghostCutCells full, solidFractionBothSides and ramp: the
    // force density is zero in every cell more than half a cell out of both
    // cubes (the cells their surfaces do not cut), and the fluid there keeps
    // its velocity; in the gap, one row of cells lies 0.49 cells from a face
    // (cut, forced) and the other 0.51 (free)
    for (const word cut : {"full", "solidFractionBothSides", "ramp"})
    {
        SCOPED_TRACE(cut);
        twoCubesInAGap g;
        volVectorField& U = g.tU.ref();
        const vectorField before(U.primitiveField());
        const scalar h = twoCubesInAGap::h;
        dictionary dict(ghostCells());
        dict.add("ghostCutCells", cut);
        fictitiousDomain fd(g.mesh, dict);
        if (fd.needsFluidRelaxation())
        {
            fd.setFluidRelaxation(scalarField(g.mesh.nCells(), 0.5));
        }
        const List<fictitiousDomain::result>& res = fd.solve(U, g.bodies, 0.01);
        label free = 0, freeInGap = 0, cutInGap = 0;
        forAll(U, c)
        {
            const point& x = g.mesh.C()[c];
            scalar out = GREAT;
            for (const auto& b : g.bodies)
            {
                out = min
                (
                    out,
                    particleGeometry::outsideDistanceBound(g.cube, b.centre, b.R, x)
                );
            }
            const bool inGap = twoCubesInAGap::inGap(x, h);
            if (out < 0.5*h)
            {
                cutInGap += inGap && out > 0 && mag(fd.source()[c]) > 0;
                continue;
            }
            ++free;
            freeInGap += inGap;
            EXPECT_EQ(mag(fd.source()[c]), 0) << str(x);
            EXPECT_EQ(mag(U[c] - before[c]), 0) << str(x);
        }
        EXPECT_GT(freeInGap, 20);
        EXPECT_GT(cutInGap, 20);
        EXPECT_GT(free, 10000);
        for (const auto& r : res)
        {
            EXPECT_GT(mag(r.sumLambda), 0);
            EXPECT_EQ(r.nSurfaceDropped, 0);
        }
    }
}


TEST(ghostCells, cutCellsAreForcedInProportionToTheirPartInsideTheBody)
{
    // A fixed cube of edge 0.3 (h = 1/24) whose +x face lies 0.3 cell
    // beyond a row of cell centres (a body cell d = 0.3 h in) and whose -x
    // face 0.1 cell short of one (a fluid cell s = 0.1 h out). With
    // ghostCutCells solidFractionBothSides the force density in every cell
    // is that of ghostCutCells full times phi beta/(phi beta + 1 - phi), phi
    // the part of the cell inside the body, 1/2 + d/h_n between 0 and 1
    // (under the middle of those faces 0.8 and 0.4, in the cells deeper
    // than half a cell 1), beta the fluid's relaxation over the step
    test::foamTestCase tc;
    const scalar h = 1.0/24, edge = 0.3;
    const fvMesh& mesh = tc.makeBoxMesh(24, 24, 24, vector::one);
    tmp<volVectorField> tU = zeroU(mesh);
    using constant::mathematical::twoPi;
    forAll(tU(), c)
    {
        const point& x = mesh.C()[c];
        tU.ref()[c] = vector
        (
            0.1*std::sin(twoPi*x.y()), 0.05*std::cos(twoPi*x.z()) + 0.03,
            0.08*std::sin(twoPi*x.x())
        );
    }
    particleShapes::platonicSolid cube("cube", "cube", edge);
    List<fictitiousDomain::body> bodies(1);
    bodies[0].shape = &cube;
    bodies[0].excessDensity = 1;
    bodies[0].free = false;
    bodies[0].centre = point(0.5 + 0.2*h, 0.5, 0.5);

    // The fluid's relaxation over the step, beta = dt A_f, the same in
    // every cell: the cell is moved phi beta/(phi beta + 1 - phi) of its way
    const scalar beta = 0.7;
    const auto sourceWith = [&](const word& cut)
    {
        volVectorField U("U", tU());
        dictionary dict(ghostCells());
        dict.add("ghostCutCells", cut);
        fictitiousDomain fd(mesh, dict);
        if (fd.needsFluidRelaxation())
        {
            fd.setFluidRelaxation(scalarField(mesh.nCells(), beta));
        }
        fd.solve(U, bodies, 0.01);
        return vectorField(fd.source().primitiveField());
    };
    const vectorField full(sourceWith("full"));
    const vectorField share(sourceWith("solidFractionBothSides"));

    // The part inside, 1/2 + d/h_n (d < 0 outside, h_n the cell's width
    // along the normal at the nearest surface point), between 0 and 1
    label nIn = 0, nOut = 0, nForced = 0;
    forAll(full, c)
    {
        const point& x = mesh.C()[c];
        point p;
        vector n;
        const scalar d =
            particleGeometry::depth(cube, bodies[0].centre, bodies[0].R, x, p, n);
        const scalar hn = h*(mag(n.x()) + mag(n.y()) + mag(n.z()));
        const scalar expected = min(max(0.5 + d/hn, scalar(0)), scalar(1));
        const bool middle =
            mag(x.y() - 0.5) < 0.1 && mag(x.z() - 0.5) < 0.1;
        if (middle && mag(x.x() - (0.5 + 0.2*h + edge/2 - 0.3*h)) < 1e-9)
        {
            EXPECT_NEAR(expected, 0.8, 1e-9) << str(x);
            ++nIn;
        }
        if (middle && mag(x.x() - (0.5 + 0.2*h - edge/2 - 0.1*h)) < 1e-9)
        {
            EXPECT_NEAR(expected, 0.4, 1e-9) << str(x);
            ++nOut;
        }
        nForced += mag(full[c]) > 0;
        const scalar step =
            expected >= 1 ? 1 : expected*beta/(expected*beta + 1 - expected);
        EXPECT_LT(mag(share[c] - step*full[c]), 1e-9*(1 + mag(full[c])))
            << str(x) << " expected " << expected << " of " << str(full[c])
            << ", got " << str(share[c]);
    }
    EXPECT_GT(nIn, 10);
    EXPECT_GT(nOut, 10);
    EXPECT_GT(nForced, 500);
}


TEST(ghostCells, badSettingsAreRefusedNamingTheValidOnes)
{
    // A misspelt treatment lists the valid names; a fit narrower than one
    // and a half cells (it must reach a cell beyond the cut cells) is
    // refused with the keyword, the value and what is allowed
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(8, 8, 8, vector::one);
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    const std::string typo = testInput::errorOf([&]
    {
        fictitiousDomain fd(mesh, testInput::parse("surfaceTreatment ghostCell;"));
    });
    EXPECT_NE(typo.find("ghostCell"), std::string::npos) << typo;
    EXPECT_NE(typo.find("fluidStencil"), std::string::npos) << typo;
    EXPECT_NE(typo.find("ghostCells"), std::string::npos) << typo;
    const std::string narrow = testInput::errorOf([&]
    {
        fictitiousDomain fd
        (
            mesh,
            testInput::parse("surfaceTreatment ghostCells; ghostFitRadius 1;")
        );
    });
    EXPECT_NE(narrow.find("ghostFitRadius = 1"), std::string::npos) << narrow;
    EXPECT_NE(narrow.find(">= 1.5"), std::string::npos) << narrow;
    const std::string order = testInput::errorOf([&]
    {
        fictitiousDomain fd
        (
            mesh,
            testInput::parse("surfaceTreatment ghostCells; ghostFitOrder 3;")
        );
    });
    EXPECT_NE(order.find("ghostFitOrder = 3"), std::string::npos) << order;
    EXPECT_NE(order.find("1 (s a_t) or 2"), std::string::npos) << order;
    const std::string shear = testInput::errorOf([&]
    {
        fictitiousDomain fd
        (
            mesh,
            testInput::parse("surfaceTreatment ghostCells; ghostShear viscus;")
        );
    });
    for (const char* name : {"viscus", "mirrored", "rigid", "viscous"})
    {
        EXPECT_NE(shear.find(name), std::string::npos) << shear;
    }
    const std::string distance = testInput::errorOf([&]
    {
        fictitiousDomain fd
        (
            mesh,
            testInput::parse("surfaceTreatment ghostCells; ghostFitDistance surfce;")
        );
    });
    for (const char* name : {"surfce", "normal", "surface"})
    {
        EXPECT_NE(distance.find(name), std::string::npos) << distance;
    }
    // The cut cells' solid fraction needs the fluid step's relaxation of
    // the time step under way, and a negative one is refused
    fictitiousDomain fd
    (
        mesh,
        testInput::parse("surfaceTreatment ghostCells; ghostCutCells solidFraction;")
    );
    volVectorField U
    (
        IOobject("U", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );
    const std::string unset = testInput::errorOf([&]
    {
        fd.solve(U, List<fictitiousDomain::body>(), 0.01);
    });
    EXPECT_NE(unset.find("solidFraction needs the fluid step's momentum diagonal"),
        std::string::npos) << unset;
    scalarField beta(mesh.nCells(), 1);
    beta[3] = -0.5;
    const std::string negative = testInput::errorOf([&]
    {
        fd.setFluidRelaxation(beta);
    });
    EXPECT_NE(negative.find("negative in cell 3"), std::string::npos) << negative;
    EXPECT_NE(negative.find("-0.5"), std::string::npos) << negative;
}


// ************************************************************************* //

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
    (surfaceTreatment ghostCells): with the default ghostShear link the
    ghost cells move rigidly whatever the fluid's normal flow next to them;
    with ghostShear viscous a shear flow
    along a face is carried through the wall into the viscous fluxes of
    the faces between the ghost and the fluid cells, the ghost cells moving
    rigidly; every cell within a cell of the surface has fluid to fit,
    whatever the resolution (no point is left out); no fluid cell is
    forced, in a two-cell gap between two cubes neither; with a cut-cell
    forcing, only those the surface cuts (centres less than half a cell
    out), each for the share its forcing gives it.

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

TEST(ghostCells, viscousShearMovesNoMassButGivesTheFluidTheWallShear)
{
    // A fixed cube of edge 0.4 whose +x face sits at x = 0.717, a third of a
    // cell from the cell faces (h = 1/24); fluid in a shear U_y = a (x - xf)
    // on that side. With ghostShear viscous the ghost cells under the
    // middle of that face move rigidly (no velocity along the shell, so no
    // mass flux through the body), and the face between each of them and
    // its fluid neighbour carries the viscous flux of the linear profile
    // continued through the wall, a (x_g - xf) < 0: the fluid cell gains
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


TEST(ghostCells, withLinksTheGhostCellsMoveRigidlyWhateverTheFluidsNormalFlow)
{
    // The fluid next to the cube's +x face flows away from it, U_x = b (x -
    // xf)^2 (as beside a face where the flow separates), over the shear.
    // With the default (ghostShear link) every cell of the fixed cube, the
    // ghost cells under that face included, is brought to rest: no normal
    // deviation is fitted from the fluid's normal velocity (under the links
    // it fed back on it: stability.faceOnCubeAtRe100). With ghostShear
    // viscous the same ghost cells do take one, so this test would see it
    const scalar b = 30;
    for (const word shear : {"link", "viscous"})
    {
        faceShear s;
        forAll(s.U, c)
        {
            const scalar dx = s.mesh.C()[c].x() - s.xf;
            if (dx > 0)
            {
                s.U[c].x() = b*sqr(dx);
            }
        }
        dictionary dict(ghostCells());
        dict.add("ghostShear", shear);
        fictitiousDomain fd(s.mesh, dict);
        const fictitiousDomain::result r = fd.solve(s.U, s.bodies, 0.01)[0];
        const labelList under(s.cellsUnderFace(r));
        ASSERT_GE(label(under.size()), 9);
        if (shear == "link")
        {
            for (const label g : r.interiorCells)
            {
                EXPECT_LT(mag(s.U[g]), 1e-12) << str(s.mesh.C()[g]);
            }
            EXPECT_LT(gMax(mag(fd.deviation().primitiveField())), 1e-12);
        }
        else
        {
            scalar largestUnder = 0;
            for (const label g : under)
            {
                largestUnder = max(largestUnder, mag(s.U[g].x()));
            }
            EXPECT_GT(largestUnder, 1e-4) << "ghostShear viscous";
        }
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
            // The default fits nothing: the fits are ghostShear viscous's
            dictionary dict(ghostCells());
            dict.add("ghostShear", word("viscous"));
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
    // ghostCutCells solidFraction and ramp: the
    // force density is zero in every cell more than half a cell out of both
    // cubes (the cells their surfaces do not cut), and the fluid there keeps
    // its velocity; in the gap, one row of cells lies 0.49 cells from a face
    // (cut, forced) and the other 0.51 (free)
    for (const word cut : {"solidFraction", "ramp"})
    {
        SCOPED_TRACE(cut);
        twoCubesInAGap g;
        volVectorField& U = g.tU.ref();
        const vectorField before(U.primitiveField());
        const scalar h = twoCubesInAGap::h;
        dictionary dict(ghostCells());
        dict.add("ghostCutCells", cut);
        fictitiousDomain fd(g.mesh, dict);
        fd.setFluidRelaxation(scalarField(g.mesh.nCells(), 0.5));
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


TEST(ghostCells, cutCellsAreForcedInProportionToTheShareTheirForcingGivesThem)
{
    // A fixed cube of edge 0.3 (h = 1/24) whose -x face lies 0.1 cell short
    // of a row of cell centres (a fluid cell s = 0.1 h out) and whose +x
    // face 0.3 cell beyond one (a fluid cell s = 0.7 h out, not cut). Both
    // forcings move a cut cell towards the same fitted profile, by the
    // step share phi beta/(phi beta + 1 - phi) of its way (beta the fluid's
    // relaxation over the step), phi its part inside the body with
    // solidFraction, 1/2 - s/h_n (0.4 under the middle of the -x face), and
    // 1 - 2 s/h with ramp (0.8 there): the two force densities of every cut
    // cell differ by the ratio of their shares, and no other cell is forced
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

    const scalar beta = 0.7;
    const auto step = [&](const scalar phi)
    {
        return phi >= 1 ? 1 : phi*beta/(phi*beta + 1 - phi);
    };
    const auto sourceWith = [&](const word& cut)
    {
        volVectorField U("U", tU());
        dictionary dict(ghostCells());
        dict.add("ghostCutCells", cut);
        fictitiousDomain fd(mesh, dict);
        EXPECT_TRUE(fd.needsFluidRelaxation());
        fd.setFluidRelaxation(scalarField(mesh.nCells(), beta));
        fd.solve(U, bodies, 0.01);
        return vectorField(fd.source().primitiveField());
    };
    const vectorField solidFraction(sourceWith("solidFraction"));
    const vectorField ramp(sourceWith("ramp"));

    label nMiddle = 0, nCut = 0;
    forAll(ramp, c)
    {
        const point& x = mesh.C()[c];
        point p;
        vector n;
        const scalar s =
            -particleGeometry::depth(cube, bodies[0].centre, bodies[0].R, x, p, n);
        if (s <= 0)
        {
            continue;
        }
        if (s >= 0.5*h)
        {
            EXPECT_EQ(mag(ramp[c]), 0) << str(x);
            EXPECT_EQ(mag(solidFraction[c]), 0) << str(x);
            continue;
        }
        const scalar hn = h*(mag(n.x()) + mag(n.y()) + mag(n.z()));
        const scalar phiS = min(max(0.5 - s/hn, scalar(0)), scalar(1));
        // (ramp's half cell is fictitiousDomain's cut-cell limit, half a
        // cell less a rounding margin of 1e-6)
        const scalar phiR = 1 - s/(0.5*(1 - 1e-6)*h);
        if
        (
            mag(x.y() - 0.5) < 0.1 && mag(x.z() - 0.5) < 0.1
         && mag(x.x() - (0.5 + 0.2*h - edge/2 - 0.1*h)) < 1e-9
        )
        {
            EXPECT_NEAR(phiS, 0.4, 1e-9) << str(x);
            EXPECT_NEAR(phiR, 0.8, 1e-6) << str(x);
            ++nMiddle;
        }
        nCut += mag(ramp[c]) > 0;
        // (a cell whose solid fraction is zero, s >= h_n/2 near an edge,
        // is not forced by solidFraction at all)
        const vector expected = (step(phiS)/step(phiR))*ramp[c];
        EXPECT_LT(mag(solidFraction[c] - expected), 1e-9*(1 + mag(ramp[c])))
            << str(x) << " s/h " << s/h << ": expected " << str(expected)
            << ", got " << str(solidFraction[c]);
    }
    // (the cut cells are the -x face's 8 x 8: the other faces leave the
    // nearest centres 0.1 cell inside or 0.7 and 0.9 cell out)
    EXPECT_GT(nMiddle, 10);
    EXPECT_EQ(nCut, 64);
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
    const std::string shear = testInput::errorOf([&]
    {
        fictitiousDomain fd
        (
            mesh,
            testInput::parse("surfaceTreatment ghostCells; ghostShear viscus;")
        );
    });
    for (const char* name : {"viscus", "link", "viscous"})
    {
        EXPECT_NE(shear.find(name), std::string::npos) << shear;
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

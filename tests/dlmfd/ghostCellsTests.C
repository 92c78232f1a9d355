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
    forced, in a two-cell gap between two cubes neither; a retired option
    is refused naming what replaced it.

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
    ASSERT_TRUE(fd.treatment().mirrorsWallVelocity());
    const fictitiousDomain::result r = fd.solve(s.U, s.bodies, 0.01)[0];
    const volScalarField nuField
    (
        IOobject("nu", s.mesh.time().timeName(), s.mesh),
        s.mesh,
        dimensionedScalar("nu", dimViscosity, nu)
    );
    // The treatment's term of the fluid step: its source over the cell
    // volumes is the force density the mirrored shear gives each cell
    const tmp<fvVectorMatrix> tm =
        fd.treatment().fluidStepTerms(s.U, nuField, s.bodies, fd);
    const vectorField src(tm().source()/s.mesh.V().field());

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
    EXPECT_LT(mag(gSum(s.mesh.V().field()*src)), 1e-14);
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


TEST(ghostCells, noFluidCellIsForcedNotEvenInATwoCellGap)
{
    // No fluid cell is forced at all, those of a two-cell gap between two
    // cubes included; the cubes' own cells take the whole force
    twoCubesInAGap g;
    volVectorField& U = g.tU.ref();
    const vectorField before(U.primitiveField());
    fictitiousDomain fd(g.mesh, ghostCells());
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


TEST(ghostCells, badSettingsAreRefusedNamingTheValidOnes)
{
    // A misspelt treatment lists the valid name; a fit narrower than one
    // and a half cells (it must reach a cell beyond the cut cells) is
    // refused with the keyword, the value and what is allowed; a retired
    // keyword with what replaced it
    test::foamTestCase tc;
    const fvMesh& mesh = tc.makeBoxMesh(8, 8, 8, vector::one);
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    const std::string typo = testInput::errorOf([&]
    {
        fictitiousDomain fd(mesh, testInput::parse("surfaceTreatment ghostCell;"));
    });
    // (the run-time selection's own message: the valid names from its table)
    EXPECT_NE(typo.find("Unknown surfaceTreatment type ghostCell"), std::string::npos) << typo;
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
    // Each retired keyword (or value) is named with its value and what
    // replaced it, before anything is made
    const std::pair<const char*, const char*> retired[] =
    {
        {"surfaceTreatment fluidStencil;", "surfaceTreatment fluidStencil"},
        {"surfaceStencilRadius 1.2;", "surfaceStencilRadius 1.2"},
        {"tolerance 1e-8;", "no CG"},
        {"ghostCutCells solidFraction;", "ghostCutCells solidFraction"},
        {"ghostCutCells none;", "no fluid cell is forced"},
        {"fluidStepForce penalty;", "fluidStepForce penalty"},
        {"penaltyFactor 10;", "the last multipliers' force"}
    };
    for (const auto& r : retired)
    {
        const std::string message = testInput::errorOf([&]
        {
            fictitiousDomain fd(mesh, testInput::parse(r.first));
        });
        EXPECT_NE(message.find(r.second), std::string::npos) << r.first << ": " << message;
        EXPECT_NE(message.find("is no longer read"), std::string::npos) << r.first << ": " << message;
    }
    // ghostFitRadius is read with ghostShear viscous only
    const std::string unread = testInput::errorOf([&]
    {
        fictitiousDomain fd(mesh, testInput::parse("ghostFitRadius 2;"));
    });
    EXPECT_NE(unread.find("ghostFitRadius is read with ghostShear viscous only"),
        std::string::npos) << unread;
}


// ************************************************************************* //

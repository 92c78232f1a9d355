/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.
\*---------------------------------------------------------------------------*/

#include "fluidAgitation.H"
#include "suspensionInput.H"
#include "periodicImages.H"
#include "particleGeometry.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidAgitation::fluidAgitation
(
    const suspensionScales& sc,
    Time& runTime,
    const fvMesh& mesh,
    granularSystem& granular,
    const instantList& times,
    const scalar tStart,
    const scalar cvEdge,
    const fileName& outDir
)
:
    sumVertical_(0),
    sumHorizontal_(0),
    sumSolidFraction_(0),
    nTimes_(0)
{
    suspensionInput::csvFile fs
    (
        outDir/"fluidStatistics.csv",
        "t_tg,varU_vertical_ug2,varU_horizontal_ug2,phi_local"
    );
    const cellCentreSearch search(mesh);
    const scalar half = 0.5*cvEdge*sc.D;
    const scalar ug2 = sqr(sc.ug);
    for (const instant& t : times)
    {
        runTime.setTime(t, 0);
        const fileName pFile(runTime.timePath()/"uniform"/"particles");
        IOobject Uheader
        (
            "U", runTime.timeName(), mesh, IOobject::MUST_READ
        );
        if (!isFile(pFile) || !Uheader.typeHeaderOk<volVectorField>(true))
        {
            continue;
        }
        granular.readParticles(pFile);
        const volVectorField U(Uheader, mesh);
        const vectorField& C = mesh.C();
        const scalarField& V = mesh.V();

        // The periodic shifts of a ball of radius r about x
        const auto shifts = [&](const point& x, const scalar r)
        {
            return periodicImages::shifts
            (
                mesh.bounds(), sc.period, x, r
            );
        };

        // Cells inside a particle
        boolList solid(mesh.nCells(), false);
        DynamicList<label> near;
        for (label i = 0; i < granular.size(); ++i)
        {
            const rigidParticle& p = granular.particle(i);
            const scalar rb = p.shape().boundingRadius();
            for (const vector& s : shifts(p.position(), rb))
            {
                near.clear();
                search.cellsInBall(p.position() - s, rb, near);
                for (const label c : near)
                {
                    if
                    (
                        particleGeometry::contains
                        (
                            p.shape(), p.position(), p.R(), C[c] + s
                        )
                    )
                    {
                        solid[c] = true;
                    }
                }
            }
        }

        // The cubes
        scalar w = 0, phiLoc = 0;
        vector su(Zero), su2(Zero);
        for (label i = 0; i < granular.size(); ++i)
        {
            const point& x = granular.particle(i).position();
            scalar cubeV = 0, solidV = 0;
            for (const vector& s : shifts(x, std::sqrt(3.0)*half))
            {
                near.clear();
                search.cellsInBall(x - s, std::sqrt(3.0)*half, near);
                for (const label c : near)
                {
                    const vector d = C[c] + s - x;
                    if (cmptMax(cmptMag(d)) > half)
                    {
                        continue;
                    }
                    cubeV += V[c];
                    if (solid[c])
                    {
                        solidV += V[c];
                        continue;
                    }
                    w += V[c];
                    su += V[c]*U[c];
                    su2 += V[c]*cmptMultiply(U[c], U[c]);
                }
            }
            phiLoc += solidV/max(cubeV, VSMALL);
        }
        phiLoc /= granular.size();
        const vector mean = su/max(w, VSMALL);
        const vector var = su2/max(w, VSMALL) - cmptMultiply(mean, mean);
        const scalar vz = var[sc.vert];
        const scalar vh = 0.5*(var[sc.hx] + var[sc.hy]);
        fs() << runTime.value()/sc.tg << ',' << vz/ug2 << ','
            << vh/ug2 << ',' << phiLoc << nl;
        Info<< "Time " << runTime.timeName() << ": fluid variance "
            << vz/ug2 << " (vertical), " << vh/ug2
            << " (horizontal) u_g^2, local solid fraction " << phiLoc
            << nl;
        if (runTime.value() >= tStart)
        {
            ++nTimes_;
            sumVertical_ += vz;
            sumHorizontal_ += vh;
            sumSolidFraction_ += phiLoc;
        }
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Application
    granularFoam

Group
    grpDlmfdSolvers

Description
    Dry granular flow: the discrete element solver of libdlmfdGranular
    (soft-sphere contacts of spheres and convex polyhedra, walls, periodic
    directions) with no fluid at all. Needs no mesh: only system/controlDict
    and the dictionaries below.

    Each time step of controlDict (deltaT) is sub-cycled in steps no longer
    than T_c/N. At every write time the particle state goes to
    <time>/particles (enough to restart exactly), VTK polydata of the
    particle shapes to VTK/ with .series files for ParaView, and a line per
    time step to postProcessing/granular/<startTime>/granular.dat.

Usage
    \b granularFoam [OPTIONS]

    Reads:
    - constant/particleProperties (shapes, materials)
    - constant/collisionProperties (law, pairs, walls, domain; and
      wallPatches { patches (floor sides); material steel; } to take plane
      walls from the planar patches of constant/polyMesh)
    - constant/g (optional; no gravity without it)
    - <startTime>/particles

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "uniformDimensionedFields.H"
#include "OFstream.H"
#include "clockTime.H"
#include "granularSystem.H"
#include "granularVTKWriter.H"
#include "polyMesh.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Dry granular flow: soft-sphere DEM of spheres and convex polyhedra"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    const IOdictionary particleProperties
    (
        IOobject
        (
            "particleProperties",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    const IOdictionary collisionProperties
    (
        IOobject
        (
            "collisionProperties",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    granularSystem granular(particleProperties, collisionProperties);

    // Walls from the planar patches of a mesh, where asked for
    if (granular.wantsWallPatches())
    {
        Info<< "Reading the mesh for its wall patches" << nl;
        const polyMesh mesh
        (
            IOobject
            (
                polyMesh::defaultRegion,
                runTime.timeName(),
                runTime,
                IOobject::MUST_READ
            )
        );
        granular.addWallPatches(mesh);
    }

    IOobject gHeader
    (
        "g",
        runTime.constant(),
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (gHeader.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        const uniformDimensionedVectorField g(gHeader);
        granular.setGravity(g.value());
    }
    Info<< "Gravity " << granular.gravity() << " m/s^2" << nl;

    const fileName particleFile(runTime.timePath()/"particles");
    if (!isFile(particleFile))
    {
        FatalErrorInFunction
            << "no particle file " << particleFile << nl
            << "    Place particles with placeParticles, or copy them from"
            << " 0.orig" << exit(FatalError);
    }
    granular.readParticles(particleFile);

    Info<< "Particles: " << granular.size() << " from " << particleFile
        << nl << "Shapes:";
    for (const particleShape& s : granular.shapes())
    {
        Info<< ' ' << s.name() << " (" << s.type() << ", D = "
            << s.equivalentDiameter() << " m)";
    }
    Info<< nl << "Walls: " << granular.walls().size() << nl;
    for (const planeWall& w : granular.walls())
    {
        Info<< "    wall " << w.name << ": point " << w.origin << " normal "
            << w.normal << " material " << w.material << nl;
    }
    Info<< "Periodic " << granular.periodic() << nl
        << "Granular sub-step T_c/N = " << granular.maxSubStep() << " s,"
        << " skin " << granular.skin() << " m" << nl << endl;

    granularVTKWriter vtk
    (
        runTime.path()/"VTK", runTime.value()
    );
    label outputIndex = runTime.timeIndex();
    if (runTime.timeIndex() == 0 || !isDir(runTime.path()/"VTK"))
    {
        vtk.write(granular, runTime.value(), outputIndex);
    }

    const fileName datDir
    (
        runTime.path()/"postProcessing"/"granular"/runTime.timeName()
    );
    mkDir(datDir);
    OFstream dat(datDir/"granular.dat");
    dat << "# time kineticEnergy[J] nSubSteps contacts wallContacts"
        << " maxOverlapRatio listBuilds cpuTime[s]" << nl;

    clockTime clock;
    scalar granularSeconds = 0, outputSeconds = 0;
    label nSubTotal = 0;

    while (runTime.run())
    {
        ++runTime;

        clock.timeIncrement();
        const label nSub = granular.evolve(runTime.deltaTValue());
        granularSeconds += clock.timeIncrement();
        nSubTotal += nSub;

        const granularSystem::statistics& s = granular.stats();
        dat << runTime.value() << ' ' << s.kineticEnergy << ' '
            << nSub << ' ' << s.nContacts << ' ' << s.nWallContacts << ' '
            << s.maxOverlapRatio << ' ' << s.nListBuilds << ' '
            << runTime.elapsedCpuTime() << nl;

        if (runTime.writeTime())
        {
            clock.timeIncrement();
            runTime.write();
            granular.writeParticles(runTime.timePath());
            vtk.write(granular, runTime.value(), runTime.timeIndex());
            outputSeconds += clock.timeIncrement();

            Info<< "Time = " << runTime.timeName()
                << "  sub-steps " << nSub
                << "  contacts " << s.nContacts << " + " << s.nWallContacts
                << " walls  max overlap " << s.maxOverlapRatio << " D"
                << "  kinetic energy " << s.kineticEnergy << " J"
                << "  ExecutionTime = " << runTime.elapsedCpuTime() << " s"
                << endl;
        }
    }

    const scalar total = granularSeconds + outputSeconds;
    Info<< nl << "Cost: granular " << granularSeconds << " s ("
        << 100*granularSeconds/max(total, SMALL) << " %), output "
        << outputSeconds << " s (" << 100*outputSeconds/max(total, SMALL)
        << " %); " << nSubTotal << " sub-steps, "
        << scalar(nSubTotal)*granular.size()/max(granularSeconds, SMALL)
        << " particle-steps/s" << nl << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //

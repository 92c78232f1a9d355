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

#include "granularRun.H"
#include "granularVTKWriter.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "Time.H"
#include "clockTime.H"
#include "polyMesh.H"
#include "progressLog.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::granularRun::granularRun(Time& runTime, const sceneEffects& effects)
:
    runTime_(runTime),
    granular_(),
    granularSeconds_(0),
    outputSeconds_(0),
    nSubSteps_(0)
{
    const auto constantDict = [&](const word& name)
    {
        return IOdictionary
        (
            IOobject
            (
                name,
                runTime.constant(),
                runTime,
                IOobject::MUST_READ,
                IOobject::NO_WRITE
            )
        );
    };
    granular_.reset
    (
        new granularSystem
        (
            constantDict("particleProperties"),
            constantDict("collisionProperties"),
            effects
        )
    );
    granularSystem& granular = *granular_;

    // Walls from the planar patches of a mesh, where asked for: the mesh
    // is read for its geometry only
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

    granular.readGravity(runTime);
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
        << " skin " << granular.skin() << " m" << nl;
    granular.effects().report(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::granularRun::run()
{
    granularSystem& granular = *granular_;

    granularVTKWriter vtk(runTime_.path()/"VTK", runTime_.value());
    if (runTime_.timeIndex() == 0 || !isDir(runTime_.path()/"VTK"))
    {
        vtk.write(granular, runTime_.value(), runTime_.timeIndex());
    }

    const fileName datDir
    (
        runTime_.path()/"postProcessing"/"granular"/runTime_.timeName()
    );
    mkDir(datDir);
    OFstream dat(datDir/"granular.dat");
    dat << "# time kineticEnergy[J] nSubSteps contacts wallContacts"
        << " maxOverlapRatio listBuilds cpuTime[s]" << nl;

    clockTime clock;
    progressLog progress(runTime_);
    while (runTime_.run())
    {
        ++runTime_;

        clock.timeIncrement();
        const label nSub = granular.evolve(runTime_.deltaTValue());
        granularSeconds_ += clock.timeIncrement();
        granular.checkHealth(runTime_.value());
        nSubSteps_ += nSub;

        const granularSystem::statistics& s = granular.stats();
        dat << runTime_.value() << ' ' << s.kineticEnergy << ' '
            << nSub << ' ' << s.nContacts << ' ' << s.nWallContacts << ' '
            << s.maxOverlapRatio << ' ' << s.nListBuilds << ' '
            << runTime_.elapsedCpuTime() << nl;

        if (runTime_.writeTime())
        {
            clock.timeIncrement();
            runTime_.write();
            granular.writeParticles(runTime_.timePath());
            vtk.write(granular, runTime_.value(), runTime_.timeIndex());
            outputSeconds_ += clock.timeIncrement();

            Info<< "Time = " << runTime_.timeName()
                << "  sub-steps " << nSub
                << "  contacts " << s.nContacts << " + " << s.nWallContacts
                << " walls  max overlap " << s.maxOverlapRatio << " D"
                << "  kinetic energy " << s.kineticEnergy << " J"
                << "  ExecutionTime = " << runTime_.elapsedCpuTime() << " s"
                << endl;
        }
        progress.step();
    }
}


// ************************************************************************* //

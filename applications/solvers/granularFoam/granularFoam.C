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

    In parallel (mpirun -np P granularFoam -parallel), with
    particleDistribution owned in constant/collisionProperties and a
    system/decomposeParDict of P subdomains, method simple and its
    simpleCoeffs n: each rank moves the particles of its box of the
    collision domain (Foam::ownedGranularSteps), with the same bits as one
    process; nothing is decomposed beforehand, and the particle file and
    VTK files are written by the master.

Usage
    \b granularFoam [OPTIONS]

    Reads:
    - constant/sceneProperties (optional: the effects the scene declares,
      Foam::sceneEffects; fluid must be off)
    - constant/particleProperties (shapes, materials)
    - constant/collisionProperties (law, pairs, walls, domain; and
      wallPatches { patches (floor sides); material steel; } to take plane
      walls from the planar patches of constant/polyMesh)
    - constant/g (optional; no gravity without it)
    - <startTime>/particles

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "granularRun.H"
#include "costLine.H"
#include "restartableTime.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Dry granular flow: soft-sphere DEM of spheres and convex polyhedra"
    );

    // A parallel run (particleDistribution owned) reads and writes the
    // case itself, and per-rank folders only for the restart's clock:
    // nothing to decompose beforehand
    argList::noCheckProcessorDirectories();

    #include "setRootCase.H"
    Info<< "Create time\n" << endl;
    // As createTime.H, restoring a restart's exact time state and
    // writing before a stop on SIGINT/SIGTERM
    restartableTime runTime(Time::controlDictName, args);

    sceneEffects effects(sceneEffects::read(runTime));
    if (effects.settle("fluid", false, "granularFoam"))
    {
        effects.contradiction
        (
            "fluid", "granularFoam has no fluid; run dlmfdFoam"
        );
    }

    granularRun scene(runTime, effects);
    scene.run();

    const scalar g = scene.granularSeconds(), o = scene.outputSeconds();
    Info<< nl << costLine::text
    (
        wordList({"granular", "output"}), scalarList({g, o})
    ).c_str() << "; " << scene.nSubSteps() << " sub-steps, "
        << scalar(scene.nSubSteps())*scene.nParticles()/max(g, SMALL)
        << " particle-steps/s" << nl << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Class
Application
    dlmfdFoam

Group
    grpIncompressibleSolvers

Description
    Transient solver for the incompressible, laminar flow of Newtonian and
    generalised-Newtonian fluids (singlePhaseTransportModel) with the
    PISO/PIMPLE algorithm of pimpleControl, driven or held by a run-time
    selectable mean pressure gradient (meanFlowControl).

    This is the fluid half of the DLM/FD method: the particle coupling of
    Glowinski et al. (1999) and Wachs (2009) is wired in here by later
    libraries; the fluid step stays the one below.

    Momentum, in kinematic form (p is pressure over density):

    \f[
        \ddt{U} + \div(\phi U)
      - \div\left(\nu (\grad U + \grad U^T)\right)
      = - \grad p + G + S_{fvOptions}
    \f]

Usage
    \b dlmfdFoam [OPTION]

    Reads:
    \table
        File                           | Contents
        constant/transportProperties   | transportModel and its coefficients
        constant/flowControlProperties | meanFlowControl model, see Foam::meanFlowControl
        system/fvSolution PIMPLE       | nOuterCorrectors (the particles' constraint after each), nCorrectors, ...
        constant/fvOptions (optional)  | extra sources and constraints
        constant/sceneProperties (optional) | effects, Foam::sceneEffects
        constant/dynamicMeshDict (optional) | a refining mesh (dynamicRefineFvMesh), see below
    \endtable

    The mesh is a dynamicFvMesh: without constant/dynamicMeshDict (or with
    dynamicFvMesh staticFvMesh) it never changes and every result is the
    static mesh's. A refining mesh changes once per time step, before the
    fluid step: the fluxes are made from the mapped face velocities Uf and
    made conservative again (CorrectPhi, fvSolution's pcorr solver; PIMPLE
    correctPhi, on by default), the pressure's reference cell is chosen
    again, and the particles' cell data made again
    (Foam::dlmfdCoupling::updateMesh). Refused: 2D meshes, any mesh other
    than staticFvMesh, dynamicRefineFvMesh or one derived from it (points
    that move, other topology changers).

    With "fluid off" in constant/sceneProperties the case is a dry granular
    scene: no fluid field, transport model or coupling is made, the
    granular system runs alone (Foam::granularRun, as granularFoam).

    Writes the fields U, p, phi at every write time, \<time\>/uniform/gradP,
    and postProcessing/meanFlowControl/\<startTime\>/meanFlowControl.dat.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "dynamicRefineFvMesh.H"
#include "CorrectPhi.H"
#include "particleRefinementTargets.H"
#include "singlePhaseTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "meanFlowControl.H"
#include "dlmfdCoupling.H"
#include "granularRun.H"
#include "restartableTime.H"
#include "progressLog.H"
#include "uniformDimensionedFields.H"
#include "clockTime.H"
#include "knownKeywords.H"
#include "costLine.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient solver for incompressible, laminar flow of Newtonian and"
        " generalised-Newtonian fluids with a run-time selectable mean"
        " pressure gradient (the fluid step of the DLM/FD method)."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    Info<< "Create time\n" << endl;
    // As createTime.H, restoring a restart's exact time state and
    // writing before a stop on SIGINT/SIGTERM
    restartableTime runTime(Time::controlDictName, args);

    // The effects the scene declares (constant/sceneProperties): a dry
    // scene (fluid off) makes no fluid field at all
    sceneEffects effects(sceneEffects::read(runTime));
    if (!effects.settle("fluid", true, "dlmfdFoam"))
    {
        #include "runDryScene.H"
        return 0;
    }

    #include "createDynamicFvMesh.H"
    #include "createDyMControls.H"
    #include "checkChangingMesh.H"
    #include "createFields.H"
    #include "createUfIfPresent.H"
    #include "createFvOptions.H"
    #include "initContinuityErrs.H"
    #include "CourantNo.H"
    #include "setInitialDeltaT.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;

    // Wall-clock seconds per phase, for the cost line at the end
    clockTime clock;
    scalar fluidSeconds = 0, outputSeconds = 0, meshSeconds = 0;
    progressLog progress(runTime);

    while (runTime.run())
    {
        #include "readDyMControls.H"
        #include "CourantNo.H"
        #include "setDeltaT.H"

        ++runTime;
        if (particles.valid())
        {
            particles->checkPressureCorrectors
            (
                laminarTransport.nu(), pimple.nCorrPISO()
            );
        }

        Info<< "Time = " << runTime.timeName() << nl << endl;

        clock.timeIncrement();

        // --- Pressure-velocity PIMPLE corrector loop
        while (pimple.loop())
        {
            // A refining mesh changes once per time step, before the
            // fluid step (constant/dynamicMeshDict; none: no change)
            if (pimple.firstIter())
            {
                fluidSeconds += clock.timeIncrement();
                #include "updateMesh.H"
                meshSeconds += clock.timeIncrement();
            }

            #include "UEqn.H"

            // --- Pressure corrector loop
            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            laminarTransport.correct();

            // With more than one outer corrector the constraint is imposed
            // after each but the last too: the next fluid step carries its
            // force (the last is imposed by evolve below)
            if (particles.valid() && !pimple.finalIter())
            {
                fluidSeconds += clock.timeIncrement();
                particles->correct(U);
                clock.timeIncrement();
            }
        }

        fluidSeconds += clock.timeIncrement();

        // Granular predictor, fictitious domain, granular corrector
        if (particles.valid())
        {
            particles->evolve(U);
            clock.timeIncrement();
        }

        meanFlow->log(U);

        runTime.write();
        if (particles.valid())
        {
            particles->write();
        }
        outputSeconds += clock.timeIncrement();

        runTime.printExecutionTime(Info);
        progress.step();
    }

    // The cost by phase, on the master: the fluid's own communication is
    // inside the fluid solves; that of the particles (cells and forces
    // exchanged, state broadcast, with the waiting it includes) apart
    const scalar fdSeconds =
        particles.valid() ? particles->fictitiousDomainSeconds() : 0;
    const scalar granularSeconds =
        particles.valid() ? particles->granularSeconds() : 0;
    const scalar commSeconds =
        particles.valid() ? particles->communicationSeconds() : 0;
    // The particles' time series (particles.dat) is output too
    const scalar seriesSeconds =
        particles.valid() ? particles->seriesSeconds() : 0;
    // (a changing mesh: the refinement's update, with the fluxes' correction
    // and the particles' cell data made again, as a phase of its own)
    wordList phases({"fluid", "DLM/FD", "granular", "communication", "output"});
    scalarList seconds
    ({
        fluidSeconds, fdSeconds, granularSeconds, commSeconds,
        outputSeconds + seriesSeconds
    });
    if (mesh.dynamic())
    {
        phases.append("mesh");
        seconds.append(meshSeconds);
    }
    // (owned mode: the load imbalance of the granular step after it)
    const string note = particles.valid() ? particles->costLineNote() : "";
    Info<< costLine::text(phases, seconds).c_str() << note.c_str() << nl
        << endl;
    if (particles.valid())
    {
        particles->reportExchange();
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //

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
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::autoPtr<Foam::granularSystem> Foam::granularRun::readScene
(
    const sceneEffects& effects,
    const bool log,
    const bool withParticles
) const
{
    // (IOdictionary: read from the case itself in a parallel run too)
    const auto constantDict = [&](const word& name)
    {
        return IOdictionary
        (
            IOobject
            (
                name,
                runTime_.constant(),
                runTime_,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
    };
    auto scene = autoPtr<granularSystem>::New
    (
        constantDict("particleProperties"),
        constantDict("collisionProperties"),
        effects
    );
    granularSystem& granular = *scene;

    // Walls from the planar patches of a mesh, where asked for: the mesh
    // is read for its geometry only (in parallel each rank's part of the
    // decomposed mesh; planeWall::fromPatches sums each patch over them)
    if (granular.wantsWallPatches())
    {
        const fileName meshDir
        (
            runTime_.path()/runTime_.constant()/polyMesh::meshSubDir
        );
        if (!isDir(meshDir))
        {
            FatalErrorInFunction
                << "constant/collisionProperties: wallPatches takes the"
                << " walls from the mesh, but there is none at " << meshDir
                << ": run blockMesh"
                << (Pstream::parRun() ? ", then decomposePar," : "")
                << " or give the walls in walls { }" << exit(FatalError);
        }
        if (log)
        {
            Info<< "Reading the mesh for its wall patches" << nl;
        }
        const polyMesh mesh
        (
            IOobject
            (
                polyMesh::defaultRegion,
                runTime_.timeName(),
                runTime_,
                IOobject::MUST_READ
            )
        );
        granular.addWallPatches(mesh);
    }

    granular.readGravity(runTime_);
    if (withParticles)
    {
        readParticleFile(granular);
    }
    return scene;
}


void Foam::granularRun::readParticleFile(granularSystem& into) const
{
    const fileName particleFile
    (
        runTime_.globalPath()/runTime_.timeName()/"particles"
    );
    if (!isFile(particleFile))
    {
        FatalErrorInFunction
            << "no particle file " << particleFile << nl
            << "    Place particles with placeParticles, or copy them from"
            << " 0.orig" << exit(FatalError);
    }
    into.readParticles(particleFile);
}


void Foam::granularRun::setOwned(const sceneEffects& effects)
{
    labelVector n(1, 1, 1);
    if (Pstream::parRun())
    {
        const IOdictionary decomposeDict
        (
            IOobject
            (
                "decomposeParDict",
                runTime_.system(),
                runTime_,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        const label nDomains = decomposeDict.get<label>("numberOfSubdomains");
        if (nDomains != Pstream::nProcs())
        {
            FatalIOErrorInFunction(decomposeDict)
                << "numberOfSubdomains " << nDomains << " for a run on "
                << Pstream::nProcs() << " ranks; they must be equal"
                << exit(FatalIOError);
        }
        const word method = decomposeDict.get<word>("method");
        if (method != "simple")
        {
            FatalIOErrorInFunction(decomposeDict)
                << "particleDistribution owned: method " << method
                << " is not allowed for granularFoam; valid: simple (the"
                << " boxes simpleCoeffs n over the collision domain)"
                << exit(FatalIOError);
        }
        n = decomposeDict.subDict("simpleCoeffs").get<labelVector>("n");
        if (cmptProduct(n) != Pstream::nProcs() || cmptMin(n) < 1)
        {
            FatalIOErrorInFunction(decomposeDict)
                << "particleDistribution owned: simpleCoeffs n " << n
                << " makes " << cmptProduct(n) << " boxes for "
                << Pstream::nProcs() << " ranks; each count >= 1 and"
                << " their product the number of ranks" << exit(FatalIOError);
        }
    }
    const granularSystem& granular = *granular_;
    boxes_.reset
    (
        new boxDecomposition(granular.domain(), granular.periodic(), n)
    );
    // The master hands each rank its own particles: no other rank reads
    // the whole scene
    UPtrList<granularSystem> part(1);
    part.set(0, granular_.get());
    ownedGranularSteps::scatterScene
    (
        exchange_, *boxes_, Pstream::master() ? whole_.get() : nullptr,
        List<labelList>(Pstream::master() ? whole_->size() : 0), part
    );
    if (!Pstream::master())
    {
        whole_.clear();
    }
    owned_.reset(new ownedGranularSteps(std::move(part), *boxes_, exchange_));
    Info<< "Particle distribution: owned, " << n.x() << " x " << n.y()
        << " x " << n.z() << " boxes of the domain; each rank moves the"
        << " particles in its box" << nl;
}


const Foam::granularSystem* Foam::granularRun::sceneToWrite()
{
    if (!owned_)
    {
        return granular_.get();
    }
    owned_->gatherScene(whole_.get());
    return whole_.get();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::granularRun::granularRun(Time& runTime, const sceneEffects& effects)
:
    runTime_(runTime),
    granular_(),
    boxes_(),
    exchange_(),
    owned_(),
    whole_(),
    granularSeconds_(0),
    outputSeconds_(0),
    nSubSteps_(0),
    nParticles_(0),
    ownedTotals_(),
    nOwnedSteps_(0)
{
    // With owned particles the master alone reads the particles, into
    // whole_ (the dictionaries are read on every rank: a collective read)
    granular_ = readScene(effects, true, false);
    if (granular_->ownedDistribution())
    {
        whole_ = readScene(effects, false, Pstream::master());
    }
    else
    {
        readParticleFile(*granular_);
    }
    const granularSystem& granular = whole_.valid() ? *whole_ : *granular_;
    nParticles_ = returnReduce(granular.size(), maxOp<label>());
    Info<< "Gravity " << granular.gravity() << " m/s^2" << nl;
    Info<< "Particles: " << nParticles_ << " from "
        << runTime_.globalPath()/runTime_.timeName()/"particles" << nl
        << "Shapes:";
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
    if (granular.ownedDistribution())
    {
        setOwned(effects);
    }
    else if (Pstream::parRun())
    {
        FatalErrorInFunction
            << "granularFoam runs in parallel with particleDistribution"
            << " owned (constant/collisionProperties) only; with master the"
            << " master would move every particle while the other ranks"
            << " wait" << exit(FatalError);
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::granularRun::run()
{
    granularSystem& granular = *granular_;

    // The VTK files: the master's whole scene, or with owned particles on
    // several ranks each rank's piece and the master's index of them
    granularVTKWriter vtk(runTime_.globalPath()/"VTK", runTime_.value());
    const bool pieces = owned_.valid() && Pstream::parRun();
    const auto writeVTK = [&](const granularSystem* scene)
    {
        // (the step just taken, for the contacts' mean force: none
        // before the first)
        const granularVTKWriter::loads given
        {
            runTime_.timeIndex() > 0 ? runTime_.deltaTValue() : 0,
            nullptr, nullptr
        };
        if (pieces)
        {
            vtk.writePieces
            (
                granular, runTime_.value(), runTime_.timeIndex(), given
            );
        }
        else if (scene)
        {
            vtk.write(*scene, runTime_.value(), runTime_.timeIndex(), given);
        }
    };
    if (runTime_.timeIndex() == 0 || !isDir(runTime_.globalPath()/"VTK"))
    {
        writeVTK(pieces ? nullptr : sceneToWrite());
    }

    autoPtr<OFstream> dat;
    if (Pstream::master())
    {
        const fileName datDir
        (
            runTime_.globalPath()/"postProcessing"/"granular"
           /runTime_.timeName()
        );
        mkDir(datDir);
        dat.reset(new OFstream(datDir/"granular.dat"));
        dat() << "# time kineticEnergy[J] nSubSteps contacts wallContacts"
            << " maxOverlapRatio listBuilds cpuTime[s]" << nl;
    }

    clockTime clock;
    progressLog progress(runTime_);
    while (runTime_.run())
    {
        ++runTime_;

        clock.timeIncrement();
        const label nSub =
            owned_
          ? owned_->evolve(runTime_.deltaTValue())
          : granular.evolve(runTime_.deltaTValue());
        granularSeconds_ += clock.timeIncrement();
        granular.checkHealth(runTime_.value());
        nSubSteps_ += nSub;

        // The counters of the step over the ranks (owned mode: the
        // kinetic energy summed rank by rank, the list builds of every
        // rank)
        const granularSystem::statistics s =
            owned_ ? owned_->stats() : granular.stats();
        if (owned_)
        {
            const ownedGranularSteps::counters& c = owned_->lastCounters();
            if (c.nFarRecords)
            {
                WarningInFunction
                    << "t = " << runTime_.value() << ": " << c.nFarRecords
                    << " ghost records came to a rank beyond their reach"
                    << " and were dropped" << endl;
            }
            ownedTotals_.ghostsSent += c.nGhostsSent;
            ownedTotals_.migrated += c.nMigrated;
            ownedTotals_.widerReach += c.nWiderReach;
            ownedTotals_.rankMessages += c.maxRankMessages;
            ownedTotals_.rankBytes += c.maxRankBytes;
            ownedTotals_.maxNeighbours =
                max(ownedTotals_.maxNeighbours, c.maxNeighbours);
            ownedTotals_.farRecords += c.nFarRecords;
            ownedTotals_.maxHeld = max(ownedTotals_.maxHeld, c.maxHeld);
            ownedTotals_.maxSearchCells =
                max(ownedTotals_.maxSearchCells, c.maxSearchCells);
            ++nOwnedSteps_;
        }
        if (dat)
        {
            dat() << runTime_.value() << ' ' << s.kineticEnergy << ' '
                << nSub << ' ' << s.nContacts << ' ' << s.nWallContacts
                << ' ' << s.maxOverlapRatio << ' ' << s.nListBuilds << ' '
                << runTime_.elapsedCpuTime() << nl;
        }

        if (runTime_.writeTime())
        {
            clock.timeIncrement();
            runTime_.write();
            // (owned mode: the restart file gathered on the master)
            const granularSystem* scene = sceneToWrite();
            if (scene)
            {
                scene->writeParticles
                (
                    runTime_.globalPath()/runTime_.timeName()
                );
            }
            writeVTK(scene);
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

    if (owned_ && nOwnedSteps_)
    {
        const Pair<scalar> work = owned_->workPerRank();
        const scalar perStep = 1.0/nOwnedSteps_;
        Info<< nl << "Owned particles, per step over " << nOwnedSteps_
            << " steps: the busiest rank sent "
            << perStep*ownedTotals_.rankMessages << " messages and "
            << perStep*ownedTotals_.rankBytes << " bytes, to at most "
            << ownedTotals_.maxNeighbours << " neighbouring ranks; "
            << perStep*ownedTotals_.ghostsSent << " ghost copies and "
            << perStep*ownedTotals_.migrated << " changes of rank over"
            << " all ranks; " << ownedTotals_.widerReach << " steps redone"
            << " with a wider reach; " << ownedTotals_.farRecords
            << " records beyond reach; at most " << ownedTotals_.maxHeld
            << " particles held by a rank (of " << nParticles_ << "), its"
            << " contact search over at most " << ownedTotals_.maxSearchCells
            << " cells" << nl
            << "Granular work per rank (less its exchanges and waiting):"
            << " max/mean " << work.first()/max(work.second(), VSMALL)
            << " (max " << work.first() << " s, mean " << work.second()
            << " s)" << endl;
    }
}


// ************************************************************************* //

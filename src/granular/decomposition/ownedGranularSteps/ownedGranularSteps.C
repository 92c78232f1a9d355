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

#include "ownedGranularSteps.H"
#include "velocityVerletIntegrator.H"

#include <chrono>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type, class Op>
Foam::List<Type> Foam::ownedGranularSteps::perRank(const Op& op)
{
    List<Type> values(systems_.size());
    forAll(systems_, k)
    {
        values[k] = op(systems_[k]);
    }
    return values;
}


bool Foam::ownedGranularSteps::subSteps
(
    const scalar Deltat,
    const label n,
    const scalar travel,
    const bool inReach,
    const scalar inReachTravel,
    bool& widen
)
{
    widen = false;
    for (granularSystem& s : systems_)
    {
        s.keepStart();
    }
    const bool contacts = inReach || systems_[0].contactsOn();
    const scalar dt = Deltat/n;
    for (label k = 0; k < n; ++k)
    {
        for (granularSystem& s : systems_)
        {
            s.openSubStep(dt, k > 0);
        }
        updateGhosts();
        if (contacts)
        {
            for (granularSystem& s : systems_)
            {
                s.contactForces(dt);
            }
        }
        if (k == n - 1)
        {
            for (granularSystem& s : systems_)
            {
                s.closeStep(dt);
            }
        }
        widen = exchange_.anyOf
        (
            perRank<bool>
            (
                [&](const granularSystem& s)
                {
                    return s.travelledFarther(travel, false);
                }
            )
        );
        const bool fallBack =
            !widen
         && inReach
         && exchange_.anyOf
            (
                perRank<bool>
                (
                    [&](const granularSystem& s)
                    {
                        return s.travelledFarther(inReachTravel, true);
                    }
                )
            );
        if (widen || fallBack)
        {
            for (granularSystem& s : systems_)
            {
                s.restoreStart();
                s.clearInReach();
            }
            return false;
        }
    }
    for (granularSystem& s : systems_)
    {
        s.clearInReach();
    }
    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ownedGranularSteps::ownedGranularSteps
(
    UPtrList<granularSystem>&& systems,
    const particleDecomposition& decomposition,
    const rankExchange& exchange
)
:
    decomposition_(decomposition),
    exchange_(exchange),
    systems_(std::move(systems)),
    scene_(),
    messages_(systems_.size()),
    sendTo_(systems_.size()),
    receiveFrom_(systems_.size()),
    counters_(),
    rankMessages_(),
    rankBytes_(),
    searchRegions_(),
    workSeconds_(0)
{
    if (systems_.size() != exchange_.localRanks().size())
    {
        FatalErrorInFunction
            << systems_.size() << " systems for the "
            << exchange_.localRanks().size() << " ranks of this process"
            << abort(FatalError);
    }
    if (decomposition_.size() != exchange_.nRanks())
    {
        FatalErrorInFunction
            << "a decomposition of " << decomposition_.size()
            << " regions for " << exchange_.nRanks() << " ranks"
            << abort(FatalError);
    }

    // Each rank keeps the particles it owns
    using record = granularSystem::particleRecord;
    List<DynamicList<record>> owned(systems_.size());
    forAll(systems_, k)
    {
        const granularSystem& s = systems_[k];
        const label rank = exchange_.localRanks()[k];
        for (label i = 0; i < s.size(); ++i)
        {
            const label r = decomposition_.rankOf(s.particle(i).position());
            if (r < 0)
            {
                FatalErrorInFunction
                    << "particle " << s.id(i) << " at "
                    << s.particle(i).position() << " lies outside the"
                    << " decomposed domain" << exit(FatalError);
            }
            if (i && s.globalIndex(i) <= s.globalIndex(i - 1))
            {
                FatalErrorInFunction
                    << "the system of rank " << rank << " does not hold"
                    << " its particles in ascending global order"
                    << abort(FatalError);
            }
            if (r == rank)
            {
                owned[k].append(s.record(i));
            }
        }
    }
    // Each rank's own particles, their centres in its box: the contact
    // search over the box until the ghosts come
    searchRegions_.setSize(systems_.size());
    forAll(systems_, k)
    {
        granularSystem& s = systems_[k];
        searchRegions_[k] = decomposition_.bounds(exchange_.localRanks()[k]);
        s.setScene(s.localConstants());
        s.setParticles
        (
            owned[k], boolList(owned[k].size(), false), &searchRegions_[k]
        );
    }

    // The scene's constants: exact reductions of the ranks' own
    const List<granularSystem::sceneConstants> local
    (
        perRank<granularSystem::sceneConstants>
        (
            [](const granularSystem& s) { return s.localConstants(); }
        )
    );
    labelList n(local.size());
    scalarList rMax(local.size()), minusDmin(local.size());
    forAll(local, k)
    {
        n[k] = local[k].n;
        rMax[k] = local[k].rMax;
        minusDmin[k] = -local[k].Dmin;
    }
    scene_.n = exchange_.sumOf(n);
    scene_.rMax = exchange_.maxOf(rMax);
    scene_.Dmin = -exchange_.maxOf(minusDmin);
    scene_.minMass = local[0].minMass;
    forAll(scene_.minMass, a)
    {
        scalarList minusMass(local.size());
        forAll(local, k)
        {
            minusMass[k] = -local[k].minMass[a];
        }
        scene_.minMass[a] = -exchange_.maxOf(minusMass);
    }
    for (granularSystem& s : systems_)
    {
        s.setScene(scene_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::ownedGranularSteps::evolve(const scalar Deltat)
{
    const scalar exchanged = exchange_.seconds();
    const auto start = std::chrono::steady_clock::now();
    const label n = step(Deltat);
    workSeconds_ +=
        std::chrono::duration<scalar>
        (
            std::chrono::steady_clock::now() - start
        ).count()
      - (exchange_.seconds() - exchanged);
    return n;
}


Foam::Pair<Foam::scalar> Foam::ownedGranularSteps::workPerRank() const
{
    // (ranks in one process share its clock: each its share)
    const scalarList perRank
    (
        systems_.size(), workSeconds_/max(systems_.size(), label(1))
    );
    return Pair<scalar>
    (
        exchange_.maxOf(perRank),
        exchange_.sumOf(perRank)/exchange_.nRanks()
    );
}


Foam::label Foam::ownedGranularSteps::step(const scalar Deltat)
{
    counters_ = counters();
    // (none left before a step that moves nothing)
    departures_.setSize(systems_.size());
    for (DynamicList<labelPair>& d : departures_)
    {
        d.clear();
    }
    rankMessages_.setSize(systems_.size());
    rankMessages_ = 0;
    rankBytes_.setSize(systems_.size());
    rankBytes_ = 0;
    for (granularSystem& s : systems_)
    {
        s.resetStatistics(false);
        s.startContactImpulses();
    }
    const bool anyMoving = exchange_.anyOf
    (
        perRank<bool>
        (
            [](const granularSystem& s) { return s.moving().size() > 0; }
        )
    );
    if (!anyMoving)
    {
        // Nothing moves (no particle, or all fixed): no granular work
        return 0;
    }

    // The global decisions, as granularSystem::evolve takes them for the
    // whole scene
    const scalar maxReach = exchange_.maxOf
    (
        perRank<scalar>
        (
            [&](granularSystem& s) { return s.stepReach(Deltat); }
        )
    );
    const granularSystem& first = systems_[0];
    const scalar inReachTravel = max(3*maxReach, 0.1*skinOf());
    scalar travel = max(inReachTravel, 0.5*skinOf());

    label n = 0;
    while (true)
    {
        distributeGhosts(travel);
        for (granularSystem& s : systems_)
        {
            s.stepReach(Deltat);
        }

        // collisions automatic: no contact within reach anywhere, one
        // velocity-Verlet step without contact work
        if
        (
            first.collisionsAutomatic()
         && !exchange_.anyOf
            (
                perRank<bool>
                (
                    [&](granularSystem& s)
                    {
                        return s.contactsWithin(maxReach);
                    }
                )
            )
        )
        {
            for (granularSystem& s : systems_)
            {
                s.openSubStep(Deltat, false);
                s.closeStep(Deltat);
                s.setStepStatistics(1, true, -1);
            }
            n = 1;
            break;
        }

        n = velocityVerletIntegrator::nSubSteps(Deltat, first.maxSubStep());

        // subCycling inReach: the marks of every rank, or every
        // particle's contact work when a rank cannot tell or every
        // particle is in reach
        bool inReach = false;
        label nInReach = -1;
        if (first.subCycleInReach() && first.contactsOn() && n > 1)
        {
            const labelList marks
            (
                perRank<label>
                (
                    [&](granularSystem& s)
                    {
                        return s.markInReach(inReachTravel);
                    }
                )
            );
            List<bool> cannotTell(marks.size()), notAll(marks.size());
            forAll(marks, k)
            {
                cannotTell[k] = marks[k] < 0;
                notAll[k] = marks[k] != systems_[k].moving().size();
            }
            if (!exchange_.anyOf(cannotTell) && exchange_.anyOf(notAll))
            {
                inReach = true;
                nInReach = exchange_.sumOf(marks);
            }
            else
            {
                for (granularSystem& s : systems_)
                {
                    s.clearInReach();
                }
            }
        }

        bool widen = false;
        if (subSteps(Deltat, n, travel, inReach, inReachTravel, widen))
        {
            for (granularSystem& s : systems_)
            {
                s.setStepStatistics(n, false, nInReach);
            }
            break;
        }
        if (!widen)
        {
            // subCycling inReach's fallback: every particle's contact work
            for (granularSystem& s : systems_)
            {
                s.resetStatistics(true);
                s.noteFallback();
            }
            if (subSteps(Deltat, n, travel, false, inReachTravel, widen))
            {
                for (granularSystem& s : systems_)
                {
                    s.setStepStatistics(n, false, -1);
                }
                break;
            }
        }
        // A particle went beyond the ghosts' reach: the step again, with
        // twice the reach
        travel *= 2;
        ++counters_.nWiderReach;
        for (granularSystem& s : systems_)
        {
            s.resetStatistics(false);
        }
    }
    dropGhostsAndMigrate();

    // The most any one rank sent, and the most neighbours
    scalarList msgs(systems_.size()), bytes(systems_.size());
    scalarList nbrs(systems_.size());
    forAll(systems_, k)
    {
        msgs[k] = rankMessages_[k];
        bytes[k] = rankBytes_[k];
        nbrs[k] = messages_[k].ranks.size();
    }
    // (summed over the ranks of this process so far)
    for (label* c :
        {
            &counters_.nGhostsSent, &counters_.nMigrated,
            &counters_.nMessages, &counters_.nFarRecords
        })
    {
        *c = exchange_.sumOf(labelList(1, *c));
    }
    counters_.nBytes = exchange_.sumOf(scalarList(1, counters_.nBytes));
    counters_.maxRankMessages = label(exchange_.maxOf(msgs));
    counters_.maxRankBytes = exchange_.maxOf(bytes);
    counters_.maxNeighbours = label(exchange_.maxOf(nbrs));
    counters_.maxHeld =
        label(exchange_.maxOf(scalarList(1, scalar(counters_.maxHeld))));
    counters_.maxSearchCells = label
    (
        exchange_.maxOf(scalarList(1, scalar(counters_.maxSearchCells)))
    );
    return n;
}


Foam::List<Foam::granularSystem::particleRecord>
Foam::ownedGranularSteps::ownedRecords() const
{
    DynamicList<granularSystem::particleRecord> records;
    for (const granularSystem& s : systems_)
    {
        for (label i = 0; i < s.size(); ++i)
        {
            if (!s.ghost(i))
            {
                records.append(s.record(i));
            }
        }
    }
    return List<granularSystem::particleRecord>(std::move(records));
}


Foam::granularSystem::statistics Foam::ownedGranularSteps::stats() const
{
    const label K = systems_.size();
    labelList nCandidates(K), nContacts(K), nWalls(K), nBuilds(K);
    scalarList overlap(K), energy(K);
    forAll(systems_, k)
    {
        const granularSystem::statistics& s = systems_[k].stats();
        nCandidates[k] = s.nCandidatePairs;
        nContacts[k] = s.nContacts;
        nWalls[k] = s.nWallContacts;
        nBuilds[k] = s.nListBuilds;
        overlap[k] = s.maxOverlapRatio;
        energy[k] = s.kineticEnergy;
    }
    // (the step's decisions, the same on every rank)
    granularSystem::statistics s = systems_[0].stats();
    s.nCandidatePairs = exchange_.sumOf(nCandidates);
    s.nContacts = exchange_.sumOf(nContacts);
    s.nWallContacts = exchange_.sumOf(nWalls);
    s.nListBuilds = exchange_.sumOf(nBuilds);
    s.maxOverlapRatio = exchange_.maxOf(overlap);
    s.maxOverlapContact = labelPair(-1, -1);
    s.kineticEnergy = exchange_.sumOf(energy);
    return s;
}


// ************************************************************************* //

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
#include "Map.H"
#include "SortableList.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * * * Local Types * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A contact's history as it travels with a particle
struct historyEntry
{
    label i;
    label j;
    vector h;
};

void put(DynamicList<char>& buf, const rigidParticle::motionState& s)
{
    rankExchange::put(buf, s.x);
    rankExchange::put(buf, s.q);
    rankExchange::put(buf, s.U);
    rankExchange::put(buf, s.omega);
    rankExchange::put(buf, s.F);
    rankExchange::put(buf, s.T);
    rankExchange::put(buf, s.Fstart);
    rankExchange::put(buf, s.Tstart);
}

void get(const UList<char>& buf, label& pos, rigidParticle::motionState& s)
{
    rankExchange::get(buf, pos, s.x);
    rankExchange::get(buf, pos, s.q);
    rankExchange::get(buf, pos, s.U);
    rankExchange::get(buf, pos, s.omega);
    rankExchange::get(buf, pos, s.F);
    rankExchange::get(buf, pos, s.T);
    rankExchange::get(buf, pos, s.Fstart);
    rankExchange::get(buf, pos, s.Tstart);
}

//- What a ghost needs of its owner's state at a sub-step: pose,
//- velocities and the forces the sub-step started with (its dashpots
//- predict the velocities with them); the force being summed is the
//- owner's alone
void putGhost(DynamicList<char>& buf, const rigidParticle::motionState& s)
{
    rankExchange::put(buf, s.x);
    rankExchange::put(buf, s.q);
    rankExchange::put(buf, s.U);
    rankExchange::put(buf, s.omega);
    rankExchange::put(buf, s.Fstart);
    rankExchange::put(buf, s.Tstart);
}

void getGhost
(
    const UList<char>& buf,
    label& pos,
    rigidParticle::motionState& s
)
{
    rankExchange::get(buf, pos, s.x);
    rankExchange::get(buf, pos, s.q);
    rankExchange::get(buf, pos, s.U);
    rankExchange::get(buf, pos, s.omega);
    rankExchange::get(buf, pos, s.Fstart);
    rankExchange::get(buf, pos, s.Tstart);
    s.F = Zero;
    s.T = Zero;
}

void put(DynamicList<char>& buf, const granularSystem::particleRecord& r)
{
    rankExchange::put(buf, r.global);
    rankExchange::put(buf, r.id);
    rankExchange::put(buf, r.shape);
    rankExchange::put(buf, r.material);
    rankExchange::put(buf, r.motion);
    put(buf, r.state);
    rankExchange::put(buf, r.Fext);
    rankExchange::put(buf, r.Text);
}

void get(const UList<char>& buf, label& pos, granularSystem::particleRecord& r)
{
    rankExchange::get(buf, pos, r.global);
    rankExchange::get(buf, pos, r.id);
    rankExchange::get(buf, pos, r.shape);
    rankExchange::get(buf, pos, r.material);
    rankExchange::get(buf, pos, r.motion);
    get(buf, pos, r.state);
    rankExchange::get(buf, pos, r.Fext);
    rankExchange::get(buf, pos, r.Text);
}

void put(DynamicList<char>& buf, const historyEntry& h)
{
    rankExchange::put(buf, h.i);
    rankExchange::put(buf, h.j);
    rankExchange::put(buf, h.h);
}

void get(const UList<char>& buf, label& pos, historyEntry& h)
{
    rankExchange::get(buf, pos, h.i);
    rankExchange::get(buf, pos, h.j);
    rankExchange::get(buf, pos, h.h);
}

} // End anonymous namespace


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


Foam::label Foam::ownedGranularSteps::neighbourIndex
(
    const label k,
    const label r
) const
{
    const label m = messages_[k].ranks.find(r);
    if (m < 0)
    {
        FatalErrorInFunction
            << "rank " << exchange_.localRanks()[k] << " has a record for"
            << " rank " << r << ", which is not among its neighbours "
            << messages_[k].ranks << abort(FatalError);
    }
    return m;
}


void Foam::ownedGranularSteps::setNeighbours(const scalar reach)
{
    // (a margin against the round-off of box edges: a rank too many costs
    // an empty message, one too few would stop the run)
    const scalar margin = 1e-9*reach;
    forAll(systems_, k)
    {
        decomposition_.neighbours
        (
            exchange_.localRanks()[k], reach + margin, near_
        );
        messages_[k].setRanks(near_);
        sendTo_[k].setSize(near_.size());
        receiveFrom_[k].setSize(near_.size());
        for (DynamicList<label>& l : sendTo_[k])
        {
            l.clear();
        }
        for (DynamicList<label>& l : receiveFrom_[k])
        {
            l.clear();
        }
    }
}


void Foam::ownedGranularSteps::countMessages()
{
    forAll(messages_, k)
    {
        const rankExchange::messages& m = messages_[k];
        counters_.nMessages += m.out.size();
        rankMessages_[k] += m.out.size();
        for (const DynamicList<char>& buf : m.out)
        {
            counters_.nBytes += buf.size();
            rankBytes_[k] += buf.size();
        }
    }
}


void Foam::ownedGranularSteps::distributeGhosts(const scalar travel)
{
    // Two particles can touch over the step only if their centres start
    // within r_i + r_j + 2 travel of each other; the skin is a margin
    const scalar reachBeyond = scene_.rMax + skinOf() + 2*travel;
    setNeighbours(2*scene_.rMax + skinOf() + 2*travel);

    using record = granularSystem::particleRecord;

    forAll(systems_, k)
    {
        const granularSystem& s = systems_[k];
        const label rank = exchange_.localRanks()[k];
        rankExchange::messages& msg = messages_[k];
        for (label i = 0; i < s.size(); ++i)
        {
            if (s.ghost(i))
            {
                continue;
            }
            const rigidParticle& p = s.particle(i);
            decomposition_.ranksWithin
            (
                p.position(), p.shape().boundingRadius() + reachBeyond, near_
            );
            for (const label r : near_)
            {
                if (r == rank)
                {
                    continue;
                }
                const label m = neighbourIndex(k, r);
                sendTo_[k][m].append(s.globalIndex(i));
                put(msg.out[m], s.record(i));
                ++counters_.nGhostsSent;
            }
        }
    }
    exchange_.exchange(messages_);
    countMessages();

    forAll(systems_, k)
    {
        granularSystem& s = systems_[k];
        const rankExchange::messages& msg = messages_[k];

        // Owned particles and ghosts, then in global order
        DynamicList<record> held(s.size());
        DynamicList<label> from(s.size());
        for (label i = 0; i < s.size(); ++i)
        {
            if (!s.ghost(i))
            {
                held.append(s.record(i));
                from.append(-1);
            }
        }
        forAll(msg.in, m)
        {
            label pos = 0;
            while (pos < msg.in[m].size())
            {
                record r;
                get(msg.in[m], pos, r);
                // A record about a particle that cannot touch this rank's
                // own is not one it should have been sent
                decomposition_.ranksWithin
                (
                    r.state.x,
                    s.shapes()[r.shape].boundingRadius() + reachBeyond,
                    near_
                );
                if (!near_.found(exchange_.localRanks()[k]))
                {
                    ++counters_.nFarRecords;
                    continue;
                }
                held.append(r);
                from.append(m);
            }
        }
        SortableList<label> globals(held.size());
        forAll(held, h)
        {
            globals[h] = held[h].global;
        }
        globals.sort();
        const labelList& order = globals.indices();
        List<record> sorted(held.size());
        boolList isGhost(held.size());
        forAll(order, n)
        {
            sorted[n] = held[order[n]];
            isGhost[n] = from[order[n]] >= 0;
            if (n && globals[n] == globals[n - 1])
            {
                FatalErrorInFunction
                    << "rank " << exchange_.localRanks()[k] << " holds"
                    << " particle " << held[order[n]].id << " (global index "
                    << globals[n] << ") twice" << abort(FatalError);
            }
        }
        s.setParticles(sorted, isGhost);

        // Where each ghost and each particle sent now sits
        forAll(order, n)
        {
            if (isGhost[n])
            {
                receiveFrom_[k][from[order[n]]].append(n);
            }
        }
        Map<label> place(2*sorted.size());
        forAll(sorted, n)
        {
            place.insert(sorted[n].global, n);
        }
        for (DynamicList<label>& sent : sendTo_[k])
        {
            for (label& g : sent)
            {
                g = place[g];
            }
        }
    }
}


void Foam::ownedGranularSteps::updateGhosts()
{
    forAll(systems_, k)
    {
        const granularSystem& s = systems_[k];
        rankExchange::messages& msg = messages_[k];
        forAll(msg.out, m)
        {
            msg.out[m].clear();
            for (const label i : sendTo_[k][m])
            {
                putGhost(msg.out[m], s.particle(i).state());
            }
        }
    }
    exchange_.exchange(messages_);
    countMessages();
    forAll(systems_, k)
    {
        granularSystem& s = systems_[k];
        const rankExchange::messages& msg = messages_[k];
        forAll(msg.in, m)
        {
            label pos = 0;
            rigidParticle::motionState state;
            for (const label g : receiveFrom_[k][m])
            {
                getGhost(msg.in[m], pos, state);
                s.setGhostState(g, state);
            }
        }
    }
}


void Foam::ownedGranularSteps::dropGhostsAndMigrate()
{
    using record = granularSystem::particleRecord;

    List<DynamicList<record>> kept(systems_.size());
    forAll(systems_, k)
    {
        granularSystem& s = systems_[k];
        const label rank = exchange_.localRanks()[k];
        rankExchange::messages& msg = messages_[k];
        List<DynamicList<record>> leaving(msg.ranks.size());
        Map<label> leaves;
        for (label i = 0; i < s.size(); ++i)
        {
            if (s.ghost(i))
            {
                continue;
            }
            const label r = decomposition_.rankOf(s.particle(i).position());
            if (r < 0)
            {
                FatalErrorInFunction
                    << "particle " << s.id(i) << " at "
                    << s.particle(i).position() << " left the domain"
                    << abort(FatalError);
            }
            if (r == rank)
            {
                kept[k].append(s.record(i));
                continue;
            }
            const label m = neighbourIndex(k, r);
            leaving[m].append(s.record(i));
            leaves.insert(s.globalIndex(i), m);
            ++counters_.nMigrated;
        }

        // The histories of their contacts go with them
        List<DynamicList<historyEntry>> histories(msg.ranks.size());
        if (leaves.size())
        {
            for (const auto& e : s.history().entries())
            {
                const label i = e.first.first(), j = e.first.second();
                const label mi = leaves.lookup(i, -1);
                const label mj = j >= 0 ? leaves.lookup(j, -1) : -1;
                if (mi >= 0)
                {
                    histories[mi].append({i, j, e.second});
                }
                if (mj >= 0 && mj != mi)
                {
                    histories[mj].append({i, j, e.second});
                }
            }
        }
        forAll(msg.out, m)
        {
            DynamicList<char>& buf = msg.out[m];
            buf.clear();
            rankExchange::put(buf, leaving[m].size());
            for (const record& r : leaving[m])
            {
                put(buf, r);
            }
            rankExchange::put(buf, histories[m].size());
            for (const historyEntry& h : histories[m])
            {
                put(buf, h);
            }
        }
    }
    exchange_.exchange(messages_);
    countMessages();

    forAll(systems_, k)
    {
        granularSystem& s = systems_[k];
        const rankExchange::messages& msg = messages_[k];
        DynamicList<historyEntry> histories;
        forAll(msg.in, m)
        {
            label pos = 0;
            label nRecords = 0, nEntries = 0;
            rankExchange::get(msg.in[m], pos, nRecords);
            for (label n = 0; n < nRecords; ++n)
            {
                record r;
                get(msg.in[m], pos, r);
                if
                (
                    decomposition_.rankOf(r.state.x)
                 != exchange_.localRanks()[k]
                )
                {
                    FatalErrorInFunction
                        << "particle " << r.id << " at " << r.state.x
                        << " came to rank " << exchange_.localRanks()[k]
                        << " from rank " << msg.ranks[m] << ", but lies in"
                        << " the region of rank "
                        << decomposition_.rankOf(r.state.x)
                        << abort(FatalError);
                }
                kept[k].append(r);
            }
            rankExchange::get(msg.in[m], pos, nEntries);
            for (label n = 0; n < nEntries; ++n)
            {
                historyEntry h;
                get(msg.in[m], pos, h);
                histories.append(h);
            }
        }
        SortableList<label> globals(kept[k].size());
        forAll(kept[k], n)
        {
            globals[n] = kept[k][n].global;
        }
        globals.sort();
        List<record> sorted(kept[k].size());
        forAll(sorted, n)
        {
            sorted[n] = kept[k][globals.indices()[n]];
        }
        s.setParticles(sorted, boolList(sorted.size(), false));
        for (const historyEntry& h : histories)
        {
            s.history().set(h.i, h.j, h.h);
        }
    }
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
    counters_()
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
            if (s.globalIndex(i) != i)
            {
                FatalErrorInFunction
                    << "the system of rank " << rank << " does not hold"
                    << " the whole scene in global order"
                    << abort(FatalError);
            }
            if (r == rank)
            {
                owned[k].append(s.record(i));
            }
        }
    }
    forAll(systems_, k)
    {
        granularSystem& s = systems_[k];
        s.setScene(s.localConstants());
        s.setParticles(owned[k], boolList(owned[k].size(), false));
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
    counters_ = counters();
    rankMessages_.setSize(systems_.size());
    rankMessages_ = 0;
    rankBytes_.setSize(systems_.size());
    rankBytes_ = 0;
    for (granularSystem& s : systems_)
    {
        s.resetStatistics(false);
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


Foam::List<Foam::DynamicList<char>> Foam::ownedGranularSteps::packOwned
(
    const bool withHistory
) const
{
    List<DynamicList<char>> parts(systems_.size());
    forAll(systems_, k)
    {
        const granularSystem& s = systems_[k];
        DynamicList<char>& buf = parts[k];
        labelHashSet owned;
        for (label i = 0; i < s.size(); ++i)
        {
            if (!s.ghost(i))
            {
                owned.insert(s.globalIndex(i));
            }
        }
        rankExchange::put(buf, owned.size());
        for (label i = 0; i < s.size(); ++i)
        {
            if (!s.ghost(i))
            {
                rankExchange::put(buf, s.globalIndex(i));
                put(buf, s.particle(i).state());
            }
        }
        DynamicList<historyEntry> entries;
        if (withHistory)
        {
            for (const auto& e : s.history().entries())
            {
                if (owned.found(e.first.first()))
                {
                    entries.append
                    (
                        {e.first.first(), e.first.second(), e.second}
                    );
                }
            }
        }
        rankExchange::put(buf, entries.size());
        for (const historyEntry& h : entries)
        {
            put(buf, h);
        }
    }
    return parts;
}


void Foam::ownedGranularSteps::unpackScene
(
    const UList<List<char>>& all,
    granularSystem& whole,
    const bool withHistory
) const
{
    label nStates = 0;
    if (withHistory)
    {
        whole.history().clear();
    }
    rigidParticle::motionState state;
    for (const List<char>& buf : all)
    {
        label pos = 0, n = 0;
        rankExchange::get(buf, pos, n);
        for (label k = 0; k < n; ++k)
        {
            label global = -1;
            rankExchange::get(buf, pos, global);
            get(buf, pos, state);
            if (global < 0 || global >= whole.size())
            {
                FatalErrorInFunction
                    << "a particle of global index " << global
                    << " is not in a scene of " << whole.size()
                    << abort(FatalError);
            }
            whole.particle(global).setState(state);
            ++nStates;
        }
        rankExchange::get(buf, pos, n);
        for (label k = 0; k < n; ++k)
        {
            historyEntry h;
            get(buf, pos, h);
            whole.history().set(h.i, h.j, h.h);
        }
    }
    if (nStates != whole.size())
    {
        FatalErrorInFunction
            << "the ranks own " << nStates << " particles; the scene has "
            << whole.size() << abort(FatalError);
    }
}


void Foam::ownedGranularSteps::gatherScene(granularSystem* whole) const
{
    const List<List<char>> all(exchange_.gather(packOwned(true)));
    if (all.empty())
    {
        return;
    }
    if (!whole)
    {
        FatalErrorInFunction
            << "no system on rank 0 to take the whole scene"
            << abort(FatalError);
    }
    unpackScene(all, *whole, true);
}


void Foam::ownedGranularSteps::mirrorScene(granularSystem& whole) const
{
    unpackScene(exchange_.allGather(packOwned(false)), whole, false);
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


Foam::label Foam::ownedGranularSteps::nContacts() const
{
    labelList n(systems_.size());
    forAll(systems_, k)
    {
        n[k] = systems_[k].stats().nContacts;
    }
    return exchange_.sumOf(n);
}


// ************************************************************************* //

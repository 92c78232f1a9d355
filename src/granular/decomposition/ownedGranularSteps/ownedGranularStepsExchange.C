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
    The messages of Foam::ownedGranularSteps: the neighbours of a step,
    the ghosts and their states, the particles that change rank, and the
    whole scene gathered for output.

\*---------------------------------------------------------------------------*/

#include "ownedGranularSteps.H"
#include "ownedGranularStepsRecords.H"
#include "Map.H"
#include "SortableList.H"
#include "HashSet.H"

#include <algorithm>

using namespace Foam::ownedGranularRecords;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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

    // Each rank's contact search covers its box and the ghosts' reach,
    // with their travel over the step: no grid over the whole domain
    searchRegions_.setSize(systems_.size());
    forAll(systems_, k)
    {
        const boundBox box
        (
            decomposition_.bounds(exchange_.localRanks()[k])
        );
        const vector grow(vector::one*(scene_.rMax + reachBeyond + travel));
        searchRegions_[k] = boundBox(box.min() - grow, box.max() + grow);
    }

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
        s.setParticles(sorted, isGhost, &searchRegions_[k]);
        counters_.maxHeld = max(counters_.maxHeld, s.size());
        counters_.maxSearchCells =
            max(counters_.maxSearchCells, s.nSearchCells());

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
            departures_[k].append(labelPair(s.globalIndex(i), r));
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
        s.setParticles(sorted, boolList(sorted.size(), false), &searchRegions_[k]);
        for (const historyEntry& h : histories)
        {
            s.history().set(h.i, h.j, h.h);
        }
    }
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


Foam::label Foam::ownedGranularSteps::takeStates
(
    const UList<char>& buf,
    label& pos,
    granularSystem& whole
)
{
    label n = 0;
    rankExchange::get(buf, pos, n);
    rigidParticle::motionState state;
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
    }
    return n;
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
    for (const List<char>& buf : all)
    {
        label pos = 0, n = 0;
        nStates += takeStates(buf, pos, whole);
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


Foam::Pair<Foam::scalar> Foam::ownedGranularSteps::sendStates
(
    const UList<List<labelList>>& sendTo,
    const UList<labelList>& partners,
    DynamicList<granularSystem::particleRecord>& mirror
) const
{
    using record = granularSystem::particleRecord;
    const labelList& ranks = exchange_.localRanks();
    if (sendTo.size() != systems_.size() || partners.size() != systems_.size())
    {
        FatalErrorInFunction
            << sendTo.size() << " lists of destinations and "
            << partners.size() << " of partners for " << systems_.size()
            << " local ranks" << abort(FatalError);
    }
    mirror.clear();
    List<rankExchange::messages> perRank(systems_.size());
    forAll(systems_, k)
    {
        const granularSystem& s = systems_[k];
        rankExchange::messages& m = perRank[k];
        m.setRanks(partners[k]);
        if (sendTo[k].size() != s.size())
        {
            FatalErrorInFunction
                << "destinations for " << sendTo[k].size() << " of rank "
                << ranks[k] << "'s " << s.size() << " particles"
                << abort(FatalError);
        }
        labelList nTo(m.ranks.size(), 0);
        forAll(sendTo[k], i)
        {
            for (const label r : sendTo[k][i])
            {
                const label j = findSortedIndex(m.ranks, r);
                if (j < 0)
                {
                    FatalErrorInFunction
                        << "particle " << s.id(i) << " of rank " << ranks[k]
                        << " is to go to rank " << r << ", which is not"
                        << " among the ranks it talks to " << m.ranks
                        << abort(FatalError);
                }
                ++nTo[j];
            }
        }
        forAll(m.ranks, j)
        {
            rankExchange::put(m.out[j], nTo[j]);
        }
        forAll(sendTo[k], i)
        {
            if (sendTo[k][i].empty())
            {
                continue;
            }
            const record r(s.record(i));
            for (const label to : sendTo[k][i])
            {
                putCopy(m.out[findSortedIndex(m.ranks, to)], r);
            }
        }
        // This rank's own particles are in the mirror too
        for (label i = 0; i < s.size(); ++i)
        {
            if (!s.ghost(i))
            {
                record r(s.record(i));
                r.Fext = Zero;
                r.Text = Zero;
                mirror.append(r);
            }
        }
    }
    exchange_.exchange(perRank);

    Pair<scalar> received(0, 0);
    for (const rankExchange::messages& m : perRank)
    {
        for (const List<char>& buf : m.in)
        {
            label pos = 0, n = 0;
            rankExchange::get(buf, pos, n);
            for (label k = 0; k < n; ++k)
            {
                record r;
                getCopy(buf, pos, r);
                mirror.append(r);
            }
            received.first() += 1;
            received.second() += buf.size();
        }
    }
    // In ascending global index, each once (several local ranks in one
    // process may take the same particle)
    std::sort
    (
        mirror.begin(), mirror.end(),
        [](const record& a, const record& b) { return a.global < b.global; }
    );
    label nUnique = 0;
    forAll(mirror, i)
    {
        if (i == 0 || mirror[i].global != mirror[nUnique - 1].global)
        {
            mirror[nUnique++] = mirror[i];
        }
    }
    mirror.resize(nUnique);
    return received;
}


// ************************************************************************* //

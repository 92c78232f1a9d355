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
    Foam::ownedGranularSteps at the start: the scene read on rank 0 handed
    out, each rank given its own particles and those named for it, so
    that no other rank holds the whole scene.

\*---------------------------------------------------------------------------*/

#include "ownedGranularSteps.H"
#include "ownedGranularStepsRecords.H"

using namespace Foam::ownedGranularRecords;

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::List<Foam::List<Foam::granularSystem::particleRecord>>
Foam::ownedGranularSteps::scatterScene
(
    const rankExchange& exchange,
    const particleDecomposition& decomposition,
    const granularSystem* whole,
    const UList<labelList>& destinations,
    UPtrList<granularSystem>& parts
)
{
    using record = granularSystem::particleRecord;
    const label nRanks = exchange.nRanks();
    const labelList& localRanks = exchange.localRanks();
    if (parts.size() != localRanks.size())
    {
        FatalErrorInFunction
            << parts.size() << " systems for the " << localRanks.size()
            << " ranks of this process" << abort(FatalError);
    }
    const bool first = localRanks.size() && localRanks[0] == 0;
    if (first != bool(whole))
    {
        FatalErrorInFunction
            << "the whole scene is given on the process of rank 0 only"
            << abort(FatalError);
    }

    // On rank 0: per rank, the records (ascending global index) and the
    // histories of its own particles' contacts
    List<DynamicList<char>> out;
    if (whole)
    {
        const granularSystem& w = *whole;
        if (destinations.size() != w.size())
        {
            FatalErrorInFunction
                << "destinations for " << destinations.size() << " of the "
                << w.size() << " particles" << abort(FatalError);
        }
        List<DynamicList<label>> toRank(nRanks);
        labelList ownerOf(w.size());
        for (label i = 0; i < w.size(); ++i)
        {
            if (w.globalIndex(i) != i)
            {
                FatalErrorInFunction
                    << "the system given does not hold the whole scene in"
                    << " global order" << abort(FatalError);
            }
            const point& x = w.particle(i).position();
            const label owner = decomposition.rankOf(x);
            if (owner < 0)
            {
                FatalErrorInFunction
                    << "particle " << w.id(i) << " at " << x << " lies"
                    << " outside the decomposed domain" << exit(FatalError);
            }
            ownerOf[i] = owner;
            toRank[owner].append(i);
            for (const label r : destinations[i])
            {
                if (r < 0 || r >= nRanks)
                {
                    FatalErrorInFunction
                        << "particle " << w.id(i) << " is to go to rank "
                        << r << " of " << nRanks << abort(FatalError);
                }
                if (toRank[r].empty() || toRank[r].last() != i)
                {
                    toRank[r].append(i);
                }
            }
        }
        List<DynamicList<historyEntry>> histories
        (
            nRanks
        );
        for (const auto& e : w.history().entries())
        {
            const label i = e.first.first(), j = e.first.second();
            const label ri = ownerOf[i];
            histories[ri].append({i, j, e.second});
            if (j >= 0 && ownerOf[j] != ri)
            {
                histories[ownerOf[j]].append({i, j, e.second});
            }
        }
        out.setSize(nRanks);
        forAll(out, r)
        {
            DynamicList<char>& buf = out[r];
            rankExchange::put(buf, toRank[r].size());
            for (const label i : toRank[r])
            {
                put(buf, w.record(i));
            }
            toRank[r].clear();
            rankExchange::put(buf, histories[r].size());
            for (const historyEntry& h : histories[r])
            {
                put(buf, h);
            }
            histories[r].clear();
        }
    }
    const List<List<char>> in(exchange.scatter(out));
    out.clear();

    // Each rank's records; its own particles and their histories into its
    // part
    List<List<record>> sent(parts.size());
    forAll(parts, k)
    {
        const List<char>& buf = in[k];
        label pos = 0, n = 0;
        rankExchange::get(buf, pos, n);
        sent[k].setSize(n);
        DynamicList<record> own(n);
        forAll(sent[k], m)
        {
            get(buf, pos, sent[k][m]);
            if (decomposition.rankOf(sent[k][m].state.x) == localRanks[k])
            {
                own.append(sent[k][m]);
            }
        }
        granularSystem& s = parts[k];
        s.setScene(s.localConstants());
        s.setParticles(own, boolList(own.size(), false), nullptr);
        rankExchange::get(buf, pos, n);
        for (label m = 0; m < n; ++m)
        {
            historyEntry h;
            get(buf, pos, h);
            s.history().set(h.i, h.j, h.h);
        }
    }
    return sent;
}


// ************************************************************************* //

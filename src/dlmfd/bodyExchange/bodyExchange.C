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

#include "bodyExchange.H"
#include "PstreamBuffers.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

Ostream& operator<<(Ostream& os, const fictitiousDomain::contribution& c)
{
    os  << c.body << token::SPACE << c.centres << token::SPACE << c.volumes
        << token::SPACE << c.u << token::SPACE << c.nInterior
        << token::SPACE << c.deviation << token::SPACE << c.owed
        << token::SPACE << c.owedMoment;
    return os;
}


Istream& operator>>(Istream& is, fictitiousDomain::contribution& c)
{
    is  >> c.body >> c.centres >> c.volumes >> c.u >> c.nInterior
        >> c.deviation >> c.owed >> c.owedMoment;
    return is;
}

} // End namespace Foam


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::List<Foam::List<Foam::bodyExchange::contribution>>
Foam::bodyExchange::toSolvers
(
    UList<DynamicList<contribution>>& outgoing,
    scalar& commSeconds,
    exchangeTraffic& received
)
{
    const label nProcs = Pstream::nProcs();
    if (!Pstream::parRun())
    {
        // Serial: the rank's own contributions, moved, without the round
        // trip through the buffers (binary, so the values are the same)
        List<List<contribution>> incoming(1);
        incoming[0].transfer(outgoing[0]);
        return incoming;
    }
    // Nothing is written for a rank that gets no contribution: its buffer
    // stays empty and no message goes to it
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (label q = 0; q < nProcs; ++q)
    {
        if (outgoing[q].empty())
        {
            continue;
        }
        // One by one: a List of them would be checked for equal elements,
        // which contributions do not compare
        UOPstream os(q, buffers);
        os << outgoing[q].size();
        for (const contribution& con : outgoing[q])
        {
            os << con;
        }
    }
    clockTime clock;
    labelList recvSizes;
    buffers.finishedSends(recvSizes);
    received.add(recvSizes, Pstream::myProcNo());
    commSeconds += clock.timeIncrement();

    List<List<contribution>> incoming(nProcs);
    for (label r = 0; r < nProcs; ++r)
    {
        if (recvSizes[r] == 0)
        {
            continue;
        }
        UIPstream is(r, buffers);
        label size = 0;
        is >> size;
        incoming[r].setSize(size);
        for (contribution& con : incoming[r])
        {
            is >> con;
        }
    }
    return incoming;
}


void Foam::bodyExchange::toOwners
(
    UList<List<vectorField>>& forces,
    UList<List<vectorField>>& deviations,
    List<List<vectorField>>& back,
    List<List<vectorField>>& backDev,
    scalar& commSeconds,
    exchangeTraffic& received
)
{
    const label nProcs = Pstream::nProcs();
    if (!Pstream::parRun())
    {
        back.setSize(1);
        backDev.setSize(1);
        back[0].transfer(forces[0]);
        backDev[0].transfer(deviations[0]);
        return;
    }
    clockTime clock;
    // Back only to the ranks that sent something
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (label r = 0; r < nProcs; ++r)
    {
        if (forces[r].empty())
        {
            continue;
        }
        UOPstream os(r, buffers);
        os << forces[r] << deviations[r];
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);
    received.add(recvSizes, Pstream::myProcNo());
    commSeconds += clock.timeIncrement();

    back.setSize(nProcs);
    backDev.setSize(nProcs);
    for (label q = 0; q < nProcs; ++q)
    {
        back[q].clear();
        backDev[q].clear();
        if (recvSizes[q] == 0)
        {
            continue;
        }
        UIPstream is(q, buffers);
        is >> back[q] >> backDev[q];
    }
}


Foam::labelList Foam::bodyExchange::solvingRanks
(
    const labelUList& nHere,
    scalar& commSeconds
)
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    // One maximum per body over the ranks: the share first, then the
    // lower rank (nProcs - 1 - rank larger); exact in a double up to
    // 2^53 / nProcs cells
    scalarList key(nHere.size(), scalar(-1));
    forAll(nHere, b)
    {
        if (nHere[b] > 0)
        {
            key[b] = scalar(nHere[b])*nProcs + (nProcs - 1 - me);
        }
    }
    if (Pstream::parRun())
    {
        clockTime clock;
        reduce(key, maxOp<scalarList>());
        commSeconds += clock.elapsedTime();
    }
    labelList solver(nHere.size(), -1);
    forAll(key, b)
    {
        if (key[b] >= 0)
        {
            solver[b] = nProcs - 1 - label(std::fmod(key[b], nProcs));
        }
    }
    return solver;
}


void Foam::bodyExchange::sendResults
(
    const labelUList& solved,
    const labelUList& solvedGlobal,
    const labelUList& destination,
    const bodyPlaces& places,
    List<result>& results,
    scalar& commSeconds,
    exchangeTraffic& received
)
{
    if (!Pstream::parRun())
    {
        return;
    }
    clockTime clock;
    constexpr label nValues = 16;
    const label nProcs = Pstream::nProcs();
    const label self = Pstream::myProcNo();

    // Each destination's bodies (places here, and global indices), in the
    // ascending order they were solved
    List<DynamicList<label>> to(nProcs), toGlobal(nProcs);
    forAll(solved, k)
    {
        if (destination[k] != self)
        {
            to[destination[k]].append(solved[k]);
            toGlobal[destination[k]].append(solvedGlobal[k]);
        }
    }
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(to, q)
    {
        if (to[q].empty())
        {
            continue;
        }
        scalarList values(nValues*to[q].size());
        forAll(to[q], k)
        {
            const result& r = results[to[q][k]];
            scalar* v = &values[nValues*k];
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                v[d] = r.dV[d];
                v[3 + d] = r.dOmega[d];
                v[6 + d] = r.sumLambda[d];
                v[9 + d] = r.sumMoment[d];
            }
            v[12] = r.nInterior;
            v[13] = r.nSurface;
            v[14] = r.nSurfaceDropped;
            v[15] = r.constraintError;
        }
        UOPstream os(q, buffers);
        os << labelList(toGlobal[q]) << values;
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);
    received.add(recvSizes, self);
    for (label q = 0; q < nProcs; ++q)
    {
        if (q == self || recvSizes[q] == 0)
        {
            continue;
        }
        UIPstream is(q, buffers);
        labelList bodies;
        scalarList values;
        is >> bodies >> values;
        forAll(bodies, k)
        {
            const label b = places(bodies[k]);
            if (b < 0)
            {
                FatalErrorInFunction
                    << "rank " << q << " sent the result of particle "
                    << bodies[k] << " (global index) to rank " << self
                    << ", which does not hold it" << exit(FatalError);
            }
            result& r = results[b];
            const scalar* v = &values[nValues*k];
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                r.dV[d] = v[d];
                r.dOmega[d] = v[3 + d];
                r.sumLambda[d] = v[6 + d];
                r.sumMoment[d] = v[9 + d];
            }
            r.nInterior = label(v[12]);
            r.nSurface = label(v[13]);
            r.nSurfaceDropped = label(v[14]);
            r.constraintError = v[15];
        }
    }
    commSeconds += clock.elapsedTime();
}


// ************************************************************************* //

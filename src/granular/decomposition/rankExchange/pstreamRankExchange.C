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

#include "pstreamRankExchange.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include "IPstream.H"
#include "OPstream.H"

#include <chrono>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- Adds the wall-clock time of its scope to a sum
    class timed
    {
        Foam::scalar& sum_;
        const std::chrono::steady_clock::time_point start_;

    public:

        explicit timed(Foam::scalar& sum)
        :
            sum_(sum),
            start_(std::chrono::steady_clock::now())
        {}

        ~timed()
        {
            sum_ += std::chrono::duration<Foam::scalar>
            (
                std::chrono::steady_clock::now() - start_
            ).count();
        }
    };
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pstreamRankExchange::pstreamRankExchange()
:
    ranks_(1, Pstream::myProcNo()),
    seconds_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::pstreamRankExchange::nRanks() const
{
    return Pstream::nProcs();
}


void Foam::pstreamRankExchange::exchange(UList<messages>& perRank) const
{
    const timed clock(seconds_);
    if (perRank.size() != 1)
    {
        FatalErrorInFunction
            << perRank.size() << " ranks' messages in one process"
            << abort(FatalError);
    }
    messages& m = perRank[0];
    const label n = m.ranks.size();
    if (!Pstream::parRun() || !n)
    {
        return;
    }
    // A tag of its own: no message of OpenFOAM's own collectives (which
    // use msgType()) can ever be taken for one of these
    const int tag = UPstream::msgType() + 2718;
    const auto comms = UPstream::commsTypes::nonBlocking;

    // The sizes, then the messages (a rank hears only from its
    // neighbours, which name it among theirs)
    labelList sizeOut(n), sizeIn(n, 0);
    label start = UPstream::nRequests();
    forAll(m.ranks, k)
    {
        UIPstream::read
        (
            comms, m.ranks[k], reinterpret_cast<char*>(&sizeIn[k]),
            sizeof(label), tag
        );
    }
    forAll(m.ranks, k)
    {
        sizeOut[k] = m.out[k].size();
        UOPstream::write
        (
            comms, m.ranks[k], reinterpret_cast<const char*>(&sizeOut[k]),
            sizeof(label), tag
        );
    }
    UPstream::waitRequests(start);

    start = UPstream::nRequests();
    forAll(m.ranks, k)
    {
        m.in[k].setSize(sizeIn[k]);
        if (sizeIn[k])
        {
            UIPstream::read
            (
                comms, m.ranks[k], m.in[k].data(), sizeIn[k], tag
            );
        }
    }
    forAll(m.ranks, k)
    {
        if (sizeOut[k])
        {
            UOPstream::write
            (
                comms, m.ranks[k], m.out[k].cdata(), sizeOut[k], tag
            );
        }
    }
    UPstream::waitRequests(start);
}


Foam::List<Foam::List<char>> Foam::pstreamRankExchange::gather
(
    const UList<DynamicList<char>>& perRank
) const
{
    const timed clock(seconds_);
    List<List<char>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = perRank[0];
    Pstream::gatherList(all);
    if (!Pstream::master())
    {
        all.clear();
    }
    return all;
}


bool Foam::pstreamRankExchange::anyOf(const UList<bool>& perRank) const
{
    const timed clock(seconds_);
    bool any = false;
    for (const bool b : perRank)
    {
        any = any || b;
    }
    return returnReduce(any, orOp<bool>());
}


Foam::scalar Foam::pstreamRankExchange::maxOf
(
    const UList<scalar>& perRank
) const
{
    const timed clock(seconds_);
    scalar m = -VGREAT;
    for (const scalar s : perRank)
    {
        m = max(m, s);
    }
    return returnReduce(m, maxOp<scalar>());
}


Foam::label Foam::pstreamRankExchange::sumOf(const labelUList& perRank) const
{
    const timed clock(seconds_);
    label n = 0;
    for (const label v : perRank)
    {
        n += v;
    }
    return returnReduce(n, sumOp<label>());
}


Foam::scalar Foam::pstreamRankExchange::sumOf
(
    const UList<scalar>& perRank
) const
{
    const timed clock(seconds_);
    scalar sum = 0;
    for (const scalar v : perRank)
    {
        sum += v;
    }
    return returnReduce(sum, sumOp<scalar>());
}


Foam::List<Foam::List<char>> Foam::pstreamRankExchange::allGather
(
    const UList<DynamicList<char>>& perRank
) const
{
    const timed clock(seconds_);
    List<List<char>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = perRank[0];
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    return all;
}


Foam::List<Foam::List<char>> Foam::pstreamRankExchange::scatter
(
    const UList<DynamicList<char>>& fromFirst
) const
{
    const timed clock(seconds_);
    List<List<char>> mine(1);
    if (Pstream::master())
    {
        if (fromFirst.size() != Pstream::nProcs())
        {
            FatalErrorInFunction
                << fromFirst.size() << " messages for "
                << Pstream::nProcs() << " ranks" << abort(FatalError);
        }
        // One rank at a time, each waiting for its message: a scheduled
        // (standard) send, not a buffered one, whose buffer (OpenFOAM's
        // mpiBufferSize, 20 MB by default) a large scene's message would
        // overflow
        for (label q = 1; q < Pstream::nProcs(); ++q)
        {
            OPstream os(Pstream::commsTypes::scheduled, q);
            os << fromFirst[q];
        }
        mine[0] = fromFirst[0];
    }
    else
    {
        IPstream is(Pstream::commsTypes::scheduled, Pstream::masterNo());
        is >> mine[0];
    }
    return mine;
}


// ************************************************************************* //

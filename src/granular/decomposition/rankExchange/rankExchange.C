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

#include "rankExchange.H"
#include "ListOps.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::rankExchange::messages::setRanks(const labelUList& r)
{
    ranks = r;
    out.setSize(r.size());
    for (DynamicList<char>& buf : out)
    {
        buf.clear();
    }
    in.setSize(r.size());
    for (List<char>& buf : in)
    {
        buf.clear();
    }
}


void Foam::rankExchange::put(DynamicList<char>& buf, const vector& v)
{
    put(buf, v.x());
    put(buf, v.y());
    put(buf, v.z());
}


void Foam::rankExchange::put(DynamicList<char>& buf, const quaternion& q)
{
    put(buf, q.w());
    put(buf, q.v());
}


void Foam::rankExchange::get(const UList<char>& buf, label& pos, vector& v)
{
    get(buf, pos, v.x());
    get(buf, pos, v.y());
    get(buf, pos, v.z());
}


void Foam::rankExchange::get
(
    const UList<char>& buf,
    label& pos,
    quaternion& q
)
{
    scalar w;
    vector v;
    get(buf, pos, w);
    get(buf, pos, v);
    // (as it was, not normalised)
    q = quaternion(w, v);
}


void Foam::rankExchange::tooShort(const label size, const label pos)
{
    FatalErrorInFunction
        << "a message of " << size << " bytes read past its end (at "
        << pos << ")" << abort(FatalError);
    std::abort();
}


Foam::virtualRankExchange::virtualRankExchange(const label n)
:
    ranks_(identity(n))
{}


void Foam::virtualRankExchange::exchange(UList<messages>& perRank) const
{
    forAll(perRank, from)
    {
        const messages& m = perRank[from];
        forAll(m.ranks, k)
        {
            const label to = m.ranks[k];
            const label back = perRank[to].ranks.find(from);
            if (back < 0)
            {
                FatalErrorInFunction
                    << "rank " << from << " sends to rank " << to
                    << ", which does not exchange with it (its ranks "
                    << perRank[to].ranks << ")" << abort(FatalError);
            }
            perRank[to].in[back] = m.out[k];
        }
    }
}


Foam::List<Foam::List<char>> Foam::virtualRankExchange::gather
(
    const UList<DynamicList<char>>& perRank
) const
{
    List<List<char>> all(perRank.size());
    forAll(perRank, r)
    {
        all[r] = perRank[r];
    }
    return all;
}


bool Foam::virtualRankExchange::anyOf(const UList<bool>& perRank) const
{
    for (const bool b : perRank)
    {
        if (b)
        {
            return true;
        }
    }
    return false;
}


Foam::scalar Foam::virtualRankExchange::maxOf
(
    const UList<scalar>& perRank
) const
{
    scalar m = -VGREAT;
    for (const scalar s : perRank)
    {
        m = max(m, s);
    }
    return m;
}


Foam::label Foam::virtualRankExchange::sumOf(const labelUList& perRank) const
{
    label n = 0;
    for (const label v : perRank)
    {
        n += v;
    }
    return n;
}


Foam::scalar Foam::virtualRankExchange::sumOf
(
    const UList<scalar>& perRank
) const
{
    scalar sum = 0;
    for (const scalar v : perRank)
    {
        sum += v;
    }
    return sum;
}


Foam::List<Foam::List<char>> Foam::virtualRankExchange::allGather
(
    const UList<DynamicList<char>>& perRank
) const
{
    return gather(perRank);
}


Foam::List<Foam::List<char>> Foam::virtualRankExchange::scatter
(
    const UList<DynamicList<char>>& fromFirst
) const
{
    if (fromFirst.size() != ranks_.size())
    {
        FatalErrorInFunction
            << fromFirst.size() << " messages for " << ranks_.size()
            << " ranks" << abort(FatalError);
    }
    List<List<char>> all(fromFirst.size());
    forAll(fromFirst, r)
    {
        all[r] = fromFirst[r];
    }
    return all;
}


// ************************************************************************* //

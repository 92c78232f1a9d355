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

#include "bodyHolders.H"
#include "periodicImages.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bodyHolders::reductionOrderSum
(
    const labelUList& ranks,
    const UList<scalar>& values
)
{
    if (!Pstream::parRun())
    {
        return ranks.empty() ? 0 : values[0];
    }
    // The schedule reduce() follows (PstreamReduceOps.H)
    return reductionOrderSum
    (
        Pstream::nProcs() < UPstream::nProcsSimpleSum
      ? UPstream::linearCommunication()
      : UPstream::treeCommunication(),
        ranks,
        values
    );
}


Foam::scalar Foam::bodyHolders::reductionOrderSum
(
    const UList<UPstream::commsStruct>& comms,
    const labelUList& ranks,
    const UList<scalar>& values
)
{
    if (ranks.empty())
    {
        return 0;
    }
    // Each rank adds what every rank directly below it sends, in turn, to
    // its own value, and sends the sum up. Only the ranks on a path from a
    // holder to the master take part here: the others' sums are zero and
    // add nothing
    DynamicList<label> onPath;
    for (const label r : ranks)
    {
        for (label q = r; q >= 0 && !onPath.found(q); q = comms[q].above())
        {
            onPath.append(q);
        }
    }
    // Depth first from the master, a rank's sum after those below it
    struct frame
    {
        label rank;
        label next;
        scalar sum;
        bool any;
    };
    DynamicList<frame> stack;
    const auto own = [&](const label r, scalar& v)
    {
        const label k = ranks.find(r);
        v = k < 0 ? 0 : values[k];
        return k >= 0;
    };
    {
        frame f{0, 0, 0, false};
        f.any = own(0, f.sum);
        stack.append(f);
    }
    scalar total = 0;
    while (stack.size())
    {
        frame& f = stack.last();
        const labelList& below = comms[f.rank].below();
        while (f.next < below.size() && !onPath.found(below[f.next]))
        {
            ++f.next;
        }
        if (f.next < below.size())
        {
            frame child{below[f.next], 0, 0, false};
            ++f.next;
            child.any = own(child.rank, child.sum);
            stack.append(child);
            continue;
        }
        const frame done = f;
        stack.remove();
        if (stack.empty())
        {
            total = done.sum;
        }
        else if (done.any)
        {
            frame& parent = stack.last();
            // 0 + x is x exactly: a rank without a value of its own adds
            // nothing to the first sum it receives
            parent.sum = parent.any ? parent.sum + done.sum : done.sum;
            parent.any = true;
        }
    }
    return total;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyHolders::update
(
    const cellCentreSearch& search,
    const boundBox& mesh
)
{
    boxes_.setSize(Pstream::nProcs());
    boxes_[Pstream::myProcNo()] = search.bounds();
    Pstream::gatherList(boxes_);
    Pstream::scatterList(boxes_);
    meshBounds_ = mesh;
}


bool Foam::bodyHolders::rankNear
(
    const label r,
    const point& x,
    const scalar reach,
    const vector& period
) const
{
    const List<vector> shifts
    (
        periodicImages::shifts(meshBounds_, period, x, reach)
    );
    for (const vector& s : shifts)
    {
        if (cellCentreSearch::ballReaches(boxes_[r], x - s, reach))
        {
            return true;
        }
    }
    return false;
}


bool Foam::bodyHolders::boxNear
(
    const label r,
    const boundBox& bb,
    const scalar reach,
    const vector& period
) const
{
    const boundBox& box = boxes_[r];
    scalar dist2 = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        scalar gap = VGREAT;
        for (const scalar k : {0.0, -1.0, 1.0})
        {
            if (k != 0 && !(period[d] > 0))
            {
                continue;
            }
            const scalar lo = bb.min()[d] + k*period[d];
            const scalar hi = bb.max()[d] + k*period[d];
            gap = min(gap, max(scalar(0), max(lo - box.max()[d], box.min()[d] - hi)));
        }
        dist2 += sqr(gap);
    }
    return dist2 <= sqr(reach);
}


void Foam::bodyHolders::ranksNear
(
    const point& x,
    const scalar reach,
    const vector& period,
    DynamicList<label>& ranks
) const
{
    ranks.clear();
    const List<vector> shifts
    (
        periodicImages::shifts(meshBounds_, period, x, reach)
    );
    forAll(boxes_, r)
    {
        for (const vector& s : shifts)
        {
            if (cellCentreSearch::ballReaches(boxes_[r], x - s, reach))
            {
                ranks.append(r);
                break;
            }
        }
    }
}


// ************************************************************************* //

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
    Foam::fictitiousDomain with bodies per rank: which ranks hold a body,
    and the cell sums of each body shared among them.

\*---------------------------------------------------------------------------*/

#include "fictitiousDomain.H"
#include "bodyExchange.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fictitiousDomain::holderReach
(
    const particleShape& shape
) const
{
    // A body's points lie within its bounding radius and reach() cells of
    // it (with h, the mean size of its cells, at most the largest), and
    // its wall links within three faces of its cells; the cells it held at
    // the last step, a step's travel back, within one more cell (a body
    // moving farther is refused in owedForCellsLeft)
    return shape.boundingRadius() + (holderCells() + 1)*perRank_.largestCellSize;
}


Foam::scalar Foam::fictitiousDomain::holderCells() const
{
    // The treatment's (with wall links, a fluid cell two faces from a
    // body's cell may link through the body to its neighbour beyond: the
    // rank of a cell three faces out needs the body)
    return treatment_->holderCells();
}


void Foam::fictitiousDomain::ranksHolding
(
    const body& B,
    DynamicList<label>& ranks
) const
{
    perRank_.holders.ranksNear
    (
        B.centre, holderReach(*B.shape), images_.period(), ranks
    );
    if (!ranks.found(B.resultRank))
    {
        ranks.append(B.resultRank);
        Foam::sort(ranks);
    }
}


void Foam::fictitiousDomain::updateHolders()
{
    perRank_.holders.update(search_, mesh_.bounds());
    perRank_.largestCellSize = 0;
    forAll(mesh_.V(), c)
    {
        perRank_.largestCellSize = max(perRank_.largestCellSize, cellSize(mesh_.V()[c]));
    }
    reduce(perRank_.largestCellSize, maxOp<scalar>());
    perRank_.partners = holderPartners();
    perRank_.heldBy.clear();
}


Foam::labelList Foam::fictitiousDomain::holderPartners() const
{
    const label me = Pstream::myProcNo();
    const scalar R = perRank_.largestRadius + (holderCells() + 1)*perRank_.largestCellSize;
    const vector& period = images_.period();
    DynamicList<label> partners;
    for (label q = 0; q < Pstream::nProcs(); ++q)
    {
        if
        (
            q != me
         && (
                perRank_.holders.boxNear(q, perRank_.holders.box(me), 2*R, period)
             || perRank_.holders.boxNear(me, perRank_.holders.box(q), 2*R, period)
             || perRank_.holders.boxNear(me, perRank_.ownerBoxes[q], R, period)
             || perRank_.holders.boxNear(q, perRank_.ownerBoxes[me], R, period)
            )
        )
        {
            partners.append(q);
        }
    }
    return labelList(std::move(partners));
}


const Foam::List<Foam::labelList>& Foam::fictitiousDomain::holdersOf
(
    const UList<body>& bodies
) const
{
    if (perRank_.heldBy.foundFor(bodies))
    {
        return perRank_.heldBy.holders;
    }
    const label me = Pstream::myProcNo();

    // Each body's holders, found alike by each of them; the ranks this
    // rank talks to are its partners by the boxes alone, so that a rank
    // that lacks a body another holds still answers (with records the
    // other finds wrong: a message, not a wait)
    List<labelList>& holders = perRank_.heldBy.holders;
    perRank_.heldBy.clear();
    holders.setSize(bodies.size());
    DynamicList<label> near;
    forAll(bodies, b)
    {
        const label particle = bodyPlaces::global(bodies, b);
        if (b > 0 && !(bodyPlaces::global(bodies, b - 1) < particle))
        {
            FatalErrorInFunction
                << "with bodies per rank the list must be in ascending"
                << " global index: particle " << particle << " follows "
                << bodyPlaces::global(bodies, b - 1) << exit(FatalError);
        }
        ranksHolding(bodies[b], near);
        if (!near.found(me))
        {
            FatalErrorInFunction
                << "rank " << me << " was given particle " << particle
                << " at " << bodies[b].centre << ", which none of its cell"
                << " centres comes within " << holderReach(*bodies[b].shape)
                << " m of and whose results rank " << bodies[b].resultRank
                << " takes" << exit(FatalError);
        }
        if (bodies[b].shape->boundingRadius() > perRank_.largestRadius)
        {
            FatalErrorInFunction
                << "particle " << particle << " reaches "
                << bodies[b].shape->boundingRadius() << " m from its centre,"
                << " beyond the largest bounding radius given at the start, "
                << perRank_.largestRadius << " m" << exit(FatalError);
        }
        holders[b] = near;
        for (const label r : near)
        {
            if (r != me && findSortedIndex(perRank_.partners, r) < 0)
            {
                FatalErrorInFunction
                    << "rank " << r << " holds particle " << particle
                    << " with rank " << me << " but is not among its"
                    << " partners " << perRank_.partners << " (their boxes lie"
                    << " beyond the largest holder reach)" << exit(FatalError);
            }
        }
    }
    perRank_.heldBy.keepKey(bodies);
    return holders;
}


void Foam::fictitiousDomain::exchangeAmongHolders
(
    UList<rankExchange::messages>& m
)
{
    clockTime clock;
    perRank_.exchange.exchange(m);
    traffic_.commSeconds += clock.elapsedTime();
    for (const rankExchange::messages& msg : m)
    {
        for (const List<char>& in : msg.in)
        {
            if (in.size())
            {
                ++traffic_.received.messages;
                traffic_.received.bytes += in.size();
            }
        }
    }
}


void Foam::fictitiousDomain::shareAmongHolders
(
    const UList<body>& bodies,
    scalarField& sumV,
    scalarField& count,
    labelList& solver,
    boolList& masterHolds
)
{
    const label me = Pstream::myProcNo();
    const label n = bodies.size();

    const List<labelList>& holders = holdersOf(bodies);
    masterHolds.setSize(n);
    forAll(bodies, b)
    {
        masterHolds[b] = holders[b].found(0);
    }
    List<rankExchange::messages> m(1);
    m[0].setRanks(perRank_.partners);
    const labelList& partners = m[0].ranks;
    forAll(bodies, b)
    {
        for (const label r : holders[b])
        {
            if (r != me)
            {
                DynamicList<char>& out = m[0].out[findSortedIndex(partners, r)];
                rankExchange::put(out, bodyPlaces::global(bodies, b));
                rankExchange::put(out, sumV[b]);
                rankExchange::put(out, count[b]);
            }
        }
    }
    exchangeAmongHolders(m);

    // Every holder's sums, added in the whole scene's reduction order; the
    // solver: the most cells, the lowest rank of those with as many
    labelList pos(partners.size(), 0);
    solver.setSize(n);
    scalarList v, c;
    forAll(bodies, b)
    {
        const labelList& H = holders[b];
        v.setSize(H.size());
        c.setSize(H.size());
        forAll(H, j)
        {
            if (H[j] == me)
            {
                v[j] = sumV[b];
                c[j] = count[b];
            }
            else
            {
                const label k = findSortedIndex(partners, H[j]);
                label g = -1;
                rankExchange::get(m[0].in[k], pos[k], g);
                if (g != bodyPlaces::global(bodies, b))
                {
                    FatalErrorInFunction
                        << "rank " << H[j] << " sent rank " << me << " the"
                        << " cell sums of particle " << g << " where those of "
                        << bodyPlaces::global(bodies, b) << " were expected:"
                        << " the two ranks do not agree on the bodies they"
                        << " hold (a particle that travelled farther than the"
                        << " margin its state was sent with)" << exit(FatalError);
                }
                rankExchange::get(m[0].in[k], pos[k], v[j]);
                rankExchange::get(m[0].in[k], pos[k], c[j]);
            }
        }
        sumV[b] = bodyHolders::reductionOrderSum(H, v);
        count[b] = bodyHolders::reductionOrderSum(H, c);
        solver[b] = -1;
        scalar most = 0;
        forAll(H, j)
        {
            if (c[j] > most)
            {
                most = c[j];
                solver[b] = H[j];
            }
        }
    }
    forAll(partners, k)
    {
        if (pos[k] != m[0].in[k].size())
        {
            FatalErrorInFunction
                << "rank " << partners[k] << " sent rank " << me << " "
                << m[0].in[k].size() << " bytes of cell sums, " << pos[k]
                << " expected: the two ranks do not agree on the bodies"
                << " they hold (a particle that travelled farther than the"
                << " margin its state was sent with)" << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fictitiousDomain::sumAmongHolders
(
    const UList<body>& bodies,
    const label width,
    scalarList& values,
    scalarList& shared,
    boolList& has
)
{
    const label me = Pstream::myProcNo();
    const label n = bodies.size();
    if
    (
        values.size() != width*n || shared.size() != width*n
     || has.size() != n
    )
    {
        FatalErrorInFunction
            << "sums of " << width << " numbers for " << n << " bodies need "
            << width*n << " values and as many to share, given "
            << values.size() << " and " << shared.size() << exit(FatalError);
    }

    // A record per body both ranks hold: its global index, the sender's
    // values, whether it has the values to share, and those
    const List<labelList>& holders = holdersOf(bodies);
    List<rankExchange::messages> m(1);
    m[0].setRanks(perRank_.partners);
    const labelList& partners = m[0].ranks;
    forAll(bodies, b)
    {
        for (const label r : holders[b])
        {
            if (r == me)
            {
                continue;
            }
            DynamicList<char>& out = m[0].out[findSortedIndex(partners, r)];
            rankExchange::put(out, bodyPlaces::global(bodies, b));
            for (label i = 0; i < width; ++i)
            {
                rankExchange::put(out, values[width*b + i]);
            }
            rankExchange::put(out, label(has[b]));
            for (label i = 0; has[b] && i < width; ++i)
            {
                rankExchange::put(out, shared[width*b + i]);
            }
        }
    }
    exchangeAmongHolders(m);

    // Each holder's values, added in the whole scene's reduction order
    labelList pos(partners.size(), 0);
    List<scalarList> v(width);
    forAll(bodies, b)
    {
        const labelList& H = holders[b];
        const label g = bodyPlaces::global(bodies, b);
        for (scalarList& column : v)
        {
            column.setSize(H.size());
        }
        forAll(H, j)
        {
            if (H[j] == me)
            {
                for (label i = 0; i < width; ++i)
                {
                    v[i][j] = values[width*b + i];
                }
                continue;
            }
            const label k = findSortedIndex(partners, H[j]);
            label sent = -1;
            rankExchange::get(m[0].in[k], pos[k], sent);
            if (sent != g)
            {
                FatalErrorInFunction
                    << "rank " << H[j] << " sent rank " << me << " the"
                    << " values of particle " << sent << " where those of "
                    << g << " were expected: the two ranks do not agree on"
                    << " the bodies they hold" << exit(FatalError);
            }
            for (label i = 0; i < width; ++i)
            {
                rankExchange::get(m[0].in[k], pos[k], v[i][j]);
            }
            label sentShared = 0;
            rankExchange::get(m[0].in[k], pos[k], sentShared);
            // This rank's own values to share, or the lowest holder's
            scalar x = 0;
            for (label i = 0; sentShared && i < width; ++i)
            {
                rankExchange::get(m[0].in[k], pos[k], x);
                if (!has[b])
                {
                    shared[width*b + i] = x;
                }
            }
            has[b] = has[b] || sentShared;
        }
        for (label i = 0; i < width; ++i)
        {
            values[width*b + i] = bodyHolders::reductionOrderSum(H, v[i]);
        }
    }
    forAll(partners, k)
    {
        if (pos[k] != m[0].in[k].size())
        {
            FatalErrorInFunction
                << "rank " << partners[k] << " sent rank " << me << " "
                << m[0].in[k].size() << " bytes of sums among the holders, "
                << pos[k] << " expected: the two ranks do not agree on the"
                << " bodies they hold" << exit(FatalError);
        }
    }
}



void Foam::fictitiousDomain::setBodiesPerRank
(
    List<boundBox>&& ownerBoxes,
    const scalar largestRadius
)
{
    if (ownerBoxes.size() != Pstream::nProcs())
    {
        FatalErrorInFunction
            << ownerBoxes.size() << " boxes of owned particles for "
            << Pstream::nProcs() << " ranks" << exit(FatalError);
    }
    perRank_.on = true;
    perRank_.ownerBoxes.transfer(ownerBoxes);
    perRank_.largestRadius = largestRadius;
    updateHolders();
}


bool Foam::fictitiousDomain::holds(const body& B) const
{
    return !perRank_.on || rankHolds(Pstream::myProcNo(), B);
}


bool Foam::fictitiousDomain::rankHolds(const label r, const body& B) const
{
    // The test ranksHolding makes for rank r
    return
        B.resultRank == r
     || perRank_.holders.rankNear
        (
            r, B.centre, holderReach(*B.shape), images_.period()
        );
}


void Foam::fictitiousDomain::setMasterOwed
(
    Map<vector>&& momentum,
    Map<vector>&& moment
)
{
    owed_.masterMomentum.transfer(momentum);
    owed_.masterMoment.transfer(moment);
}


// ************************************************************************* //

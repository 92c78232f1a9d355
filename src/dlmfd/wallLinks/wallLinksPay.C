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
    Foam::wallLinks::pay: the momentum the bodies pay for what the fluid
    gained at their links in a step, with the share of each body's history
    that the time scheme carries into this one.

\*---------------------------------------------------------------------------*/

#include "wallLinks.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::vector> Foam::wallLinks::gainedAtLinks
(
    const volVectorField& U,
    const scalar dt,
    const scalar ddtCoeff
) const
{
    const label nBodies = globalOf_.size();
    // A 1/c share of the flux per body, its momentum then its moment
    List<vector> gained(2*nBodies, Zero);
    const vectorField& u = U.primitiveField();
    const PtrList<vectorField> uNbr(neighbourVelocities(U));
    for (const link& L : links_)
    {
        const label c = L.fluid;
        // c's row: the link's flux (implicit in u_E, across a coupled
        // patch too)
        const vector uE = L.farWall ? L.uFar : oppositeVelocity(L, u, uNbr);
        vector gain =
          - (
                L.coeffs[0]*L.uWall + L.coeffs[1]*u[c]
              + L.coeffs[2]*uE
            );
        // c no longer exchanges the Laplacian's flux with g, while g's
        // row keeps k0 (u_c - u_g) (on the other rank across a processor
        // patch, which has no link for it), unless g is a fluid cell with
        // its own link through the body
        if (!L.through)
        {
            const vector uG =
                L.face >= 0 ? u[L.solid] : uNbr[L.patch][L.patchFace];
            gain += L.coeffs[3]*(u[c] - uG);
        }
        const vector p = dt/ddtCoeff*gain;
        gained[L.body] += p;
        gained[nBodies + L.body] += L.arm ^ p;
    }

    return gained;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::wallLinks::sizeHistory(const label nBodies, const label nScene)
{
    if (globalOf_.size() != nBodies)
    {
        FatalErrorInFunction
            << "paying for " << nBodies << " bodies, but the links were"
            << " found (update) for " << globalOf_.size()
            << exit(FatalError);
    }
    // A restart's history is one per particle, by global index; a body
    // added later starts without one (known: it is zero). With bodies per
    // rank every particle of the scene from the first step on: a body that
    // comes near later has its history from its holders, not a zero
    const label nGlobal =
        max(globalOf_.empty() ? label(0) : max(globalOf_) + 1, nScene);
    if (nGlobal == 0)
    {
        return;
    }
    if (historyMomentum_.size() < nGlobal)
    {
        historyMomentum_.setSize(nGlobal, Zero);
        historyMoment_.setSize(nGlobal, Zero);
    }
    if (historyIndex_.size() < historyMomentum_.size())
    {
        historyIndex_.setSize(historyMomentum_.size(), lastPayIndex_);
    }
}


void Foam::wallLinks::pay
(
    const volVectorField& U,
    const scalar dt,
    const scalar ddtCoeff,
    List<vector>& momentum,
    List<vector>& moment
)
{
    const label nBodies = momentum.size();
    sizeHistory(nBodies);

    // This step's flux on this rank: a 1/c share per body, its momentum
    // then its moment (one list: one reduction below)
    List<vector> gained(gainedAtLinks(U, dt, ddtCoeff));

    // Each rank pays its own share; (c - 1)/c of the history (the same on
    // every rank) once, on the master
    const scalar carried = (ddtCoeff - 1)/ddtCoeff;
    for (label b = 0; b < nBodies; ++b)
    {
        momentum[b] += gained[b];
        moment[b] += gained[nBodies + b];
        if (Pstream::master())
        {
            momentum[b] += carried*historyMomentum_[globalOf_[b]];
            moment[b] += carried*historyMoment_[globalOf_[b]];
        }
    }

    // The history for the next step: this step's gain of every rank
    Pstream::listCombineGather(gained, plusEqOp<vector>());
    Pstream::listCombineScatter(gained);
    for (label b = 0; b < nBodies; ++b)
    {
        vector& H = historyMomentum_[globalOf_[b]];
        vector& HMoment = historyMoment_[globalOf_[b]];
        H = gained[b] + carried*H;
        HMoment = gained[nBodies + b] + carried*HMoment;
    }
}


void Foam::wallLinks::payAmongHolders
(
    const volVectorField& U,
    const scalar dt,
    const scalar ddtCoeff,
    fictitiousDomain& fd,
    const UList<body>& held,
    List<vector>& momentum,
    List<vector>& moment,
    Map<vector>& masterOwedMomentum,
    Map<vector>& masterOwedMoment,
    const label nScene
)
{
    const label me = Pstream::myProcNo();
    const label nBodies = momentum.size();
    sizeHistory(nBodies, nScene);
    const List<vector> gained(gainedAtLinks(U, dt, ddtCoeff));

    // Per body this rank holds: its gain here, summed over the holders as
    // the reduction of pay() would (a rank with links of a body holds
    // it), and its history from the holders that updated it at the last
    // step (those whose cells are near it then and now; its owner, the
    // box its centre is in, may be a new holder)
    const label width = 6;
    const label n = held.size();
    const bodyPlaces& places = places_;
    scalarList values(width*n, Zero), history(width*n, Zero);
    boolList has(n, false);
    for (label k = 0; k < n; ++k)
    {
        const label g = bodyPlaces::global(held, k);
        const label b = places(g);
        if (b < 0)
        {
            FatalErrorInFunction
                << "rank " << me << " holds particle " << g << ", which is"
                << " not in the list its links were found for (update)"
                << exit(FatalError);
        }
        has[k] = historyIndex_[g] == lastPayIndex_;
        for (label i = 0; i < 3; ++i)
        {
            values[width*k + i] = gained[b][i];
            values[width*k + 3 + i] = gained[nBodies + b][i];
            if (has[k])
            {
                history[width*k + i] = historyMomentum_[g][i];
                history[width*k + 3 + i] = historyMoment_[g][i];
            }
        }
    }
    fd.sumAmongHolders(held, width, values, history, has);
    forAll(has, k)
    {
        if (!has[k])
        {
            FatalErrorInFunction
                << "none of the ranks that hold particle "
                << bodyPlaces::global(held, k) << " now held it at the last"
                << " step (time index " << lastPayIndex_ << "): its wall"
                << " links' history (fictitiousDomain ghostShear link) is"
                << " lost" << exit(FatalError);
        }
    }

    // Each rank pays its own share; the master (c - 1)/c of the history of
    // the bodies it holds; of each other, that share is left in
    // masterOwedMomentum (the solver adds it as the master's part: 0 + x is
    // x)
    const scalar carried = (ddtCoeff - 1)/ddtCoeff;
    masterOwedMomentum.clear();
    masterOwedMoment.clear();
    const label index = U.mesh().time().timeIndex();
    const List<labelList>& holders = fd.holdersOf(held);
    for (label k = 0; k < n; ++k)
    {
        const bool masterHolds = holders[k].found(0);
        const label g = bodyPlaces::global(held, k);
        const label b = places(g);
        const vector sum
        (
            values[width*k], values[width*k + 1], values[width*k + 2]
        );
        const vector sumMoment
        (
            values[width*k + 3], values[width*k + 4], values[width*k + 5]
        );
        const vector H
        (
            history[width*k], history[width*k + 1], history[width*k + 2]
        );
        const vector HMoment
        (
            history[width*k + 3], history[width*k + 4],
            history[width*k + 5]
        );
        momentum[b] += gained[b];
        moment[b] += gained[nBodies + b];
        if (masterHolds)
        {
            if (Pstream::master())
            {
                momentum[b] += carried*H;
                moment[b] += carried*HMoment;
            }
        }
        else
        {
            masterOwedMomentum.set(g, carried*H);
            masterOwedMoment.set(g, carried*HMoment);
        }
        historyMomentum_[g] = sum + carried*H;
        historyMoment_[g] = sumMoment + carried*HMoment;
        historyIndex_[g] = index;
    }
    lastPayIndex_ = index;

    // A restart is written whole by every rank: each body's history from
    // its owner (the others give exact zeros)
    if (U.mesh().time().writeTime())
    {
        // (each rank's history reaches the largest global index it has
        // held: the ranks agree on the longest)
        const label nGlobal =
            returnReduce(historyMomentum_.size(), maxOp<label>());
        List<vector> all(2*nGlobal, Zero);
        for (label k = 0; k < n; ++k)
        {
            if (held[k].resultRank == me)
            {
                const label g = bodyPlaces::global(held, k);
                all[g] = historyMomentum_[g];
                all[nGlobal + g] = historyMoment_[g];
            }
        }
        Pstream::listCombineGather(all, plusEqOp<vector>());
        Pstream::listCombineScatter(all);
        historyMomentum_ = SubList<vector>(all, nGlobal);
        historyMoment_ = SubList<vector>(all, nGlobal, nGlobal);
    }
}


// ************************************************************************* //

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
    Foam::particleDistributions::owned's step: the owners' granular step and
    the new states sent to the ranks near each particle.

\*---------------------------------------------------------------------------*/

#include "owned.H"
#include "bodyPlaces.H"
#include "Time.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::particleDistributions::owned::statePartners
(
    const scalar reach
) const
{
    // The ranks whose cells come near this rank's box, or whose box this
    // rank's cells or box come near (each side finds the other)
    const label me = Pstream::myProcNo();
    DynamicList<label> boxNeighbours;
    boxes_->neighbours(me, reach, boxNeighbours);
    DynamicList<label> partners;
    for (label q = 0; q < Pstream::nProcs(); ++q)
    {
        if
        (
            q != me
         && (
                fd_.rankNearBox(q, boxes_->bounds(me), reach)
             || fd_.rankNearBox(me, boxes_->bounds(q), reach)
             || boxNeighbours.found(q)
            )
        )
        {
            partners.append(q);
        }
    }
    return labelList(std::move(partners));
}


void Foam::particleDistributions::owned::sendStates
(
    const List<fictitiousDomain::body>& bodies
)
{
    // A rank needs a particle's new state if its cells come within the
    // particle's holder reach of where the particle was this step (the
    // interior cells it moves with the particle below) or of where the
    // next step's predictor puts it: within that reach of its new
    // centre, plus the distance from this step's predicted centre and
    // twice the next step's travel at this step's dt (a margin for a
    // longer next step; a rank the state misses stops the next step's
    // exchange of cell sums). A mesh that changes around the particles
    // may reach farther at its next update (stateReach)
    const label me = Pstream::myProcNo();
    const granularSystem& part = *part_;
    List<List<labelList>> sendTo(1, List<labelList>(part.size()));
    if (everyStateEverywhere())
    {
        // A changing mesh that tells no reach may change cells anywhere:
        // every state to every rank
        DynamicList<label> others(Pstream::nProcs());
        for (label q = 0; q < Pstream::nProcs(); ++q)
        {
            if (q != me)
            {
                others.append(q);
            }
        }
        for (labelList& to : sendTo[0])
        {
            to = others;
        }
        const List<labelList> everyone(1, others);
        DynamicList<granularSystem::particleRecord> mirror;
        const Pair<scalar> received =
            steps_->sendStates(sendTo, everyone, mirror);
        setMirror(mirror);
        costs_.mirrorParticles += particles_.size();
        costs_.stateMessages += received.first();
        costs_.stateBytes += received.second();
        ++costs_.nStateSteps;
        return;
    }
    scalar farthest = 0;
    DynamicList<label> near, nextOwners;
    const bodyPlaces places(bodies);
    for (label i = 0; i < part.size(); ++i)
    {
        const rigidParticle& p = part.particle(i);
        const fictitiousDomain::body& B = ownBody(bodies, places, i);
        const scalar moved =
            mag(particles_.separation(p.position(), B.centre));
        const scalar next = nextStepTravel(p);
        const scalar reach = stateReach(p) + moved + next;
        farthest = max(farthest, reach);
        fd_.ranksNear(p.position(), reach, near);
        // and the ranks whose box it may enter in the next step: its owner
        // then, which needs its body in the step's list
        boxes_->ranksWithin(p.position(), next, nextOwners);
        DynamicList<label> to(near.size());
        for (const label r : near)
        {
            if (r != me)
            {
                to.append(r);
            }
        }
        for (const label r : nextOwners)
        {
            if (r != me && !near.found(r))
            {
                to.append(r);
            }
        }
        Foam::sort(to);
        sendTo[0][i].transfer(to);
    }
    reduce(farthest, maxOp<scalar>());
    // (the box bounds the owners' centres; a centre on its face is in it)
    const List<labelList> partners
    (
        1, statePartners(farthest*(1 + 1e-9) + VSMALL)
    );
    DynamicList<granularSystem::particleRecord> mirror;
    const Pair<scalar> received =
        steps_->sendStates(sendTo, partners, mirror);
    setMirror(mirror);
    costs_.mirrorParticles += particles_.size();
    costs_.stateMessages += received.first();
    costs_.stateBytes += received.second();
    ++costs_.nStateSteps;
}


Foam::label Foam::particleDistributions::owned::evolveOwned
(
    const List<fictitiousDomain::body>& bodies,
    const List<vector>& V3,
    const List<vector>& omega3
)
{
    // The new velocities, which this rank took as the owner, set on its
    // part by the same calls the master makes in the master-side step
    // (the part holds its own particles only: the last step dropped the
    // ghosts)
    granularSystem& part = *part_;
    const bodyPlaces places(bodies);
    for (label i = 0; i < part.size(); ++i)
    {
        const label g = part.globalIndex(i);
        const fictitiousDomain::body& B = ownBody(bodies, places, i);
        if (B.resultRank != Pstream::myProcNo())
        {
            FatalErrorInFunction
                << "Particle " << part.id(i) << " (global index " << g
                << ") is owned by rank " << Pstream::myProcNo()
                << " but its centre " << part.particle(i).position()
                << " lies in rank " << B.resultRank << "'s box"
                << exit(FatalError);
        }
        if (B.free)
        {
            rigidParticle& p = part.particle(i);
            p.setVelocity(V3[places(g)]);
            p.setOmega(omega3[places(g)]);
        }
    }
    const label nSub = steps_->evolve(mesh_.time().deltaTValue());
    part.checkHealth(mesh_.time().value());
    if (const label far = steps_->lastCounters().nFarRecords)
    {
        WarningInFunction
            << "t = " << mesh_.time().value() << ": " << far
            << " ghost records came to a rank beyond their reach and were"
            << " dropped" << endl;
    }

    // The new states to the ranks near each particle
    sendStates(bodies);
    return nSub;
}


// ************************************************************************* //

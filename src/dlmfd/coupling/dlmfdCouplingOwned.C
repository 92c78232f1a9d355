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
    Foam::dlmfdCoupling with particleDistribution owned: the start (the
    boxes, this rank's part and mirror from the master's reading), the bodies a
    rank's fictitious domain takes, the owners' step and the new states
    sent to the ranks near each particle.

\*---------------------------------------------------------------------------*/

#include "dlmfdCoupling.H"
#include "Time.H"
#include "meshChangeReach.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dlmfdCoupling::setOwned(const sceneEffects& effects)
{
    // The boxes: the mesh's decomposition where its ranks' cells make a
    // grid of boxes numbered x fastest (simple, hierarchical xyz), so that
    // a particle's owner is the rank its centre's cell is on; else the
    // factors of the number of ranks that cut the domain with the least
    // area between boxes (one box along a direction that is one cell
    // deep: a 2D case), which need not follow the cells: more bodies then
    // travel to ranks whose cells are far from them
    List<boundBox> meshBoxes(Pstream::nProcs());
    meshBoxes[Pstream::myProcNo()] = boundBox(mesh_.points(), false);
    Pstream::gatherList(meshBoxes);
    Pstream::scatterList(meshBoxes);
    ownedScene_.boxes = boxDecomposition::fromRankBoxes
    (
        granular_.domain(), granular_.periodic(), meshBoxes
    );
    const bool fromMesh = ownedScene_.boxes.valid();
    if (!fromMesh)
    {
        ownedScene_.boxes.reset
        (
            new boxDecomposition
            (
                granular_.domain(), granular_.periodic(),
                boxDecomposition::leastAreaBoxes
                (
                    granular_.domain().span(), Pstream::nProcs()
                )
            )
        );
    }
    const labelVector& n = ownedScene_.boxes->n();

    // Each rank's fictitious domain takes the bodies near its cells and
    // its own
    List<boundBox> ownerBoxes(Pstream::nProcs());
    forAll(ownerBoxes, r)
    {
        ownerBoxes[r] = ownedScene_.boxes->bounds(r);
    }
    scalar largestRadius = 0;
    for (label i = 0; i < scene().size(); ++i)
    {
        largestRadius =
            max(largestRadius, scene().particle(i).shape().boundingRadius());
    }
    Pstream::scatter(largestRadius);
    fd_.setBodiesPerRank(std::move(ownerBoxes), largestRadius);

    // This rank's part and mirror: its own particles and those its first
    // step lists, from the master's reading
    ownedScene_.part = sceneWithoutParticles(effects);
    UPtrList<granularSystem> parts(1);
    parts.set(0, ownedScene_.part.get());
    {
        const List<List<granularSystem::particleRecord>> near
        (
            ownedGranularSteps::scatterScene
            (
                ownedScene_.exchange, *ownedScene_.boxes,
                Pstream::master() ? ownedScene_.whole.get() : nullptr,
                Pstream::master() ? destinationsAtStart() : List<labelList>(),
                parts
            )
        );
        granular_.setScene(granular_.localConstants());
        setMirror(near[0]);
    }
    owned_.reset(new ownedGranularSteps(std::move(parts), *ownedScene_.boxes, ownedScene_.exchange));
    Info<< "Particle distribution: owned, " << n.x() << " x " << n.y()
        << " x " << n.z() << " boxes of the collision domain; each rank"
        << " moves the particles in its box" << nl;
    if (fromMesh)
    {
        Info<< "    the boxes are the mesh decomposition's: each particle is"
            << " owned by the rank of the cell its centre lies in" << nl;
    }
    else
    {
        Info<< "    the mesh decomposition's ranks do not make a grid of"
            << " boxes numbered x fastest (decomposeParDict: method simple,"
            << " or hierarchical with order xyz, do): the boxes cut the"
            << " domain evenly and a particle's owner may not be the rank"
            << " of its cell, which sends more bodies between ranks" << nl;
    }
}


const Foam::UList<Foam::fictitiousDomain::body>&
Foam::dlmfdCoupling::bodiesHeld
(
    const List<fictitiousDomain::body>& bodies,
    List<fictitiousDomain::body>& held
) const
{
    if (!owned_)
    {
        return bodies;
    }
    // Among the particles listed, whose state is the last step's, in
    // ascending global index
    DynamicList<fictitiousDomain::body> near;
    for (const fictitiousDomain::body& b : bodies)
    {
        if (fd_.holds(b))
        {
            near.append(b);
        }
    }
    held.transfer(near);
    return held;
}


Foam::label Foam::dlmfdCoupling::mirrorPlace(const label g) const
{
    return owned_ ? findSortedIndex(ownedScene_.fresh, g) : g;
}


void Foam::dlmfdCoupling::setMirror
(
    const UList<granularSystem::particleRecord>& records
)
{
    granular_.setParticles(records, boolList(records.size(), false), nullptr);
    ownedScene_.fresh.resize(records.size());
    forAll(records, k)
    {
        ownedScene_.fresh[k] = records[k].global;
    }
}


const Foam::fictitiousDomain::body& Foam::dlmfdCoupling::ownBody
(
    const UList<fictitiousDomain::body>& bodies,
    const bodyPlaces& places,
    const label i
) const
{
    const label g = ownedScene_.part->globalIndex(i);
    const label k = places(g);
    if (k < 0)
    {
        FatalErrorInFunction
            << "Particle " << ownedScene_.part->id(i) << " (global index " << g
            << ") is owned by rank " << Pstream::myProcNo() << " but is not"
            << " in the rank's list of bodies: its state was not the last"
            << " step's here (a rank is sent the state of each particle that"
            << " may enter its box in the next step)"
            << exit(FatalError);
    }
    return bodies[k];
}


const Foam::meshChangeReach* Foam::dlmfdCoupling::meshChange() const
{
    return
        mesh_.dynamic()
      ? dynamic_cast<const meshChangeReach*>(&mesh_)
      : nullptr;
}


bool Foam::dlmfdCoupling::everyStateEverywhere() const
{
    return mesh_.dynamic() && !meshChange();
}


Foam::scalar Foam::dlmfdCoupling::stateReach(const rigidParticle& p) const
{
    const scalar hold = fd_.holderReach(p.shape());
    const meshChangeReach* change = meshChange();
    if (!change)
    {
        return hold;
    }
    // (the update's look-ahead at twice this step's dt: the next step,
    // whose dt the update uses, may be longer; nextStepTravel's margin)
    return max
    (
        hold,
        change->bodyReach
        (
            p.shape().boundingRadius(), mag(p.velocity()),
            2*mesh_.time().deltaTValue()
        )
    );
}


Foam::List<Foam::labelList> Foam::dlmfdCoupling::destinationsAtStart() const
{
    // What sendStates sends after a step: a particle goes to the ranks
    // whose cells come within its reach (stateReach) and twice a step's
    // travel, and to the rank whose box it may enter in the next step; the
    // scene read at the start looked through once, on the master, so that
    // no step does
    const granularSystem& all = scene();
    List<labelList> destinations(all.size());
    const label nProcs = Pstream::nProcs();
    if (everyStateEverywhere())
    {
        // A changing mesh that tells no reach: every state to every rank
        const labelList everyone(identity(nProcs));
        for (labelList& to : destinations)
        {
            to = everyone;
        }
        return destinations;
    }
    DynamicList<label> owners, to;
    for (label g = 0; g < all.size(); ++g)
    {
        const rigidParticle& p = all.particle(g);
        const scalar next = nextStepTravel(p);
        const scalar reach = stateReach(p) + next;
        const boundBox centre(p.position(), p.position());
        ownedScene_.boxes->ranksWithin(p.position(), next, owners);
        to.clear();
        for (label q = 0; q < nProcs; ++q)
        {
            if (owners.found(q) || fd_.rankNearBox(q, centre, reach))
            {
                to.append(q);
            }
        }
        destinations[g] = to;
    }
    return destinations;
}


Foam::scalar Foam::dlmfdCoupling::nextStepTravel
(
    const rigidParticle& p
) const
{
    const scalar dt = mesh_.time().deltaTValue();
    return 2*dt*(mag(p.velocity()) + 2*dt*mag(g_));
}


Foam::labelList Foam::dlmfdCoupling::statePartners(const scalar reach) const
{
    // The ranks whose cells come near this rank's box, or whose box this
    // rank's cells or box come near (each side finds the other)
    const label me = Pstream::myProcNo();
    DynamicList<label> boxNeighbours;
    ownedScene_.boxes->neighbours(me, reach, boxNeighbours);
    DynamicList<label> partners;
    for (label q = 0; q < Pstream::nProcs(); ++q)
    {
        if
        (
            q != me
         && (
                fd_.rankNearBox(q, ownedScene_.boxes->bounds(me), reach)
             || fd_.rankNearBox(me, ownedScene_.boxes->bounds(q), reach)
             || boxNeighbours.found(q)
            )
        )
        {
            partners.append(q);
        }
    }
    return labelList(std::move(partners));
}


void Foam::dlmfdCoupling::sendStates
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
    const granularSystem& part = *ownedScene_.part;
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
            owned_->sendStates(sendTo, everyone, mirror);
        setMirror(mirror);
        costs_.mirrorParticles += granular_.size();
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
            mag(granular_.separation(p.position(), B.centre));
        const scalar next = nextStepTravel(p);
        const scalar reach = stateReach(p) + moved + next;
        farthest = max(farthest, reach);
        fd_.ranksNear(p.position(), reach, near);
        // and the ranks whose box it may enter in the next step: its owner
        // then, which needs its body in the step's list
        ownedScene_.boxes->ranksWithin(p.position(), next, nextOwners);
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
        owned_->sendStates(sendTo, partners, mirror);
    setMirror(mirror);
    costs_.mirrorParticles += granular_.size();
    costs_.stateMessages += received.first();
    costs_.stateBytes += received.second();
    ++costs_.nStateSteps;
}


Foam::label Foam::dlmfdCoupling::evolveOwned
(
    const List<fictitiousDomain::body>& bodies,
    List<vector>& V3,
    List<vector>& omega3
)
{
    // The new velocities, which this rank took as the owner, set on its
    // part by the same calls the master makes in the master-side step
    // (the part holds its own particles only: the last step dropped the
    // ghosts)
    granularSystem& part = *ownedScene_.part;
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
    const label nSub = owned_->evolve(mesh_.time().deltaTValue());
    part.checkHealth(mesh_.time().value());
    if (const label far = owned_->lastCounters().nFarRecords)
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

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

#include "owned.H"
#include "bodyPlaces.H"
#include "meshChangeReach.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleDistributions
{
    defineTypeNameAndDebug(owned, 0);
    addToRunTimeSelectionTable
    (
        particleDistribution,
        owned,
        coupling
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::autoPtr<Foam::granularSystem>
Foam::particleDistributions::owned::sceneWithoutParticles
(
    const sceneEffects& effects
) const
{
    auto scene = autoPtr<granularSystem>::New
    (
        IOdictionary(dlmfdConstantDict(mesh_, "particleProperties")),
        IOdictionary(dlmfdConstantDict(mesh_, "collisionProperties")),
        effects
    );
    scene->addWallPatches(mesh_);
    scene->readGravity(mesh_);
    scene->setGravity(Zero);
    return scene;
}


void Foam::particleDistributions::owned::setMirror
(
    const UList<granularSystem::particleRecord>& records
)
{
    particles_.setParticles(records, boolList(records.size(), false), nullptr);
    fresh_.resize(records.size());
    forAll(records, k)
    {
        fresh_[k] = records[k].global;
    }
}


const Foam::fictitiousDomain::body& Foam::particleDistributions::owned::ownBody
(
    const UList<fictitiousDomain::body>& bodies,
    const bodyPlaces& places,
    const label i
) const
{
    const label g = part_->globalIndex(i);
    const label k = places(g);
    if (k < 0)
    {
        FatalErrorInFunction
            << "Particle " << part_->id(i) << " (global index " << g
            << ") is owned by rank " << Pstream::myProcNo() << " but is not"
            << " in the rank's list of bodies: its state was not the last"
            << " step's here (a rank is sent the state of each particle that"
            << " may enter its box in the next step)"
            << exit(FatalError);
    }
    return bodies[k];
}


const Foam::meshChangeReach* Foam::particleDistributions::owned::meshChange() const
{
    return
        mesh_.dynamic()
      ? dynamic_cast<const meshChangeReach*>(&mesh_)
      : nullptr;
}


bool Foam::particleDistributions::owned::everyStateEverywhere() const
{
    return mesh_.dynamic() && !meshChange();
}


Foam::scalar Foam::particleDistributions::owned::stateReach
(
    const rigidParticle& p
) const
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


Foam::List<Foam::labelList>
Foam::particleDistributions::owned::destinationsAtStart() const
{
    // What sendStates sends after a step: a particle goes to the ranks
    // whose cells come within its reach (stateReach) and twice a step's
    // travel, and to the rank whose box it may enter in the next step; the
    // scene read at the start looked through once, on the master, so that
    // no step does
    const granularSystem& all = *whole_;
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
        boxes_->ranksWithin(p.position(), next, owners);
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


Foam::scalar Foam::particleDistributions::owned::nextStepTravel
(
    const rigidParticle& p
) const
{
    const scalar dt = mesh_.time().deltaTValue();
    return 2*dt*(mag(p.velocity()) + 2*dt*mag(g_));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleDistributions::owned::owned
(
    const fvMesh& mesh,
    granularSystem& particles,
    fictitiousDomain& fd,
    dlmfdCouplingCosts& costs,
    const vector& g
)
:
    particleDistribution(mesh, particles, fd, costs, g),
    fresh_(),
    whole_(),
    part_(),
    boxes_(),
    exchange_(),
    steps_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::particleDistributions::owned::readScene
(
    const sceneEffects& effects
)
{
    whole_ = sceneWithoutParticles(effects);
    return readParticles(*whole_, true);
}


void Foam::particleDistributions::owned::distribute(const sceneEffects& effects)
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
    boxes_ = boxDecomposition::fromRankBoxes
    (
        particles_.domain(), particles_.periodic(), meshBoxes
    );
    const bool fromMesh = boxes_.valid();
    if (!fromMesh)
    {
        boxes_.reset
        (
            new boxDecomposition
            (
                particles_.domain(), particles_.periodic(),
                boxDecomposition::leastAreaBoxes
                (
                    particles_.domain().span(), Pstream::nProcs()
                )
            )
        );
    }
    const labelVector& n = boxes_->n();

    // Each rank's fictitious domain takes the bodies near its cells and
    // its own
    List<boundBox> ownerBoxes(Pstream::nProcs());
    forAll(ownerBoxes, r)
    {
        ownerBoxes[r] = boxes_->bounds(r);
    }
    scalar largestRadius = 0;
    for (label i = 0; i < whole_->size(); ++i)
    {
        largestRadius =
            max(largestRadius, whole_->particle(i).shape().boundingRadius());
    }
    Pstream::scatter(largestRadius);
    fd_.setBodiesPerRank(std::move(ownerBoxes), largestRadius);

    // This rank's part and mirror: its own particles and those its first
    // step lists, from the master's reading
    part_ = sceneWithoutParticles(effects);
    UPtrList<granularSystem> parts(1);
    parts.set(0, part_.get());
    {
        const List<List<granularSystem::particleRecord>> near
        (
            ownedGranularSteps::scatterScene
            (
                exchange_, *boxes_,
                Pstream::master() ? whole_.get() : nullptr,
                Pstream::master() ? destinationsAtStart() : List<labelList>(),
                parts
            )
        );
        particles_.setScene(particles_.localConstants());
        setMirror(near[0]);
    }
    steps_.reset(new ownedGranularSteps(std::move(parts), *boxes_, exchange_));
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
Foam::particleDistributions::owned::bodiesHeld
(
    const List<fictitiousDomain::body>& bodies,
    List<fictitiousDomain::body>& held
) const
{
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


void Foam::particleDistributions::owned::granularStep
(
    const List<fictitiousDomain::body>& bodies,
    const List<vector>& V3,
    const List<vector>& omega3,
    dlmfdStepReport& report,
    clockTime& clock
)
{
    // The log's sums and extremes over the owners, on the master that
    // prints them (integers and maxima: the master-side step's numbers
    // exactly)
    labelList counts({report.nPoints, report.nSurface, report.nDropped});
    Pstream::listCombineGather(counts, plusEqOp<label>());
    scalarList extremes({report.maxError, report.lastChange});
    Pstream::listCombineGather(extremes, maxEqOp<scalar>());
    report.nPoints = counts[0];
    report.nSurface = counts[1];
    report.nDropped = counts[2];
    report.maxError = extremes[0];
    report.lastChange = extremes[1];
    report.nSub = evolveOwned(bodies, V3, omega3);
    costs_.granularSeconds += clock.timeIncrement();
}


Foam::labelList Foam::particleDistributions::owned::ownParticles() const
{
    const granularSystem& part = *part_;
    DynamicList<label> own(part.size());
    for (label k = 0; k < part.size(); ++k)
    {
        if (!part.ghost(k))
        {
            own.append(part.globalIndex(k));
        }
    }
    return labelList(std::move(own));
}


void Foam::particleDistributions::owned::handOverForces
(
    vectorField& Fh,
    vectorField& Th
) const
{
    // A particle whose centre crossed into another box in the granular
    // step has a new owner, which writes its row: the forces go there from
    // the rank that took its result (its owner at the step's start)
    const label self = Pstream::myProcNo();
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    List<DynamicList<label>> moved(Pstream::nProcs());
    for (const labelPair& gr : steps_->lastDepartures()[0])
    {
        moved[gr.second()].append(gr.first());
    }
    forAll(moved, q)
    {
        if (moved[q].size())
        {
            List<vector> forces(2*moved[q].size());
            forAll(moved[q], k)
            {
                forces[2*k] = Fh[moved[q][k]];
                forces[2*k + 1] = Th[moved[q][k]];
            }
            UOPstream os(q, buffers);
            os << labelList(moved[q]) << forces;
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);
    forAll(recvSizes, q)
    {
        if (q != self && recvSizes[q] > 0)
        {
            UIPstream is(q, buffers);
            labelList particles;
            List<vector> forces;
            is >> particles >> forces;
            forAll(particles, k)
            {
                Fh[particles[k]] = forces[2*k];
                Th[particles[k]] = forces[2*k + 1];
            }
        }
    }
}


void Foam::particleDistributions::owned::gatherScene()
{
    // The states and the contact histories from their owners
    steps_->gatherScene(Pstream::master() ? whole_.get() : nullptr);
}


void Foam::particleDistributions::owned::writeVTK
(
    granularVTKWriter& vtk,
    const granularVTKWriter::loads& given
) const
{
    if (!writesPerRank())
    {
        particleDistribution::writeVTK(vtk, given);
        return;
    }
    const Time& runTime = mesh_.time();
    vtk.writePieces(*part_, runTime.value(), runTime.timeIndex(), given);
}


Foam::string Foam::particleDistributions::owned::costLineNote() const
{
    if (!writesPerRank())
    {
        return string();
    }
    const Pair<scalar> work = steps_->workPerRank();
    return
        "; granular work per rank (less its exchanges) max/mean "
      + Foam::name(work.first()/max(work.second(), VSMALL))
      + " (max " + Foam::name(work.first()) + " s, mean "
      + Foam::name(work.second()) + " s)";
}


// ************************************************************************* //

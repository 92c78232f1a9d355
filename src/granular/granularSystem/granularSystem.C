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
    Construction, input and sub-cycling of the granular system (its contact
    forces: granularSystemContacts.C).

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "narrowPhase.H"
#include "granularInput.H"
#include "sphere.H"
#include "Switch.H"
#include "uniformDimensionedFields.H"
#include "objectRegistry.H"

#include "knownKeywords.H"
#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::granularSystem::buildLaws()
{
    if (!contactsOn_)
    {
        laws_.clear();
        return;
    }
    laws_.reset(new contactPairTable(collisionDict_, materials_));
    if (effects_.settled("friction") && !effects_.on("friction"))
    {
        laws_->setTangential(false);
    }
}


void Foam::granularSystem::updateParticleData(const bool keepHistory)
{
    const label n = size();
    radius_.setSize(n);
    Deq_.setSize(n);
    sphereRadius_.setSize(n);

    // The particles that move, and the effects they touch
    using motionKind = rigidParticle::motionKind;
    DynamicList<label> moving(n);
    label firstHeld = -1;
    for (label i = 0; i < n; ++i)
    {
        rigidParticle& p = particles_[i];
        // A ghost moves with its owner, not here
        if (p.motion() != motionKind::fixed && !ghost_[i])
        {
            moving.append(i);
        }
        if (p.motion() != motionKind::free && firstHeld < 0)
        {
            firstHeld = i;
        }
        if (!rotationOn_ && mag(p.omega()) > 0)
        {
            FatalErrorInFunction
                << "particle " << ids_[i] << " ("
                << rigidParticle::motionKindNames[p.motion()]
                << ") has angular velocity " << p.omega()
                << " but the effect rotation is off" << exit(FatalError);
        }
        p.setRotation(rotationOn_);
    }
    integrator_.setParticles(std::move(moving), n);
    // (owned mode: the effects were settled on the whole scene)
    if (n && !partOfScene_)
    {
        if
        (
            !effects_.settle
            (
                "fixedParticles", firstHeld >= 0, "the particles"
            )
         && firstHeld >= 0
        )
        {
            effects_.contradiction
            (
                "fixedParticles",
                "particle " + Foam::name(ids_[firstHeld]) + " at "
              + Foam::name(particles_[firstHeld].position().x()) + ' '
              + Foam::name(particles_[firstHeld].position().y()) + ' '
              + Foam::name(particles_[firstHeld].position().z()) + " is "
              + rigidParticle::motionKindNames[particles_[firstHeld].motion()]
            );
        }
    }

    for (label i = 0; i < size(); ++i)
    {
        const particleShape& shape = particles_[i].shape();
        Deq_[i] = shape.equivalentDiameter();
        const auto* s = isA<particleShapes::sphere>(shape);
        sphereRadius_[i] = s ? s->radius() : -1;
        radius_[i] = particles_[i].shape().boundingRadius();
    }
    // The sizes of the scene: of the particles held, or of the whole
    // scene when this is a part of it (owned mode: every rank takes the
    // same sub-step and searches with the same cells)
    const sceneConstants scene = partOfScene_ ? scene_ : localConstants();
    const scalar rMax = scene.rMax, Dmin = scene.Dmin;
    // Shortest contact of the scene: each pair of materials at the
    // smallest reduced mass among the particles present
    const scalarList& mMin = scene.minMass;
    scalar Tc = VGREAT;
    if (contactsOn_)
    {
        forAll(mMin, a)
        {
            if (mMin[a] == GREAT)
            {
                continue;
            }
            forAll(mMin, b)
            {
                if (mMin[b] == GREAT)
                {
                    continue;
                }
                const scalar M = mMin[a]*mMin[b]/(mMin[a] + mMin[b]);
                Tc = min(Tc, laws_->law(a, b).contactTime(M));
            }
            forAll(walls_, w)
            {
                Tc = min
                (
                    Tc, laws_->law(a, wallMaterial_[w]).contactTime(mMin[a])
                );
            }
        }
    }
    dtMax_ = Tc < VGREAT ? Tc/settings_.subStepsPerContact() : VGREAT;

    search_.reset
    (
        settings_.domain(), settings_.periodic(), scene.n, rMax, Dmin,
        searchRegion_.get()
    );
    if (!keepHistory)
    {
        history_.clear();
    }
}


Foam::granularSystem::sceneConstants
Foam::granularSystem::localConstants() const
{
    sceneConstants c;
    c.n = size();
    c.minMass.setSize(materials_.nParticleMaterials(), GREAT);
    for (label i = 0; i < size(); ++i)
    {
        const particleShape& shape = particles_[i].shape();
        c.rMax = max(c.rMax, shape.boundingRadius());
        c.Dmin = min(c.Dmin, shape.equivalentDiameter());
        c.minMass[materialOf_[i]] =
            min(c.minMass[materialOf_[i]], particles_[i].mass());
    }
    return c;
}


void Foam::granularSystem::openSubStep
(
    const scalar dt,
    const bool finishPrevious
)
{
    // The previous sub-step's second half kick, the first half kick and
    // drift, the start of the force sum, and whether the Verlet list must
    // be rebuilt (Foam::velocityVerletIntegrator)
    integrator_.openSubStep
    (
        particles_,
        dt,
        finishPrevious,
        contactsOn_ && search_.built(size()) ? &search_ : nullptr
    );
}


void Foam::granularSystem::contactForces(const scalar dt)
{
    updateCandidates();
    if (walls_.size())
    {
        for (label i = 0; i < size(); ++i)
        {
            // (subCycling inReach: no contact work out of reach; a ghost
            // meets the walls on its owner's rank)
            if
            (
                search_.nearAWall(i)
             && !(outOfReach_.size() && outOfReach_[i])
             && owns(i)
            )
            {
                addWallForces(i, dt);
            }
        }
    }
    addPairForces(dt);
}


void Foam::granularSystem::closeStep(const scalar dt)
{
    stats_.kineticEnergy = integrator_.closeStep(particles_, dt);
}


void Foam::granularSystem::subStep
(
    const scalar dt,
    const bool finishPrevious,
    const bool last,
    const bool contacts
)
{
    // (1) The first pass: kicks, drift, the start of the force sum
    openSubStep(dt, finishPrevious);

    // (2) Contacts: walls, then pairs
    if (contacts)
    {
        contactForces(dt);
    }

    // (3) On the last sub-step of evolve: its second half kick, and the
    // kinetic energy (otherwise the kick opens the next sub-step's pass)
    if (last)
    {
        closeStep(dt);
    }
}


void Foam::granularSystem::resetStatistics(const bool keepFallbacks)
{
    const label fallbacks = stats_.nFallbacks;
    stats_ = statistics();
    if (keepFallbacks)
    {
        stats_.nFallbacks = fallbacks;
    }
}


const Foam::pointField& Foam::granularSystem::positions()
{
    positionsNow_.setSize(size());
    for (label i = 0; i < size(); ++i)
    {
        positionsNow_[i] = particles_[i].position();
    }
    return positionsNow_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::granularSystem::granularSystem
(
    const dictionary& particleDict,
    const dictionary& collisionDict,
    const sceneEffects& effects
)
:
    shapes_(),
    shapeIndex_(),
    materials_(particleDict.subDict("materials")),
    walls_(),
    wallMaterial_(),
    laws_(),
    settings_(),
    effects_(effects),
    collisionMode_(sceneEffects::collisionMode::on),
    contactsOn_(true),
    rotationOn_(effects_.settle("rotation", true, "default")),
    partOfScene_(false),
    searchRegion_(),
    dtMax_(VGREAT),
    search_(),
    integrator_(settings_)
{
    // A misspelt keyword would leave a default in force or be ignored
    knownKeywords::require(particleDict, wordList({"shapes", "materials"}));
    for (const word& name : particleDict.subDict("materials").toc())
    {
        knownKeywords::require
        (
            particleDict, wordList({"density"}), "materials/" + name
        );
    }
    const dictionary& shapesDict = particleDict.subDict("shapes");
    for (const word& name : shapesDict.toc())
    {
        if (!shapesDict.isDict(name))
        {
            FatalIOErrorInFunction(shapesDict)
                << "shape " << name << " is not a dictionary; expected "
                << name << " { type <shape>; ... }" << exit(FatalIOError);
        }
        shapeIndex_.insert(name, shapes_.size());
        shapes_.append(particleShape::New(name, shapesDict.subDict(name)));
        knownKeywords::require
        (
            particleDict,
            particleShape::keywords(shapesDict.subDict(name).get<word>("type")),
            "shapes/" + name
        );
    }
    if (shapes_.empty())
    {
        FatalIOErrorInFunction(shapesDict)
            << "no shape given in " << shapesDict.name()
            << exit(FatalIOError);
    }

    collisionDict_ = collisionDict;
    readCollision(collisionDict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::granularSystem::addWalls(const UList<planeWall>& walls)
{
    for (const planeWall& w : walls)
    {
        walls_.append(w);
        wallMaterial_.append(materials_.addWallMaterial(w.material));
    }
    // New wall materials need their pair laws
    buildLaws();
    updateParticleData();
}


void Foam::granularSystem::addWallPatches(const polyMesh& mesh)
{
    if (const dictionary* wp = collisionDict_.findDict("wallPatches"))
    {
        knownKeywords::require
        (
            collisionDict_, wordList({"patches", "material"}), "wallPatches"
        );
        addWalls
        (
            planeWall::fromPatches
            (
                mesh,
                wp->get<wordRes>("patches"),
                wp->get<word>("material")
            )
        );
    }
}


Foam::label Foam::granularSystem::shapeIndex
(
    const word& name,
    const string& owner
) const
{
    const label shapei = shapeIndex_.lookup(name, -1);
    if (shapei < 0)
    {
        FatalErrorInFunction
            << owner.c_str() << ": shape " << name
            << " is not one of the shapes " << shapeIndex_.sortedToc()
            << exit(FatalError);
    }
    return shapei;
}


const Foam::particleShape& Foam::granularSystem::shape
(
    const word& name,
    const string& owner
) const
{
    return shapes_[shapeIndex(name, owner)];
}


Foam::label Foam::granularSystem::addParticle
(
    const label id,
    const word& shapeName,
    const word& materialName,
    const point& x,
    const quaternion& q
)
{
    const label shapei = shapeIndex(shapeName, "particle " + Foam::name(id));
    const label materiali = materials_.find(materialName);
    if (materiali < 0 || materials_.isWall(materiali))
    {
        FatalErrorInFunction
            << "particle " << id << ": material " << materialName
            << " is not one of the particle materials "
            << SubList<word>
               (
                   materials_.names(), materials_.nParticleMaterials()
               )
            << exit(FatalError);
    }

    const label i = size();
    particles_.emplace_back
    (
        shapes_[shapei], materials_.density(materiali), x, q
    );
    ids_.append(id);
    globalIndex_.append(i);
    ghost_.append(false);
    shapeOf_.append(shapei);
    materialOf_.append(materiali);
    return i;
}


void Foam::granularSystem::clearParticles()
{
    particles_.clear();
    ids_.clear();
    globalIndex_.clear();
    ghost_.clear();
    shapeOf_.clear();
    materialOf_.clear();
    updateParticleData();
}


void Foam::granularSystem::updated()
{
    updateParticleData();
}


Foam::scalar Foam::granularSystem::kineticEnergy() const
{
    scalar E = 0;
    for (const rigidParticle& p : particles_)
    {
        E += p.kineticEnergy();
    }
    return E;
}


Foam::vector Foam::granularSystem::momentum() const
{
    vector P(Zero);
    for (const rigidParticle& p : particles_)
    {
        P += p.mass()*p.velocity();
    }
    return P;
}


void Foam::granularSystem::startContactImpulses()
{
    for (rigidParticle& p : particles_)
    {
        p.startContactImpulse();
    }
}


Foam::label Foam::granularSystem::evolve(const scalar Deltat)
{
    resetStatistics(false);
    startContactImpulses();

    if (integrator_.moving().empty())
    {
        // Nothing moves (no particle, or all fixed): no granular work
        return 0;
    }

    // collisions automatic: a step that no contact can reach is one
    // velocity-Verlet step, with no broad or narrow phase
    if
    (
        collisionMode_ == sceneEffects::collisionMode::automatic
     && !contactsPossible(Deltat)
    )
    {
        subStep(Deltat, false, true, false);
        stats_.nSubSteps = 1;
        stats_.contactsSkipped = true;
        return 1;
    }

    const label n = velocityVerletIntegrator::nSubSteps(Deltat, dtMax_);
    if (settings_.subCycleInReach() && contactsOn_ && n > 1)
    {
        if (evolveInReach(Deltat, n))
        {
            stats_.nSubSteps = n;
            return n;
        }
    }
    const scalar dt = Deltat/n;
    for (label k = 0; k < n; ++k)
    {
        subStep(dt, k > 0, k == n - 1, contactsOn_);
    }
    stats_.nSubSteps = n;
    return n;
}


// ************************************************************************* //

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
    Construction, sub-cycling and contact forces of the granular system.

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

void Foam::granularSystem::readCollision(const dictionary& collisionDict)
{
    // A misspelt optional keyword would leave its default in force
    knownKeywords::require
    (
        collisionDict,
        wordList
        ({
            "contactLaw", "subStepsPerContact", "overlapLimit", "skin",
            "domain", "walls", "wallPatches", "pairs"
        })
    );

    subStepsPerContact_ =
        collisionDict.getOrDefault<label>("subStepsPerContact", 20);
    if (subStepsPerContact_ < 1)
    {
        FatalIOErrorInFunction(collisionDict)
            << "subStepsPerContact = " << subStepsPerContact_
            << " is not allowed; it must be >= 1 (seed 001 uses 20)"
            << exit(FatalIOError);
    }

    overlapLimit_ = collisionDict.getOrDefault<scalar>("overlapLimit", 0.05);
    if (!(overlapLimit_ > 0 && overlapLimit_ < 1))
    {
        FatalIOErrorInFunction(collisionDict)
            << "overlapLimit = " << overlapLimit_ << " is not allowed;"
            << " 0 < overlapLimit < 1 (largest overlap over the smaller"
            << " equivalent diameter; the laws' own design overlaps are"
            << " 0.001-0.01)" << exit(FatalIOError);
    }

    skin_ = -1;
    if (collisionDict.readIfPresent("skin", skin_) && !(skin_ >= 0))
    {
        FatalIOErrorInFunction(collisionDict)
            << "skin = " << skin_ << " is not allowed; it must be >= 0 [m]"
            << exit(FatalIOError);
    }

    const dictionary& domainDict = collisionDict.subDict("domain");
    const point lo = domainDict.get<point>("min");
    const point hi = domainDict.get<point>("max");
    for (direction d = 0; d < 3; ++d)
    {
        if (!(hi[d] > lo[d]))
        {
            FatalIOErrorInFunction(domainDict)
                << "domain: max " << hi << " must exceed min " << lo
                << " in every direction" << exit(FatalIOError);
        }
    }
    domain_ = boundBox(lo, hi);
    periodic_ = domainDict.getOrDefault<FixedList<bool, 3>>
    (
        "periodic", FixedList<bool, 3>(false)
    );
    anyPeriodic_ = periodic_[0] || periodic_[1] || periodic_[2];

    if (const dictionary* wallsDict = collisionDict.findDict("walls"))
    {
        for (const word& name : wallsDict->toc())
        {
            walls_.append(planeWall::read(name, wallsDict->subDict(name)));
            wallMaterial_.append
            (
                materials_.addWallMaterial(walls_.last().material)
            );
        }
    }

    // Periodicity: the domain's directions; a declaration must agree
    const string domainName = domainDict.name();
    if
    (
        effects_.settle("periodicity", anyPeriodic_, domainName + " periodic")
     != anyPeriodic_
    )
    {
        effects_.contradiction
        (
            "periodicity",
            "the domain of " + domainName + " has periodic "
          + (anyPeriodic_ ? "directions " : "none ")
          + "(periodic (" + Switch::name(periodic_[0]) + ' '
          + Switch::name(periodic_[1]) + ' ' + Switch::name(periodic_[2])
          + "))"
        );
    }

    // Collisions: off builds no law at all
    const word lawName = collisionDict.get<word>("contactLaw");
    collisionMode_ = effects_.settleCollisions
    (
        lawName == "none"
      ? sceneEffects::collisionMode::off
      : sceneEffects::collisionMode::on,
        "contactLaw " + lawName
    );
    contactsOn_ = collisionMode_ != sceneEffects::collisionMode::off;
    if (contactsOn_ && lawName == "none")
    {
        effects_.contradiction
        (
            "collisions",
            collisionDict.name() + " has contactLaw none; name a law"
            " (hookeanSpringDashpot, hookeanStaticFriction) and its pairs"
        );
    }
    // Friction is settled before the laws are built: they are built with it
    if (contactsOn_)
    {
        effects_.settle("friction", true, "default");
    }
    buildLaws();

    if (!contactsOn_)
    {
        effects_.settle("friction", false, "collisions off");
        effects_.settle("frictionHistory", false, "collisions off");
        if (effects_.declared("friction") && effects_.on("friction"))
        {
            effects_.contradiction("friction", "collisions are off");
        }
        if
        (
            effects_.declared("frictionHistory")
         && effects_.on("frictionHistory")
        )
        {
            effects_.contradiction("frictionHistory", "collisions are off");
        }
        return;
    }

    const bool history = laws_->needsHistory();
    const bool friction = effects_.on("friction");
    if
    (
        effects_.settle("frictionHistory", history, "contactLaw " + lawName)
     != history
    )
    {
        effects_.contradiction
        (
            "frictionHistory",
            "contactLaw " + lawName + " of " + collisionDict.name()
          + (
                history
              ? " keeps a tangential history; declare it on, or use"
                " hookeanSpringDashpot"
              : " keeps none; use hookeanStaticFriction"
            )
        );
    }
    if (history && !friction)
    {
        effects_.contradiction
        (
            "friction",
            "contactLaw " + lawName + " is a friction law with history;"
            " without friction use hookeanSpringDashpot"
        );
    }
}


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


void Foam::granularSystem::updateParticleData()
{
    const label n = size();
    radius_.setSize(n);
    Fext_.setSize(n, Zero);
    Text_.setSize(n, Zero);
    Deq_.setSize(n);
    sphereRadius_.setSize(n);

    // The particles that move, and the effects they touch
    using motionKind = rigidParticle::motionKind;
    DynamicList<label> moving(n);
    label firstHeld = -1;
    for (label i = 0; i < n; ++i)
    {
        rigidParticle& p = particles_[i];
        if (p.motion() != motionKind::fixed)
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
    moving_.transfer(moving);
    if (n)
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

    scalar rMax = 0, Dmin = GREAT;
    for (label i = 0; i < size(); ++i)
    {
        const particleShape& shape = particles_[i].shape();
        Deq_[i] = shape.equivalentDiameter();
        const auto* s = isA<particleShapes::sphere>(shape);
        sphereRadius_[i] = s ? s->radius() : -1;
        radius_[i] = particles_[i].shape().boundingRadius();
        rMax = max(rMax, radius_[i]);
        Dmin = min(Dmin, particles_[i].shape().equivalentDiameter());
    }
    if (skin_ < 0 && n)
    {
        skin_ = 0.1*Dmin;
    }

    // Shortest contact of the scene: each pair of materials at the
    // smallest reduced mass among the particles present
    scalarList mMin(materials_.nParticleMaterials(), GREAT);
    for (label i = 0; i < size(); ++i)
    {
        mMin[materialOf_[i]] = min(mMin[materialOf_[i]], particles_[i].mass());
    }
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
    dtMax_ = Tc < VGREAT ? Tc/subStepsPerContact_ : VGREAT;

    // Cells no narrower than the interaction distance, and no more of
    // them than particles: a pair search never sweeps a mostly empty grid
    const scalar cellWidth = max
    (
        2*rMax + max(skin_, scalar(0)),
        std::cbrt(domain_.volume()/max(n, label(1)))
    );
    cells_.reset(new linkedCells(domain_, periodic_, cellWidth));
    cellWidth_ = cellWidth;
    rMax_ = rMax;
    xAtBuild_.clear();
    rebuildList_ = true;
    history_.clear();
}


void Foam::granularSystem::wrapPeriodicDirections(rigidParticle& p) const
{
    point x = p.position();
    bool moved = false;
    for (direction d = 0; d < 3; ++d)
    {
        if (!periodic_[d])
        {
            continue;
        }
        const scalar lo = domain_.min()[d];
        const scalar L = domain_.span()[d];
        if (x[d] < lo || x[d] >= lo + L)
        {
            x[d] -= L*std::floor((x[d] - lo)/L);
            moved = true;
        }
    }
    if (moved)
    {
        p.setPosition(x);
    }
}


void Foam::granularSystem::updateCandidates()
{
    if (!rebuildList_ && xAtBuild_.size() == size())
    {
        return;
    }
    rebuildList_ = false;

    xAtBuild_.setSize(size());
    for (label i = 0; i < size(); ++i)
    {
        xAtBuild_[i] = particles_[i].position();
    }
    // In (i, j) order: the forces are summed in the same order whenever
    // the list was built, so that a restart continues bitwise
    cells_->findPairs(xAtBuild_, radius_, skin_, candidates_);

    // A particle moves by at most skin/2 relative to a wall before the
    // next build; a whole skin is kept, as for the pairs
    nearWallStart_.setSize(size() + 1);
    DynamicList<label> near(nearWalls_.size());
    for (label i = 0; i < size(); ++i)
    {
        nearWallStart_[i] = near.size();
        if (particles_[i].motion() != rigidParticle::motionKind::free)
        {
            continue;
        }
        forAll(walls_, w)
        {
            if (walls_[w].distance(xAtBuild_[i]) <= radius_[i] + skin_)
            {
                near.append(w);
            }
        }
    }
    nearWallStart_[size()] = near.size();
    nearWalls_.transfer(near);

    ++stats_.nListBuilds;
}


Foam::vector Foam::granularSystem::contactForce
(
    const contactLaw& law,
    const contactGeometry& c,
    const vector& Urel,
    const scalar M,
    const scalar dt,
    const std::uint64_t key
)
{
    if (!law.needsHistory())
    {
        vector unused(Zero);
        return law.force(c.overlap, c.normal, Urel, M, dt, unused);
    }

    vector h(Zero);
    const auto iter = history_.find(key);
    if (iter != history_.end())
    {
        h = iter->second;
    }
    const vector F = law.force(c.overlap, c.normal, Urel, M, dt, h);
    historyNew_[key] = h;
    return F;
}


void Foam::granularSystem::addWallForces(const label i, const scalar dt)
{
    rigidParticle& pi = particles_[i];
    if (pi.motion() != rigidParticle::motionKind::free)
    {
        return;
    }
    contactGeometry c;
    for (label k = nearWallStart_[i]; k < nearWallStart_[i + 1]; ++k)
    {
        const label w = nearWalls_[k];
        if (!wallTouches(i, w, c))
        {
            continue;
        }
        vector Ui, omegai;
        pi.predictedVelocities(dt, Ui, omegai);
        const vector Urel = Ui + (omegai ^ (c.position - pi.position()));
        const contactLaw& law = laws_->law(materialOf_[i], wallMaterial_[w]);
        const vector F =
            contactForce(law, c, Urel, pi.mass(), dt, wallKey(i, w));
        pi.addForceAt(F, c.position);
        if (c.spread > 0)
        {
            pi.addTorque
            (
                law.regionTorque
                (
                    c.normal, omegai, c.spread, pi.mass(), F & c.normal
                )
            );
        }

        ++stats_.nWallContacts;
        noteOverlap(i, -1 - w, c.overlap/Deq_[i]);
    }
}


void Foam::granularSystem::addPairForces(const scalar dt)
{
    using motionKind = rigidParticle::motionKind;

    stats_.nCandidatePairs = candidates_.size();

    contactGeometry c;

    for (const labelPair& ij : candidates_)
    {
        const label i = ij.first(), j = ij.second();
        rigidParticle& pi = particles_[i];
        rigidParticle& pj = particles_[j];
        const bool iMoves = pi.motion() == motionKind::free;
        const bool jMoves = pj.motion() == motionKind::free;
        // A fixed particle carries no force (it is in no sub-step pass)
        const bool iHeld = pi.motion() == motionKind::fixed;
        const bool jHeld = pj.motion() == motionKind::fixed;
        if (!iMoves && !jMoves)
        {
            continue;
        }

        point xjImage;
        if (!pairTouches(i, j, c, xjImage))
        {
            continue;
        }
        const vector shift = xjImage - pj.position();

        const scalar M =
            !iMoves ? pj.mass()
          : !jMoves ? pi.mass()
          : pi.mass()*pj.mass()/(pi.mass() + pj.mass());

        // Velocities predicted to the end of the sub-step, for the
        // dashpots
        vector Ui, omegai, Uj, omegaj;
        pi.predictedVelocities(dt, Ui, omegai);
        pj.predictedVelocities(dt, Uj, omegaj);
        const auto relativeVelocity = [&](const point& p)
        {
            return
                (Ui + (omegai ^ (p - pi.position())))
              - (Uj + (omegaj ^ (p - shift - pj.position())));
        };

        const contactLaw& law = laws_->law(materialOf_[i], materialOf_[j]);
        if (c.nPoints > 1 && !law.needsHistory())
        {
            // A face or edge in contact: the law at each overlapping corner
            // of the contact region, at its own overlap and velocity,
            // weighted by its share of the summed overlap. Equal overlaps,
            // or a single corner, give the law itself; a corner lifting
            // off fades out continuously; the corners' dashpots damp
            // rocking and twist.
            scalar sumDepth = 0;
            for (label k = 0; k < c.nPoints; ++k)
            {
                sumDepth += c.depths[k];
            }
            vector unused(Zero);
            for (label k = 0; k < c.nPoints; ++k)
            {
                const point& pk = c.points[k];
                const vector Uk = relativeVelocity(pk);
                const vector Fk =
                    (c.depths[k]/sumDepth)
                   *law.force(c.depths[k], c.normal, Uk, M, dt, unused);
                if (!iHeld)
                {
                    pi.addForceAt(Fk, pk);
                }
                if (!jHeld)
                {
                    pj.addForceAt(-Fk, pk - shift);
                }
            }
            ++stats_.nContacts;
            noteOverlap(i, j, c.overlap/min(Deq_[i], Deq_[j]));
            continue;
        }
        const vector Urel = relativeVelocity(c.position);
        const vector F = contactForce(law, c, Urel, M, dt, pairKey(i, j));
        if (!iHeld)
        {
            pi.addForceAt(F, c.position);
        }
        if (!jHeld)
        {
            pj.addForceAt(-F, c.position - shift);
        }
        if (c.spread > 0)
        {
            const vector T = law.regionTorque
            (
                c.normal, omegai - omegaj,
                c.spread, M, F & c.normal
            );
            if (!iHeld)
            {
                pi.addTorque(T);
            }
            if (!jHeld)
            {
                pj.addTorque(-T);
            }
        }

        ++stats_.nContacts;
        noteOverlap(i, j, c.overlap/min(Deq_[i], Deq_[j]));
    }

    // Contacts that ended lose their history
    history_.swap(historyNew_);
    historyNew_.clear();
}


void Foam::granularSystem::subStep
(
    const scalar dt,
    const bool finishPrevious,
    const bool last,
    const bool contacts
)
{
    // (1) The previous sub-step's second half kick (same arithmetic as a
    // pass of its own, one sweep over the particles fewer), the first half
    // kick and drift, the start of the force sum, and whether the Verlet
    // list must be rebuilt. Fixed particles take no part: they never move
    // and carry no force.
    const bool checkList = contactsOn_ && xAtBuild_.size() == size();
    const scalar limit2 = sqr(0.5*skin_);
    const bool weight = magSqr(g_) > 0;
    const label nMoving = moving_.size();
    // The records are read in order, and each fills several cache lines:
    // they are requested a few particles ahead, so that the memory works
    // while the arithmetic does (10^5 free-falling spheres: 6.7 s -> 5.0 s)
    for (label k = 0; k < nMoving; ++k)
    {
        if (k + ahead < nMoving)
        {
            prefetchParticle(moving_[k + ahead]);
        }
        const label i = moving_[k];
        rigidParticle& p = particles_[i];
        if (finishPrevious)
        {
            p.kick(dt);
        }
        p.kickDrift(dt);
        wrapPeriodic(p);
        p.clearForces();
        if (weight)
        {
            p.addForce(p.mass()*g_);
        }
        if (externalForcesOn_)
        {
            p.addForce(Fext_[i]);
            p.addTorque(Text_[i]);
        }
        if
        (
            checkList
         && magSqr(cells_->separation(p.position(), xAtBuild_[i])) > limit2
        )
        {
            rebuildList_ = true;
        }
    }

    // (2) Contacts: walls, then pairs
    if (contacts)
    {
        updateCandidates();
        if (walls_.size())
        {
            for (label i = 0; i < size(); ++i)
            {
                if (nearWallStart_[i + 1] > nearWallStart_[i])
                {
                    addWallForces(i, dt);
                }
            }
        }
        addPairForces(dt);
    }

    // (3) On the last sub-step of evolve: its second half kick, and the
    // kinetic energy (otherwise the kick opens the next sub-step's pass)
    if (!last)
    {
        return;
    }
    scalar E = 0;
    for (label k = 0; k < nMoving; ++k)
    {
        if (k + ahead < nMoving)
        {
            prefetchParticle(moving_[k + ahead]);
        }
        rigidParticle& p = particles_[moving_[k]];
        p.kick(dt);
        E += p.kineticEnergy();
    }
    stats_.kineticEnergy = E;
}


bool Foam::granularSystem::contactsPossible(const scalar Deltat)
{
    // How far each particle can get over the step, from its speed and its
    // acceleration (weight and external force held over the step)
    scalar maxReach = 0;
    reach_.setSize(size());
    reach_ = 0;
    for (const label i : moving_)
    {
        const rigidParticle& p = particles_[i];
        vector a = Zero;
        if (p.motion() == rigidParticle::motionKind::free)
        {
            a = g_;
            if (externalForcesOn_)
            {
                a += Fext_[i]/p.mass();
            }
        }
        reach_[i] = mag(p.velocity())*Deltat + 0.5*mag(a)*sqr(Deltat);
        maxReach = max(maxReach, reach_[i]);
    }

    // A wall a particle can reach
    for (const label i : moving_)
    {
        if (particles_[i].motion() != rigidParticle::motionKind::free)
        {
            continue;
        }
        for (const planeWall& w : walls_)
        {
            if
            (
                w.distance(particles_[i].position())
             <= radius_[i] + reach_[i] + skin_
            )
            {
                return true;
            }
        }
    }

    // A pair that can touch: the broad phase at the distance two
    // particles can close over the step (a skin at least), without the
    // narrow phase. The linked cells find pairs up to a cell apart only:
    // a reach beyond that is treated as a possible contact.
    const scalar search = max(skin_, 2*maxReach);
    if (2*rMax_ + search > cellWidth_)
    {
        return true;
    }
    positionsNow_.setSize(size());
    for (label i = 0; i < size(); ++i)
    {
        positionsNow_[i] = particles_[i].position();
    }
    cells_->findPairs(positionsNow_, radius_, search, reachPairs_);
    return reachPairs_.size() > 0;
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
    domain_(),
    periodic_(false),
    anyPeriodic_(false),
    subStepsPerContact_(20),
    overlapLimit_(0.05),
    skin_(-1),
    g_(Zero),
    effects_(effects),
    collisionMode_(sceneEffects::collisionMode::on),
    contactsOn_(true),
    rotationOn_(effects_.settle("rotation", true, "default")),
    externalForcesOn_(false),
    dtMax_(VGREAT),
    rebuildList_(true),
    cellWidth_(0),
    rMax_(0)
{
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
    shapeOf_.append(shapei);
    materialOf_.append(materiali);
    return i;
}


void Foam::granularSystem::clearParticles()
{
    particles_.clear();
    ids_.clear();
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


void Foam::granularSystem::clearExternalForces()
{
    Fext_ = Zero;
    Text_ = Zero;
    externalForcesOn_ = false;
}


Foam::label Foam::granularSystem::evolve(const scalar Deltat)
{
    stats_ = statistics();

    if (moving_.empty())
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

    const label n =
        dtMax_ < VGREAT
      ? max(label(1), label(std::ceil(Deltat/dtMax_*(1 - 1e-12))))
      : 1;
    const scalar dt = Deltat/n;
    for (label k = 0; k < n; ++k)
    {
        subStep(dt, k > 0, k == n - 1, contactsOn_);
    }
    stats_.nSubSteps = n;
    return n;
}


// ************************************************************************* //

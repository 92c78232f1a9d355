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
    The reach of the particles over a step: whether any contact can happen
    (collisions automatic) and the step that does the contact work of the
    particles in reach only (subCycling inReach).

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::granularSystem::stepReach(const scalar Deltat)
{
    scalar maxReach = 0;
    reach_.setSize(size());
    reach_ = 0;
    for (const label i : integrator_.moving())
    {
        const rigidParticle& p = particles_[i];
        vector a = Zero;
        if (p.motion() == rigidParticle::motionKind::free)
        {
            a = integrator_.gravity();
            if (integrator_.externalForcesOn())
            {
                a += integrator_.externalForce(i)/p.mass();
            }
        }
        reach_[i] = mag(p.velocity())*Deltat + 0.5*mag(a)*sqr(Deltat);
        maxReach = max(maxReach, reach_[i]);
    }
    return maxReach;
}


bool Foam::granularSystem::contactsPossible(const scalar Deltat)
{
    // How far each particle can get over the step, from its speed and its
    // acceleration (weight and external force held over the step)
    return contactsWithin(stepReach(Deltat));
}


bool Foam::granularSystem::contactsWithin(const scalar maxReach)
{
    // A wall a particle can reach
    for (const label i : integrator_.moving())
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
             <= radius_[i] + reach_[i] + search_.skin()
            )
            {
                return true;
            }
        }
    }

    // A pair that can touch: the broad phase at the distance two
    // particles can close over the step (a skin at least), without the
    // narrow phase
    return search_.anyPairWithin
    (
        positions(), radius_, max(search_.skin(), 2*maxReach)
    );
}


bool Foam::granularSystem::evolveInReach(const scalar Deltat, const label n)
{
    // How far a particle in reach may travel over the step: a contact can
    // turn and speed a particle up (an elastic rebound from a heavier one:
    // up to about three times its speed), so three times the largest reach
    // without contacts, and a tenth of the skin at least for the particles
    // at rest. The travel is checked at every sub-step below: beyond it
    // the step is redone with the contact work of every particle, so the
    // bound decides the cost, never the result
    const scalar allowed = max(3*stepReach(Deltat), 0.1*search_.skin());

    const label nInReach = markInReach(allowed);
    if (nInReach < 0)
    {
        return false;
    }
    if (nInReach == integrator_.moving().size())
    {
        // Every particle in reach: the whole scene's contact work, as with
        // subCycling all
        clearInReach();
        return false;
    }

    // The start of the step, to redo it if a particle in reach travels
    // farther than allowed
    keepStart();

    // Every moving particle takes the sub-steps (the same arithmetic as
    // subCycling all: the particles out of reach move by the same bits),
    // the contact work is done for the particles in reach only
    const scalar dt = Deltat/n;
    for (label k = 0; k < n; ++k)
    {
        subStep(dt, k > 0, k == n - 1, true);
        if (travelledFarther(allowed, true))
        {
            restoreStart();
            clearInReach();
            resetStatistics(true);
            noteFallback();
            return false;
        }
    }
    clearInReach();
    stats_.nInReach = nInReach;
    return true;
}


Foam::label Foam::granularSystem::markInReach(const scalar allowed)
{
    // Out of reach: no wall within the allowed travel, and no particle
    // within twice it (both may close in)
    const pointField& x = positions();
    const DynamicList<labelPair>* near =
        search_.pairsWithin(x, radius_, 2*allowed);
    if (!near)
    {
        return -1;
    }
    outOfReach_.setSize(size());
    outOfReach_ = false;
    for (const label i : integrator_.moving())
    {
        outOfReach_[i] = true;
    }
    for (const labelPair& ij : *near)
    {
        const label i = ij.first(), j = ij.second();
        if ((outOfReach_[i] || outOfReach_[j]) && !pairApart(i, j, 2*allowed))
        {
            outOfReach_[i] = false;
            outOfReach_[j] = false;
        }
    }
    for (const label i : integrator_.moving())
    {
        if
        (
            !outOfReach_[i]
         || particles_[i].motion() != rigidParticle::motionKind::free
        )
        {
            continue;
        }
        forAll(walls_, w)
        {
            if
            (
                walls_[w].distance(x[i]) <= radius_[i] + allowed
             && !wallApart(i, w, allowed)
            )
            {
                outOfReach_[i] = false;
                break;
            }
        }
    }
    inReach_.clear();
    for (const label i : integrator_.moving())
    {
        if (!outOfReach_[i])
        {
            inReach_.append(i);
        }
    }
    return inReach_.size();
}


void Foam::granularSystem::keepStart()
{
    atStart_.clear();
    for (const label i : integrator_.moving())
    {
        atStart_.push_back(particles_[i]);
    }
    historyAtStart_ = history_;
}


bool Foam::granularSystem::travelledFarther
(
    const scalar allowed,
    const bool inReachOnly
) const
{
    const labelList& moving = integrator_.moving();
    forAll(moving, m)
    {
        const label i = moving[m];
        if (inReachOnly && outOfReach_[i])
        {
            continue;
        }
        if
        (
            magSqr
            (
                search_.separation
                (
                    atStart_[m].position(), particles_[i].position()
                )
            ) > sqr(allowed)
        )
        {
            return true;
        }
    }
    return false;
}


void Foam::granularSystem::restoreStart()
{
    const labelList& moving = integrator_.moving();
    forAll(moving, m)
    {
        const label i = moving[m];
        particles_[i] = atStart_[m];
        search_.noteMoved(i, particles_[i].position());
    }
    history_ = historyAtStart_;
}


// ************************************************************************* //

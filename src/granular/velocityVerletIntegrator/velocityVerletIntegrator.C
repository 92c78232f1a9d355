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

#include "velocityVerletIntegrator.H"
#include "verletList.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::velocityVerletIntegrator::velocityVerletIntegrator
(
    const collisionSettings& settings
)
:
    settings_(settings),
    moving_(),
    g_(Zero),
    Fext_(),
    Text_(),
    externalForcesOn_(false)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::velocityVerletIntegrator::wrapPeriodicDirections
(
    rigidParticle& p
) const
{
    point x = p.position();
    bool moved = false;
    for (direction d = 0; d < 3; ++d)
    {
        if (!settings_.periodic()[d])
        {
            continue;
        }
        const scalar lo = settings_.domain().min()[d];
        const scalar L = settings_.domain().span()[d];
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::velocityVerletIntegrator::setParticles
(
    labelList&& moving,
    const label n
)
{
    moving_.transfer(moving);
    Fext_.setSize(n, Zero);
    Text_.setSize(n, Zero);
}


void Foam::velocityVerletIntegrator::clearExternalForces()
{
    Fext_ = Zero;
    Text_ = Zero;
    externalForcesOn_ = false;
}


Foam::label Foam::velocityVerletIntegrator::nSubSteps
(
    const scalar Deltat,
    const scalar dtMax
)
{
    // The 1e-12 keeps a step of exactly n sub-steps from becoming n + 1 by
    // round-off
    return
        dtMax < VGREAT
      ? max(label(1), label(std::ceil(Deltat/dtMax*(1 - 1e-12))))
      : 1;
}


void Foam::velocityVerletIntegrator::openSubStep
(
    std::vector<rigidParticle>& particles,
    const scalar dt,
    const bool finishPrevious,
    verletList* list
) const
{
    const bool weight = magSqr(g_) > 0;
    const label nMoving = moving_.size();
    for (label k = 0; k < nMoving; ++k)
    {
        if (k + ahead < nMoving)
        {
            prefetch(particles[moving_[k + ahead]]);
        }
        const label i = moving_[k];
        rigidParticle& p = particles[i];
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
        if (list)
        {
            list->noteMoved(i, p.position());
        }
    }
}


Foam::scalar Foam::velocityVerletIntegrator::closeStep
(
    std::vector<rigidParticle>& particles,
    const scalar dt
) const
{
    scalar E = 0;
    const label nMoving = moving_.size();
    for (label k = 0; k < nMoving; ++k)
    {
        if (k + ahead < nMoving)
        {
            prefetch(particles[moving_[k + ahead]]);
        }
        rigidParticle& p = particles[moving_[k]];
        p.kick(dt);
        E += p.kineticEnergy();
    }
    return E;
}


// ************************************************************************* //

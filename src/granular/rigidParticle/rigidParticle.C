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
    Velocity Verlet for one rigid particle.

\*---------------------------------------------------------------------------*/

#include "rigidParticle.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::rigidParticle::motionKind>
Foam::rigidParticle::motionKindNames
({
    { motionKind::free, "free" },
    { motionKind::fixed, "fixed" },
    { motionKind::prescribed, "prescribed" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidParticle::rigidParticle
(
    const particleShape& shape,
    const scalar density,
    const point& x,
    const quaternion& q
)
:
    shape_(&shape),
    mass_(density*shape.volume()),
    inertia_(density*shape.volumeInertia()),
    invInertia_(inv(inertia_)),
    x_(x),
    q_(q),
    R_(tensor::I),
    U_(Zero),
    omegaBody_(Zero),
    F_(Zero),
    T_(Zero),
    Fstart_(Zero),
    Tstart_(Zero),
    motion_(motionKind::free),
    planar_(shape.planar())
{
    if (!(density > 0))
    {
        FatalErrorInFunction
            << "shape " << shape.name() << ": density " << density
            << " is not allowed; it must be > 0" << exit(FatalError);
    }
    q_.normalize();
    R_ = q_.R();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rigidParticle::constrainToPlane()
{
    if (planar_)
    {
        // Body z stays along world z: rotation about z only
        U_.z() = 0;
        omegaBody_.x() = 0;
        omegaBody_.y() = 0;
    }
}


void Foam::rigidParticle::halfKick(const scalar dt)
{
    if (motion_ != motionKind::free)
    {
        return;
    }

    U_ += (0.5*dt/mass_)*F_;

    // In the body frame: I dw/dt = T_b - w x (I w)
    // Euler's equations, unless nothing turns
    if (T_ != vector::zero || omegaBody_ != vector::zero)
    {
        const vector Tbody = T_ & R_;
        omegaBody_ +=
            0.5*dt
           *(invInertia_ & (Tbody - (omegaBody_ ^ (inertia_ & omegaBody_))));
    }

    constrainToPlane();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rigidParticle::predictedVelocities
(
    const scalar dt,
    vector& U,
    vector& omegaWorld
) const
{
    if (motion_ != motionKind::free || dt == 0)
    {
        U = U_;
        omegaWorld = R_ & omegaBody_;
        return;
    }

    // The second half kick predicted with the force and torque the step
    // started with
    U = U_ + (0.5*dt/mass_)*Fstart_;
    vector omegaB = omegaBody_;
    if (Tstart_ != vector::zero || omegaBody_ != vector::zero)
    {
        omegaB +=
            0.5*dt
           *(
                invInertia_
              & ((Tstart_ & R_) - (omegaBody_ ^ (inertia_ & omegaBody_)))
            );
    }
    if (planar_)
    {
        U.z() = 0;
        omegaB.x() = 0;
        omegaB.y() = 0;
    }
    omegaWorld = R_ & omegaB;
}


Foam::vector Foam::rigidParticle::velocityAt(const point& p, const scalar dt) const
{
    vector U, omega;
    predictedVelocities(dt, U, omega);
    return U + (omega ^ (p - x_));
}


Foam::scalar Foam::rigidParticle::kineticEnergy() const
{
    return
        0.5*mass_*magSqr(U_)
      + 0.5*(omegaBody_ & (inertia_ & omegaBody_));
}


void Foam::rigidParticle::setMotion(const motionKind motion)
{
    motion_ = motion;
    if (motion_ == motionKind::fixed)
    {
        U_ = Zero;
        omegaBody_ = Zero;
    }
}


void Foam::rigidParticle::kickDrift(const scalar dt)
{
    Fstart_ = F_;
    Tstart_ = T_;

    if (motion_ == motionKind::fixed)
    {
        return;
    }

    halfKick(dt);

    x_ += dt*U_;

    const scalar magOmega = mag(omegaBody_);
    if (magOmega*dt > 0)
    {
        // Rotation about the body-frame axis: compose on the right
        q_ = q_*quaternion(omegaBody_/magOmega, magOmega*dt);
        q_.normalize();
        R_ = q_.R();
    }
}


void Foam::rigidParticle::kick(const scalar dt)
{
    halfKick(dt);
}


// ************************************************************************* //

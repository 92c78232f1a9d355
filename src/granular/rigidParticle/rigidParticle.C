/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Class
\*---------------------------------------------------------------------------*/

#include "rigidParticle.H"

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
    U_(Zero),
    omegaBody_(Zero),
    F_(Zero),
    T_(Zero)
{
    if (!(density > 0))
    {
        FatalErrorInFunction
            << "shape " << shape.name() << ": density " << density
            << " is not allowed; it must be > 0" << exit(FatalError);
    }
    q_.normalize();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rigidParticle::halfKick(const scalar dt)
{
    U_ += (0.5*dt/mass_)*F_;

    // Euler's equations in the body frame: I dw/dt = T_b - w x (I w)
    const vector Tbody = T_ & R();
    omegaBody_ +=
        0.5*dt*(invInertia_ & (Tbody - (omegaBody_ ^ (inertia_ & omegaBody_))));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::rigidParticle::velocityAt(const point& p, const scalar dt) const
{
    // Velocities at the end of the step: the second half kick predicted
    // with the forces of the step's start
    const tensor R(this->R());
    const vector U = U_ + (0.5*dt/mass_)*F_;
    const vector omegaB =
        omegaBody_
      + 0.5*dt
       *(invInertia_ & ((T_ & R) - (omegaBody_ ^ (inertia_ & omegaBody_))));

    return U + ((R & omegaB) ^ (p - x_));
}


Foam::scalar Foam::rigidParticle::kineticEnergy() const
{
    return
        0.5*mass_*magSqr(U_)
      + 0.5*(omegaBody_ & (inertia_ & omegaBody_));
}


void Foam::rigidParticle::kickDrift(const scalar dt)
{
    halfKick(dt);

    x_ += dt*U_;

    const scalar magOmega = mag(omegaBody_);
    if (magOmega*dt > 0)
    {
        // Rotation about the body-frame axis: compose on the right
        q_ = q_*quaternion(omegaBody_/magOmega, magOmega*dt);
        q_.normalize();
    }
}


void Foam::rigidParticle::kick(const scalar dt)
{
    halfKick(dt);
}


// ************************************************************************* //

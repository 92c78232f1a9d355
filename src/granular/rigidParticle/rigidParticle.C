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
    x_(x),
    U_(Zero),
    omega_(Zero),
    F_(Zero),
    T_(Zero),
    Fstart_(Zero),
    Tstart_(Zero),
    mass_(density*shape.volume()),
    invMass_(0),
    invInertiaIso_(0),
    motion_(motionKind::free),
    planar_(shape.planar()),
    rotates_(true),
    isotropic_(false),
    rotationInvariant_(shape.rotationInvariant()),
    q_(q),
    R_(tensor::I),
    Fc_(Zero),
    Tc_(Zero),
    Ic_(Zero),
    Jc_(Zero),
    shape_(&shape),
    inertia_(density*shape.volumeInertia()),
    invInertia_(inv(inertia_))
{
    if (!(density > 0))
    {
        FatalErrorInFunction
            << "shape " << shape.name() << ": density " << density
            << " is not allowed; it must be > 0" << exit(FatalError);
    }
    invMass_ = 1/mass_;

    // Isotropic to round-off (spheres, the Platonic solids): the
    // gyroscopic term vanishes and no change of frame is needed
    const scalar Iiso = tr(inertia_)/3;
    isotropic_ =
        mag(inertia_ - Iiso*symmTensor(I)) <= 1e-12*Iiso;
    if (isotropic_)
    {
        invInertiaIso_ = 1/Iiso;
    }

    q_.normalize();
    R_ = q_.R();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rigidParticle::halfKickAnisotropic
(
    const scalar h,
    const vector& T,
    vector& omega
) const
{
    if (T == vector::zero && omega == vector::zero)
    {
        return;
    }
    // In the body frame: I dw/dt = T_b - w x (I w)
    vector omegaB = omega & R_;
    omegaB += h*(invInertia_ & ((T & R_) - (omegaB ^ (inertia_ & omegaB))));
    omega = R_ & omegaB;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rigidParticle::setMotion(const motionKind motion)
{
    motion_ = motion;
    if (motion_ == motionKind::fixed)
    {
        U_ = Zero;
        omega_ = Zero;
    }
}


// ************************************************************************* //

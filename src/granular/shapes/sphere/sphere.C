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

#include "sphere.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "granularInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(sphere, 0);
    addToRunTimeSelectionTable(particleShape, sphere, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::sphere::sphere(const word& name, const scalar D)
:
    particleShape(name),
    radius_(0.5*D)
{
    if (!(D > 0))
    {
        FatalErrorInFunction
            << "shape " << name << ": diameter D = " << D
            << " must be > 0" << exit(FatalError);
    }
}


Foam::particleShapes::sphere::sphere
(
    const word& name,
    const dictionary& dict
)
:
    particleShape(name),
    radius_(0.5*granularInput::positive(dict, "D", "shape " + name, dimLength))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleShapes::sphere::volume() const
{
    return 4.0/3.0*constant::mathematical::pi*pow3(radius_);
}


Foam::symmTensor Foam::particleShapes::sphere::volumeInertia() const
{
    return (0.4*sqr(radius_)*volume())*symmTensor::I;
}


Foam::scalar Foam::particleShapes::sphere::boundingRadius() const
{
    return radius_;
}


Foam::vector Foam::particleShapes::sphere::support(const vector& dir) const
{
    const scalar magDir = mag(dir);
    return magDir > VSMALL ? (radius_/magDir)*dir : vector(radius_, 0, 0);
}


// ************************************************************************* //

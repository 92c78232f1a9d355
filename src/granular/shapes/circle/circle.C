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
    A circle of a 2D case (cylinder one cell deep).

\*---------------------------------------------------------------------------*/

#include "circle.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "granularInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(circle, 0);
    addToRunTimeSelectionTable(particleShape, circle, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::circle::circle
(
    const word& name,
    const scalar D,
    const scalar depth
)
:
    particleShape(name),
    radius_(0.5*D),
    depth_(depth)
{}


Foam::particleShapes::circle::circle
(
    const word& name,
    const dictionary& dict
)
:
    circle
    (
        name,
        granularInput::positive(dict, "D", "shape " + name, dimLength),
        granularInput::positive(dict, "depth", "shape " + name, dimLength)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleShapes::circle::volume() const
{
    return constant::mathematical::pi*sqr(radius_)*depth_;
}


Foam::symmTensor Foam::particleShapes::circle::volumeInertia() const
{
    const scalar V = volume();
    const scalar Jxx = V*(sqr(radius_)/4 + sqr(depth_)/12);
    return symmTensor(Jxx, 0, 0, Jxx, 0, V*sqr(radius_)/2);
}


Foam::scalar Foam::particleShapes::circle::boundingRadius() const
{
    return sqrt(sqr(radius_) + sqr(0.5*depth_));
}


Foam::vector Foam::particleShapes::circle::support(const vector& dir) const
{
    const scalar magXY = sqrt(sqr(dir.x()) + sqr(dir.y()));
    vector s(Zero);
    if (magXY > VSMALL)
    {
        s.x() = radius_*dir.x()/magXY;
        s.y() = radius_*dir.y()/magXY;
    }
    // Along the plane the rim's middle, so that contact points stay on
    // the mid-plane
    if (mag(dir.z()) > 1e-12*mag(dir))
    {
        s.z() = 0.5*depth_*sign(dir.z());
    }
    return s;
}


// ************************************************************************* //

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

#include "particleRefinementTargets.H"
#include "objectRegistry.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(particleRefinementTargets, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleRefinementTargets::particleRefinementTargets
(
    const objectRegistry& mesh
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            mesh.time().constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    centres_(),
    radii_(),
    velocities_(),
    fluidVelocity_(Zero),
    period_(Zero),
    deltaT_(0),
    set_(false)
{}


// * * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * //

Foam::particleRefinementTargets& Foam::particleRefinementTargets::New
(
    const objectRegistry& mesh
)
{
    if (!mesh.foundObject<particleRefinementTargets>(typeName))
    {
        particleRefinementTargets* targets =
            new particleRefinementTargets(mesh);
        targets->store();
    }
    return mesh.lookupObjectRef<particleRefinementTargets>(typeName);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleRefinementTargets::set
(
    const pointField& centres,
    const scalarField& radii,
    const vectorField& velocities,
    const vector& fluidVelocity,
    const vector& period,
    const scalar deltaT
)
{
    centres_ = centres;
    radii_ = radii;
    velocities_ = velocities;
    fluidVelocity_ = fluidVelocity;
    period_ = period;
    deltaT_ = deltaT;
    set_ = true;
}


// ************************************************************************* //

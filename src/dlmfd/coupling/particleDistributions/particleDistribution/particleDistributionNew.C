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

#include "particleDistribution.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::particleDistribution> Foam::particleDistribution::New
(
    const fvMesh& mesh,
    granularSystem& particles,
    fictitiousDomain& fd,
    dlmfdCouplingCosts& costs,
    const vector& g
)
{
    // The collision settings read and check the keyword too (granularFoam
    // reads it without a mesh); here it names the model
    const IOdictionary collisions(dlmfdConstantDict(mesh, "collisionProperties"));
    const word modelType
    (
        collisions.getOrDefault<word>("particleDistribution", "master")
    );

    auto cstrIter = couplingConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            collisions,
            "particleDistribution",
            modelType,
            *couplingConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<particleDistribution>
    (
        cstrIter()(mesh, particles, fd, costs, g)
    );
}


// ************************************************************************* //

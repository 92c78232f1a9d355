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
    // (constant/collisionProperties' particleDistribution, which the
    // collision settings read and check, naming the file and the values
    // allowed: granularFoam reads it too)
    const word modelType(particles.ownedDistribution() ? "owned" : "master");

    auto cstrIter = couplingConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalErrorInLookup
        (
            "particleDistribution",
            modelType,
            *couplingConstructorTablePtr_
        ) << exit(FatalError);
    }

    return autoPtr<particleDistribution>
    (
        cstrIter()(mesh, particles, fd, costs, g)
    );
}


// ************************************************************************* //

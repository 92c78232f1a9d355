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
#include "particleFileReader.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(particleDistribution, 0);
    defineRunTimeSelectionTable(particleDistribution, coupling);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleDistribution::particleDistribution
(
    const fvMesh& mesh,
    granularSystem& particles,
    fictitiousDomain& fd,
    dlmfdCouplingCosts& costs,
    const vector& g
)
:
    mesh_(mesh),
    particles_(particles),
    fd_(fd),
    costs_(costs),
    g_(g)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::particleDistribution::readParticles
(
    granularSystem& into,
    const bool masterOnly
) const
{
    fileName file;
    if (masterOnly)
    {
        if (Pstream::master())
        {
            file = particleFileReader::startFile(mesh_.time());
            into.readParticles(file);
        }
        Pstream::scatter(file);
    }
    else
    {
        const dictionary dict =
            particleFileReader::readStartOnEveryRank(mesh_.time(), file);
        into.readParticles(dict, file);
    }
    return file;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::particleDistribution::ownParticles() const
{
    return identity(particles_.size());
}


void Foam::particleDistribution::writeVTK
(
    granularVTKWriter& vtk,
    const granularVTKWriter::loads& given
) const
{
    if (Pstream::master())
    {
        const Time& runTime = mesh_.time();
        vtk.write(scene(), runTime.value(), runTime.timeIndex(), given);
    }
}


// ************************************************************************* //

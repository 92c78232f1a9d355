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

#include "master.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleDistributions
{
    defineTypeNameAndDebug(master, 0);
    addToRunTimeSelectionTable
    (
        particleDistribution,
        master,
        coupling
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::particleDistributions::master::broadcastState()
{
    if (!Pstream::parRun())
    {
        return;
    }
    constexpr label nValues = 13;
    const label n = particles_.size();
    scalarList state(nValues*n);
    if (Pstream::master())
    {
        for (label i = 0; i < n; ++i)
        {
            const rigidParticle& p = particles_.particle(i);
            scalar* v = &state[nValues*i];
            const quaternion& q = p.orientation();
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                v[d] = p.position()[d];
                v[3 + d] = q.v()[d];
                v[7 + d] = p.velocity()[d];
                v[10 + d] = p.omega()[d];
            }
            v[6] = q.w();
        }
    }
    Pstream::scatter(state);
    ++costs_.nStateSteps;
    if (!Pstream::master())
    {
        costs_.stateMessages += 1;
        costs_.stateBytes += state.byteSize();
        for (label i = 0; i < n; ++i)
        {
            rigidParticle& p = particles_.particle(i);
            const scalar* v = &state[nValues*i];
            p.setPosition(point(v[0], v[1], v[2]));
            p.restoreOrientation(quaternion(v[6], vector(v[3], v[4], v[5])));
            p.setVelocity(vector(v[7], v[8], v[9]));
            p.setOmega(vector(v[10], v[11], v[12]));
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleDistributions::master::master
(
    const fvMesh& mesh,
    granularSystem& particles,
    fictitiousDomain& fd,
    dlmfdCouplingCosts& costs,
    const vector& g
)
:
    particleDistribution(mesh, particles, fd, costs, g)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::particleDistributions::master::readScene
(
    const sceneEffects&
)
{
    return readParticles(particles_, false);
}


void Foam::particleDistributions::master::granularStep
(
    const List<fictitiousDomain::body>& bodies,
    const List<vector>& V3,
    const List<vector>& omega3,
    dlmfdStepReport& report,
    clockTime& clock
)
{
    if (Pstream::master())
    {
        // The bodies are the particles, in order; the master took them all
        forAll(bodies, i)
        {
            if (bodies[i].free)
            {
                rigidParticle& p = particles_.particle(i);
                p.setVelocity(V3[i]);
                p.setOmega(omega3[i]);
            }
        }
        report.nSub = particles_.evolve(mesh_.time().deltaTValue());
        particles_.checkHealth(mesh_.time().value());
    }
    costs_.granularSeconds += clock.timeIncrement();

    // The new state to every rank
    broadcastState();
    costs_.commSeconds += clock.timeIncrement();
}


// ************************************************************************* //

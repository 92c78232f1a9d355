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
    A granular system that holds a part of the scene (particleDistribution
    owned): the particles its rank owns and ghost copies of those of other
    ranks within reach, always in ascending global index, so that each
    particle's forces are summed in the order the whole scene sums them
    (walls, then partners by ascending global index).

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::granularSystem::setScene(const sceneConstants& scene)
{
    if (scene.minMass.size() != materials_.nParticleMaterials())
    {
        FatalErrorInFunction
            << "the scene's smallest masses name "
            << scene.minMass.size() << " materials; the system has "
            << materials_.nParticleMaterials() << abort(FatalError);
    }
    partOfScene_ = true;
    scene_ = scene;
    updateParticleData(true);
}


Foam::granularSystem::particleRecord Foam::granularSystem::record
(
    const label i
) const
{
    particleRecord r;
    r.global = globalIndex_[i];
    r.id = ids_[i];
    r.shape = shapeOf_[i];
    r.material = materialOf_[i];
    r.motion = label(particles_[i].motion());
    r.state = particles_[i].state();
    r.Fext = integrator_.externalForce(i);
    r.Text = integrator_.externalTorque(i);
    return r;
}


void Foam::granularSystem::setParticles
(
    const UList<particleRecord>& records,
    const UList<bool>& ghost,
    const boundBox* region
)
{
    if (!partOfScene_)
    {
        FatalErrorInFunction
            << "a system that holds the whole scene takes no records"
            << " (setScene first)" << abort(FatalError);
    }
    searchRegion_.reset(region ? new boundBox(*region) : nullptr);
    particles_.clear();
    particles_.reserve(records.size());
    ids_.clear();
    globalIndex_.clear();
    ghost_.clear();
    shapeOf_.clear();
    materialOf_.clear();
    forAll(records, k)
    {
        const particleRecord& r = records[k];
        if (k && r.global <= records[k - 1].global)
        {
            FatalErrorInFunction
                << "records out of global order: " << records[k - 1].global
                << " then " << r.global << abort(FatalError);
        }
        particles_.emplace_back
        (
            shapes_[r.shape], materials_.density(r.material), r.state.x,
            r.state.q
        );
        rigidParticle& p = particles_.back();
        p.setMotion(rigidParticle::motionKind(r.motion));
        p.setRotation(rotationOn_);
        p.setState(r.state);
        ids_.append(r.id);
        globalIndex_.append(r.global);
        ghost_.append(ghost[k]);
        shapeOf_.append(r.shape);
        materialOf_.append(r.material);
    }
    updateParticleData(true);
    forAll(records, k)
    {
        integrator_.takeExternalForce(k, records[k].Fext, records[k].Text);
    }
}


void Foam::granularSystem::setGhostState
(
    const label i,
    const rigidParticle::motionState& state
)
{
    particles_[i].setState(state);
    if (search_.built(size()))
    {
        search_.noteMoved(i, state.x);
    }
}


// ************************************************************************* //

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
    Contact forces of the granular system: the candidate pairs of the
    broad phase, and the wall and pair contacts of a sub-step, each
    resolved by Foam::contactResolution.

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "narrowPhase.H"
#include "contactResolution.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::granularSystem::updateCandidates()
{
    if (!search_.needsBuild(size()))
    {
        return;
    }
    // Walls act on the free particles only
    boolList wallsAct(size());
    for (label i = 0; i < size(); ++i)
    {
        wallsAct[i] =
            particles_[i].motion() == rigidParticle::motionKind::free;
    }
    search_.build(positions(), radius_, walls_, wallsAct);

    ++stats_.nListBuilds;
}


void Foam::granularSystem::addWallForces(const label i, const scalar dt)
{
    rigidParticle& pi = particles_[i];
    if (pi.motion() != rigidParticle::motionKind::free)
    {
        return;
    }
    contactGeometry c;
    for (const label w : search_.nearWalls(i))
    {
        if (!wallTouches(i, w, c))
        {
            continue;
        }
        contactResolution::wall
        (
            laws_->law(materialOf_[i], wallMaterial_[w]), c, pi, dt,
            history_, i, w
        );
        ++stats_.nWallContacts;
        noteOverlap(i, -1 - w, c.overlap/Deq_[i]);
    }
}


void Foam::granularSystem::addPairForces(const scalar dt)
{
    using motionKind = rigidParticle::motionKind;

    const DynamicList<labelPair>& candidates = search_.pairs();
    stats_.nCandidatePairs = candidates.size();

    contactGeometry c;

    for (const labelPair& ij : candidates)
    {
        const label i = ij.first(), j = ij.second();
        rigidParticle& pi = particles_[i];
        rigidParticle& pj = particles_[j];
        // A pair of which neither moves needs no narrow phase
        if
        (
            pi.motion() != motionKind::free
         && pj.motion() != motionKind::free
        )
        {
            continue;
        }

        point xjImage;
        if (!pairTouches(i, j, c, xjImage))
        {
            continue;
        }
        contactResolution::pair
        (
            laws_->law(materialOf_[i], materialOf_[j]), c, pi, pj,
            xjImage - pj.position(), dt, history_, i, j
        );
        ++stats_.nContacts;
        noteOverlap(i, j, c.overlap/min(Deq_[i], Deq_[j]));
    }

    // Contacts that ended lose their history
    history_.endSubStep();
}


// ************************************************************************* //

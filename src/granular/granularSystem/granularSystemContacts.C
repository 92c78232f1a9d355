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


bool Foam::granularSystem::pairApart
(
    const label i,
    const label j,
    const scalar gap
) const
{
    const rigidParticle& pi = particles_[i];
    const rigidParticle& pj = particles_[j];
    const vector d = search_.separation(pi.position(), pj.position());
    if (sphereRadius_[i] > 0 && sphereRadius_[j] > 0)
    {
        return mag(d) > sphereRadius_[i] + sphereRadius_[j] + gap;
    }
    // An axis along which the two extents leave more than gap between
    // them bounds the distance from below, so "apart" is never wrong; the
    // axes tried are the line of centres and each body's own axes (a
    // cube's face normals). Bounding spheres alone would keep cubes at
    // phi 0.2 nearly all in reach of one another (their bounding spheres
    // fill 0.54 of the space)
    const point xjImage = pi.position() - d;
    const tensor Ri = pi.R();
    const tensor Rj = pj.R();
    const posedShape bi{pi.shape(), pi.position(), Ri};
    const posedShape bj{pj.shape(), xjImage, Rj};
    const FixedList<vector, 7> axes
    ({
        xjImage - pi.position(),
        Ri.cx(), Ri.cy(), Ri.cz(), Rj.cx(), Rj.cy(), Rj.cz()
    });
    for (const vector& axis : axes)
    {
        const scalar length = mag(axis);
        if (length < VSMALL)
        {
            continue;
        }
        const vector n = axis/length;
        const scalar jBeyondI = (n & bj.support(-n)) - (n & bi.support(n));
        const scalar iBeyondJ = (n & bi.support(-n)) - (n & bj.support(n));
        if (max(jBeyondI, iBeyondJ) > gap)
        {
            return true;
        }
    }
    return false;
}


bool Foam::granularSystem::wallApart
(
    const label i,
    const label w,
    const scalar gap
) const
{
    const rigidParticle& pi = particles_[i];
    const planeWall& wall = walls_[w];
    const posedShape b{pi.shape(), pi.position(), pi.R()};
    return wall.distance(b.support(-wall.normal)) > gap;
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
            history_, globalIndex_[i], w
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
        // Owned mode: a pair of two ghosts is computed on their owners'
        // ranks
        if (ghost_[i] && ghost_[j])
        {
            continue;
        }
        // subCycling inReach: a particle out of reach has no contact over
        // the step
        if (outOfReach_.size() && (outOfReach_[i] || outOfReach_[j]))
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
            xjImage - pj.position(), dt, history_, globalIndex_[i],
            globalIndex_[j]
        );
        // (counted once over the ranks: by the owner of the first)
        if (owns(i))
        {
            ++stats_.nContacts;
            noteOverlap(i, j, c.overlap/min(Deq_[i], Deq_[j]));
        }
    }

    // Contacts that ended lose their history
    history_.endSubStep();
}


// ************************************************************************* //

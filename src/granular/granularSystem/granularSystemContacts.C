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
    broad phase, the force of one contact, and the wall and pair forces of
    a sub-step with their tangential histories.

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "narrowPhase.H"

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
        vector Ui, omegai;
        pi.predictedVelocities(dt, Ui, omegai);
        const vector Urel = Ui + (omegai ^ (c.position - pi.position()));
        const contactLaw& law = laws_->law(materialOf_[i], wallMaterial_[w]);
        const vector F =
            history_.force(law, c, Urel, pi.mass(), dt, i, -1 - w);
        pi.addForceAt(F, c.position);
        if (c.spread > 0)
        {
            pi.addTorque
            (
                law.regionTorque
                (
                    c.normal, omegai, c.spread, pi.mass(), F & c.normal
                )
            );
        }

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
        const bool iMoves = pi.motion() == motionKind::free;
        const bool jMoves = pj.motion() == motionKind::free;
        // A fixed particle carries no force (it is in no sub-step pass)
        const bool iHeld = pi.motion() == motionKind::fixed;
        const bool jHeld = pj.motion() == motionKind::fixed;
        if (!iMoves && !jMoves)
        {
            continue;
        }

        point xjImage;
        if (!pairTouches(i, j, c, xjImage))
        {
            continue;
        }
        const vector shift = xjImage - pj.position();

        const scalar M =
            !iMoves ? pj.mass()
          : !jMoves ? pi.mass()
          : pi.mass()*pj.mass()/(pi.mass() + pj.mass());

        // Velocities predicted to the end of the sub-step, for the
        // dashpots
        vector Ui, omegai, Uj, omegaj;
        pi.predictedVelocities(dt, Ui, omegai);
        pj.predictedVelocities(dt, Uj, omegaj);
        const auto relativeVelocity = [&](const point& p)
        {
            return
                (Ui + (omegai ^ (p - pi.position())))
              - (Uj + (omegaj ^ (p - shift - pj.position())));
        };

        const contactLaw& law = laws_->law(materialOf_[i], materialOf_[j]);
        if (c.nPoints > 1 && !law.needsHistory())
        {
            // A face or edge in contact: the law at each overlapping corner
            // of the contact region, at its own overlap and velocity,
            // weighted by its share of the summed overlap. Equal overlaps,
            // or a single corner, give the law itself; a corner lifting
            // off fades out continuously; the corners' dashpots damp
            // rocking and twist.
            scalar sumDepth = 0;
            for (label k = 0; k < c.nPoints; ++k)
            {
                sumDepth += c.depths[k];
            }
            vector unused(Zero);
            for (label k = 0; k < c.nPoints; ++k)
            {
                const point& pk = c.points[k];
                const vector Uk = relativeVelocity(pk);
                const vector Fk =
                    (c.depths[k]/sumDepth)
                   *law.force(c.depths[k], c.normal, Uk, M, dt, unused);
                if (!iHeld)
                {
                    pi.addForceAt(Fk, pk);
                }
                if (!jHeld)
                {
                    pj.addForceAt(-Fk, pk - shift);
                }
            }
            ++stats_.nContacts;
            noteOverlap(i, j, c.overlap/min(Deq_[i], Deq_[j]));
            continue;
        }
        const vector Urel = relativeVelocity(c.position);
        const vector F = history_.force(law, c, Urel, M, dt, i, j);
        if (!iHeld)
        {
            pi.addForceAt(F, c.position);
        }
        if (!jHeld)
        {
            pj.addForceAt(-F, c.position - shift);
        }
        if (c.spread > 0)
        {
            const vector T = law.regionTorque
            (
                c.normal, omegai - omegaj,
                c.spread, M, F & c.normal
            );
            if (!iHeld)
            {
                pi.addTorque(T);
            }
            if (!jHeld)
            {
                pj.addTorque(-T);
            }
        }

        ++stats_.nContacts;
        noteOverlap(i, j, c.overlap/min(Deq_[i], Deq_[j]));
    }

    // Contacts that ended lose their history
    history_.endSubStep();
}


// ************************************************************************* //

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

#include "contactResolution.H"

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

bool Foam::contactResolution::pair
(
    const contactLaw& law,
    const contactGeometry& c,
    rigidParticle& pi,
    rigidParticle& pj,
    const vector& shift,
    const scalar dt,
    contactHistory& history,
    const label i,
    const label j
)
{
    using motionKind = rigidParticle::motionKind;

    const bool iMoves = pi.motion() == motionKind::free;
    const bool jMoves = pj.motion() == motionKind::free;
    const bool iHeld = pi.motion() == motionKind::fixed;
    const bool jHeld = pj.motion() == motionKind::fixed;
    if (!iMoves && !jMoves)
    {
        return false;
    }

    const scalar M =
        !iMoves ? pj.mass()
      : !jMoves ? pi.mass()
      : pi.mass()*pj.mass()/(pi.mass() + pj.mass());

    // Velocities predicted to the end of the sub-step, for the dashpots
    vector Ui, omegai, Uj, omegaj;
    pi.predictedVelocities(dt, Ui, omegai);
    pj.predictedVelocities(dt, Uj, omegaj);
    const auto relativeVelocity = [&](const point& p)
    {
        return
            (Ui + (omegai ^ (p - pi.position())))
          - (Uj + (omegaj ^ (p - shift - pj.position())));
    };

    if (c.nPoints > 1 && !law.needsHistory())
    {
        // A face or edge in contact: the law at each overlapping corner,
        // weighted by its share of the summed overlap
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
                pi.addContactForceAt(Fk, pk);
            }
            if (!jHeld)
            {
                pj.addContactForceAt(-Fk, pk - shift);
            }
        }
        return true;
    }

    const vector Urel = relativeVelocity(c.position);
    const vector F = history.force(law, c, Urel, M, dt, i, j);
    if (!iHeld)
    {
        pi.addContactForceAt(F, c.position);
    }
    if (!jHeld)
    {
        pj.addContactForceAt(-F, c.position - shift);
    }
    if (c.spread > 0)
    {
        const vector T = law.regionTorque
        (
            c.normal, omegai - omegaj, c.spread, M, F & c.normal
        );
        if (!iHeld)
        {
            pi.addContactTorque(T);
        }
        if (!jHeld)
        {
            pj.addContactTorque(-T);
        }
    }
    return true;
}


void Foam::contactResolution::wall
(
    const contactLaw& law,
    const contactGeometry& c,
    rigidParticle& pi,
    const scalar dt,
    contactHistory& history,
    const label i,
    const label w
)
{
    vector Ui, omegai;
    pi.predictedVelocities(dt, Ui, omegai);
    const vector Urel = Ui + (omegai ^ (c.position - pi.position()));
    const vector F = history.force(law, c, Urel, pi.mass(), dt, i, -1 - w);
    pi.addContactForceAt(F, c.position);
    if (c.spread > 0)
    {
        pi.addContactTorque
        (
            law.regionTorque
            (
                c.normal, omegai, c.spread, pi.mass(), F & c.normal
            )
        );
    }
}


// ************************************************************************* //

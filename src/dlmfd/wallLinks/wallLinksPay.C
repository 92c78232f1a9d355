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
    Foam::wallLinks::pay: the momentum the bodies pay for what the fluid
    gained at their links in a step, with the share of each body's history
    that the time scheme carries into this one.

\*---------------------------------------------------------------------------*/

#include "wallLinks.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::wallLinks::pay
(
    const volVectorField& U,
    const scalar dt,
    const scalar ddtCoeff,
    List<vector>& momentum,
    List<vector>& moment,
    const boolUList& masterHolds,
    List<vector>* unpaidMomentum,
    List<vector>* unpaidMoment
)
{
    const label nBodies = momentum.size();
    if (globalOf_.size() != nBodies)
    {
        FatalErrorInFunction
            << "paying for " << nBodies << " bodies, but the links were"
            << " found (update) for " << globalOf_.size()
            << exit(FatalError);
    }
    // A restart's history is one per particle, by global index; a body
    // added later starts without one
    const label nGlobal = nBodies ? max(globalOf_) + 1 : 0;
    if (historyMomentum_.size() < nGlobal)
    {
        historyMomentum_.setSize(nGlobal, Zero);
        historyMoment_.setSize(nGlobal, Zero);
    }

    // This step's flux on this rank: a 1/c share per body, its momentum
    // then its moment (one list: one reduction below)
    List<vector> gained(2*nBodies, Zero);
    const vectorField& u = U.primitiveField();
    const PtrList<vectorField> uNbr(neighbourVelocities(U));
    for (const link& L : links_)
    {
        const label c = L.fluid;
        // c's row: the link's flux (implicit in u_E, across a coupled
        // patch too)
        const vector uE = L.farWall ? L.uFar : oppositeVelocity(L, u, uNbr);
        vector gain =
          - (
                L.coeffs[0]*L.uWall + L.coeffs[1]*u[c]
              + L.coeffs[2]*uE
            );
        // c no longer exchanges the Laplacian's flux with g, while g's
        // row keeps k0 (u_c - u_g) (on the other rank across a processor
        // patch, which has no link for it), unless g is a fluid cell with
        // its own link through the body
        if (!L.through)
        {
            const vector uG =
                L.face >= 0 ? u[L.solid] : uNbr[L.patch][L.patchFace];
            gain += L.coeffs[3]*(u[c] - uG);
        }
        const vector p = dt/ddtCoeff*gain;
        gained[L.body] += p;
        gained[nBodies + L.body] += L.arm ^ p;
    }

    // Each rank pays its own share; (c - 1)/c of the history (the same on
    // every rank) once, on the master
    const scalar carried = (ddtCoeff - 1)/ddtCoeff;
    if (unpaidMomentum)
    {
        unpaidMomentum->setSize(nBodies, Zero);
        unpaidMoment->setSize(nBodies, Zero);
    }
    for (label b = 0; b < nBodies; ++b)
    {
        momentum[b] += gained[b];
        moment[b] += gained[nBodies + b];
        if (masterHolds.size() && !masterHolds[b])
        {
            // (what the master's part would have held: 0 + x is x)
            if (unpaidMomentum)
            {
                (*unpaidMomentum)[b] = carried*historyMomentum_[globalOf_[b]];
                (*unpaidMoment)[b] = carried*historyMoment_[globalOf_[b]];
            }
        }
        else if (Pstream::master())
        {
            momentum[b] += carried*historyMomentum_[globalOf_[b]];
            moment[b] += carried*historyMoment_[globalOf_[b]];
        }
    }

    // The history for the next step: this step's gain of every rank
    Pstream::listCombineGather(gained, plusEqOp<vector>());
    Pstream::listCombineScatter(gained);
    for (label b = 0; b < nBodies; ++b)
    {
        vector& H = historyMomentum_[globalOf_[b]];
        vector& HMoment = historyMoment_[globalOf_[b]];
        H = gained[b] + carried*H;
        HMoment = gained[nBodies + b] + carried*HMoment;
    }
}

// ************************************************************************* //

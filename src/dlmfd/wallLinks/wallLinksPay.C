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
    gained at their links in a step, with the share of the last step's
    payment that the time scheme's history carries into this one.

\*---------------------------------------------------------------------------*/

#include "wallLinks.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::wallLinks::pay
(
    const volVectorField& U,
    const scalar dt,
    const scalar ddtCoeff,
    List<vector>& momentum,
    List<vector>& moment
)
{
    // (c - 1)/c of what each cell gained last step, to the body that paid
    const scalar carried = (ddtCoeff - 1)/ddtCoeff;
    const label nBodies = momentum.size();
    vectorField& M = paidMomentum_.primitiveFieldRef();
    vectorField& A = paidMoment_.primitiveFieldRef();
    scalarField& B = paidBody_.primitiveFieldRef();
    forAll(M, celli)
    {
        const label body = label(B[celli]);
        if (body < 0)
        {
            continue;
        }
        M[celli] *= carried;
        A[celli] *= carried;
        if (body < nBodies)
        {
            momentum[body] += M[celli];
            moment[body] += A[celli];
        }
        if (M[celli] == vector::zero)
        {
            B[celli] = -1;
        }
    }
    // A cell whose links now go to another body: its carried share was that
    // body's (paid above), this step's share starts afresh
    for (const link& L : links_)
    {
        if (label(B[L.fluid]) != L.body)
        {
            M[L.fluid] = Zero;
            A[L.fluid] = Zero;
            B[L.fluid] = L.body;
        }
    }

    // This step's flux: a 1/c share, kept per cell for the next step
    const vectorField& u = U.primitiveField();
    const PtrList<vectorField> uNbr(neighbourVelocities(U));
    const label nInternal = mesh_.nInternalFaces();
    for (const link& L : links_)
    {
        const label c = L.fluid;
        // c's row: the link's flux, its third point as the matrix took it
        // (explicitly across a coupled patch)
        const vector uE =
            L.farWall ? L.uFar
          : L.opposite >= nInternal ? L.uOppositeExplicit
          : oppositeVelocity(L, u, uNbr);
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
            const scalar k0 = L.coeffs[3];
            if (L.face >= 0)
            {
                gain += k0*(u[c] - u[L.solid]);
            }
            else
            {
                // Across a coupled patch c's row kept the Laplacian's
                // coupling to g, less the matrix's explicit k0 u_g
                const vector uG = uNbr[L.patch][L.patchFace];
                gain += k0*(u[c] - uG) + k0*(uG - L.uSolidExplicit);
            }
        }
        const vector p = dt/ddtCoeff*gain;
        momentum[L.body] += p;
        moment[L.body] += L.arm ^ p;
        M[c] += p;
        A[c] += L.arm ^ p;
        B[c] = L.body;
    }
}

// ************************************************************************* //

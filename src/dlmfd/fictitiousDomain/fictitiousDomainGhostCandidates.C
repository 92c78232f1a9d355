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
    The cells of each body: those inside it (claimed by the closest
    centre), and, where the surface treatment reads them, the fluid cells
    near its surface; and what the bodies owe for the deviations that
    cells leaving them take into the fluid. Solving a body from them: the
    surface treatment (Foam::surfaceTreatment::solveBody).

\*---------------------------------------------------------------------------*/

#include "fictitiousDomain.H"
#include "posedShape.H"
#include "fictitiousDomainParts.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fictitiousDomain::findGhostCandidates
(
    const UList<body>& bodies,
    candidates& cand
)
{
    startCandidates(bodies, cand);
    const vectorField& C = mesh_.C();

    // Every body's inside cells first, so that the fluid cells of the
    // next pass are those inside no body
    DynamicList<label> near;
    forAll(bodies, b)
    {
        const body& B = bodies[b];
        const posedShape S(*B.shape, B.centre, B.R);
        const scalar rb = B.shape->boundingRadius();
        const scalar h = cand.h[b];
        cand.shifts[b] = images_.reaching(B.centre, rb + reach()*h);
        const List<vector>& shifts = cand.shifts[b];
        forAll(shifts, si)
        {
            near.clear();
            search_.cellsInBall(B.centre - shifts[si], rb + h, near);
            for (const label c : near)
            {
                const point x = C[c] + shifts[si];
                if (S.contains(x))
                {
                    cand.interior[b].append(c);
                    cand.interiorShift[b].append(si);
                    owners_.claim(c, b, magSqr(x - B.centre), true);
                }
            }
        }
    }

    // Where the treatment reads them, the cells outside the body within
    // reach of its surface (those inside another body are left out when
    // collected)
    if (!treatment_->readsFluidNearSurface())
    {
        return;
    }
    forAll(bodies, b)
    {
        const body& B = bodies[b];
        const posedShape S(*B.shape, B.centre, B.R);
        const scalar rb = B.shape->boundingRadius();
        const scalar h = cand.h[b];
        const scalar r = reach()*h;
        const List<vector>& shifts = cand.shifts[b];
        DynamicList<label> fluid, fluidShift;
        forAll(shifts, si)
        {
            near.clear();
            search_.cellsInBall(B.centre - shifts[si], rb + r, near);
            for (const label c : near)
            {
                const point x = C[c] + shifts[si];
                const scalar bound = S.outsideDistanceBound(x);
                if (bound >= 0 && bound < r)
                {
                    fluid.append(c);
                    fluidShift.append(si);
                }
            }
        }
        cand.near[b].transfer(fluid);
        cand.nearShift[b].transfer(fluidShift);
    }
}


void Foam::fictitiousDomain::owedForCellsLeft
(
    const UList<body>& bodies,
    List<vector>& owed,
    List<vector>& moment
) const
{
    owed.setSize(bodies.size());
    moment.setSize(bodies.size());
    owed = Zero;
    moment = Zero;
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    forAll(ghostOwner_, c)
    {
        // The owner field holds global indices
        const label g = label(ghostOwner_[c]);
        if (g < 0)
        {
            continue;
        }
        const label o = places_(g);
        if (o < 0)
        {
            // Its deviation would be lost: the body travelled farther
            // than its holders' reach, or was not given to this rank
            FatalErrorInFunction
                << "cell " << c << " at " << C[c] << " held a deviation of"
                << " particle " << g << " at the last step, which this"
                << " rank's list of bodies does not hold" << exit(FatalError);
        }
        if (owners_.owner(c) == o && owners_.inside(c))
        {
            continue;
        }
        // The nearest periodic image of the cell to the body
        const vector arm =
            images_.nearest(C[c] - bodies[o].centre);
        const vector p = V[c]*deviation_[c];
        owed[o] += p;
        moment[o] += arm ^ p;
    }
}


// ************************************************************************* //

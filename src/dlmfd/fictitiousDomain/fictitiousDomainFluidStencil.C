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
    The fluidStencil surface treatment of Foam::fictitiousDomain: the
    candidate cells and surface stencils on this rank, the collocation
    points gathered from the ranks with their least-squares weights
    (Foam::surfaceStencils), and each body's multipliers
    (Foam::multiplierSolver).

    Collocation points of each body: the centres of the cells inside it,
    and surface points about one cell apart whose velocity is the linear
    least-squares fit of the fluid cells outside the body within
    surfaceStencilRadius cells, extrapolated to the point
    (Foam::surfaceStencils);
    their multipliers act on those cells (a wider stencil slows a thicker
    layer: two cells gave a fixed sphere 14 % too much drag at D/dx 8,
    benchmarks/validation); a point whose cells cannot fit a linear field
    is left out (result::nSurfaceDropped). A cell belongs to one body (the
    closest centre's, Foam::cellOwnership): the bodies are independent.

    For each body, with B the interpolation from cell velocities to its
    points, M = diag(V_c) the cell volumes, U the rigid modes (U y)_k =
    y_V + y_Omega x r_k, and lambda_k the force on the fluid at point k:

    \f[
        V_c (u_c - \hat u_c)/\Delta t = (B^T \lambda)_c, \qquad
        (m - 1) v_p (V - V^*)/\Delta t = - \sum_k \lambda_k,
    \f]
    \f[
        (m - 1) J (\Omega - \Omega^*)/\Delta t
      = - \sum_k r_k \times \lambda_k, \qquad
        B u = V + \Omega \times r_k,
    \f]

    with \hat u the velocity after the fluid step without the previous
    step's multiplier force (the new one replaces it). Eliminating u, V
    and Omega leaves the Uzawa problem (A + U C U^T) lambda = g, A = dt
    B M^-1 B^T, C = dt diag(1/((m-1) v_p), ((m-1) J)^-1), g = V^* +
    Omega^* x r - B \hat u, indefinite for m < 1 and singular at m = 1:
    Foam::multiplierSolver solves it through the Sherman-Morrison-Woodbury
    identity (conjugate gradients on A, a 6x6 system for the rigid modes).

    The new fluid velocity in the bodies' cells is \hat u + dt M^-1 B^T
    lambda, and M^-1 B^T lambda is kept as a cell force density [m/s^2],
    the source of the next fluid step (seed 001, eq A1a).

\*---------------------------------------------------------------------------*/

#include "fictitiousDomain.H"
#include "posedShape.H"
#include "fictitiousDomainParts.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fictitiousDomain::findCandidates
(
    const UList<body>& bodies,
    candidates& cand
)
{
    startCandidates(bodies, cand);
    if (treatment_ == surfaceTreatment::ghostCells)
    {
        findGhostCandidates(bodies, cand);
        return;
    }

    const vectorField& C = mesh_.C();

    DynamicList<label> near;
    DynamicList<point> pts;
    forAll(bodies, b)
    {
        const body& B = bodies[b];
        const particleShape& shape = *B.shape;
        const posedShape S(shape, B.centre, B.R);
        const scalar rb = shape.boundingRadius();
        const scalar h = cand.h[b];
        cand.shifts[b] = images_.reaching(B.centre, rb + reach()*h);
        const List<vector>& shifts = cand.shifts[b];
        if (shifts.empty())
        {
            // Far from this rank: no cell, no surface point to place
            continue;
        }

        // A cell at C counts at C + s: it is near the body at x when C is
        // near x - s
        forAll(shifts, si)
        {
            near.clear();
            search_.cellsInBall(B.centre - shifts[si], rb + 2*h, near);
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

        // Each surface point's velocity is the linear least-squares fit
        // of the fluid cells around it outside the body, extrapolated to
        // the point: the constraint puts the no-slip surface where the
        // body's surface is, without making those cells move rigidly
        // (a stencil across the surface did: the body acted half a cell
        // thicker)
        stencils_.points(*B.shape, B.centre, B.R, h, pts);
        cand.stencils[b].setSize(pts.size());
        cand.stencilShifts[b].setSize(pts.size());
        forAll(pts, k)
        {
            DynamicList<label> st, stShift;
            forAll(shifts, si)
            {
                near.clear();
                search_.cellsInBall
                (
                    pts[k] - shifts[si], stencils_.radius()*h, near
                );
                for (const label c : near)
                {
                    const point x = C[c] + shifts[si];
                    if (!S.contains(x))
                    {
                        st.append(c);
                        stShift.append(si);
                        owners_.claim(c, b, magSqr(x - B.centre), false);
                    }
                }
            }
            cand.stencils[b][k].transfer(st);
            cand.stencilShifts[b][k].transfer(stShift);
        }
    }
}


void Foam::fictitiousDomain::assemble
(
    const body& B,
    const scalar h,
    const UList<const contribution*>& parts,
    collocationSet& s,
    result& res
) const
{
    // The cells, rank after rank
    label nCells = 0;
    for (const contribution* c : parts)
    {
        nCells += c->centres.size();
    }
    s.centres.setSize(nCells);
    s.invVolume.setSize(nCells);
    s.u.setSize(nCells);
    labelList offset(parts.size());
    nCells = 0;
    forAll(parts, r)
    {
        const contribution& c = *parts[r];
        offset[r] = nCells;
        forAll(c.centres, i)
        {
            s.centres[nCells] = c.centres[i];
            s.invVolume[nCells] = 1/c.volumes[i];
            s.u[nCells] = c.u[i];
            ++nCells;
        }
    }

    DynamicList<point> points;
    DynamicList<label> rowStart, rowCell;
    DynamicList<scalar> rowWeight;

    // Interior points: the centres of the cells inside
    forAll(parts, r)
    {
        for (label i = 0; i < parts[r]->nInterior; ++i)
        {
            rowStart.append(rowCell.size());
            rowCell.append(offset[r] + i);
            rowWeight.append(1);
            points.append(s.centres[offset[r] + i]);
        }
    }
    s.nInterior = points.size();

    // Surface points: the fit of their stencils, gathered from the ranks
    DynamicList<point> surface;
    stencils_.points(*B.shape, B.centre, B.R, h, surface);
    List<DynamicList<label>> stencil(surface.size());
    forAll(parts, r)
    {
        const contribution& c = *parts[r];
        forAll(c.surfacePoint, j)
        {
            DynamicList<label>& st = stencil[c.surfacePoint[j]];
            for (label e = c.stencilStart[j]; e < c.stencilStart[j + 1]; ++e)
            {
                st.append(offset[r] + c.stencilCell[e]);
            }
        }
    }
    scalarList w;
    forAll(surface, k)
    {
        const List<point> centres(UIndirectList<point>(s.centres, stencil[k]));
        if (stencil[k].empty() || !stencils_.weights(surface[k], centres, h, w))
        {
            ++res.nSurfaceDropped;
            continue;
        }
        rowStart.append(rowCell.size());
        forAll(stencil[k], i)
        {
            rowCell.append(stencil[k][i]);
            rowWeight.append(w[i]);
        }
        points.append(surface[k]);
    }
    rowStart.append(rowCell.size());

    s.points.transfer(points);
    s.rowStart.transfer(rowStart);
    s.rowCell.transfer(rowCell);
    s.rowWeight.transfer(rowWeight);
    res.nInterior = s.nInterior;
    res.nSurface = s.points.size() - s.nInterior;
}


void Foam::fictitiousDomain::solveBody
(
    const label b,
    const body& B,
    collocationSet& s,
    const scalar dt,
    vectorField& f,
    result& res
) const
{
    multiplierSolver::rigidBody rb;
    rb.centre = B.centre;
    rb.V = B.V;
    rb.omega = B.omega;
    rb.excessDensity = B.excessDensity;
    rb.volume = B.shape->volume();
    rb.volumeInertia = B.R & B.shape->volumeInertia() & B.R.T();
    rb.free = B.free;
    rb.rotates = B.rotates;

    multiplierSolver::outcome out;
    multipliers_.solve(b, rb, s, dt, f, out);
    res.dV = out.dV;
    res.dOmega = out.dOmega;
    res.sumLambda += out.sumLambda;
    res.sumMoment += out.sumMoment;
    res.iterations = max(res.iterations, out.iterations);
    res.constraintError = max(res.constraintError, out.constraintError);
}


// ************************************************************************* //

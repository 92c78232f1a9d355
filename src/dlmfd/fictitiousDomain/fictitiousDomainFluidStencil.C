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
    candidate cells and surface stencils, the collocation points with
    their least-squares weights, and each body's multipliers by
    conjugate gradients with the rigid modes (Sherman-Morrison-Woodbury).

\*---------------------------------------------------------------------------*/

#include "fictitiousDomain.H"
#include "particleGeometry.H"
#include "smallDenseSolve.H"
#include "fictitiousDomainParts.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::fictitiousDomain::fitWeights
(
    const point& p,
    const UList<point>& centres,
    const scalar h,
    scalarList& weights
) const
{
    // u(c) ~ a + G.(x_c - p): weights of a by linear least squares,
    // w = X (X^T X)^-1 e_0, lengths scaled by the cell size
    const label nCoeff = twoD_ ? 3 : 4;
    if (centres.size() < nCoeff)
    {
        return false;
    }

    List<scalarList> XtX(nCoeff, scalarList(nCoeff, scalar(0)));
    List<scalarList> rows(centres.size(), scalarList(nCoeff));
    forAll(centres, i)
    {
        const vector d = (centres[i] - p)/h;
        rows[i][0] = 1;
        rows[i][1] = d.x();
        rows[i][2] = d.y();
        if (!twoD_)
        {
            rows[i][3] = d.z();
        }
        for (label a = 0; a < nCoeff; ++a)
        {
            for (label b = 0; b < nCoeff; ++b)
            {
                XtX[a][b] += rows[i][a]*rows[i][b];
            }
        }
    }
    scalarList e0(nCoeff, scalar(0));
    e0[0] = 1;
    if (!smallDenseSolve(XtX, e0))
    {
        return false;
    }
    weights.setSize(centres.size());
    forAll(centres, i)
    {
        scalar w = 0;
        for (label a = 0; a < nCoeff; ++a)
        {
            w += rows[i][a]*e0[a];
        }
        weights[i] = w;
    }
    return true;
}


void Foam::fictitiousDomain::surfacePointsOf
(
    const body& B,
    const scalar h,
    DynamicList<point>& pts
) const
{
    pts.clear();
    if (!surfacePoints_)
    {
        return;
    }
    const scalar zPlane = twoD_ ? mesh_.bounds().centre().z() : 0;
    particleGeometry::surfacePoints
    (
        *B.shape, B.centre, B.R, surfaceSpacing_*h, zPlane, pts
    );
    if (retraction_ > 0)
    {
        // Towards the centre by retraction h (in the plane in 2D)
        for (point& p : pts)
        {
            vector d = p - B.centre;
            if (twoD_)
            {
                d.z() = 0;
            }
            const scalar r = mag(d);
            if (r > VSMALL)
            {
                p -= (min(retraction_*h, 0.5*r)/r)*d;
            }
        }
    }
}


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
        const scalar rb = shape.boundingRadius();
        const scalar h = cand.h[b];
        cand.shifts[b] = nearShifts(B.centre, rb + reach()*h);
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
                if (particleGeometry::contains(shape, B.centre, B.R, x))
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
        surfacePointsOf(B, h, pts);
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
                    pts[k] - shifts[si], stencilRadius_*h, near
                );
                for (const label c : near)
                {
                    const point x = C[c] + shifts[si];
                    if (!particleGeometry::contains(shape, B.centre, B.R, x))
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
    surfacePointsOf(B, h, surface);
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
        if (stencil[k].empty() || !fitWeights(surface[k], centres, h, w))
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

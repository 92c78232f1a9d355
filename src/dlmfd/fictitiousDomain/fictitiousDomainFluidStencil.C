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

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- y = A x = dt B M^-1 B^T x
void applyA
(
    const fictitiousDomain::collocationSet& s,
    const scalar dt,
    const UList<vector>& x,
    vectorField& work,
    UList<vector>& y
)
{
    work = Zero;
    forAll(s.points, k)
    {
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            work[s.rowCell[e]] += s.rowWeight[e]*x[k];
        }
    }
    forAll(work, c)
    {
        work[c] *= dt*s.invVolume[c];
    }
    forAll(s.points, k)
    {
        vector sum(Zero);
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            sum += s.rowWeight[e]*work[s.rowCell[e]];
        }
        y[k] = sum;
    }
}


//- The inverse diagonal of A, the Jacobi preconditioner
scalarField inverseDiagonal(const fictitiousDomain::collocationSet& s, const scalar dt)
{
    scalarField invDiag(s.points.size());
    forAll(s.points, k)
    {
        scalar d = 0;
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            d += sqr(s.rowWeight[e])*s.invVolume[s.rowCell[e]];
        }
        invDiag[k] = 1/(dt*d);
    }
    return invDiag;
}


//- Jacobi-preconditioned conjugate gradients on A x = b (x starts at 0),
//- to |r| <= tolerance max(|b|, normFloor): the floor keeps a right-hand
//- side of round-off size (a fluid already moving with the body) from
//- being chased into A's near null space; returns the iterations, -1 if
//- the tolerance was not reached
label conjugateGradient
(
    const fictitiousDomain::collocationSet& s,
    const scalar dt,
    const UList<vector>& b,
    const scalar tolerance,
    const label maxIterations,
    const scalar normFloor,
    const scalarField& invDiag,
    vectorField& x,
    scalar& residual
)
{
    const label n = b.size();
    x.setSize(n);
    x = Zero;
    vectorField work(s.invVolume.size());

    vectorField r(b);
    scalar normB = 0;
    for (const vector& v : b)
    {
        normB += magSqr(v);
    }
    normB = max(std::sqrt(normB), normFloor);
    residual = 0;
    if (normB == 0)
    {
        return 0;
    }

    residual = 0;
    for (const vector& v : r)
    {
        residual += magSqr(v);
    }
    residual = std::sqrt(residual)/normB;
    if (residual <= tolerance)
    {
        return 0;
    }

    vectorField z(n), p(n), Ap(n);
    forAll(z, k)
    {
        z[k] = invDiag[k]*r[k];
    }
    p = z;
    scalar rz = 0;
    forAll(r, k)
    {
        rz += r[k] & z[k];
    }

    for (label it = 1; it <= maxIterations; ++it)
    {
        applyA(s, dt, p, work, Ap);
        scalar pAp = 0;
        forAll(p, k)
        {
            pAp += p[k] & Ap[k];
        }
        const scalar alpha = rz/pAp;
        scalar rr = 0;
        forAll(x, k)
        {
            x[k] += alpha*p[k];
            r[k] -= alpha*Ap[k];
            rr += magSqr(r[k]);
        }
        residual = std::sqrt(rr)/normB;
        if (residual <= tolerance)
        {
            return it;
        }
        scalar rzNew = 0;
        forAll(z, k)
        {
            z[k] = invDiag[k]*r[k];
            rzNew += r[k] & z[k];
        }
        const scalar beta = rzNew/rz;
        rz = rzNew;
        forAll(p, k)
        {
            p[k] = z[k] + beta*p[k];
        }
    }
    return -1;
}

} // End anonymous namespace


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
    const label n = s.points.size();
    vectorField& u = s.u;

    // Right-hand side g = V* + Omega* x r - B u_hat (in-plane in 2D)
    const auto Bu = [&](const label k)
    {
        vector sum(Zero);
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            sum += s.rowWeight[e]*u[s.rowCell[e]];
        }
        return sum;
    };
    const auto inPlane = [&](vector v)
    {
        if (twoD_)
        {
            v.z() = 0;
        }
        return v;
    };
    vectorField g(n);
    scalar velocityScale2 = 0;
    forAll(g, k)
    {
        const vector r = s.points[k] - B.centre;
        const vector rigid = B.V + (B.omega ^ r);
        const vector fluid = Bu(k);
        g[k] = inPlane(rigid - fluid);
        velocityScale2 += max(magSqr(rigid), magSqr(fluid));
    }

    scalar residual = 0;
    const scalarField invDiag(inverseDiagonal(s, dt));
    const auto cg = [&]
    (
        const UList<vector>& rhs,
        const scalar floor,
        vectorField& x
    )
    {
        const label it = conjugateGradient
        (
            s, dt, rhs, tolerance_, maxIterations_, floor, invDiag, x,
            residual
        );
        if (it < 0)
        {
            FatalErrorInFunction
                << "particle " << b << ": the fictitious-domain CG did"
                << " not reach the tolerance " << tolerance_ << " in "
                << maxIterations_ << " iterations (residual "
                << residual << "); raise maxIterations or tolerance"
                << " in constant/dlmfdProperties" << exit(FatalError);
        }
        res.iterations = max(res.iterations, it);
    };

    // The multipliers for the velocities as they are; the tolerance is
    // relative to the velocities at the points, not to their
    // difference from the rigid motion
    vectorField lambda;
    cg(g, std::sqrt(velocityScale2), lambda);

    vector w_V(Zero), w_Omega(Zero);
    if (B.free)
    {
        // The rigid modes: translations e_a, rotations e_a x r;
        // in 2D only x, y and the rotation about z
        const labelList modes
        (
            twoD_
          ? (B.rotates ? labelList{0, 1, 5} : labelList{0, 1})
          : (B.rotates ? labelList{0, 1, 2, 3, 4, 5} : labelList{0, 1, 2})
        );
        const auto mode = [&](const label a, const label k)
        {
            vector e(Zero);
            e[a % 3] = 1;
            return a < 3 ? e : (e ^ (s.points[k] - B.centre));
        };
        const label nm = modes.size();
        List<vectorField> Umodes(nm, vectorField(n));
        List<vectorField> Z(nm);
        forAll(modes, i)
        {
            forAll(Umodes[i], k)
            {
                Umodes[i][k] = inPlane(mode(modes[i], k));
            }
            cg(Umodes[i], 0, Z[i]);
        }

        // K = C^-1 + U^T Z; C^-1 = diag((m-1) v_p, (m-1) J)/dt
        const scalar vp = B.shape->volume();
        const tensor J =
            B.R & B.shape->volumeInertia() & B.R.T();
        List<scalarList> K(nm, scalarList(nm, scalar(0)));
        scalarList rhs(nm, scalar(0));
        forAll(modes, i)
        {
            const label a = modes[i];
            forAll(modes, j)
            {
                const label c = modes[j];
                scalar sum = 0;
                for (label k = 0; k < n; ++k)
                {
                    sum += Umodes[i][k] & Z[j][k];
                }
                K[i][j] = sum;
                if (a < 3 && c < 3 && a == c)
                {
                    K[i][j] += B.excessDensity*vp/dt;
                }
                else if (a >= 3 && c >= 3)
                {
                    K[i][j] += B.excessDensity*J(a - 3, c - 3)/dt;
                }
            }
            for (label k = 0; k < n; ++k)
            {
                rhs[i] += Umodes[i][k] & lambda[k];
            }
        }
        if (!smallDenseSolve(K, rhs))
        {
            FatalErrorInFunction
                << "particle " << b << ": the rigid-mode system of the"
                << " fictitious-domain step is singular (m = "
                << 1 + B.excessDensity << ", " << n << " points);"
                << " the particle needs m > 0 and cells inside it"
                << exit(FatalError);
        }
        forAll(modes, i)
        {
            const label a = modes[i];
            forAll(lambda, k)
            {
                lambda[k] -= rhs[i]*Z[i][k];
            }
            if (a < 3)
            {
                w_V[a] = rhs[i];
            }
            else
            {
                w_Omega[a - 3] = rhs[i];
            }
        }
    }
    res.dV = -w_V;
    res.dOmega = -w_Omega;

    // The fluid in the body's cells, and the new force density
    f.setSize(u.size());
    f = Zero;
    forAll(s.points, k)
    {
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            f[s.rowCell[e]] += s.rowWeight[e]*lambda[k];
        }
        res.sumLambda += lambda[k];
        res.sumMoment += (s.points[k] - B.centre) ^ lambda[k];
    }
    forAll(f, i)
    {
        f[i] *= s.invVolume[i];
        u[i] += dt*f[i];
    }

    // What is left of the constraint
    const vector Vnew = B.V - w_V;
    const vector omegaNew = B.omega - w_Omega;
    forAll(s.points, k)
    {
        const vector r = s.points[k] - B.centre;
        res.constraintError = max
        (
            res.constraintError,
            mag(inPlane(Bu(k) - (Vnew + (omegaNew ^ r))))
        );
    }
}


// ************************************************************************* //

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
    The ghost-cell surface treatment of Foam::fictitiousDomain
    (surfaceTreatment ghostCells).

    The multipliers act on the body's own cells only (the cells whose
    centres lie inside it), as in Glowinski's method where lambda lives on
    the particle; the fluid cells are never forced, so the gaps between
    close bodies are never blocked by a constraint force. A cell deeper
    than one cell size below the surface moves rigidly. A cell within one
    cell size of the surface (a ghost cell, depth d below its nearest
    surface point p, outward normal n there) takes the velocity that puts
    the no-slip wall at p for the fluid cells around it:

    \f[
        u_c = u_r(x_c) - d\, a, \qquad
        a = \frac{\sum_f s_f (u_f - u_r(x_f))}{\sum_f s_f^2}, \quad
        s_f = n \cdot (x_f - p) > 0
    \f]

    with u_r the rigid motion and a the wall-normal derivative of the
    fluid's velocity relative to the body, fitted to the model w = s a
    that vanishes on the wall (its tangential derivatives do). The fluid
    cells of the fit are those outside every body within ghostFitRadius
    cell sizes of p; where they do not reach a cell size into the fluid
    (sum of s^2 below h^2) the radius grows by half a cell, twice, so that
    a ghost cell's velocity never amplifies the fluid's by much more than
    its depth over a cell. A ghost cell with no fluid cell in reach (two
    bodies in contact) moves rigidly.

    Every u_c is affine in the body's velocities (V, Omega). The fluid's
    cells get the force density f_c = (u_c - \hat u_c)/dt; the body takes
    the momentum that brings its cells from \hat u_c less the deviation
    delta_c = u_c - u_r(x_c) they were given by the last step to its rigid
    motion:

    \f[
        (m - 1) v_p (V - V^*) = - \sum_c V_c (u_r(x_c) - \hat u_c + \delta_c),
        \quad
        (m - 1) J (\Omega - \Omega^*)
      = - \sum_c V_c\, r_c \times (u_r(x_c) - \hat u_c + \delta_c)
    \f]

    a 6x6 linear system (about m v_p and m J on the diagonal, positive
    definite for every m > 0): the step is direct, with no iteration. The
    deviations are the fluid's extension through the wall, not momentum of
    the body: in a steady state they cancel, and a cell entering or leaving
    the ghost layer inwards as the body moves through the grid (a jump of
    up to a cell times the wall-normal derivative) does not kick the body
    (with them in its balance the ten Cate E2 sphere's speed jumped by
    2.5 % at each layer of cells it crossed). A cell that leaves the body
    leaves its deviation, about zero as its centre crosses the surface, in
    the fluid, and the body pays for it (contribution::released), so that
    the fluid's momentum less the deviations' sum (field ghostDeviation),
    plus the bodies', is kept exactly.

\*---------------------------------------------------------------------------*/

#include "fictitiousDomain.H"
#include "particleGeometry.H"
#include "smallDenseSolve.H"
#include "fictitiousDomainParts.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fictitiousDomain::findGhostCandidates
(
    const UList<body>& bodies,
    candidates& cand
)
{
    const vectorField& C = mesh_.C();

    for (const label c : touched_)
    {
        cellOwner_[c] = -1;
        ownerDist2_[c] = GREAT;
        ownerInside_[c] = false;
    }
    touched_.clear();

    const label n = bodies.size();
    cand.h = cellSizes(bodies);
    cand.shifts.setSize(n);
    cand.interior.setSize(n);
    cand.interiorShift.setSize(n);
    cand.stencils.setSize(n);
    cand.stencilShifts.setSize(n);

    // Every body's inside cells first, so that the fluid cells of the
    // next pass are those inside no body
    DynamicList<label> near;
    forAll(bodies, b)
    {
        const body& B = bodies[b];
        const scalar rb = B.shape->boundingRadius();
        const scalar h = cand.h[b];
        cand.shifts[b] = cellCentreSearch::periodicShifts
        (
            mesh_.bounds(), period_, B.centre, rb + reach()*h
        );
        const List<vector>& shifts = cand.shifts[b];
        forAll(shifts, si)
        {
            near.clear();
            search_.cellsInBall(B.centre - shifts[si], rb + h, near);
            for (const label c : near)
            {
                const point x = C[c] + shifts[si];
                if (particleGeometry::contains(*B.shape, B.centre, B.R, x))
                {
                    cand.interior[b].append(c);
                    cand.interiorShift[b].append(si);
                    claim(c, b, magSqr(x - B.centre), true);
                }
            }
        }
    }

    // The cells outside the body within reach of its surface (those inside
    // another body are left out when collected)
    forAll(bodies, b)
    {
        const body& B = bodies[b];
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
                const scalar bound = particleGeometry::outsideDistanceBound
                (
                    *B.shape, B.centre, B.R, x
                );
                if (bound >= 0 && bound < r)
                {
                    fluid.append(c);
                    fluidShift.append(si);
                }
            }
        }
        cand.stencils[b].setSize(1);
        cand.stencilShifts[b].setSize(1);
        cand.stencils[b][0].transfer(fluid);
        cand.stencilShifts[b][0].transfer(fluidShift);
    }
}


void Foam::fictitiousDomain::releasedDeviations
(
    const UList<body>& bodies,
    List<vector>& released,
    List<vector>& moment
) const
{
    released.setSize(bodies.size());
    moment.setSize(bodies.size());
    released = Zero;
    moment = Zero;
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    forAll(ghostOwner_, c)
    {
        const label o = label(ghostOwner_[c]);
        if (o < 0 || o >= bodies.size() || cellOwner_[c] == o)
        {
            continue;
        }
        // The nearest periodic image of the cell to the body
        vector arm = C[c] - bodies[o].centre;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (period_[d] > 0)
            {
                arm[d] -= period_[d]*std::round(arm[d]/period_[d]);
            }
        }
        const vector p = V[c]*deviation_[c];
        released[o] += p;
        moment[o] += arm ^ p;
    }
}


void Foam::fictitiousDomain::solveGhostBody
(
    const body& B,
    const scalar h,
    const UList<const contribution*>& parts,
    const scalar dt,
    vectorField& f,
    vectorField& dev,
    result& res
) const
{
    // The inside cells (rank after rank) and the fluid cells around
    DynamicList<point> xIn, xFluid;
    DynamicList<scalar> vIn;
    DynamicList<vector> uIn, devIn, uFluid;
    vector released(Zero), releasedMoment(Zero);
    for (const contribution* c : parts)
    {
        released += c->released;
        releasedMoment += c->releasedMoment;
        forAll(c->centres, i)
        {
            if (i < c->nInterior)
            {
                xIn.append(c->centres[i]);
                vIn.append(c->volumes[i]);
                uIn.append(c->u[i]);
                devIn.append(c->deviation[i]);
            }
            else
            {
                xFluid.append(c->centres[i]);
                uFluid.append(c->u[i]);
            }
        }
    }
    const label nIn = xIn.size();
    const point& X = B.centre;

    // Each inside cell's velocity after the step, W V + Omega x rt - e
    scalarField W(nIn, scalar(1));
    vectorField rt(nIn), e(nIn, Zero);
    const scalar R1 = ghostFitRadius_*h;
    const scalarList radii({R1, R1 + 0.5*h, R1 + h});
    label nGhost = 0, nAlone = 0;
    for (label c = 0; c < nIn; ++c)
    {
        rt[c] = xIn[c] - X;
        point foot;
        vector normal;
        const scalar d = particleGeometry::depth
        (
            *B.shape, X, B.R, xIn[c], foot, normal
        );
        if (d >= h)
        {
            continue;
        }
        ++nGhost;

        // The sums of the fit within each radius
        scalarList S2(3, Zero), S1(3, Zero);
        List<vector> Sx(3, Zero), Su(3, Zero);
        forAll(xFluid, j)
        {
            const vector q = xFluid[j] - foot;
            const scalar s = normal & q;
            const scalar r2 = magSqr(q);
            if (s <= 0 || r2 > sqr(radii[2]))
            {
                continue;
            }
            const label k = r2 <= sqr(radii[0]) ? 0 : r2 <= sqr(radii[1]) ? 1 : 2;
            S2[k] += s*s;
            S1[k] += s;
            Sx[k] += s*(xFluid[j] - X);
            Su[k] += s*uFluid[j];
        }
        scalar s2 = 0, s1 = 0;
        vector sx(Zero), su(Zero);
        for (label k = 0; k < 3; ++k)
        {
            s2 += S2[k];
            s1 += S1[k];
            sx += Sx[k];
            su += Su[k];
            if (s2 >= h*h)
            {
                break;
            }
        }
        if (s2 <= 0)
        {
            ++nAlone;
            continue;
        }
        W[c] = 1 + d*s1/s2;
        rt[c] += (d/s2)*sx;
        e[c] = (d/s2)*su;
    }

    // The 6x6 balance of the body's momentum, K y = rhs, y = (V, Omega).
    // The body takes the momentum that brings its cells to its rigid
    // motion from the fluid step's velocities less the deviations the last
    // step gave them: the ghost cells' deviations are the fluid's
    // extension through the wall, not momentum of the body, and a cell
    // that enters or leaves the ghost layer (the body moving through the
    // grid) must not kick it
    const scalar mvp = B.excessDensity*B.shape->volume();
    const tensor mJ = B.excessDensity*(B.R & B.shape->volumeInertia() & B.R.T());
    scalar sumV = 0;
    tensor KVO(Zero), KOO(mJ);
    vector sumVr(Zero), rhsV = mvp*B.V, rhsO = mJ & B.omega;
    for (label c = 0; c < nIn; ++c)
    {
        const vector r = xIn[c] - X;
        const scalar V = vIn[c];
        sumV += V;
        sumVr += V*r;
        // Omega x r = -[r]x Omega; r x (Omega x r) = ((r.r) I - r r) Omega
        KOO += V*(magSqr(r)*tensor::I - (r*r));
        const vector known = uIn[c] - devIn[c];
        rhsV += V*known;
        rhsO += V*(r ^ known);
    }
    KVO = -tensor(0, -sumVr.z(), sumVr.y(), sumVr.z(), 0, -sumVr.x(), -sumVr.y(), sumVr.x(), 0);
    const tensor KOV = -KVO;
    rhsV -= released;
    rhsO -= releasedMoment;

    // The unknown modes: translations 0-2, rotations 3-5; the others keep
    // their predicted values
    labelList modes;
    if (B.free)
    {
        modes = twoD_
          ? (B.rotates ? labelList{0, 1, 5} : labelList{0, 1})
          : (B.rotates ? labelList{0, 1, 2, 3, 4, 5} : labelList{0, 1, 2});
    }
    const auto K = [&](const label a, const label b) -> scalar
    {
        if (a < 3 && b < 3)
        {
            return a == b ? mvp + sumV : 0;
        }
        if (a < 3)
        {
            return KVO(a, b - 3);
        }
        if (b < 3)
        {
            return KOV(a - 3, b);
        }
        return KOO(a - 3, b - 3);
    };
    scalarList y(6);
    for (direction d = 0; d < 3; ++d)
    {
        y[d] = B.V[d];
        y[3 + d] = B.omega[d];
    }
    if (modes.size())
    {
        const label nm = modes.size();
        List<scalarList> A(nm, scalarList(nm));
        scalarList rhs(nm);
        boolList unknown(6, false);
        for (const label a : modes)
        {
            unknown[a] = true;
        }
        forAll(modes, i)
        {
            const label a = modes[i];
            rhs[i] = a < 3 ? rhsV[a] : rhsO[a - 3];
            for (label b = 0; b < 6; ++b)
            {
                if (!unknown[b])
                {
                    rhs[i] -= K(a, b)*y[b];
                }
            }
            forAll(modes, j)
            {
                A[i][j] = K(a, modes[j]);
            }
        }
        if (!smallDenseSolve(A, rhs))
        {
            FatalErrorInFunction
                << "the momentum balance of a particle at " << X
                << " (m = " << 1 + B.excessDensity << ", " << nIn
                << " cells inside) is singular; the particle needs m > 0"
                << " and cells inside it" << exit(FatalError);
        }
        forAll(modes, i)
        {
            y[modes[i]] = rhs[i];
        }
    }
    const vector Vnew(y[0], y[1], y[2]);
    const vector omegaNew(y[3], y[4], y[5]);
    res.dV = Vnew - B.V;
    res.dOmega = omegaNew - B.omega;

    // The cells' new velocities, the force density and the sums
    f.setSize(nIn);
    dev.setSize(nIn);
    vector momentum(Zero);
    for (label c = 0; c < nIn; ++c)
    {
        const vector r = xIn[c] - X;
        vector uNew = W[c]*Vnew + (omegaNew ^ rt[c]) - e[c];
        if (twoD_)
        {
            uNew.z() = uIn[c].z();
        }
        const vector rigid = Vnew + (omegaNew ^ r);
        dev[c] = uNew - rigid;
        f[c] = (uNew - uIn[c])/dt;
        // The force the body feels (see the balance above)
        const vector lambda = vIn[c]*(rigid - (uIn[c] - devIn[c]))/dt;
        res.sumLambda += lambda;
        res.sumMoment += r ^ lambda;
        momentum += dt*lambda;
    }
    res.sumLambda += released/dt;
    res.sumMoment += releasedMoment/dt;
    momentum += released;
    res.nInterior = nIn - nGhost;
    res.nSurface = nGhost;
    res.nSurfaceDropped = nAlone;
    res.iterations = 0;

    // What is left of the linear momentum balance (round-off), as a
    // velocity of the body's volume [m/s]
    if (B.free)
    {
        res.constraintError =
            mag(mvp*res.dV + momentum)/max(B.shape->volume(), VSMALL);
        if (twoD_)
        {
            vector m = mvp*res.dV + momentum;
            m.z() = 0;
            res.constraintError = mag(m)/max(B.shape->volume(), VSMALL);
        }
    }
}


// ************************************************************************* //

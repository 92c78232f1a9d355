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
    the particle; no fluid cell is forced, so the gaps between close bodies
    are not blocked by a constraint force. A cell deeper than one and a half cells below the
    surface moves rigidly. So does a cell within a cell and a half of it (a
    ghost cell) with ghostShear link (the default, Foam::wallLinks): the
    links carry the wall's shear along each grid link the surface cuts,
    and a normal deviation, which the fluid would meet only through
    convection and the mass flux (no viscous term to damp it), fed back on
    the fluid's normal velocity it was fitted from (a face-on cube at Re
    100, D/dx 12, never settled with it: benchmarks/fixedBodyDrag).

    With ghostShear viscous a ghost cell (depth d below its nearest surface
    point p, outward normal n there) takes the rigid motion u_r plus a
    normal deviation that makes the flux through the faces it shares with
    its fluid neighbours that of the wall; from one to one and a half
    cells deep the deviation fades to zero.

    With w = u - u_r the fluid's velocity relative to the body, fitted
    about p over the fluid cells within R = ghostFitRadius cells (s = n.(x
    - p) > 0, weights kappa = (1 - r^2/R^2)^2): at a no-slip wall w
    vanishes with its tangential derivatives, so its tangential part grows
    as s a_t and, by continuity, its normal part as b s^2. Along n the
    deviation is what makes the flux through the faces shared with the
    fluid neighbours that of the wall (zero where the face lies inside the
    body). Tangentially a ghost cell moves rigidly; the wall's shear
    reaches its fluid neighbours through the viscous flux of each face
    between them, the fitted profile carried through the wall, -d a_t, in
    that face's viscous flux (wallShearSource, in the next fluid step: the
    fluid cell gains what the ghost cell, and through its balance the
    body, loses). Every weight and the fade vanish where a cell enters or
    leaves them, so that the ghost velocities change continuously as the
    body moves through the grid. A ghost cell with no fluid cell in reach
    (two bodies in contact) moves rigidly.

    The fluid's cells get the force density f_c = (u_c - \hat u_c)/dt;
    the body takes the momentum that brings its cells from \hat u_c, less
    the deviation delta_c the last step gave them, to its rigid motion:

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
    the ghost layer as the body moves through the grid does not kick the
    body. A cell that leaves the body leaves its deviation, about zero as
    its centre crosses the surface, in the fluid, and the body pays for it
    (contribution::released), so that the fluid's momentum less the
    deviations' sum (field ghostDeviation), plus the bodies', is kept
    exactly.

\*---------------------------------------------------------------------------*/

#include "fictitiousDomain.H"
#include "pointBins.H"
#include "posedShape.H"
#include "rigidMomentumBalance.H"
#include "fictitiousDomainParts.H"

#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fictitiousDomain::solveGhostBody
(
    const UList<body>& bodies,
    const label bi,
    const scalar h,
    const UList<const contribution*>& parts,
    const scalar dt,
    vectorField& f,
    vectorField& dev,
    result& res
) const
{
    const body& B = bodies[bi];
    // The body's cells and (ghostShear viscous) the fluid cells around
    // (data), rank after rank; f and dev follow the order of the body's
    // cells, part after part
    DynamicList<point> xIn, xData;
    DynamicList<scalar> vIn;
    DynamicList<vector> uIn, devIn, uData;
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
                xData.append(c->centres[i]);
                uData.append(c->u[i]);
            }
        }
    }
    const label nIn = xIn.size();
    const point& X = B.centre;
    const posedShape S(*B.shape, X, B.R);
    const scalar fitRadius = ghostFitRadius_*h;
    const scalar R2 = sqr(fitRadius);

    // The data cells in bins of a third of the fit radius: a fit looks at
    // the cells of the bins that the box of its half-ball (the fluid side
    // of its surface point) meets, a ghost cell's links (1.1 cells) at
    // those of its ball's box, instead of every cell; the cells kept are
    // sorted, so that the sums run in the order of the cells as before,
    // bit for bit
    const pointBins dataBins(xData, fitRadius/3);
    DynamicList<label> near;

    // The fit about a surface point p (outward normal n) of the relative
    // velocity w = u - u_r of the data cells at least half a cell out
    // (s = n.(x - p) >= h/2, within R = ghostFitRadius cells of p, weights
    // kappa = (1 - r^2/R^2)^2 of their distance r from p): w = s a_t +
    // b s^2 n near a no-slip wall (w and its tangential derivatives vanish
    // on it; by continuity the normal part starts quadratically). Returned
    // as weights: a = sum alpha_k w_k, b = sum beta_k (w_k.n)
    const auto fit = [&]
    (
        const point& p,
        const vector& n,
        DynamicList<label>& cells,
        DynamicList<scalar>& alpha,
        DynamicList<scalar>& beta
    )
    {
        cells.clear();
        alpha.clear();
        beta.clear();
        near.clear();
        point lo, hi;
        pointBins::capBox(p, fitRadius, n, cutCellLimit*h, lo, hi);
        dataBins.forInBox(lo, hi, [&](const label k)
        {
            const vector q = xData[k] - p;
            if ((n & q) >= cutCellLimit*h && magSqr(q) < R2)
            {
                near.append(k);
            }
        });
        std::sort(near.begin(), near.end());
        scalar S2 = 0, S4 = 0;
        for (const label k : near)
        {
            const vector q = xData[k] - p;
            const scalar sk = n & q;
            const scalar kappa = sqr(1 - magSqr(q)/R2);
            cells.append(k);
            alpha.append(kappa*sk);
            beta.append(kappa*sk*sk);
            S2 += kappa*sk*sk;
            S4 += kappa*sqr(sk*sk);
        }
        for (scalar& x : alpha)
        {
            x /= S2;
        }
        for (scalar& x : beta)
        {
            x /= S4;
        }
        return cells.size() > 0;
    };

    // The momentum balance, K y = rhs, y = (V, Omega). The body takes the
    // momentum that brings its cells to its rigid motion from the fluid
    // step's velocities less the deviations the last step gave them (see
    // the description above)
    const scalar mvp = B.excessDensity*B.shape->volume();
    const tensor mJ = B.excessDensity*(B.R & B.shape->volumeInertia() & B.R.T());
    rigidMomentumBalance balance
    (
        mvp, mJ, B.V, B.omega, released, releasedMoment
    );
    for (label c = 0; c < nIn; ++c)
    {
        balance.addRigidCell(xIn[c] - X, vIn[c], uIn[c] - devIn[c]);
    }

    DynamicList<label> cells;
    DynamicList<scalar> alpha, beta;

    // The unknown modes: translations 0-2, rotations 3-5; the others keep
    // their predicted values
    labelList modes;
    if (B.free)
    {
        modes = twoD_
          ? (B.rotates ? labelList{0, 1, 5} : labelList{0, 1})
          : (B.rotates ? labelList{0, 1, 2, 3, 4, 5} : labelList{0, 1, 2});
    }
    vector Vnew = B.V, omegaNew = B.omega;
    if (!balance.solve(modes, Vnew, omegaNew))
    {
        FatalErrorInFunction
            << "the momentum balance of a particle at " << X
            << " (m = " << 1 + B.excessDensity << ", " << nIn
            << " cells inside) is singular; the particle needs m > 0"
            << " and cells inside it" << exit(FatalError);
    }
    res.dV = Vnew - B.V;
    res.dOmega = omegaNew - B.omega;
    const auto rigidAt = [&](const point& x)
    {
        return Vnew + (omegaNew ^ (x - X));
    };

    // The ghost cells, within one and a half cells below the surface
    // (with ghostShear viscous): the rigid motion plus the profile of the
    // fit carried through the wall at its nearest point p, -d a_t
    // tangentially; along n, what makes
    // the flux through the faces shared with the fluid neighbours (within
    // 1.1 cells) that of the model, b s_face^2 where the face lies in the
    // fluid, zero where it lies inside the body. From one to one and a
    // half cells deep the deviation fades to zero, so that a cell sinking
    // into the body (or rising out of it) changes smoothly; every weight
    // of the fit vanishes where a cell enters or leaves it.
    const auto fadeOf = [&](const scalar d)
    {
        return d <= h ? scalar(1) : max(scalar(0), 3 - 2*d/h);
    };
    dev.setSize(nIn);
    dev = Zero;
    // The mirrored profile, for the viscous fluxes only
    const bool viscous = ghostShear_ == ghostShearModel::viscous;
    vectorField mirror(viscous ? nIn : 0, Zero);
    label nGhost = 0, nAlone = 0;
    const scalar link2 = sqr(1.1*h);
    for (label c = 0; c < nIn; ++c)
    {
        point p;
        vector n;
        const scalar d = S.depth(xIn[c], p, n);
        const scalar fade = fadeOf(d);
        if (fade <= 0)
        {
            continue;
        }
        ++nGhost;
        // With ghostShear link the ghost cell moves rigidly (why: the
        // Description)
        if (!viscous)
        {
            continue;
        }
        if (!fit(p, n, cells, alpha, beta))
        {
            ++nAlone;
            continue;
        }
        // The wall slope a_t and b for the normal part
        vector a(Zero);
        scalar b = 0;
        forAll(cells, i)
        {
            const label k = cells[i];
            const vector w = uData[k] - rigidAt(xData[k]);
            a += alpha[i]*w;
            b += beta[i]*(w & n);
        }
        // The normal part through the faces to the fluid neighbours, the
        // links weighed by how far out the neighbour is
        scalar linkSum = 0, linkWeight = 0;
        const auto addLink = [&](const point& x)
        {
            const vector link = x - xIn[c];
            const scalar sx = n & (x - p);
            if (sx <= 0 || magSqr(link) > link2)
            {
                return;
            }
            const scalar sFace = n & (xIn[c] + 0.5*link - p);
            linkSum += sx*(2*b*sqr(max(sFace, scalar(0))) - b*sqr(sx));
            linkWeight += sx;
        };
        // The cells of a set within link reach, in their order
        const auto addLinks = [&](const pointBins& bins, const UList<point>& xs)
        {
            near.clear();
            bins.forNear(xIn[c], 1.1*h, [&](const label k)
            {
                if (magSqr(xs[k] - xIn[c]) <= link2)
                {
                    near.append(k);
                }
            });
            std::sort(near.begin(), near.end());
            for (const label k : near)
            {
                addLink(xs[k]);
            }
        };
        addLinks(dataBins, xData);
        const scalar wn = linkSum/max(linkWeight, 0.5*h);
        // Tangentially the cell moves rigidly: the fitted profile carried
        // through the wall, -d a_t, enters the viscous fluxes to its fluid
        // neighbours
        dev[c] = fade*(wn*n);
        vector profile(-d*(a - (a & n)*n));
        if (twoD_)
        {
            dev[c].z() = 0;
            profile.z() = 0;
        }
        mirror[c] = fade*profile;
    }

    // The new velocities, the force density on the fluid and what the body
    // takes, in the order of the parts. With ghostShear viscous the
    // mirrored velocities follow, in the same order
    f.setSize(nIn);
    vectorField devOut((viscous ? 2 : 1)*nIn, Zero);
    vector momentum(Zero);
    for (label c = 0; c < nIn; ++c)
    {
        const vector r = xIn[c] - X;
        const vector rigid = rigidAt(xIn[c]);
        vector uNew = rigid + dev[c];
        if (twoD_)
        {
            uNew.z() = uIn[c].z();
        }
        f[c] = (uNew - uIn[c])/dt;
        devOut[c] = dev[c];
        if (viscous)
        {
            devOut[nIn + c] = mirror[c];
        }
        const vector lambda = vIn[c]*(rigid - (uIn[c] - devIn[c]))/dt;
        res.sumLambda += lambda;
        res.sumMoment += r ^ lambda;
        momentum += dt*lambda;
    }
    dev.transfer(devOut);
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
        vector m = mvp*res.dV + momentum;
        if (twoD_)
        {
            m.z() = 0;
        }
        res.constraintError = mag(m)/max(B.shape->volume(), VSMALL);
    }
}


// ************************************************************************* //

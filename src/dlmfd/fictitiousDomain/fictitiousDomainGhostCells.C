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
    the particle; a fluid cell is forced only for the part of it the
    body's surface cuts off (below), so the gaps between close bodies are
    not blocked by a constraint force. A cell deeper
    than one and a half cells below the surface moves rigidly. A cell
    within a cell of it (a ghost cell, depth d below its nearest surface
    point p, outward normal n there) takes the rigid motion u_r plus a
    deviation that makes its fluid neighbours feel the wall at p; from one
    to one and a half cells deep the deviation fades to zero.

    With w = u - u_r the fluid's velocity relative to the body, fitted
    about p over the fluid cells within R = ghostFitRadius cells (s = n.(x
    - p) > 0, weights kappa = (1 - r^2/R^2)^2): at a no-slip wall w
    vanishes with its tangential derivatives, so its tangential part grows
    as s a_t and, by continuity, its normal part as b s^2. Along n the
    deviation is what makes the flux through the faces shared with the
    fluid neighbours that of the wall (zero where the face lies inside the
    body). Tangentially the profile carried through the wall, -d a_t, gives
    the right shear at the wall; with ghostShear viscous (the default) it
    is not the cell's velocity but enters the viscous flux of each face
    between the ghost cell and a fluid cell (wallShearSource, in the next
    fluid step: the fluid cell gains what the ghost cell, and through its
    balance the body, loses). With ghostShear mirrored the cells carry it:
    along the body's shell their velocities then run against the outer
    flow, and the projection makes that a mass flux through the body (a
    fixed sphere at Re 100 passed a fifth of the flow it met through its
    inside, out at the front stagnation point, and lost 16 % of its drag:
    benchmarks/fixedBodyDrag, case.ghostCellsBodyPassesNoFlow). Every
    weight and the fade vanish where a cell enters or leaves them, so that
    the ghost velocities change continuously as the body moves through the
    grid. A ghost cell with no fluid cell in reach (two bodies in contact)
    moves rigidly.

    The cells the surface cuts (centres within half a cell of it): with
    ghostCutCells solidFractionBothSides each is forced by
    the part of it inside the body, phi = 1/2 + d/h_n (d the centre's
    depth, negative outside; h_n the cell's width along n): a fluid cell
    s = -d out is held at phi of the fitted profile u_r + s a_t + b s^2 n,
    a body cell keeps the rest of its velocity (counted in its deviation,
    so the body's balance below does not change). Held means: in a steady
    state u = phi u_t + (1 - phi) u_f, u_t the target, u_f the velocity
    the fluid's own equation gives the cell (A_f u_f its neighbours' and
    the pressure's pull, A_f its momentum diagonal without the ddt part),
    as a Brinkman term (phi/(1 - phi)) A_f (u_t - u) would. The fluid step
    carries the last force S, which this step replaces, so in a steady
    state S = (sigma/(1 - sigma)) (u_t - u)/dt for a step that moves the
    cell the share sigma of its way to u_t: sigma = phi beta/(phi beta +
    1 - phi), beta = dt A_f (setFluidRelaxation), gives the Brinkman
    term whatever dt (fluidStepForce penalty holds the bodies' own cells
    in the fluid step, but the cut cells' S is carried there too). Before
    2026-12-03 sigma = phi: a hold growing as 1/dt (a frozen sphere array,
    +15 % drag from CFL 0.5 to 0.1; benchmarks/frozenArrays). Without it
    (none, the default) the blockage of the body is that of the cells
    whose centres lie inside: a cube whose faces stand 0.4 cell beyond a
    row of centres acted 0.8 cell thinner, with 22 % too little drag at
    D/dx 6
    (benchmarks/fixedBodyDrag). It is not the default because free bodies
    settle slower with it (doc/dictionaries.md): a cell crossing the
    surface then carries a deviation of about half the fluid's relative
    velocity, which the body pays as it leaves (suspected, not shown).

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
    body (with them in its balance the ten Cate E2 sphere's speed jumped by
    2.5 % at each layer of cells it crossed). A cell that leaves the body
    leaves its deviation, about zero as its centre crosses the surface, in
    the fluid, and the body pays for it (contribution::released), so that
    the fluid's momentum less the deviations' sum (field ghostDeviation),
    plus the bodies', is kept exactly.

\*---------------------------------------------------------------------------*/

#include "fictitiousDomain.H"
#include "pointBins.H"
#include "posedShape.H"
#include "rigidMomentumBalance.H"
#include "fictitiousDomainParts.H"
#include "neighbourSurfaces.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// The share of its way to the target a cell of solid fraction s is moved
// in a step whose fluid relaxation is beta (dt A_f, see the description):
// s beta/(s beta + 1 - s), which makes the steady state s target + (1 -
// s) u_f whatever dt
Foam::scalar stepShare(const Foam::scalar s, const Foam::scalar beta)
{
    return s >= 1 ? 1 : s*beta/(s*beta + 1 - s);
}

} // End anonymous namespace


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
    // The body's cells, the fluid cells its surface cuts and the other
    // fluid cells around (data), rank after rank; f and dev follow the
    // order of the first two groups, part after part
    DynamicList<point> xIn, xCut, xData;
    DynamicList<scalar> vIn, vCut, betaIn, betaCut;
    DynamicList<vector> uIn, devIn, uCut, uData;
    DynamicList<label> order;    // into In (>= 0) or Cut (-1 - index)
    vector released(Zero), releasedMoment(Zero);
    for (const contribution* c : parts)
    {
        released += c->released;
        releasedMoment += c->releasedMoment;
        forAll(c->centres, i)
        {
            if (i < c->nInterior)
            {
                order.append(xIn.size());
                xIn.append(c->centres[i]);
                vIn.append(c->volumes[i]);
                uIn.append(c->u[i]);
                devIn.append(c->deviation[i]);
                if (c->relaxation.size())
                {
                    betaIn.append(c->relaxation[i]);
                }
            }
            else if (i < c->nInterior + c->nCut)
            {
                order.append(-1 - xCut.size());
                xCut.append(c->centres[i]);
                vCut.append(c->volumes[i]);
                uCut.append(c->u[i]);
                if (c->relaxation.size())
                {
                    betaCut.append(c->relaxation[i]);
                }
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
    const bool quadratic = ghostFitOrder_ == 2;

    // ghostFitOrder 2: the other bodies (nearest images) whose surface a
    // fit may meet, and a spare slot at the end of the data for the datum
    // a fit takes from that surface
    neighbourSurfaces walls;
    const label nData = xData.size();
    if (quadratic)
    {
        const scalar reachB = B.shape->boundingRadius() + fitRadius;
        forAll(bodies, o)
        {
            const body& O = bodies[o];
            const vector d = images_.nearest(O.centre - X);
            if (o != bi && mag(d) < reachB + O.shape->boundingRadius())
            {
                walls.add(*O.shape, X + d, O.R, O.V, O.omega);
            }
        }
        xData.append(X);
        uData.append(Zero);
    }

    // ghostFitDistance surface: each data cell's own distance to the
    // body's surface (the largest face-plane distance for polyhedra),
    // computed once per body; the wall datum's slot is set by each fit
    scalarList sData;
    if (fitDistance_ == ghostFitDistance::surface)
    {
        sData.setSize(xData.size());
        for (label k = 0; k < nData; ++k)
        {
            sData[k] = S.outsideDistanceBound(xData[k]);
        }
    }

    // The data and cut cells in bins of a third of the fit radius: a fit
    // looks at the cells of the bins that the box of its half-ball (the
    // fluid side of its surface point) meets, a ghost cell's links (1.1
    // cells) at those of its ball's box, instead of every cell; the cells
    // kept are sorted, so that the sums run in the order of the cells as
    // before, bit for bit
    const pointBins dataBins(xData, fitRadius/3);
    const pointBins cutBins(xCut, fitRadius/3);
    DynamicList<label> near;

    // The fit about a surface point p (outward normal n) of the relative
    // velocity w = u - u_r of the data cells at least half a cell out
    // (s = n.(x - p) >= h/2, within R = ghostFitRadius cells of p, weights
    // kappa = (1 - r^2/R^2)^2 of their distance r from p): w = s a_t +
    // b s^2 n near a no-slip wall (w and its tangential derivatives vanish
    // on it; by continuity the normal part starts quadratically). Returned
    // as weights: a = sum alpha_k w_k / s-scale, b = sum beta_k (w_k.n).
    // With ghostFitOrder 2 the tangential part is s a_t + s^2 c_t, c =
    // sum gamma_k w_k: a linear fit of a profile that bends (a gap between
    // two walls, a boundary layer thinner than R) underestimates the wall
    // slope. Its least squares carry a penalty eps S4 c^2 (eps = 1e-4),
    // which keeps the weights bounded where the cells lie at about one s
    // (the fit then tends to the linear one). It takes as a datum the
    // surface of another body that the ray p + t n meets within R, with
    // that body's rigid velocity there: in a gap narrower than R the
    // profile then vanishes at both walls (in a one-dimensional model of
    // the coupling, benchmarks/frozenArrays/gapModel, a gap of two cells
    // passes 29 % too much flow without it, 0.0 % with it; 50 % with
    // ghostFitOrder 1)
    const auto fit = [&]
    (
        const point& p,
        const vector& n,
        DynamicList<label>& cells,
        DynamicList<scalar>& alpha,
        DynamicList<scalar>& beta,
        DynamicList<scalar>& gamma
    )
    {
        cells.clear();
        alpha.clear();
        beta.clear();
        gamma.clear();
        near.clear();
        // (with the surface distance a cell beyond an edge may count
        // though it lies behind the plane through p: the whole ball)
        point lo, hi;
        if (sData.size())
        {
            lo = p - vector::uniform(fitRadius);
            hi = p + vector::uniform(fitRadius);
        }
        else
        {
            pointBins::capBox(p, fitRadius, n, cutCellLimit*h, lo, hi);
        }
        dataBins.forInBox(lo, hi, [&](const label k)
        {
            const vector q = xData[k] - p;
            const scalar sk = sData.size() ? sData[k] : (n & q);
            if (sk >= cutCellLimit*h && magSqr(q) < R2)
            {
                near.append(k);
            }
        });
        std::sort(near.begin(), near.end());
        // The other body's surface counts as a layer of cells at its
        // distance t (neighbourSurfaces::layerWeight)
        scalar wallWeight = 0, t;
        vector uWall;
        if
        (
            quadratic
         && walls.firstAlong(p, n, fitRadius, 0.25*h, t, uWall)
        )
        {
            xData[nData] = p + t*n;
            uData[nData] = uWall;
            if (sData.size())
            {
                sData[nData] = t;
            }
            near.append(nData);
            wallWeight = neighbourSurfaces::layerWeight(t, fitRadius, h, twoD_);
        }
        scalar S2 = 0, S3 = 0, S4 = 0;
        for (const label k : near)
        {
            const vector q = xData[k] - p;
            const scalar sk = sData.size() ? sData[k] : (n & q);
            const scalar r2 = magSqr(q);
            // (nData, the spare slot, exists with ghostFitOrder 2 only)
            const scalar kappa = k == nData ? wallWeight : sqr(1 - r2/R2);
            cells.append(k);
            alpha.append(kappa*sk);
            beta.append(kappa*sk*sk);
            S2 += kappa*sk*sk;
            S3 += kappa*sk*sk*sk;
            S4 += kappa*sqr(sk*sk);
        }
        if (quadratic && cells.size())
        {
            // [S2 S3; S3 (1 + eps) S4] (a, c) = sum kappa (s, s^2) w
            const scalar S4e = 1.0001*S4;
            const scalar det = S2*S4e - S3*S3;
            forAll(cells, i)
            {
                const scalar ks = alpha[i], ks2 = beta[i];
                alpha[i] = (S4e*ks - S3*ks2)/det;
                gamma.append((S2*ks2 - S3*ks)/det);
            }
        }
        else
        {
            for (scalar& x : alpha)
            {
                x /= S2;
            }
            gamma.setSize(cells.size(), Zero);
        }
        for (scalar& x : beta)
        {
            x /= S4;
        }
        return cells.size() > 0;
    };
    const auto cross = &rigidMomentumBalance::cross;

    // The momentum balance, K y = rhs, y = (V, Omega). The body takes the
    // momentum that brings its cells to its rigid motion from the fluid
    // step's velocities less the deviations the last step gave them (see
    // the description above), and that of the cut cells it forces
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

    // A cut cell, s < h/2 out: u = u_r + s a_t + b s^2 n = P V + Q Omega +
    // E, affine in the body's velocities (w_k = u_k - V - Omega x r_k)
    const label nCut = xCut.size();
    List<tensor> P(nCut, tensor::I), Q(nCut);
    List<vector> E(nCut, Zero);
    boolList forced(nCut, false);
    scalarList share(nCut, scalar(1));
    DynamicList<label> cells;
    DynamicList<scalar> alpha, beta, gamma;
    for (label j = 0; j < nCut; ++j)
    {
        const vector rj = xCut[j] - X;
        Q[j] = -cross(rj);
        point p;
        vector n;
        const scalar sj = -S.depth(xCut[j], p, n);
        if (!fit(p, n, cells, alpha, beta, gamma))
        {
            continue;
        }
        forced[j] = true;
        // The share of the cell inside the body: all of it (full), or
        // 1/2 - s/h_n, h_n the width of an axis-aligned cell along n
        if
        (
            cutCells_ == cutCellForcing::solidFraction
         || cutCells_ == cutCellForcing::solidFractionBothSides
        )
        {
            const scalar hn = h*(mag(n.x()) + mag(n.y()) + mag(n.z()));
            share[j] = stepShare
            (
                min(max(0.5 - sj/hn, scalar(0)), scalar(1)), betaCut[j]
            );
        }
        else if (cutCells_ == cutCellForcing::ramp)
        {
            share[j] = stepShare
            (
                min(max(1 - sj/(cutCellLimit*h), scalar(0)), scalar(1)),
                betaCut[j]
            );
        }
        const tensor nn(n*n), tt(tensor::I - nn);
        scalar sa = 0, sb = 0;
        vector ua(Zero), ub(Zero), ra(Zero), rb(Zero);
        forAll(cells, i)
        {
            const label k = cells[i];
            // The tangential weight at sj: s alpha_k + s^2 gamma_k
            const scalar at = alpha[i] + sj*gamma[i];
            sa += at;
            sb += beta[i];
            ua += at*uData[k];
            ub += beta[i]*uData[k];
            ra += at*(xData[k] - X);
            rb += beta[i]*(xData[k] - X);
        }
        // T_k = sj alpha_k tt + sj^2 beta_k nn; sum T_k, sum T_k u_k,
        // sum T_k [r_k]x
        const tensor A = sj*sa*tt + sqr(sj)*sb*nn;
        E[j] = sj*(tt & ua) + sqr(sj)*(nn & ub);
        P[j] = tensor::I - A;
        Q[j] += sj*(tt & cross(ra)) + sqr(sj)*(nn & cross(rb));
        balance.addAffineCell
        (
            rj, share[j]*vCut[j], P[j], Q[j], E[j], uCut[j]
        );
    }

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

    // The ghost cells, within one and a half cells below the surface:
    // the rigid motion plus the profile of the fit carried through the
    // wall at its nearest point p, -d a_t tangentially; along n, what makes
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
    // ghostShear viscous: the mirrored profile, for the viscous fluxes only
    const bool viscous = ghostShear_ == ghostShearModel::viscous;
    vectorField mirror(viscous ? nIn : 0, Zero);
    label nGhost = 0, nAlone = 0;
    const scalar link2 = sqr(1.1*h);
    // The share of each body cell inside the body: 1, or 1/2 + d/h_n with
    // the cut cells' solid fraction on both sides of the surface
    scalarList shareIn(nIn, scalar(1));
    for (label c = 0; c < nIn; ++c)
    {
        point p;
        vector n;
        const scalar d = S.depth(xIn[c], p, n);
        if (cutCells_ == cutCellForcing::solidFractionBothSides)
        {
            const scalar hn = h*(mag(n.x()) + mag(n.y()) + mag(n.z()));
            shareIn[c] = stepShare(min(0.5 + d/hn, scalar(1)), betaIn[c]);
        }
        const scalar fade = fadeOf(d);
        if (fade <= 0)
        {
            continue;
        }
        ++nGhost;
        if (!fit(p, n, cells, alpha, beta, gamma))
        {
            ++nAlone;
            continue;
        }
        vector a(Zero), cq(Zero);
        scalar b = 0;
        forAll(cells, i)
        {
            const label k = cells[i];
            const vector w = uData[k] - rigidAt(xData[k]);
            a += alpha[i]*w;
            b += beta[i]*(w & n);
            cq += gamma[i]*w;
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
        addLinks(cutBins, xCut);
        const scalar wn = linkSum/max(linkWeight, 0.5*h);
        // The profile carried through the wall: in the cell's velocity
        // (mirrored) or in the viscous fluxes to its fluid neighbours
        // (viscous)
        vector profile(-d*(a - (a & n)*n));
        if (quadratic)
        {
            // The parabola continued through the wall, exact for a gap's
            // Poiseuille profile (with the line, ghostFitOrder 1, a gap of
            // 2, 3, 4 cells passes 50, 22, 12 % too much flow:
            // benchmarks/frozenArrays/gapModel)
            profile += sqr(d)*(cq - (cq & n)*n);
        }
        if (twoD_)
        {
            profile.z() = 0;
        }
        const bool carried = ghostShear_ == ghostShearModel::mirrored;
        dev[c] = fade*((carried ? profile : vector(Zero)) + wn*n);
        if (twoD_)
        {
            dev[c].z() = 0;
        }
        if (viscous)
        {
            mirror[c] = fade*profile;
        }
    }

    // The new velocities, the force density on the fluid and what the body
    // takes, in the order of the parts
    // With ghostShear viscous the mirrored velocities follow, in the same
    // order (zero for the cut cells)
    f.setSize(order.size());
    vectorField devOut((viscous ? 2 : 1)*order.size(), Zero);
    vector momentum(Zero);
    forAll(order, i)
    {
        if (order[i] >= 0)
        {
            const label c = order[i];
            const vector r = xIn[c] - X;
            const vector rigid = rigidAt(xIn[c]);
            // A cell partly outside the body keeps that part of its
            // velocity; what it keeps counts as its deviation, so that the
            // body's balance above holds whatever the share
            vector uNew = rigid + dev[c];
            if (shareIn[c] < 1)
            {
                uNew = uIn[c] + shareIn[c]*(uNew - uIn[c]);
            }
            if (twoD_)
            {
                uNew.z() = uIn[c].z();
            }
            f[i] = (uNew - uIn[c])/dt;
            devOut[i] = dev[c];
            if (viscous)
            {
                devOut[order.size() + i] = mirror[c];
            }
            if (shareIn[c] < 1)
            {
                devOut[i] = uNew - rigid;
                if (twoD_)
                {
                    devOut[i].z() = dev[c].z();
                }
            }
            const vector lambda = vIn[c]*(rigid - (uIn[c] - devIn[c]))/dt;
            res.sumLambda += lambda;
            res.sumMoment += r ^ lambda;
            momentum += dt*lambda;
        }
        else
        {
            const label j = -1 - order[i];
            f[i] = Zero;
            if (!forced[j])
            {
                continue;
            }
            vector uNew = (P[j] & Vnew) + (Q[j] & omegaNew) + E[j];
            if (twoD_)
            {
                uNew.z() = uCut[j].z();
            }
            f[i] = share[j]*(uNew - uCut[j])/dt;
            const vector lambda = vCut[j]*f[i];
            res.sumLambda += lambda;
            res.sumMoment += (xCut[j] - X) ^ lambda;
            momentum += dt*lambda;
        }
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

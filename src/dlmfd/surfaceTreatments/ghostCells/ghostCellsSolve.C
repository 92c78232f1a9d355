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
    One body's constraint with the ghost cells (Foam::surfaceTreatments::
    ghostCells, whose header gives the equations): its momentum balance
    over its cells, its new velocities, and with ghostShear viscous the
    normal deviation and the mirrored wall velocity of its outer cells
    from the fit of the fluid near its surface.

\*---------------------------------------------------------------------------*/

#include "ghostCells.H"
#include "pointBins.H"
#include "posedShape.H"
#include "rigidMomentumBalance.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::surfaceTreatments::ghostCells::solveBody
(
    const fictitiousDomainBody& B,
    const scalar h,
    const UList<const fictitiousDomainContribution*>& parts,
    const scalar dt,
    vectorField& f,
    vectorField& dev,
    fictitiousDomainResult& res
) const
{
    // The body's cells and (ghostShear viscous) the fluid cells around
    // (data), rank after rank; f and dev follow the order of the body's
    // cells, part after part
    DynamicList<point> xIn, xData;
    DynamicList<scalar> vIn;
    DynamicList<vector> uIn, devIn, uData;
    vector owed(Zero), owedMoment(Zero);
    for (const fictitiousDomainContribution* c : parts)
    {
        owed += c->owed;
        owedMoment += c->owedMoment;
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
    const scalar fitRadius = fitRadius_*h;
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
        mvp, mJ, B.V, B.omega, owed, owedMoment
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
    const bool viscous = shear_ == shearModel::viscous;
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
    res.sumLambda += owed/dt;
    res.sumMoment += owedMoment/dt;
    momentum += owed;
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

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
    ghostCells, whose header gives the equations): its cells gathered from
    the ranks' parts, its momentum balance and new velocities, with
    ghostShear viscous the normal deviation and the mirrored wall velocity
    of its outer cells from the fit of the fluid near its surface, and the
    force density and deviation of each of its cells.

\*---------------------------------------------------------------------------*/

#include "ghostCells.H"
#include "pointBins.H"
#include "posedShape.H"
#include "rigidMomentumBalance.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace surfaceTreatments
{

//- A body's cells as every rank sent them, rank after rank: its own
//- (inside), and the fluid cells around that its fits read (data), with
//- what it owes the fluid
struct ghostCellsGathered
{
    DynamicList<point> xIn, xData;
    DynamicList<scalar> vIn;
    DynamicList<vector> uIn, devIn, uData;
    vector owed = Zero;
    vector owedMoment = Zero;

    explicit ghostCellsGathered
    (
        const UList<const fictitiousDomainContribution*>& parts
    )
    {
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
    }
};


//- The fit, about a surface point p (outward normal n), of the relative
//- velocity w = u - u_r of the data cells at least half a cell out (s =
//- n.(x - p) >= h/2, within R = ghostFitRadius cells of p, weights kappa =
//- (1 - r^2/R^2)^2 of their distance r from p): w = s a_t + b s^2 n near a
//- no-slip wall (w and its tangential derivatives vanish on it; by
//- continuity the normal part starts quadratically). The data cells sit in
//- bins of a third of the fit radius: a fit looks at the cells of the bins
//- that the box of its half-ball (the fluid side of its surface point)
//- meets, a ghost cell's links (1.1 cells) at those of its ball's box,
//- instead of every cell; the cells kept are sorted, so that the sums run
//- in the order of the cells, bit for bit
class ghostCellsNearWallFit
{
    const UList<point>& x_;
    const scalar h_;
    const scalar fitRadius_;
    const scalar R2_;
    const pointBins bins_;
    mutable DynamicList<label> near_;

public:

    ghostCellsNearWallFit
    (
        const UList<point>& x,
        const scalar h,
        const scalar fitRadius
    )
    :
        x_(x),
        h_(h),
        fitRadius_(fitRadius),
        R2_(sqr(fitRadius)),
        bins_(x, fitRadius/3),
        near_()
    {}

    //- The weights of the fit about p: a = sum alpha_k w_k, b = sum
    //- beta_k (w_k.n) over the data cells cells; false: no data cell
    bool fit
    (
        const point& p,
        const vector& n,
        DynamicList<label>& cells,
        DynamicList<scalar>& alpha,
        DynamicList<scalar>& beta
    ) const
    {
        const scalar cut = ghostCells::cutCellLimit*h_;
        cells.clear();
        alpha.clear();
        beta.clear();
        near_.clear();
        point lo, hi;
        pointBins::capBox(p, fitRadius_, n, cut, lo, hi);
        bins_.forInBox(lo, hi, [&](const label k)
        {
            const vector q = x_[k] - p;
            if ((n & q) >= cut && magSqr(q) < R2_)
            {
                near_.append(k);
            }
        });
        std::sort(near_.begin(), near_.end());
        scalar S2 = 0, S4 = 0;
        for (const label k : near_)
        {
            const vector q = x_[k] - p;
            const scalar sk = n & q;
            const scalar kappa = sqr(1 - magSqr(q)/R2_);
            cells.append(k);
            alpha.append(kappa*sk);
            beta.append(kappa*sk*sk);
            S2 += kappa*sk*sk;
            S4 += kappa*sqr(sk*sk);
        }
        for (scalar& a : alpha)
        {
            a /= S2;
        }
        for (scalar& b : beta)
        {
            b /= S4;
        }
        return cells.size() > 0;
    }

    //- Visit the data cells within r of x (r2 = r^2), in their order
    template<class Visitor>
    void forWithin
    (
        const point& x,
        const scalar r,
        const scalar r2,
        Visitor visit
    ) const
    {
        near_.clear();
        bins_.forNear(x, r, [&](const label k)
        {
            if (magSqr(x_[k] - x) <= r2)
            {
                near_.append(k);
            }
        });
        std::sort(near_.begin(), near_.end());
        for (const label k : near_)
        {
            visit(x_[k]);
        }
    }
};

} // End namespace surfaceTreatments
} // End namespace Foam


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
    // f and dev follow the order of the body's cells, part after part
    const ghostCellsGathered g(parts);
    const label nIn = g.xIn.size();
    const point& X = B.centre;

    // The momentum balance, K y = rhs, y = (V, Omega). The body takes the
    // momentum that brings its cells to its rigid motion from the fluid
    // step's velocities less the deviations the last step gave them (see
    // the description in the header)
    const scalar mvp = B.excessDensity*B.shape->volume();
    const tensor mJ = B.excessDensity*(B.R & B.shape->volumeInertia() & B.R.T());
    rigidMomentumBalance balance
    (
        mvp, mJ, B.V, B.omega, g.owed, g.owedMoment
    );
    for (label c = 0; c < nIn; ++c)
    {
        balance.addRigidCell(g.xIn[c] - X, g.vIn[c], g.uIn[c] - g.devIn[c]);
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

    // The outer cells' deviations and, with ghostShear viscous, their
    // mirrored wall velocity
    const bool viscous = shear_ == shearModel::viscous;
    vectorField mirror(viscous ? nIn : 0, Zero);
    label nGhost = 0, nAlone = 0;
    outerCells
    (
        B, h, g.xIn, g.xData, g.uData, Vnew, omegaNew, dev, mirror, nGhost,
        nAlone
    );

    // The new velocities, the force density on the fluid and what the body
    // takes, in the order of the parts. With ghostShear viscous the
    // mirrored velocities follow, in the same order
    f.setSize(nIn);
    vectorField devOut((viscous ? 2 : 1)*nIn, Zero);
    vector momentum(Zero);
    for (label c = 0; c < nIn; ++c)
    {
        const vector r = g.xIn[c] - X;
        const vector rigid = Vnew + (omegaNew ^ (g.xIn[c] - X));
        vector uNew = rigid + dev[c];
        if (twoD_)
        {
            uNew.z() = g.uIn[c].z();
        }
        f[c] = (uNew - g.uIn[c])/dt;
        devOut[c] = dev[c];
        if (viscous)
        {
            devOut[nIn + c] = mirror[c];
        }
        const vector lambda = g.vIn[c]*(rigid - (g.uIn[c] - g.devIn[c]))/dt;
        res.sumLambda += lambda;
        res.sumMoment += r ^ lambda;
        momentum += dt*lambda;
    }
    dev.transfer(devOut);
    res.sumLambda += g.owed/dt;
    res.sumMoment += g.owedMoment/dt;
    momentum += g.owed;
    res.nInterior = nIn - nGhost;
    res.nSurface = nGhost;
    res.nSurfaceDropped = nAlone;

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


void Foam::surfaceTreatments::ghostCells::outerCells
(
    const fictitiousDomainBody& B,
    const scalar h,
    const UList<point>& xIn,
    const UList<point>& xData,
    const UList<vector>& uData,
    const vector& Vnew,
    const vector& omegaNew,
    vectorField& dev,
    vectorField& mirror,
    label& nGhost,
    label& nAlone
) const
{
    // The ghost cells, within one and a half cells below the surface
    // (with ghostShear viscous): the rigid motion plus the profile of the
    // fit carried through the wall at its nearest point p, -d a_t
    // tangentially; along n, what makes the flux through the faces shared
    // with the fluid neighbours (within 1.1 cells) that of the model, b
    // s_face^2 where the face lies in the fluid, zero where it lies inside
    // the body. From one to one and a half cells deep the deviation fades
    // to zero, so that a cell sinking into the body (or rising out of it)
    // changes smoothly; every weight of the fit vanishes where a cell
    // enters or leaves it.
    const point& X = B.centre;
    const posedShape S(*B.shape, X, B.R);
    const ghostCellsNearWallFit nearWall(xData, h, fitRadius_*h);
    const auto rigidAt = [&](const point& x)
    {
        return Vnew + (omegaNew ^ (x - X));
    };
    const auto fadeOf = [&](const scalar d)
    {
        return d <= h ? scalar(1) : max(scalar(0), 3 - 2*d/h);
    };
    const label nIn = xIn.size();
    dev.setSize(nIn);
    dev = Zero;
    const bool viscous = shear_ == shearModel::viscous;
    const scalar link2 = sqr(1.1*h);
    DynamicList<label> cells;
    DynamicList<scalar> alpha, beta;
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
        // header's Description)
        if (!viscous)
        {
            continue;
        }
        if (!nearWall.fit(p, n, cells, alpha, beta))
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
        // The normal part through the faces to the fluid neighbours (the
        // data cells within link reach, in their order), the links
        // weighed by how far out the neighbour is
        scalar linkSum = 0, linkWeight = 0;
        nearWall.forWithin(xIn[c], 1.1*h, link2, [&](const point& x)
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
        });
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
}


// ************************************************************************* //

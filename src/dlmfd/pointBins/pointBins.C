/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.
\*---------------------------------------------------------------------------*/

#include "pointBins.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pointBins::pointBins()
:
    origin_(Zero),
    width_(vector::one),
    nBins_(1, 1, 1),
    binStart_(2, label(0)),
    binPoints_()
{}


Foam::pointBins::pointBins(const UList<point>& x, const scalar width)
:
    origin_(Zero),
    width_(vector::uniform(width)),
    nBins_(1, 1, 1),
    binStart_(),
    binPoints_()
{
    if (!(width > 0))
    {
        FatalErrorInFunction
            << "bin width " << width << " is not allowed; it must be > 0"
            << exit(FatalError);
    }
    if (x.empty())
    {
        binStart_.setSize(2, label(0));
        return;
    }
    point lo(x[0]), hi(x[0]);
    for (const point& p : x)
    {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    origin_ = lo;
    for (direction d = 0; d < 3; ++d)
    {
        nBins_[d] = label(std::floor((hi[d] - lo[d])/width_[d])) + 1;
    }
    fill(x);
}


Foam::pointBins::pointBins
(
    const UList<point>& x,
    const point& origin,
    const vector& width,
    const labelVector& nBins
)
:
    origin_(origin),
    width_(width),
    nBins_(nBins),
    binStart_(),
    binPoints_()
{
    // forInBox skips a box wholly outside the grid: every point must be in
    // it, or such a box would miss the points clamped into the edge bins
    for (direction d = 0; d < 3; ++d)
    {
        if (!(width_[d] > 0) || nBins_[d] < 1)
        {
            FatalErrorInFunction
                << "bin width " << width_[d] << " and count " << nBins_[d]
                << " along direction " << label(d) << " are not allowed;"
                << " the width must be > 0 and the count >= 1"
                << exit(FatalError);
        }
    }
    const point top = origin_ + cmptMultiply(width_, vector(nBins_));
    forAll(x, k)
    {
        for (direction d = 0; d < 3; ++d)
        {
            if (x[k][d] < origin_[d] || x[k][d] > top[d])
            {
                FatalErrorInFunction
                    << "point " << k << " " << x[k] << " lies outside the"
                    << " bins' box " << origin_ << " " << top
                    << exit(FatalError);
            }
        }
    }
    fill(x);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::pointBins::fill(const UList<point>& x)
{
    const label nAll = nBins_.x()*nBins_.y()*nBins_.z();
    labelList binOf(x.size());
    binStart_.setSize(nAll + 1, label(0));
    binStart_ = 0;
    forAll(x, k)
    {
        binOf[k] =
            binAlong(x[k], 0)
          + nBins_.x()*(binAlong(x[k], 1) + nBins_.y()*binAlong(x[k], 2));
        ++binStart_[binOf[k] + 1];
    }
    for (label b = 0; b < nAll; ++b)
    {
        binStart_[b + 1] += binStart_[b];
    }
    // Filled in ascending order of k, so ascending within each bin
    labelList next(SubList<label>(binStart_, nAll));
    binPoints_.setSize(x.size());
    forAll(x, k)
    {
        binPoints_[next[binOf[k]]++] = k;
    }
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

void Foam::pointBins::capBox
(
    const point& p,
    const scalar r,
    const vector& n,
    const scalar c,
    point& lo,
    point& hi
)
{
    // Along each axis the cap reaches r where the ball's extreme point lies
    // on its side of the plane, else as far as the circle where the plane
    // cuts the sphere, c n_d +- sqrt(r^2 - c^2) sqrt(1 - n_d^2)
    const scalar rc = std::sqrt(max(sqr(r) - sqr(c), scalar(0)));
    const scalar margin = 1e-9*r;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar across = rc*std::sqrt(max(1 - sqr(n[d]), scalar(0)));
        const scalar up = n[d]*r >= c ? r : c*n[d] + across;
        const scalar down = -n[d]*r >= c ? -r : c*n[d] - across;
        lo[d] = p[d] + down - margin;
        hi[d] = p[d] + up + margin;
    }
}


// ************************************************************************* //

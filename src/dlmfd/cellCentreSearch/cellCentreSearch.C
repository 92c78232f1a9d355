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

#include "cellCentreSearch.H"
#include "boundBox.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellCentreSearch::cellCentreSearch(const polyMesh& mesh)
:
    centres_(mesh.cellCentres()),
    bounds_(),
    origin_(Zero),
    width_(Zero),
    nBins_(Zero)
{
    const label n = centres_.size();
    boundBox bb(centres_, false);
    if (n == 0)
    {
        bb = boundBox(point::zero, point::one);
    }
    bb.inflate(1e-6);
    bounds_ = bb;
    origin_ = bb.min();

    // Bins about two cells wide along each direction that has extent
    const scalar meanCell = n ? std::cbrt(bb.volume()/n) : 1;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar span = bb.span()[d];
        nBins_[d] = max(label(1), label(span/(2*meanCell)));
        width_[d] = span/nBins_[d];
    }

    const label nTotal = cmptProduct(nBins_);
    binStart_.setSize(nTotal + 1, 0);
    labelList binOfCell(n);
    forAll(centres_, c)
    {
        const labelVector b = binOf(centres_[c]);
        binOfCell[c] = b.x() + nBins_.x()*(b.y() + nBins_.y()*b.z());
        ++binStart_[binOfCell[c] + 1];
    }
    for (label b = 0; b < nTotal; ++b)
    {
        binStart_[b + 1] += binStart_[b];
    }
    binCells_.setSize(n);
    labelList fill(SubList<label>(binStart_, nTotal));
    forAll(centres_, c)
    {
        binCells_[fill[binOfCell[c]]++] = c;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelVector Foam::cellCentreSearch::binOf(const point& p) const
{
    labelVector b;
    for (direction d = 0; d < 3; ++d)
    {
        const label k = label(std::floor((p[d] - origin_[d])/width_[d]));
        b[d] = max(label(0), min(nBins_[d] - 1, k));
    }
    return b;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellCentreSearch::cellsInBall
(
    const point& x,
    const scalar r,
    DynamicList<label>& cells
) const
{
    if (!reaches(x, r))
    {
        return;
    }
    const labelVector lo = binOf(x - vector::uniform(r));
    const labelVector hi = binOf(x + vector::uniform(r));
    const scalar r2 = sqr(r);
    for (label k = lo.z(); k <= hi.z(); ++k)
    {
        for (label j = lo.y(); j <= hi.y(); ++j)
        {
            for (label i = lo.x(); i <= hi.x(); ++i)
            {
                const label b = i + nBins_.x()*(j + nBins_.y()*k);
                for (label m = binStart_[b]; m < binStart_[b + 1]; ++m)
                {
                    const label c = binCells_[m];
                    if (magSqr(centres_[c] - x) <= r2)
                    {
                        cells.append(c);
                    }
                }
            }
        }
    }
}


bool Foam::cellCentreSearch::ballReaches
(
    const boundBox& bb,
    const point& x,
    const scalar r
)
{
    scalar dist2 = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const scalar out = max(bb.min()[d] - x[d], x[d] - bb.max()[d]);
        if (out > 0)
        {
            dist2 += sqr(out);
        }
    }
    return dist2 <= sqr(r);
}


bool Foam::cellCentreSearch::reaches(const point& x, const scalar r) const
{
    return ballReaches(bounds_, x, r);
}


Foam::List<Foam::vector> Foam::cellCentreSearch::periodicShifts
(
    const boundBox& bb,
    const vector& period,
    const point& x,
    const scalar r
)
{
    // Every sum of -1, 0 or +1 period per periodic direction, kept when
    // the ball about x - s reaches the box
    DynamicList<vector> shifts(1, vector::zero);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (period[d] <= 0)
        {
            continue;
        }
        const label n = shifts.size();
        for (const scalar sign : {-1.0, 1.0})
        {
            for (label i = 0; i < n; ++i)
            {
                vector s = shifts[i];
                s[d] += sign*period[d];
                if (ballReaches(bb, x - s, r))
                {
                    shifts.append(s);
                }
            }
        }
    }
    return List<vector>(std::move(shifts));
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Class
    Foam::linkedCells

\*---------------------------------------------------------------------------*/

#include "linkedCells.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linkedCells::linkedCells
(
    const boundBox& domain,
    const FixedList<bool, 3>& periodic,
    const scalar minCellWidth
)
:
    // The region the whole domain: every periodic direction wraps
    linkedCells(domain, periodic, minCellWidth, domain)
{}


Foam::linkedCells::linkedCells
(
    const boundBox& domain,
    const FixedList<bool, 3>& periodic,
    const scalar minCellWidth,
    const boundBox& region
)
:
    domain_(domain),
    periodic_(periodic),
    unwrapped_(false),
    nCells_(Zero),
    cellWidth_(Zero),
    span_(domain.span()),
    anyPeriodic_(periodic[0] || periodic[1] || periodic[2]),
    anyUnwrapped_(false)
{
    point lo = domain.min(), hi = domain.max();
    for (direction d = 0; d < 3; ++d)
    {
        const scalar width = region.max()[d] - region.min()[d];
        if (periodic[d])
        {
            // Half a period at most: no image of a centre within the
            // region's reach can be binned at the region's other end
            if (width < 0.5*span_[d])
            {
                periodic_[d] = false;
                unwrapped_[d] = true;
                anyUnwrapped_ = true;
                lo[d] = region.min()[d];
                hi[d] = region.max()[d];
            }
        }
        else
        {
            // (centres beyond the domain's walls go to the edge cells)
            lo[d] = max(region.min()[d], domain.min()[d]);
            hi[d] = min(region.max()[d], domain.max()[d]);
            if (!(hi[d] > lo[d]))
            {
                FatalErrorInFunction
                    << "region " << region << " lies outside the domain "
                    << domain << " along direction " << label(d)
                    << exit(FatalError);
            }
        }
    }
    domain_ = boundBox(lo, hi);
    layCells(minCellWidth);
}


void Foam::linkedCells::layCells(const scalar minCellWidth)
{
    if (!(minCellWidth > 0))
    {
        FatalErrorInFunction
            << "cell width " << minCellWidth << " must be > 0"
            << exit(FatalError);
    }

    const vector span = domain_.span();
    for (direction d = 0; d < 3; ++d)
    {
        nCells_[d] = max(label(1), label(span[d]/minCellWidth));
        cellWidth_[d] = span[d]/nCells_[d];
    }

    // The neighbour table: with fewer than three cells along a periodic
    // direction the neighbours repeat, and are listed once
    const label nTotal = cmptProduct(nCells_);
    neighbourStart_.setSize(nTotal + 1);
    DynamicList<label> all(27*nTotal);
    DynamicList<label> around(27);
    for (label c = 0; c < nTotal; ++c)
    {
        neighbourStart_[c] = all.size();
        const labelVector ijk
        (
            c % nCells_.x(),
            (c/nCells_.x()) % nCells_.y(),
            c/(nCells_.x()*nCells_.y())
        );
        around.clear();
        for (label dz = -1; dz <= 1; ++dz)
        {
            for (label dy = -1; dy <= 1; ++dy)
            {
                for (label dx = -1; dx <= 1; ++dx)
                {
                    const label n = index(ijk + labelVector(dx, dy, dz));
                    if (n >= 0 && !around.found(n))
                    {
                        around.append(n);
                    }
                }
            }
        }
        all.append(around);
    }
    neighbourStart_[nTotal] = all.size();
    neighbours_.transfer(all);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelVector Foam::linkedCells::cellOf(const point& p) const
{
    labelVector ijk;
    for (direction d = 0; d < 3; ++d)
    {
        scalar x = p[d];
        if (anyUnwrapped_ && unwrapped_[d])
        {
            // The image nearest the region's centre
            const scalar c = 0.5*(domain_.min()[d] + domain_.max()[d]);
            x -= span_[d]*std::round((x - c)/span_[d]);
        }
        const scalar s = (x - domain_.min()[d])/cellWidth_[d];
        label c = label(std::floor(s));
        if (periodic_[d])
        {
            c %= nCells_[d];
            if (c < 0)
            {
                c += nCells_[d];
            }
        }
        else
        {
            c = max(label(0), min(nCells_[d] - 1, c));
        }
        ijk[d] = c;
    }
    return ijk;
}


Foam::label Foam::linkedCells::index(labelVector ijk) const
{
    for (direction d = 0; d < 3; ++d)
    {
        if (periodic_[d])
        {
            ijk[d] = ((ijk[d] % nCells_[d]) + nCells_[d]) % nCells_[d];
        }
        else if (ijk[d] < 0 || ijk[d] >= nCells_[d])
        {
            return -1;
        }
    }
    return ijk.x() + nCells_.x()*(ijk.y() + nCells_.y()*ijk.z());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::linkedCells::findPairs
(
    const UList<point>& x,
    const UList<scalar>& r,
    const scalar skin,
    DynamicList<labelPair>& pairs
) const
{
    pairs.clear();
    const label n = x.size();
    const label nTotal = cmptProduct(nCells_);

    // Counting sort by cell; particles of a cell in increasing index
    cellStart_.setSize(nTotal + 1);
    cellStart_ = 0;
    cellOfParticle_.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        cellOfParticle_[i] = index(cellOf(x[i]));
        ++cellStart_[cellOfParticle_[i] + 1];
    }
    for (label c = 0; c < nTotal; ++c)
    {
        cellStart_[c + 1] += cellStart_[c];
    }
    sorted_.setSize(n);
    sortedX_.setSize(n);
    sortedR_.setSize(n);
    {
        labelList fill(SubList<label>(cellStart_, nTotal));
        for (label i = 0; i < n; ++i)
        {
            const label k = fill[cellOfParticle_[i]]++;
            sorted_[k] = i;
            sortedX_[k] = x[i];
            sortedR_[k] = r[i];
        }
    }

    // Each particle, its partners of larger index in order
    for (label i = 0; i < n; ++i)
    {
        const point& xi = x[i];
        const scalar reach = r[i] + skin;
        const label c = cellOfParticle_[i];
        partners_.clear();
        for (label m = neighbourStart_[c]; m < neighbourStart_[c + 1]; ++m)
        {
            const label nc = neighbours_[m];
            for (label k = cellStart_[nc]; k < cellStart_[nc + 1]; ++k)
            {
                if
                (
                    sorted_[k] > i
                 && magSqr(separation(xi, sortedX_[k]))
                  < sqr(reach + sortedR_[k])
                )
                {
                    partners_.append(sorted_[k]);
                }
            }
        }
        // A few partners: insertion sort
        for (label a = 1; a < partners_.size(); ++a)
        {
            const label j = partners_[a];
            label b = a;
            for (; b > 0 && partners_[b - 1] > j; --b)
            {
                partners_[b] = partners_[b - 1];
            }
            partners_[b] = j;
        }
        for (const label j : partners_)
        {
            pairs.append(labelPair(i, j));
        }
    }
}


// ************************************************************************* //

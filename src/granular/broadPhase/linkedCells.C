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
    domain_(domain),
    periodic_(periodic),
    nCells_(Zero),
    cellWidth_(Zero)
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
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelVector Foam::linkedCells::cellOf(const point& p) const
{
    labelVector ijk;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar s = (p[d] - domain_.min()[d])/cellWidth_[d];
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
    const label nTotal = cmptProduct(nCells_);

    // Cell lists: head of each cell, next of each particle
    labelList head(nTotal, -1);
    labelList next(x.size(), -1);
    labelList cellIndex(x.size());
    forAll(x, i)
    {
        cellIndex[i] = index(cellOf(x[i]));
        next[i] = head[cellIndex[i]];
        head[cellIndex[i]] = i;
    }

    // The distinct neighbour cells of each cell (27 or fewer)
    DynamicList<label> around(27);
    for (label c = 0; c < nTotal; ++c)
    {
        if (head[c] < 0)
        {
            continue;
        }
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
                    if (n >= 0 && head[n] >= 0 && !around.found(n))
                    {
                        around.append(n);
                    }
                }
            }
        }

        for (label i = head[c]; i >= 0; i = next[i])
        {
            for (const label n : around)
            {
                for (label j = head[n]; j >= 0; j = next[j])
                {
                    if
                    (
                        j > i
                     && magSqr(separation(x[i], x[j])) < sqr(r[i] + r[j] + skin)
                    )
                    {
                        pairs.append(labelPair(i, j));
                    }
                }
            }
        }
    }
}


// ************************************************************************* //

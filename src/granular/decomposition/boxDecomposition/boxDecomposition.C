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

#include "boxDecomposition.H"
#include <algorithm>
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::boxDecomposition::slab
(
    const direction d,
    const scalar x
) const
{
    const scalar lo = domain_.min()[d];
    const scalar L = domain_.max()[d] - lo;
    scalar s = (x - lo)/L;
    if (periodic_[d])
    {
        s -= std::floor(s);
    }
    else if (s < 0 || s > 1)
    {
        return -1;
    }
    // [lo, hi) per box, the last one closed
    if (planes_[d].empty())
    {
        return min(label(s*n_[d]), n_[d] - 1);
    }
    // The planes inside the domain at or below x (wrapped)
    const scalarList& p = planes_[d];
    const scalar w = periodic_[d] ? lo + s*L : x;
    const label above = std::upper_bound(p.cbegin() + 1, p.cend() - 1, w) - p.cbegin();
    return above - 1;
}


Foam::scalar Foam::boxDecomposition::edge
(
    const direction d,
    const label s
) const
{
    if (!planes_[d].empty())
    {
        return planes_[d][s];
    }
    const scalar lo = domain_.min()[d];
    return lo + (domain_.max()[d] - lo)*s/n_[d];
}


Foam::scalar Foam::boxDecomposition::slabDistance
(
    const direction d,
    const scalar x,
    const label s
) const
{
    const scalar lo = domain_.min()[d];
    const scalar L = domain_.max()[d] - lo;
    const scalar a = edge(d, s);
    const scalar b = edge(d, s + 1);
    const auto distance = [&](const scalar y)
    {
        return y < a ? a - y : (y > b ? y - b : 0);
    };
    if (!periodic_[d])
    {
        return distance(x);
    }
    // The nearest image of x: x wrapped into the domain, and one period
    // either side of it
    const scalar w = x - L*std::floor((x - lo)/L);
    return min(distance(w), min(distance(w - L), distance(w + L)));
}


Foam::scalar Foam::boxDecomposition::slabGap
(
    const direction d,
    const label s,
    const label t
) const
{
    const scalar a0 = edge(d, s), a1 = edge(d, s + 1);
    const scalar b0 = edge(d, t), b1 = edge(d, t + 1);
    const auto gap = [&](const scalar shift)
    {
        return max(scalar(0), max(b0 + shift - a1, a0 - b1 - shift));
    };
    if (!periodic_[d])
    {
        return gap(0);
    }
    const scalar L = domain_.max()[d] - domain_.min()[d];
    return min(gap(0), min(gap(-L), gap(L)));
}


void Foam::boxDecomposition::ranksOf
(
    const FixedList<DynamicList<label>, 3>& near,
    const FixedList<DynamicList<scalar>, 3>& dist,
    const scalar reach,
    DynamicList<label>& ranks
) const
{
    // In the ranks' order (x fastest): the ranks come ascending
    forAll(near[2], c)
    {
        forAll(near[1], b)
        {
            forAll(near[0], a)
            {
                if
                (
                    sqr(dist[0][a]) + sqr(dist[1][b]) + sqr(dist[2][c])
                 <= sqr(reach)
                )
                {
                    ranks.append
                    (
                        near[0][a] + n_.x()*(near[1][b] + n_.y()*near[2][c])
                    );
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::boxDecomposition::boxDecomposition
(
    const boundBox& domain,
    const FixedList<bool, 3>& periodic,
    const labelVector& n
)
:
    domain_(domain),
    periodic_(periodic),
    n_(n)
{
    for (direction d = 0; d < 3; ++d)
    {
        if (n_[d] < 1)
        {
            FatalErrorInFunction
                << "boxes along each direction " << n_ << ": the number"
                << " along direction " << label(d) << " is " << n_[d]
                << "; each must be at least 1" << exit(FatalError);
        }
        if (!(domain_.max()[d] > domain_.min()[d]))
        {
            FatalErrorInFunction
                << "domain " << domain_ << " has no extent along direction "
                << label(d) << exit(FatalError);
        }
    }
}


Foam::boxDecomposition::boxDecomposition
(
    const boundBox& domain,
    const FixedList<bool, 3>& periodic,
    const FixedList<scalarList, 3>& planes
)
:
    boxDecomposition
    (
        domain,
        periodic,
        labelVector
        (
            planes[0].size() - 1, planes[1].size() - 1, planes[2].size() - 1
        )
    )
{
    planes_ = planes;
    for (direction d = 0; d < 3; ++d)
    {
        const scalarList& p = planes_[d];
        bool ascending = true;
        for (label s = 1; s < p.size(); ++s)
        {
            ascending = ascending && p[s] > p[s - 1];
        }
        if
        (
            !ascending
         || p.first() != domain_.min()[d] || p.last() != domain_.max()[d]
        )
        {
            FatalErrorInFunction
                << "planes " << p << " along direction " << label(d)
                << " must ascend from the domain's start "
                << domain_.min()[d] << " to its end " << domain_.max()[d]
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::boxDecomposition> Foam::boxDecomposition::fromRankBoxes
(
    const boundBox& domain,
    const FixedList<bool, 3>& periodic,
    const UList<boundBox>& rankBoxes
)
{
    // The planes: every rank box's faces along each direction, those
    // within the tolerance of another merged (the domain's ends exact)
    const vector tol(1e-6*domain.span());
    FixedList<scalarList, 3> planes;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar lo = domain.min()[d], hi = domain.max()[d];
        DynamicList<scalar> faces(2*rankBoxes.size());
        for (const boundBox& bb : rankBoxes)
        {
            faces.append(bb.min()[d]);
            faces.append(bb.max()[d]);
        }
        Foam::sort(faces);
        DynamicList<scalar> p;
        for (const scalar f : faces)
        {
            if (f < lo - tol[d] || f > hi + tol[d])
            {
                return nullptr;
            }
            if (p.empty() || f > p.last() + tol[d])
            {
                p.append(f);
            }
        }
        if
        (
            p.size() < 2
         || mag(p.first() - lo) > tol[d]
         || mag(p.last() - hi) > tol[d]
        )
        {
            return nullptr;
        }
        p.first() = lo;
        p.last() = hi;
        planes[d] = std::move(p);
    }
    const label nBoxes =
        (planes[0].size() - 1)*(planes[1].size() - 1)*(planes[2].size() - 1);
    if (nBoxes != rankBoxes.size())
    {
        return nullptr;
    }
    autoPtr<boxDecomposition> grid
    (
        new boxDecomposition(domain, periodic, planes)
    );
    forAll(rankBoxes, r)
    {
        const boundBox b(grid->box(r));
        for (direction d = 0; d < 3; ++d)
        {
            if
            (
                mag(b.min()[d] - rankBoxes[r].min()[d]) > tol[d]
             || mag(b.max()[d] - rankBoxes[r].max()[d]) > tol[d]
            )
            {
                return nullptr;
            }
        }
    }
    return grid;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelVector Foam::boxDecomposition::leastAreaBoxes
(
    const vector& span,
    const label nBoxes
)
{
    const vector& L = span;
    labelVector n(nBoxes, 1, 1);
    scalar least = VGREAT;
    for (label nx = 1; nx <= nBoxes; ++nx)
    {
        for (label ny = 1; nx*ny <= nBoxes; ++ny)
        {
            if (nBoxes % (nx*ny))
            {
                continue;
            }
            const label nz = nBoxes/(nx*ny);
            const scalar area =
                (nx - 1)*L.y()*L.z() + (ny - 1)*L.x()*L.z()
              + (nz - 1)*L.x()*L.y();
            if (area < least)
            {
                least = area;
                n = labelVector(nx, ny, nz);
            }
        }
    }
    return n;
}


Foam::boundBox Foam::boxDecomposition::box(const label r) const
{
    const labelVector ijk(r % n_.x(), (r/n_.x()) % n_.y(), r/(n_.x()*n_.y()));
    point lo, hi;
    for (direction d = 0; d < 3; ++d)
    {
        lo[d] = edge(d, ijk[d]);
        hi[d] = edge(d, ijk[d] + 1);
    }
    return boundBox(lo, hi);
}


Foam::label Foam::boxDecomposition::rankOf(const point& x) const
{
    labelVector ijk;
    for (direction d = 0; d < 3; ++d)
    {
        ijk[d] = slab(d, x[d]);
        if (ijk[d] < 0)
        {
            return -1;
        }
    }
    return ijk.x() + n_.x()*(ijk.y() + n_.y()*ijk.z());
}


void Foam::boxDecomposition::ranksWithin
(
    const point& x,
    const scalar reach,
    DynamicList<label>& ranks
) const
{
    ranks.clear();
    if (rankOf(x) < 0)
    {
        return;
    }
    // The slabs within reach along each direction, ascending, with their
    // distances; of their product (in the ranks' order, x fastest: the
    // ranks come ascending) the boxes within reach in all
    FixedList<DynamicList<label>, 3> near;
    FixedList<DynamicList<scalar>, 3> dist;
    for (direction d = 0; d < 3; ++d)
    {
        for (label s = 0; s < n_[d]; ++s)
        {
            const scalar h = slabDistance(d, x[d], s);
            if (h <= reach)
            {
                near[d].append(s);
                dist[d].append(h);
            }
        }
    }
    ranksOf(near, dist, reach, ranks);
}


void Foam::boxDecomposition::neighbours
(
    const label r,
    const scalar reach,
    DynamicList<label>& ranks
) const
{
    ranks.clear();
    const labelVector ijk(r % n_.x(), (r/n_.x()) % n_.y(), r/(n_.x()*n_.y()));
    FixedList<DynamicList<label>, 3> near;
    FixedList<DynamicList<scalar>, 3> dist;
    for (direction d = 0; d < 3; ++d)
    {
        for (label s = 0; s < n_[d]; ++s)
        {
            const scalar h = slabGap(d, ijk[d], s);
            if (h <= reach)
            {
                near[d].append(s);
                dist[d].append(h);
            }
        }
    }
    ranksOf(near, dist, reach, ranks);
    // Not r itself
    label k = 0;
    forAll(ranks, m)
    {
        if (ranks[m] != r)
        {
            ranks[k++] = ranks[m];
        }
    }
    ranks.resize(k);
}


// ************************************************************************* //

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

#include "verletList.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::verletList::verletList()
:
    skin_(-1),
    cells_(),
    cellWidth_(0),
    rMax_(0),
    xAtBuild_(),
    rebuild_(true)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::verletList::reset
(
    const boundBox& domain,
    const FixedList<bool, 3>& periodic,
    const label n,
    const scalar rMax,
    const scalar Dmin,
    const boundBox* region
)
{
    if (skin_ < 0 && n)
    {
        skin_ = 0.1*Dmin;
    }
    const scalar cellWidth = max
    (
        2*rMax + max(skin_, scalar(0)),
        std::cbrt(domain.volume()/max(n, label(1)))
    );
    cells_.reset
    (
        region
      ? new linkedCells(domain, periodic, cellWidth, *region)
      : new linkedCells(domain, periodic, cellWidth)
    );
    cellWidth_ = cellWidth;
    rMax_ = rMax;
    xAtBuild_.clear();
    rebuild_ = true;
}


void Foam::verletList::build
(
    const pointField& x,
    const scalarList& r,
    const UList<planeWall>& walls,
    const boolList& wallsAct
)
{
    rebuild_ = false;
    xAtBuild_ = x;
    cells_->findPairs(xAtBuild_, r, skin_, pairs_);

    // A particle moves by at most skin/2 relative to a wall before the
    // next build; a whole skin is kept, as for the pairs
    const label n = x.size();
    nearWallStart_.setSize(n + 1);
    DynamicList<label> near(nearWalls_.size());
    for (label i = 0; i < n; ++i)
    {
        nearWallStart_[i] = near.size();
        if (!wallsAct[i])
        {
            continue;
        }
        forAll(walls, w)
        {
            if (walls[w].distance(xAtBuild_[i]) <= r[i] + skin_)
            {
                near.append(w);
            }
        }
    }
    nearWallStart_[n] = near.size();
    nearWalls_.transfer(near);
}


bool Foam::verletList::anyPairWithin
(
    const pointField& x,
    const scalarList& r,
    const scalar search
)
{
    const DynamicList<labelPair>* pairs = pairsWithin(x, r, search);
    return !pairs || pairs->size() > 0;
}


const Foam::DynamicList<Foam::labelPair>* Foam::verletList::pairsWithin
(
    const pointField& x,
    const scalarList& r,
    const scalar search
)
{
    if (2*rMax_ + search > cellWidth_)
    {
        return nullptr;
    }
    cells_->findPairs(x, r, search, reachPairs_);
    return &reachPairs_;
}


// ************************************************************************* //

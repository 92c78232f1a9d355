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

#include "periodicImages.H"
#include "DynamicList.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::periodicImages::periodicImages
(
    const cellCentreSearch& search,
    const boundBox& bounds
)
:
    search_(search),
    bounds_(bounds),
    period_(Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::vector> Foam::periodicImages::shifts
(
    const boundBox& bb,
    const vector& period,
    const point& x,
    const scalar r
)
{
    // Every sum of -1, 0 or +1 period per periodic direction, kept when
    // the ball about x - s reaches the box
    DynamicList<vector> found(1, vector::zero);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (period[d] <= 0)
        {
            continue;
        }
        const label n = found.size();
        for (const scalar sign : {-1.0, 1.0})
        {
            for (label i = 0; i < n; ++i)
            {
                vector s = found[i];
                s[d] += sign*period[d];
                if (cellCentreSearch::ballReaches(bb, x - s, r))
                {
                    found.append(s);
                }
            }
        }
    }
    return List<vector>(std::move(found));
}


void Foam::periodicImages::setPeriod(const vector& period)
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (period[d] < 0)
        {
            FatalErrorInFunction
                << "period " << period << " is not allowed: each component"
                << " must be > 0, or 0 for a direction that is not periodic"
                << exit(FatalError);
        }
    }
    period_ = period;
}


Foam::List<Foam::vector> Foam::periodicImages::reaching
(
    const point& x,
    const scalar r
) const
{
    const List<vector> all = shifts(x, r);
    DynamicList<vector> near(all.size());
    for (const vector& s : all)
    {
        if (search_.reaches(x - s, r))
        {
            near.append(s);
        }
    }
    return List<vector>(std::move(near));
}


void Foam::periodicImages::checkClearance
(
    const label particle,
    const scalar reach
) const
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (period_[d] > 0 && !(2*reach < period_[d]))
        {
            FatalErrorInFunction
                << "particle " << particle << ": its bounding radius with"
                << " the reach of its cells, " << reach << " m, is not below half the"
                << " period " << period_[d] << " m in direction "
                << label(d) << "; the periodic box must be longer than"
                << " twice that" << exit(FatalError);
        }
    }
}


// ************************************************************************* //

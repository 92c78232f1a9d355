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
    mesh_(mesh),
    bounds_(),
    bins_()
{
    rebuild();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellCentreSearch::rebuild()
{
    const pointField& centres = mesh_.cellCentres();
    const label n = centres.size();
    boundBox bb(centres, false);
    if (n == 0)
    {
        bb = boundBox(point::zero, point::one);
    }
    bb.inflate(1e-6);
    bounds_ = bb;

    // Bins about two cells wide along each direction that has extent
    const scalar meanCell = n ? std::cbrt(bb.volume()/n) : 1;
    labelVector nBins;
    vector width;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar span = bb.span()[d];
        nBins[d] = max(label(1), label(span/(2*meanCell)));
        width[d] = span/nBins[d];
    }
    bins_ = pointBins(centres, bb.min(), width, nBins);
}


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
    const scalar r2 = sqr(r);
    const pointField& centres = mesh_.cellCentres();
    bins_.forInBox
    (
        x - vector::uniform(r),
        x + vector::uniform(r),
        [&](const label c)
        {
            if (magSqr(centres[c] - x) <= r2)
            {
                cells.append(c);
            }
        }
    );
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


// ************************************************************************* //

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

#include "surfaceStencils.H"
#include "particleGeometry.H"
#include "smallDenseSolve.H"
#include "Switch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceStencils::surfaceStencils
(
    const dictionary& dict,
    const bool twoD,
    const scalar zPlane
)
:
    on_(dict.getOrDefault<Switch>("surfacePoints", true)),
    spacing_(dict.getOrDefault<scalar>("surfacePointSpacing", 1)),
    radius_(dict.getOrDefault<scalar>("surfaceStencilRadius", 1.2)),
    retraction_(dict.getOrDefault<scalar>("surfacePointRetraction", 0)),
    twoD_(twoD),
    zPlane_(zPlane)
{
    if (!(spacing_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "surfacePointSpacing = " << spacing_ << " is not"
            << " allowed; it must be > 0 (in cell sizes)"
            << exit(FatalIOError);
    }
    if (!(radius_ >= 1))
    {
        FatalIOErrorInFunction(dict)
            << "surfaceStencilRadius = " << radius_ << " is not"
            << " allowed; it must be >= 1 (in cell sizes)"
            << exit(FatalIOError);
    }
    if (!(retraction_ >= 0 && retraction_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "surfacePointRetraction = " << retraction_ << " is not"
            << " allowed; 0 <= it < 1 (in cell sizes)" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::surfaceStencils::points
(
    const particleShape& shape,
    const point& centre,
    const tensor& R,
    const scalar h,
    DynamicList<point>& pts
) const
{
    pts.clear();
    if (!on_)
    {
        return;
    }
    particleGeometry::surfacePoints
    (
        shape, centre, R, spacing_*h, twoD_ ? zPlane_ : 0, pts
    );
    if (retraction_ > 0)
    {
        // Towards the centre by retraction h (in the plane in 2D)
        for (point& p : pts)
        {
            vector d = p - centre;
            if (twoD_)
            {
                d.z() = 0;
            }
            const scalar r = mag(d);
            if (r > VSMALL)
            {
                p -= (min(retraction_*h, 0.5*r)/r)*d;
            }
        }
    }
}


bool Foam::surfaceStencils::weights
(
    const point& p,
    const UList<point>& centres,
    const scalar h,
    scalarList& w
) const
{
    // u(c) ~ a + G.(x_c - p): weights of a by linear least squares,
    // w = X (X^T X)^-1 e_0, lengths scaled by the cell size
    const label nCoeff = twoD_ ? 3 : 4;
    if (centres.size() < nCoeff)
    {
        return false;
    }

    List<scalarList> XtX(nCoeff, scalarList(nCoeff, scalar(0)));
    List<scalarList> rows(centres.size(), scalarList(nCoeff));
    forAll(centres, i)
    {
        const vector d = (centres[i] - p)/h;
        rows[i][0] = 1;
        rows[i][1] = d.x();
        rows[i][2] = d.y();
        if (!twoD_)
        {
            rows[i][3] = d.z();
        }
        for (label a = 0; a < nCoeff; ++a)
        {
            for (label b = 0; b < nCoeff; ++b)
            {
                XtX[a][b] += rows[i][a]*rows[i][b];
            }
        }
    }
    scalarList e0(nCoeff, scalar(0));
    e0[0] = 1;
    if (!smallDenseSolve(XtX, e0))
    {
        return false;
    }
    w.setSize(centres.size());
    forAll(centres, i)
    {
        scalar wi = 0;
        for (label a = 0; a < nCoeff; ++a)
        {
            wi += rows[i][a]*e0[a];
        }
        w[i] = wi;
    }
    return true;
}


// ************************************************************************* //

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

#include "neighbourSurfaces.H"
#include "particleGeometry.H"
#include "particleShape.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::neighbourSurfaces::layerWeight
(
    const scalar t,
    const scalar R,
    const scalar h,
    const bool twoD
)
{
    const scalar A = sqr(R) - sqr(t);
    if (A <= 0)
    {
        return 0;
    }
    const scalar R4 = sqr(sqr(R));
    return twoD
      ? 16.0/15.0*pow(A, 2.5)/(R4*h)
      : constant::mathematical::pi*pow3(A)/(3*R4*sqr(h));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::neighbourSurfaces::add
(
    const particleShape& shape,
    const point& centre,
    const tensor& R,
    const vector& V,
    const vector& omega
)
{
    neighbours_.append(neighbour{&shape, centre, R, V, omega});
}


bool Foam::neighbourSurfaces::firstAlong
(
    const point& p,
    const vector& n,
    const scalar tMax,
    const scalar step,
    scalar& t,
    vector& u
) const
{
    t = tMax;
    label first = -1;
    forAll(neighbours_, j)
    {
        const neighbour& O = neighbours_[j];
        // Skip a neighbour whose bounding ball the ray segment misses
        const vector cp = O.centre - p;
        const scalar tc = min(max(cp & n, scalar(0)), t);
        if (magSqr(cp - tc*n) > sqr(O.shape->boundingRadius()))
        {
            continue;
        }
        const auto inside = [&](const scalar s)
        {
            return particleGeometry::contains(*O.shape, O.centre, O.R, p + s*n);
        };
        scalar t0 = 0, t1 = -1;
        for (scalar s = step; t0 < t; s += step)
        {
            if (inside(min(s, t)))
            {
                t1 = min(s, t);
                break;
            }
            t0 = s;
        }
        if (t1 < 0)
        {
            continue;
        }
        for (label it = 0; it < 30; ++it)
        {
            const scalar tm = 0.5*(t0 + t1);
            (inside(tm) ? t1 : t0) = tm;
        }
        if (t1 < t)
        {
            t = t1;
            first = j;
        }
    }
    if (first < 0)
    {
        return false;
    }
    const neighbour& O = neighbours_[first];
    const point q = p + t*n;
    u = O.V + (O.omega ^ (q - O.centre));
    return true;
}


// ************************************************************************* //

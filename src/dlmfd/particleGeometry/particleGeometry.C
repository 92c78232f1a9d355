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

#include "particleGeometry.H"
#include "posedShape.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::particleGeometry::contains
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const point& p
)
{
    return posedShape(shape, x, R, "inside test").contains(p);
}


Foam::scalar Foam::particleGeometry::depth
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const point& p,
    point& foot,
    vector& normal
)
{
    return posedShape(shape, x, R, "depth function").depth(p, foot, normal);
}


Foam::scalar Foam::particleGeometry::outsideDistanceBound
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const point& p
)
{
    return posedShape(shape, x, R, "depth function").outsideDistanceBound(p);
}


// ************************************************************************* //

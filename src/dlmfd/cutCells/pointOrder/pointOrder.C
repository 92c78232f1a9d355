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

#include "pointOrder.H"
#include "cutPolygon.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- a before b in the order of their coordinates, x first; coordinates
    //  within tol count as equal
    bool before(const point& a, const point& b, const scalar tol)
    {
        for (direction i = 0; i < 3; ++i)
        {
            if (a[i] < b[i] - tol)
            {
                return true;
            }
            if (a[i] > b[i] + tol)
            {
                return false;
            }
        }
        return false;
    }
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::List<Foam::point> Foam::pointOrder::facePolygon
(
    const polyMesh& mesh,
    const label facei
)
{
    const face& f = mesh.faces()[facei];
    const pointField& pts = mesh.points();
    const label n = f.size();
    // 1e-9 of the face's span: far above round-off, far below the distance
    // between two of its points
    point lo(pts[f[0]]), hi(pts[f[0]]);
    for (const label pointi : f)
    {
        lo = min(lo, pts[pointi]);
        hi = max(hi, pts[pointi]);
    }
    const scalar tol = 1e-9*mag(hi - lo);
    label first = 0;
    for (label i = 1; i < n; ++i)
    {
        if (before(pts[f[i]], pts[f[first]], tol))
        {
            first = i;
        }
    }
    const label step =
        before(pts[f[(first + 1) % n]], pts[f[(first + n - 1) % n]], tol)
      ? 1 : n - 1;
    List<point> poly(n);
    forAll(poly, i)
    {
        poly[i] = pts[f[(first + i*step) % n]];
    }
    return poly;
}


Foam::labelList Foam::pointOrder::cellFaces
(
    const polyMesh& mesh,
    const label celli
)
{
    const cell& c = mesh.cells()[celli];
    List<List<point>> polys(c.size());
    forAll(c, i)
    {
        polys[i] = facePolygon(mesh, c[i]);
    }
    labelList order(identity(c.size()));
    std::sort
    (
        order.begin(),
        order.end(),
        [&polys](const label a, const label b)
        {
            return std::lexicographical_compare
            (
                polys[a].begin(), polys[a].end(),
                polys[b].begin(), polys[b].end(),
                [](const point& p, const point& q)
                {
                    return before(p, q, 0);
                }
            );
        }
    );
    labelList faces(c.size());
    forAll(order, i)
    {
        faces[i] = c[order[i]];
    }
    return faces;
}


Foam::scalar Foam::pointOrder::outwardSign
(
    const polyMesh& mesh,
    const label facei,
    const label celli,
    const vector& S
)
{
    // The polygon's normal is the face's or its reverse; the face's points
    // out of its owner
    return
        ((S & mesh.faceAreas()[facei]) > 0)
     == (mesh.faceOwner()[facei] == celli)
      ? 1 : -1;
}


void Foam::pointOrder::cellBounds
(
    const polyMesh& mesh,
    const label celli,
    point& lo,
    point& hi
)
{
    lo = point::max;
    hi = point::min;
    for (const label facei : mesh.cells()[celli])
    {
        for (const label pointi : mesh.faces()[facei])
        {
            lo = min(lo, mesh.points()[pointi]);
            hi = max(hi, mesh.points()[pointi]);
        }
    }
}


Foam::scalar Foam::pointOrder::cellVolume
(
    const polyMesh& mesh,
    const label celli
)
{
    point x0, hi;
    cellBounds(mesh, celli, x0, hi);
    scalar sum = 0;
    for (const label facei : cellFaces(mesh, celli))
    {
        vector S;
        point cf;
        cutPolygon::areaAndCentroid(facePolygon(mesh, facei), S, cf);
        sum += outwardSign(mesh, facei, celli, S)*((cf - x0) & S);
    }
    return sum/3;
}


// ************************************************************************* //

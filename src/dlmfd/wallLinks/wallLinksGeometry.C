/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Description
    The geometry of Foam::wallLinks: where a link between two cell centres
    crosses a body's surface (or passes through it), and the face of a
    fluid cell opposite a link, with the cell beyond it.

\*---------------------------------------------------------------------------*/

#include "wallLinks.H"
#include "posedShape.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// Bisections of a link: 2^-40 of a cell, below round-off of the centres
constexpr int nBisections = 40;

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::wallLinks::crossing
(
    const body& B,
    const periodicImages& images,
    const point& a,
    const point& b,
    vector& uWall,
    vector& arm
)
{
    // The body's image nearest the link's inside end
    const point X = b - images.nearest(b - B.centre);
    const posedShape S(*B.shape, X, B.R, "wall links");
    // Both ends inside (the fluid cell is another body's): the fluid end
    // is on the wall
    const scalar t =
        S.contains(a) ? scalar(0) : S.segmentCrossing(a, b, 0, 1, nBisections);
    arm = a + t*(b - a) - X;
    uWall = B.V + (B.omega ^ arm);
    return max(t, minFraction);
}


bool Foam::wallLinks::passesThrough
(
    const body& B,
    const periodicImages& images,
    const point& a,
    const point& b,
    scalar& tIn,
    scalar& tOut,
    vector& uIn,
    vector& uOut,
    vector& armIn,
    vector& armOut
)
{
    const point mid = 0.5*(a + b);
    const point X = mid - images.nearest(mid - B.centre);
    const posedShape S(*B.shape, X, B.R, "wall links");
    constexpr int nSamples = 16;
    int first = -1, last = -1;
    for (int k = 1; k < nSamples; ++k)
    {
        if (S.contains(a + (scalar(k)/nSamples)*(b - a)))
        {
            if (first < 0)
            {
                first = k;
            }
            last = k;
        }
    }
    if (first < 0)
    {
        return false;
    }
    // The inside of a convex body along a line is one interval
    tIn = S.segmentCrossing
    (
        a, b, scalar(first - 1)/nSamples, scalar(first)/nSamples, nBisections
    );
    tOut = S.segmentCrossing
    (
        a, b, scalar(last + 1)/nSamples, scalar(last)/nSamples, nBisections
    );
    armIn = a + tIn*(b - a) - X;
    armOut = a + tOut*(b - a) - X;
    uIn = B.V + (B.omega ^ armIn);
    uOut = B.V + (B.omega ^ armOut);
    return true;
}


Foam::label Foam::wallLinks::oppositeFace
(
    const label c,
    const vector& S,
    const scalarField& owner,
    const PtrList<scalarField>& ownerNbr,
    const PtrList<vectorField>& deltaNbr,
    point& beyond,
    label& beyondBody
) const
{
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& C = mesh_.cellCentres();
    const labelUList& own = mesh_.faceOwner();
    const labelUList& nei = mesh_.faceNeighbour();
    const vector n = S/mag(S);
    const vectorField& Cf = mesh_.faceCentres();
    label best = -1;
    scalar bestDot = -0.9;
    // Faces facing the same way (a face split by refinement: its parts)
    // are told apart by where they lie, never by their order in the cell,
    // which differs between a serial and a decomposed mesh: the nearest
    // to the line from c along -n, then the least face centre
    const scalar tie = 1e-9;
    auto offLine = [&](const label f)
    {
        const vector r = Cf[f] - C[c];
        return magSqr(r - (r & n)*n);
    };
    auto before = [&](const label f, const label g)
    {
        const scalar df = offLine(f), dg = offLine(g);
        const scalar scale = max(df, dg) + magSqr(Cf[f] - Cf[g]);
        if (mag(df - dg) > tie*scale)
        {
            return df < dg;
        }
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (mag(Cf[f][d] - Cf[g][d]) > tie*mag(Cf[f] - Cf[g]))
            {
                return Cf[f][d] < Cf[g][d];
            }
        }
        return false;
    };
    for (const label f : mesh_.cells()[c])
    {
        const vector out = own[f] == c ? Sf[f] : -Sf[f];
        const scalar dot = (out & n)/mag(out);
        if
        (
            dot < bestDot - tie
         || (best >= 0 && dot < bestDot + tie && before(f, best))
        )
        {
            bestDot = min(dot, bestDot);
            best = f;
        }
    }
    if (best < 0)
    {
        return -1;
    }
    if (best < mesh_.nInternalFaces())
    {
        const label E = own[best] == c ? nei[best] : own[best];
        beyond = C[E];
        beyondBody = label(owner[E]);
        return best;
    }
    const label patchi = mesh_.boundaryMesh().whichPatch(best);
    if (!ownerNbr.set(patchi))
    {
        return -1;
    }
    const label i = best - mesh_.boundaryMesh()[patchi].start();
    beyond = C[c] + deltaNbr[patchi][i];
    beyondBody = label(ownerNbr[patchi][i]);
    return best;
}


// ************************************************************************* //

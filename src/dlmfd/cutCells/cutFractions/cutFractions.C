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

#include "cutFractions.H"
#include "cutPolygon.H"
#include "pointOrder.H"
#include "periodicImages.H"
#include "syncTools.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    scalar largestCellReach(const polyMesh& mesh)
    {
        scalar reach = 0;
        forAll(mesh.cells(), celli)
        {
            const point& C = mesh.cellCentres()[celli];
            for (const label facei : mesh.cells()[celli])
            {
                for (const label pointi : mesh.faces()[facei])
                {
                    reach = max(reach, mag(mesh.points()[pointi] - C));
                }
            }
        }
        return returnReduce(reach, maxOp<scalar>());
    }

    //- A face's area vector, from its points in the order bodyCut
    //- measures its parts by
    vector pointOrderedArea(const polyMesh& mesh, const label facei)
    {
        const List<point> poly = pointOrder::facePolygon(mesh, facei);
        vector S;
        point c;
        cutPolygon::areaAndCentroid(poly, S, c);
        return S;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cutFractions::cutFractions(const fvMesh& mesh)
:
    mesh_(mesh),
    search_(mesh),
    cellReach_(largestCellReach(mesh)),
    solidVolume_(mesh.nCells(), 0),
    solidFaceFraction_(mesh.nFaces(), 0),
    pointOrderedSolidFlux_(mesh.nFaces(), 0),
    faceVisit_(mesh.nFaces(), -1),
    nCut_(0),
    couplingMismatch_(0),
    largestOverlap_(0),
    fluidFraction_
    (
        IOobject
        (
            "fluidFraction",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        zeroGradientFvPatchScalarField::typeName
    ),
    faceAperture_
    (
        IOobject
        (
            "faceAperture",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0)
    ),
    solidFlux_
    (
        IOobject
        (
            "solidFlux",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("zero", dimVolume/dimTime, 0.0)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cutFractions::clear()
{
    solidVolume_ = 0;
    solidFaceFraction_ = 0;
    pointOrderedSolidFlux_ = 0;
    faceVisit_ = -1;
    nCut_ = 0;
}


Foam::label Foam::cutFractions::cut
(
    const particleShape& shape,
    const point& x,
    const tensor& R,
    const vector& V,
    const vector& omega,
    const vector& period
)
{
    // A body as wide as a period would meet its own image: the fractions
    // would count the overlap twice
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (period[d] > 0 && 2*shape.boundingRadius() >= period[d])
        {
            FatalErrorInFunction
                << "shape " << shape.name() << " (bounding diameter "
                << 2*shape.boundingRadius() << " m) is not shorter than the"
                << " period " << period[d] << " m along direction " << d
                << "; it would meet its own periodic image"
                << exit(FatalError);
        }
    }
    const scalar reach = shape.boundingRadius() + cellReach_;
    const List<vector> shifts
    (
        periodicImages::shifts(mesh_.bounds(), period, x, reach)
    );
    for (const vector& s : shifts)
    {
        cut(bodyCut(shape, x - s, R), V, omega);
    }
    return shifts.size();
}


void Foam::cutFractions::cut
(
    const bodyCut& body,
    const vector& V,
    const vector& omega
)
{
    const bool moves = (magSqr(V) + magSqr(omega) > 0);
    const label visit = nCut_++;
    cells_.clear();
    search_.cellsInBall
    (
        body.centre(), body.boundingRadius() + cellReach_, cells_
    );
    for (const label celli : cells_)
    {
        solidVolume_[celli] += body.solidVolumeOfCell(mesh_, celli);
        for (const label facei : mesh_.cells()[celli])
        {
            if (faceVisit_[facei] != visit)
            {
                faceVisit_[facei] = visit;
                const bodyCut::facePart part =
                    body.solidPartOfFace(mesh_, facei);
                if (part.area > 0)
                {
                    const vector& S = part.faceArea;
                    solidFaceFraction_[facei] += part.area/mag(S);
                    if (moves)
                    {
                        const vector u =
                            V + (omega ^ (part.centroid - body.centre()));
                        pointOrderedSolidFlux_[facei] +=
                            (u & S)*part.area/mag(S);
                    }
                }
            }
        }
    }
}


void Foam::cutFractions::finish()
{
    // Both sides of a coupled face: how far apart, then the larger on both
    scalarField lower(solidFaceFraction_);
    syncTools::syncFaceList(mesh_, lower, minEqOp<scalar>());
    syncTools::syncFaceList(mesh_, solidFaceFraction_, maxEqOp<scalar>());
    couplingMismatch_ =
        returnReduce(max(solidFaceFraction_ - lower), maxOp<scalar>());
    // The flux along the point-ordered normal: the same direction on both
    // sides of a processor or cyclic face (a cyclic's sides are translated
    // copies, whose point order is the same)
    scalarField fluxLower(pointOrderedSolidFlux_);
    syncTools::syncFaceList(mesh_, fluxLower, minEqOp<scalar>());
    syncTools::syncFaceList(mesh_, pointOrderedSolidFlux_, maxEqOp<scalar>());
    couplingMismatch_ = max
    (
        couplingMismatch_,
        returnReduce(max(pointOrderedSolidFlux_ - fluxLower), maxOp<scalar>())
       /max(gMax(mag(pointOrderedSolidFlux_)), VSMALL)
    );
    // Along each face's own normal
    auto flux = [this](const label facei)
    {
        const scalar f = pointOrderedSolidFlux_[facei];
        if (f == 0)
        {
            return f;
        }
        return (pointOrderedArea(mesh_, facei) & mesh_.faceAreas()[facei]) > 0
            ? f : -f;
    };
    scalarField& phiB = solidFlux_.primitiveFieldRef();
    forAll(phiB, facei)
    {
        phiB[facei] = flux(facei);
    }
    for (fvsPatchScalarField& pf : solidFlux_.boundaryFieldRef())
    {
        const label start = pf.patch().start();
        forAll(pf, i)
        {
            pf[i] = flux(start + i);
        }
    }

    scalar overlap = 0;
    scalarField& alpha = fluidFraction_.primitiveFieldRef();
    forAll(alpha, celli)
    {
        const scalar f =
            solidVolume_[celli] > 0
          ? solidVolume_[celli]/pointOrder::cellVolume(mesh_, celli)
          : 0;
        overlap = max(overlap, f - 1);
        alpha[celli] = 1 - min(f, scalar(1));
    }
    fluidFraction_.correctBoundaryConditions();

    scalarField& alphaf = faceAperture_.primitiveFieldRef();
    forAll(alphaf, facei)
    {
        const scalar f = solidFaceFraction_[facei];
        overlap = max(overlap, f - 1);
        alphaf[facei] = 1 - min(f, scalar(1));
    }
    for (fvsPatchScalarField& pf : faceAperture_.boundaryFieldRef())
    {
        const label start = pf.patch().start();
        forAll(pf, i)
        {
            const scalar f = solidFaceFraction_[start + i];
            overlap = max(overlap, f - 1);
            pf[i] = 1 - min(f, scalar(1));
        }
    }
    // Round-off beyond the whole is no overlap
    largestOverlap_ = returnReduce(overlap, maxOp<scalar>());
    if (largestOverlap_ < 1e-12)
    {
        largestOverlap_ = 0;
    }
}


Foam::scalar Foam::cutFractions::totalSolidVolume() const
{
    return returnReduce(sum(solidVolume_), sumOp<scalar>());
}


// ************************************************************************* //

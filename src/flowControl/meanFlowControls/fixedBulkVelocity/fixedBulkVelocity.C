/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Class
\*---------------------------------------------------------------------------*/

#include "fixedBulkVelocity.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace meanFlowControls
{
    defineTypeNameAndDebug(fixedBulkVelocity, 0);
    addToRunTimeSelectionTable(meanFlowControl, fixedBulkVelocity, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meanFlowControls::fixedBulkVelocity::readCoeffs
(
    const dictionary& coeffs
)
{
    const vector direction(coeffs.get<vector>("direction"));
    if (mag(direction) < VSMALL)
    {
        FatalIOErrorInFunction(coeffs)
            << "direction " << direction << " has zero length;"
            << " give the direction of control, e.g. (0 0 1)"
            << exit(FatalIOError);
    }
    direction_ = direction/mag(direction);

    Ubar_ = dimensionedScalar("Ubar", dimVelocity, coeffs).value();

    relaxation_ = coeffs.getOrDefault<scalar>("relaxation", 1);
    if (relaxation_ <= 0 || relaxation_ > 1)
    {
        FatalIOErrorInFunction(coeffs)
            << "relaxation " << relaxation_ << " is out of range;"
            << " allowed: 0 < relaxation <= 1"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meanFlowControls::fixedBulkVelocity::fixedBulkVelocity
(
    const fvMesh& mesh,
    const dictionary& coeffs
)
:
    // The gradient reached so far is part of the state: continue from it
    meanFlowControl(mesh, coeffs, IOobject::READ_IF_PRESENT),
    direction_(Zero),
    Ubar_(0),
    relaxation_(1),
    gradP0_(gradP_.value()),
    gradP0TimeIndex_(-1)
{
    readCoeffs(coeffs);

    Info<< "    direction = " << direction_ << ", Ubar = " << Ubar_
        << " [m/s], relaxation = " << relaxation_
        << ", initial gradP = " << gradP_.value() << " [m/s^2]" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meanFlowControls::fixedBulkVelocity::correct
(
    volVectorField& U,
    const volScalarField& rAU
)
{
    // The momentum equation of this time step was assembled with the
    // gradient as it stood before the first corrector: every corrector
    // recomputes the increment from that value, never accumulates.
    const label timeIndex = mesh_.time().timeIndex();
    if (timeIndex != gradP0TimeIndex_)
    {
        gradP0_ = gradP_.value();
        gradP0TimeIndex_ = timeIndex;
    }

    const scalarField& V = mesh_.V();
    const scalar rAUave = gSum(V*rAU.primitiveField())/gSum(V);
    const scalar UbarNow = direction_ & bulkVelocity(U);

    const scalar dGradP = relaxation_*(Ubar_ - UbarNow)/rAUave;

    // U was just reconstructed from a momentum matrix holding gradP0_, so
    // it carries none of an earlier corrector's increment
    U.primitiveFieldRef() += direction_*(dGradP*rAU.primitiveField());
    U.correctBoundaryConditions();

    gradP_.value() = gradP0_ + direction_*dGradP;
}


// ************************************************************************* //

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

#include "fixedPressureGradient.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace meanFlowControls
{
    defineTypeNameAndDebug(fixedPressureGradient, 0);
    addToRunTimeSelectionTable
    (
        meanFlowControl,
        fixedPressureGradient,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meanFlowControls::fixedPressureGradient::fixedPressureGradient
(
    const fvMesh& mesh,
    const dictionary& coeffs
)
:
    // The dictionary, not a stored value, sets a fixed gradient
    meanFlowControl(mesh, coeffs, IOobject::NO_READ)
{
    gradP_ = dimensionedVector("gradP", gradP_.dimensions(), coeffs);

    Info<< "    gradP = " << gradP_.value() << " [m/s^2]" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meanFlowControls::fixedPressureGradient::correct
(
    volVectorField&,
    const volScalarField&
)
{}


// ************************************************************************* //

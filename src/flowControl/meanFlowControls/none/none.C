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

#include "none.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace meanFlowControls
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(meanFlowControl, none, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meanFlowControls::none::none
(
    const fvMesh& mesh,
    const dictionary& coeffs
)
:
    meanFlowControl(mesh, coeffs, IOobject::NO_READ)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meanFlowControls::none::correct
(
    volVectorField&,
    const volScalarField&
)
{}


// ************************************************************************* //

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

#include "meanFlowControl.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meanFlowControl, 0);
    defineRunTimeSelectionTable(meanFlowControl, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meanFlowControl::meanFlowControl
(
    const fvMesh& mesh,
    const dictionary& coeffs,
    const IOobject::readOption gradPReadOption
)
:
    // The file is opened at the first log, not here: a run that stops on
    // bad input before its first step leaves no output behind
    functionObjects::writeFile(mesh, "meanFlowControl", "meanFlowControl"),
    mesh_(mesh),
    coeffs_(coeffs),
    gradP_
    (
        IOobject
        (
            "gradP",
            mesh.time().timeName(),
            "uniform",
            mesh,
            gradPReadOption,
            IOobject::AUTO_WRITE
        ),
        dimensionedVector(dimVelocity/dimTime, Zero)
    )
{
    // writeToFile (on the master only), writePrecision
    writeFile::read(coeffs);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::meanFlowControl::bulkVelocity(const volVectorField& U)
{
    const scalarField& V = U.mesh().V();
    return gSum(V*U.primitiveField())/gSum(V);
}


void Foam::meanFlowControl::log(const volVectorField& U)
{
    const vector Ubulk(bulkVelocity(U));

    Info<< "meanFlowControl " << type() << ": bulk U = " << Ubulk
        << ", gradP = " << gradP_.value() << endl;

    // writeFile writes on the master only
    if (writeToFile())
    {
        if (!filePtr_.valid())
        {
            resetFile("meanFlowControl");
            OFstream& os = file();
            writeHeader(os, "Mean flow control: " + coeffs_.dictName());
            writeCommented(os, "Time");
            for
            (
                const word col
              : {"Ux", "Uy", "Uz", "gradPx", "gradPy", "gradPz"}
            )
            {
                writeTabbed(os, col);
            }
            os  << endl;
        }
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << Ubulk.x() << tab << Ubulk.y() << tab << Ubulk.z()
            << tab << gradP_.value().x()
            << tab << gradP_.value().y()
            << tab << gradP_.value().z() << endl;
    }
}


// ************************************************************************* //

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

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::meanFlowControl> Foam::meanFlowControl::New
(
    const fvMesh& mesh,
    const dictionary& properties
)
{
    const word modelType(properties.get<word>("meanFlowControl"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            properties,
            "meanFlowControl",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "Selecting meanFlowControl " << modelType << endl;

    // A model that needs coefficients reports the missing keyword with
    // the dictionary's name, so an absent sub-dictionary is left to it
    return autoPtr<meanFlowControl>
    (
        cstrIter()(mesh, properties.subOrEmptyDict(modelType))
    );
}


// ************************************************************************* //

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
namespace contactLaws
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(contactLaw, none, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::none::none
(
    const dictionary&,
    const materialPair& pair
)
:
    contactLaw(pair)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::contactLaws::none::contactTime(const scalar) const
{
    return VGREAT;
}


Foam::vector Foam::contactLaws::none::force
(
    const scalar,
    const vector&,
    const vector&,
    const scalar,
    const scalar,
    vector&
) const
{
    return Zero;
}


// ************************************************************************* //

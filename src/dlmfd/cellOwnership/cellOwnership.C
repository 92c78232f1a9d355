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

#include "cellOwnership.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellOwnership::cellOwnership(const label nCells)
:
    owner_(nCells, -1),
    dist2_(nCells, GREAT),
    inside_(nCells, false),
    touched_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellOwnership::reset()
{
    for (const label c : touched_)
    {
        owner_[c] = -1;
        dist2_[c] = GREAT;
        inside_[c] = false;
    }
    touched_.clear();
}


// ************************************************************************* //

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

#include "costLine.H"
#include "OStringStream.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

Foam::string Foam::costLine::text
(
    const wordList& names,
    const scalarList& seconds
)
{
    if (names.size() != seconds.size())
    {
        FatalErrorInFunction
            << names.size() << " phase names for " << seconds.size()
            << " times" << abort(FatalError);
    }
    // A run of no measurable length still gets shares, all zero
    scalar total = 0;
    for (const scalar s : seconds)
    {
        total += s;
    }
    total = max(total, SMALL);

    OStringStream os;
    os  << "Cost (wall clock):";
    forAll(names, i)
    {
        os  << (i ? ", " : " ") << names[i].c_str() << ' ' << seconds[i]
            << " s (" << 100*seconds[i]/total << " %)";
    }
    return os.str();
}


// ************************************************************************* //

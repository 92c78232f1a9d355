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

#include "progressLog.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::progressLog::progressLog(const Time& runTime, const scalar interval)
:
    runTime_(runTime),
    start_(runTime.value()),
    clock_(),
    interval_(interval),
    lastWall_(0),
    tenths_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::progressLog::step()
{
    const scalar span = runTime_.endTime().value() - start_;
    if (!(span > 0))
    {
        return;
    }
    const scalar done = (runTime_.value() - start_)/span;
    const label tenths = label(std::floor(10*done + 1e-9));
    const scalar wall = clock_.elapsedTime();
    if (tenths <= tenths_ && wall - lastWall_ < interval_)
    {
        return;
    }
    tenths_ = max(tenths_, tenths);
    lastWall_ = wall;
    const scalar left = done > 0 ? wall*(1 - done)/done : 0;
    Info<< "Progress: t = " << runTime_.timeName() << " of "
        << runTime_.endTime().value() << " (" << label(std::round(100*done))
        << " %), wall " << label(std::round(wall)) << " s, about "
        << label(std::round(left)) << " s left" << endl;
}


// ************************************************************************* //

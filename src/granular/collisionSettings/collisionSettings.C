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

#include "collisionSettings.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionSettings::collisionSettings()
:
    subStepsPerContact_(20),
    overlapLimit_(0.05),
    skin_(-1),
    domain_(),
    periodic_(false),
    subCycleInReach_(false),
    ownedDistribution_(false)
{}


Foam::collisionSettings::collisionSettings(const dictionary& collisionDict)
:
    collisionSettings()
{
    subStepsPerContact_ =
        collisionDict.getOrDefault<label>("subStepsPerContact", 20);
    if (subStepsPerContact_ < 1)
    {
        FatalIOErrorInFunction(collisionDict)
            << "subStepsPerContact = " << subStepsPerContact_
            << " is not allowed; it must be >= 1 (seed 001 uses 20)"
            << exit(FatalIOError);
    }

    overlapLimit_ = collisionDict.getOrDefault<scalar>("overlapLimit", 0.05);
    if (!(overlapLimit_ > 0 && overlapLimit_ < 1))
    {
        FatalIOErrorInFunction(collisionDict)
            << "overlapLimit = " << overlapLimit_ << " is not allowed;"
            << " 0 < overlapLimit < 1 (largest overlap over the smaller"
            << " equivalent diameter; the laws' own design overlaps are"
            << " 0.001-0.01)" << exit(FatalIOError);
    }

    if (collisionDict.readIfPresent("skin", skin_) && !(skin_ >= 0))
    {
        FatalIOErrorInFunction(collisionDict)
            << "skin = " << skin_ << " is not allowed; it must be >= 0 [m]"
            << exit(FatalIOError);
    }

    const word subCycling =
        collisionDict.getOrDefault<word>("subCycling", "all");
    if (subCycling != "all" && subCycling != "inReach")
    {
        FatalIOErrorInFunction(collisionDict)
            << "subCycling " << subCycling << " is not allowed; valid: 2"
            << nl << "(" << nl << "all" << nl << "inReach" << nl << ")"
            << nl << "(all: every moving particle takes the sub-steps;"
            << " inReach: only those that can touch a wall or another"
            << " particle over the step)" << exit(FatalIOError);
    }
    subCycleInReach_ = subCycling == "inReach";

    const word distribution =
        collisionDict.getOrDefault<word>("particleDistribution", "master");
    if (distribution != "master" && distribution != "owned")
    {
        FatalIOErrorInFunction(collisionDict)
            << "particleDistribution " << distribution << " is not allowed;"
            << " valid: 2" << nl << "(" << nl << "master" << nl << "owned"
            << nl << ")" << nl << "(master: the master rank moves every"
            << " particle; owned: each rank moves the particles in its"
            << " region)" << exit(FatalIOError);
    }
    ownedDistribution_ = distribution == "owned";

    const dictionary& domainDict = collisionDict.subDict("domain");
    knownKeywords::require
    (
        collisionDict, wordList({"min", "max", "periodic"}), "domain"
    );
    const point lo = domainDict.get<point>("min");
    const point hi = domainDict.get<point>("max");
    for (direction d = 0; d < 3; ++d)
    {
        if (!(hi[d] > lo[d]))
        {
            FatalIOErrorInFunction(domainDict)
                << "domain: max " << hi << " must exceed min " << lo
                << " in every direction" << exit(FatalIOError);
        }
    }
    domain_ = boundBox(lo, hi);
    periodic_ = domainDict.getOrDefault<FixedList<bool, 3>>
    (
        "periodic", FixedList<bool, 3>(false)
    );
}


// ************************************************************************* //

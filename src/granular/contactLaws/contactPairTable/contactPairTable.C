/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Description
    One contact law per material pair.

\*---------------------------------------------------------------------------*/

#include "contactPairTable.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactPairTable::contactPairTable
(
    const dictionary& collisionDict,
    const granularMaterials& materials
)
:
    lawName_(collisionDict.get<word>("contactLaw")),
    nMaterials_(materials.size()),
    laws_(),
    slot_(materials.size()*materials.size(), -1)
{
    // A typo in the law's name is told before any missing pair
    if (!contactLaw::dictionaryConstructorTablePtr_->found(lawName_))
    {
        FatalIOErrorInLookup
        (
            collisionDict,
            "contactLaw",
            lawName_,
            *contactLaw::dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    // A law without coefficients (none) needs no pairs dictionary
    const dictionary emptyDict;
    const dictionary* pairsPtr = collisionDict.findDict("pairs");

    for (label a = 0; a < nMaterials_; ++a)
    {
        for (label b = a; b < nMaterials_; ++b)
        {
            if (materials.isWall(a) && materials.isWall(b))
            {
                continue;
            }
            const word nameAB(materials.name(a) + "-" + materials.name(b));
            const word nameBA(materials.name(b) + "-" + materials.name(a));

            const dictionary* coeffs = nullptr;
            word given(nameAB);
            if (pairsPtr)
            {
                coeffs = pairsPtr->findDict(nameAB);
                if (!coeffs)
                {
                    coeffs = pairsPtr->findDict(nameBA);
                    given = nameBA;
                }
            }
            if (!coeffs && lawName_ != "none")
            {
                FatalIOErrorInFunction(collisionDict)
                    << "contact law " << lawName_ << ": no coefficients for"
                    << " the material pair " << nameAB << " in pairs {...};"
                    << " pairs given: "
                    << (pairsPtr ? pairsPtr->toc() : wordList())
                    << exit(FatalIOError);
            }

            // The particle material first: a wall is always the second
            const bool aIsWall = materials.isWall(a);
            const label p = aIsWall ? b : a;
            const label q = aIsWall ? a : b;
            materialPair pair
            {
                materials.name(p) + "-" + materials.name(q),
                materials.density(p),
                materials.isWall(q) ? -1 : materials.density(q)
            };

            slot_[a*nMaterials_ + b] = laws_.size();
            slot_[b*nMaterials_ + a] = laws_.size();
            laws_.append
            (
                contactLaw::New
                (
                    lawName_, coeffs ? *coeffs : emptyDict, pair
                ).ptr()
            );

            // A misspelt optional coefficient (gammat) would leave its
            // default in force
            if (coeffs)
            {
                knownKeywords::require
                (
                    collisionDict, laws_.last().keywords(), "pairs/" + given
                );
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::contactPairTable::needsHistory() const
{
    forAll(laws_, i)
    {
        if (laws_[i].needsHistory())
        {
            return true;
        }
    }
    return false;
}


void Foam::contactPairTable::setTangential(const bool on)
{
    forAll(laws_, i)
    {
        laws_[i].setTangential(on);
    }
}


// ************************************************************************* //

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
    Plane walls from a dictionary or from a mesh's planar patches.

\*---------------------------------------------------------------------------*/

#include "planeWall.H"
#include "polyMesh.H"
#include "wordRes.H"
#include "SubField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::planeWall Foam::planeWall::read(const word& name, const dictionary& dict)
{
    planeWall w;
    w.name = name;
    w.origin = dict.get<point>("point");
    const vector n = dict.get<vector>("normal");
    if (mag(n) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "wall " << name << ": normal " << n
            << " has zero length; give the normal pointing into the domain"
            << exit(FatalIOError);
    }
    w.normal = n/mag(n);
    w.material = dict.get<word>("material");
    return w;
}


Foam::List<Foam::planeWall> Foam::planeWall::fromPatches
(
    const polyMesh& mesh,
    const wordRes& patchNames,
    const word& material
)
{
    const labelList patchIDs(mesh.boundaryMesh().patchSet(patchNames).sortedToc());
    if (patchIDs.empty())
    {
        FatalErrorInFunction
            << "no patch of the mesh matches " << patchNames
            << "; patches: " << mesh.boundaryMesh().names()
            << exit(FatalError);
    }

    List<planeWall> walls(patchIDs.size());
    const scalar size = mag(mesh.bounds().span());
    forAll(patchIDs, i)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchIDs[i]];
        // Area-weighted normal and centre over every processor's part of
        // the patch (a decomposed patch may have no face on a processor);
        // the normal points out of the mesh, the wall's into it
        const vectorField Sf(pp.faceAreas());
        const vectorField Cf(pp.faceCentres());
        vector S = sum(Sf);
        vector sumAC = sum(mag(Sf)*Cf);
        scalar sumA = sum(mag(Sf));
        reduce(S, sumOp<vector>());
        reduce(sumAC, sumOp<vector>());
        reduce(sumA, sumOp<scalar>());
        const point c = sumAC/max(sumA, VSMALL);
        if (mag(S) < VSMALL)
        {
            FatalErrorInFunction
                << "patch " << pp.name() << " has no area"
                << exit(FatalError);
        }
        const vector n = -S/mag(S);
        for (const point& p : pp.localPoints())
        {
            if (mag((p - c) & n) > 1e-8*size)
            {
                FatalErrorInFunction
                    << "patch " << pp.name() << " is not planar: point " << p
                    << " is " << ((p - c) & n) << " m off its mean plane;"
                    << " give its walls in collisionProperties instead"
                    << exit(FatalError);
            }
        }
        walls[i].name = pp.name();
        walls[i].origin = c;
        walls[i].normal = n;
        walls[i].material = material;
    }
    return walls;
}


// ************************************************************************* //

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

#include "foamTestCase.H"
#include "wallPolyPatch.H"
#include "OSspecific.H"

#include <cstdlib>
#include <unistd.h>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::test::foamTestCase::foamTestCase()
{
    char pattern[] = "/tmp/dlmfdTest.XXXXXX";
    const char* dir = ::mkdtemp(pattern);
    if (!dir)
    {
        FatalErrorInFunction
            << "cannot create a temporary case folder from " << pattern
            << exit(FatalError);
    }
    caseDir_ = dir;

    dictionary controlDict;
    controlDict.add("application", "unitTest");
    controlDict.add("startFrom", "startTime");
    controlDict.add("startTime", 0);
    controlDict.add("stopAt", "endTime");
    controlDict.add("endTime", 100);
    controlDict.add("deltaT", 1);
    controlDict.add("writeControl", "timeStep");
    controlDict.add("writeInterval", 1000000);
    controlDict.add("writeFormat", "ascii");

    runTime_.reset
    (
        new Time(controlDict, caseDir_.path(), caseDir_.name(),
                 "system", "constant", false, false)
    );
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::test::foamTestCase::~foamTestCase()
{
    mesh_.clear();
    runTime_.clear();
    rmDir(caseDir_, true);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::fvMesh& Foam::test::foamTestCase::makeBoxMesh
(
    const label nx,
    const label ny,
    const label nz,
    const vector& L
)
{
    const auto pointI = [=](label i, label j, label k)
    {
        return i + (nx + 1)*(j + (ny + 1)*k);
    };
    const auto cellI = [=](label i, label j, label k)
    {
        return i + nx*(j + ny*k);
    };

    pointField points((nx + 1)*(ny + 1)*(nz + 1));
    for (label k = 0; k <= nz; ++k)
    {
        for (label j = 0; j <= ny; ++j)
        {
            for (label i = 0; i <= nx; ++i)
            {
                points[pointI(i, j, k)] = vector
                (
                    L.x()*i/nx, L.y()*j/ny, L.z()*k/nz
                );
            }
        }
    }

    // Faces normal to x, y, z at plane index i (j, k), pointing to +x (+y, +z)
    const auto xFace = [&](label i, label j, label k)
    {
        return face
        ({
            pointI(i, j, k), pointI(i, j + 1, k),
            pointI(i, j + 1, k + 1), pointI(i, j, k + 1)
        });
    };
    const auto yFace = [&](label i, label j, label k)
    {
        return face
        ({
            pointI(i, j, k), pointI(i, j, k + 1),
            pointI(i + 1, j, k + 1), pointI(i + 1, j, k)
        });
    };
    const auto zFace = [&](label i, label j, label k)
    {
        return face
        ({
            pointI(i, j, k), pointI(i + 1, j, k),
            pointI(i + 1, j + 1, k), pointI(i, j + 1, k)
        });
    };

    DynamicList<face> faces;
    DynamicList<label> owner;
    DynamicList<label> neighbour;

    // Internal faces in upper-triangular order: by owner, then neighbour
    for (label k = 0; k < nz; ++k)
    {
        for (label j = 0; j < ny; ++j)
        {
            for (label i = 0; i < nx; ++i)
            {
                const label c = cellI(i, j, k);
                if (i + 1 < nx)
                {
                    faces.append(xFace(i + 1, j, k));
                    owner.append(c);
                    neighbour.append(cellI(i + 1, j, k));
                }
                if (j + 1 < ny)
                {
                    faces.append(yFace(i, j + 1, k));
                    owner.append(c);
                    neighbour.append(cellI(i, j + 1, k));
                }
                if (k + 1 < nz)
                {
                    faces.append(zFace(i, j, k + 1));
                    owner.append(c);
                    neighbour.append(cellI(i, j, k + 1));
                }
            }
        }
    }
    const label nInternalFaces = faces.size();

    // Boundary faces, pointing out of the box
    for (label k = 0; k < nz; ++k)
    {
        for (label j = 0; j < ny; ++j)
        {
            faces.append(xFace(0, j, k).reverseFace());
            owner.append(cellI(0, j, k));
            faces.append(xFace(nx, j, k));
            owner.append(cellI(nx - 1, j, k));
        }
    }
    for (label k = 0; k < nz; ++k)
    {
        for (label i = 0; i < nx; ++i)
        {
            faces.append(yFace(i, 0, k).reverseFace());
            owner.append(cellI(i, 0, k));
            faces.append(yFace(i, ny, k));
            owner.append(cellI(i, ny - 1, k));
        }
    }
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            faces.append(zFace(i, j, 0).reverseFace());
            owner.append(cellI(i, j, 0));
            faces.append(zFace(i, j, nz));
            owner.append(cellI(i, j, nz - 1));
        }
    }
    const label nBoundaryFaces = faces.size() - nInternalFaces;

    mesh_.reset
    (
        new fvMesh
        (
            IOobject
            (
                polyMesh::defaultRegion,
                runTime_->constant(),
                *runTime_,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            std::move(points),
            faceList(std::move(faces)),
            labelList(std::move(owner)),
            labelList(std::move(neighbour))
        )
    );

    List<polyPatch*> patches(1);
    patches[0] = new wallPolyPatch
    (
        "walls",
        nBoundaryFaces,
        nInternalFaces,
        0,
        mesh_->boundaryMesh(),
        wallPolyPatch::typeName
    );
    mesh_->addFvPatches(patches);

    return *mesh_;
}


// ************************************************************************* //

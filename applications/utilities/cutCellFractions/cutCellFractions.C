/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Application
    cutCellFractions

Description
    Write the fluid fractions the particles leave open in the cells
    (fluidFraction) and on the faces (faceAperture), and the flux of their
    velocities through the faces' solid parts (solidFlux), at the start
    time, from each particle's exact shape and its periodic images
    (Foam::cutFractions), to look at in ParaView; and check the geometry:
    the solid volume over all cells against the particles' volumes, and
    the two sides of every processor and cyclic face against each other.

    The particles are those the solver would start from: the time's
    uniform/particles (written by the solver) or its particles file.

Usage
    \b cutCellFractions [-parallel] [-time T]

    Writes \<time\>/fluidFraction, \<time\>/faceAperture,
    \<time\>/solidFlux and
    postProcessing/cutCellFractions/\<time\>/cutCellFractions.dat:

    \verbatim
    # particles  images  cutCells  solidVolume  particlesVolume  volumeError  couplingMismatch  largestOverlap
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "timeSelector.H"
#include "fvMesh.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "granularSystem.H"
#include "particleFileReader.H"
#include "cutFractions.H"
#include "OSspecific.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Write the particles' cut of the mesh (fluidFraction of the cells,"
        " faceAperture of the faces) and check its geometry"
    );
    timeSelector::addOptions(false, false);

    #include "setRootCase.H"
    #include "createTime.H"

    const instantList times = timeSelector::select0(runTime, args);
    runTime.setTime(times.first(), 0);

    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion,
            runTime.timeName(),
            runTime,
            IOobject::MUST_READ
        )
    );

    const IOdictionary particleDict
    (
        IOobject
        (
            "particleProperties",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    const IOdictionary collisionDict
    (
        IOobject
        (
            "collisionProperties",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    granularSystem scene(particleDict, collisionDict);
    // The particles the solver would start from, on every rank
    fileName file;
    scene.readParticles
    (
        particleFileReader::readStartOnEveryRank(runTime, file), file
    );
    Info<< "Particles from " << file << ": " << scene.size() << nl;

    // The period from collisionProperties' domain, which must be the
    // mesh's box along its periodic directions
    vector period(Zero);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (scene.periodic()[d])
        {
            period[d] = scene.domain().span()[d];
            const scalar meshSpan = mesh.bounds().span()[d];
            if (mag(meshSpan - period[d]) > 1e-9*mag(mesh.bounds().span()))
            {
                FatalErrorInFunction
                    << "direction " << d << " is periodic in"
                    << " constant/collisionProperties with the domain's"
                    << " span " << period[d] << " m, but the mesh spans "
                    << meshSpan << " m; they must be the same"
                    << exit(FatalError);
            }
        }
    }

    cutFractions cut(mesh);
    label images = 0;
    scalar volume = 0;
    for (const rigidParticle& p : scene.particles())
    {
        images += cut.cut
        (
            p.shape(), p.position(), p.R(), p.velocity(), p.omega(), period
        );
        // A planar shape is as deep as the mesh (the solver checks it)
        volume += p.shape().volume();
    }
    cut.finish();

    label cutCells = 0;
    for (const scalar a : cut.fluidFraction().primitiveField())
    {
        cutCells += (a > 0 && a < 1);
    }
    reduce(cutCells, sumOp<label>());
    const scalar solid = cut.totalSolidVolume();
    const scalar volumeError = volume > 0 ? solid/volume - 1 : 0;

    Info<< "Cut cells " << cutCells << nl
        << "Solid volume over the cells " << solid << " m^3; the particles' "
        << volume << " m^3 (relative difference " << volumeError << ")" << nl
        << "Largest difference between the sides of a coupled face "
        << cut.couplingMismatch() << nl
        << "Largest excess of overlapping bodies over a cell or face "
        << cut.largestOverlap() << nl;

    cut.fluidFraction().write();
    cut.faceAperture().write();
    cut.solidFlux().write();

    if (Pstream::master())
    {
        const fileName dir
        (
            runTime.globalPath()/"postProcessing"/"cutCellFractions"
           /runTime.timeName()
        );
        mkDir(dir);
        OFstream os(dir/"cutCellFractions.dat");
        os.precision(12);
        os  << "# particles images cutCells solidVolume particlesVolume"
            << " volumeError couplingMismatch largestOverlap" << nl
            << scene.size() << ' ' << images << ' ' << cutCells << ' '
            << solid << ' ' << volume << ' ' << volumeError << ' '
            << cut.couplingMismatch() << ' ' << cut.largestOverlap() << nl;
    }

    Info<< "End" << nl;
    return 0;
}


// ************************************************************************* //

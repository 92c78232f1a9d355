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

#include "hexCellCheck.H"
#include "OStringStream.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Corners of a face: the vertices where its outline turns by more than
// about half a degree (a hanging vertex on a straight edge does not count)
label cornerCount(const face& f, const pointField& pts)
{
    const label n = f.size();
    label corners = 0;
    for (label i = 0; i < n; ++i)
    {
        const vector a = pts[f[i]] - pts[f[(i + n - 1) % n]];
        const vector b = pts[f[(i + 1) % n]] - pts[f[i]];
        const scalar la = mag(a), lb = mag(b);
        if (la < VSMALL || lb < VSMALL || mag(a ^ b) > 1e-2*la*lb)
        {
            ++corners;
        }
    }
    return corners;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::hexCellCheck::isHexLike
(
    const polyMesh& mesh,
    const label celli,
    string& why
)
{
    const cell& c = mesh.cells()[celli];
    const faceList& faces = mesh.faces();
    const pointField& pts = mesh.points();
    const vectorField& Sf = mesh.faceAreas();

    // Distinct face-normal directions (outward or inward alike: a split
    // face's parts share their plane's)
    DynamicList<vector> directions(6);
    forAll(c, i)
    {
        const face& f = faces[c[i]];
        const label corners = cornerCount(f, pts);
        if (corners != 4)
        {
            OStringStream os;
            os  << "cell " << celli << " at " << mesh.cellCentres()[celli]
                << " has " << c.size() << " faces; face " << c[i]
                << " has " << corners << " corners (" << f.size()
                << " vertices), where a hexahedron's faces have 4";
            why = os.str();
            return false;
        }
        const vector n = Sf[c[i]]/max(mag(Sf[c[i]]), VSMALL);
        bool known = false;
        for (const vector& d : directions)
        {
            if (mag(n & d) > 0.9995)
            {
                known = true;
                break;
            }
        }
        if (!known)
        {
            directions.append(n);
        }
    }
    // Three pairs of opposite faces: six directions at most (opposite faces
    // of a graded or curved block need not be parallel)
    if (directions.size() > 6)
    {
        OStringStream os;
        os  << "cell " << celli << " at " << mesh.cellCentres()[celli]
            << " has " << c.size() << " faces in " << directions.size()
            << " planes, where a hexahedron, split or not, has 6";
        why = os.str();
        return false;
    }
    return true;
}


Foam::label Foam::hexCellCheck::countOthers
(
    const polyMesh& mesh,
    string& firstWhy
)
{
    label nOther = 0;
    string local;
    for (label celli = 0; celli < mesh.nCells(); ++celli)
    {
        string why;
        if (!isHexLike(mesh, celli, why))
        {
            if (!nOther)
            {
                local = why;
            }
            ++nOther;
        }
    }
    List<string> whys(Pstream::nProcs());
    whys[Pstream::myProcNo()] = local;
    Pstream::gatherList(whys);
    Pstream::scatterList(whys);
    firstWhy.clear();
    forAll(whys, proci)
    {
        if (!whys[proci].empty())
        {
            firstWhy = whys[proci];
            if (Pstream::parRun())
            {
                firstWhy += " (processor " + Foam::name(proci) + ")";
            }
            break;
        }
    }
    return returnReduce(nOther, sumOp<label>());
}


void Foam::hexCellCheck::require(const polyMesh& mesh, const word& who)
{
    string why;
    const label nOther = countOthers(mesh, why);
    if (nOther)
    {
        FatalErrorInFunction
            << who << ": " << nOther << " of "
            << returnReduce(mesh.nCells(), sumOp<label>()) << " cells of"
            << " the mesh in " << mesh.facesInstance()/mesh.meshDir()
            << " are not hexahedra; the first: " << why.c_str() << nl
            << "    Supported: hexahedra (blockMesh, uniform or graded) and"
            << " split hexahedra (refineHexMesh, snappyHexMesh's castellated"
            << " mesh without snapping). Tetrahedra, prisms, pyramids and"
            << " general polyhedra are not: on tetrahedra the coupling"
            << " diverges (see benchmarks/validation/README.md)."
            << exit(FatalError);
    }
}


// ************************************************************************* //

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
    VTK polydata of the particles with .series files.

\*---------------------------------------------------------------------------*/

#include "granularVTKWriter.H"
#include "sphere.H"
#include "convexPolyhedron.H"
#include "circle.H"
#include "mathematicalConstants.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"

#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- The vectors every particle carries, after its id (and a sphere's
    //- diameter)
    const char* const vectorNames[] =
        {"velocity", "omega", "contactForce", "contactTorque"};

    void writeVectors
    (
        Ostream& os,
        const char* name,
        const UList<vector>& v
    )
    {
        os  << "<DataArray type=\"Float64\" Name=\"" << name
            << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const vector& x : v)
        {
            os  << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
        }
        os  << "</DataArray>\n";
    }

    template<class Type>
    void writeScalars
    (
        Ostream& os,
        const char* type,
        const char* name,
        const UList<Type>& v
    )
    {
        os  << "<DataArray type=\"" << type << "\" Name=\"" << name
            << "\" format=\"ascii\">\n";
        for (const Type& x : v)
        {
            os  << x << '\n';
        }
        os  << "</DataArray>\n";
    }

    //- Times in a series file are written at 12 digits
    scalar timeTolerance(const scalar t)
    {
        return 1e-10*max(scalar(1), mag(t));
    }

    //- Drop the entries at time t and after (a write at t replaces them)
    void dropFrom(List<Tuple2<word, scalar>>& entries, const scalar t)
    {
        label n = 0;
        while (n < entries.size() && entries[n].second() < t - timeTolerance(t))
        {
            ++n;
        }
        entries.setSize(n);
    }

    //- Write to a temporary file, then rename: no half-written file
    void commit(const fileName& tmp, const fileName& file)
    {
        if (!Foam::mv(tmp, file))
        {
            FatalErrorInFunction
                << "cannot rename " << tmp << " to " << file
                << exit(FatalError);
        }
    }

    //- Write a VTK XML polydata file through a temporary file: the
    //- points, the cells of one kind ("Polys" or "Verts") and the arrays
    //- that writeData writes inside a dataKind element ("CellData" or
    //- "PointData")
    template<class DataWriter>
    void writePolyData
    (
        const fileName& file,
        const UList<point>& points,
        const char* cellKind,
        const UList<label>& connectivity,
        const UList<label>& offsets,
        const char* dataKind,
        const char* activeScalars,
        const DataWriter& writeData
    )
    {
        {
            OFstream os(file + ".tmp");
            os.precision(10);
            os  << "<?xml version=\"1.0\"?>\n"
                << "<VTKFile type=\"PolyData\" version=\"0.1\""
                << " byte_order=\"LittleEndian\">\n<PolyData>\n"
                << "<Piece NumberOfPoints=\"" << points.size()
                << "\" NumberOf" << cellKind << "=\"" << offsets.size()
                << "\">\n<Points>\n";
            writeVectors(os, "Points", points);
            os  << "</Points>\n<" << cellKind << ">\n";
            writeScalars(os, "Int32", "connectivity", connectivity);
            writeScalars(os, "Int32", "offsets", offsets);
            os  << "</" << cellKind << ">\n<" << dataKind << " Scalars=\""
                << activeScalars << "\">\n";
            writeData(os);
            os  << "</" << dataKind << ">\n</Piece>\n</PolyData>\n"
                << "</VTKFile>\n";
        }
        commit(file + ".tmp", file);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::vector<Foam::granularVTKWriter::dataArray>
Foam::granularVTKWriter::arrays(const bool spheres) const
{
    std::vector<dataArray> a{{"Int32", "id", 1}};
    if (spheres)
    {
        a.push_back({"Float64", "diameter", 1});
    }
    for (const char* name : vectorNames)
    {
        a.push_back({"Float64", name, 3});
    }
    if (hydrodynamic_)
    {
        a.push_back({"Float64", "hydrodynamicForce", 3});
        a.push_back({"Float64", "hydrodynamicTorque", 3});
    }
    return a;
}


Foam::List<Foam::Tuple2<Foam::word, Foam::scalar>>
Foam::granularVTKWriter::readSeries(const fileName& file, const scalar t)
{
    DynamicList<Tuple2<word, scalar>> entries;
    std::ifstream is(file);
    std::string line;
    // One entry per line, as writeSeries writes them:
    //   { "name" : "spheres_3.vtp", "time" : 0.3 },
    while (std::getline(is, line))
    {
        const auto n0 = line.find("\"name\"");
        const auto t0 = line.find("\"time\"");
        if (n0 == std::string::npos || t0 == std::string::npos)
        {
            continue;
        }
        const auto q1 = line.find('"', line.find(':', n0) + 1);
        const auto q2 = line.find('"', q1 + 1);
        const std::string name = line.substr(q1 + 1, q2 - q1 - 1);
        const scalar time = std::stod(line.substr(line.find(':', t0) + 1));
        // (the start time's own output kept: a restart does not write it
        // again; a write at a time already listed replaces its entry)
        if (time <= t + timeTolerance(t))
        {
            entries.append(Tuple2<word, scalar>(word(name), time));
        }
    }
    return List<Tuple2<word, scalar>>(std::move(entries));
}


void Foam::granularVTKWriter::writeSeries
(
    const fileName& file,
    const UList<Tuple2<word, scalar>>& entries
)
{
    const fileName tmp(file + ".tmp");
    {
        OFstream os(tmp);
        os.precision(12);
        os  << "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
        forAll(entries, i)
        {
            os  << "    { \"name\" : \"" << entries[i].first()
                << "\", \"time\" : " << entries[i].second() << " }"
                << (i + 1 < entries.size() ? "," : "") << '\n';
        }
        os  << "  ]\n}\n";
    }
    commit(tmp, file);
}


void Foam::granularVTKWriter::writePieceIndex
(
    const fileName& file,
    const word& pieceDir,
    const word& kind,
    const char* dataKind,
    const char* activeScalars,
    const std::vector<dataArray>& arrays
)
{
    const fileName tmp(file + ".tmp");
    {
        OFstream os(tmp);
        os  << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"PPolyData\" version=\"0.1\""
            << " byte_order=\"LittleEndian\">\n<PPolyData GhostLevel=\"0\">\n"
            << "<PPoints>\n<PDataArray type=\"Float64\" Name=\"Points\""
            << " NumberOfComponents=\"3\"/>\n</PPoints>\n"
            << '<' << dataKind << " Scalars=\"" << activeScalars << "\">\n";
        for (const dataArray& a : arrays)
        {
            os  << "<PDataArray type=\"" << a.type << "\" Name=\"" << a.name
                << "\" NumberOfComponents=\"" << a.nComponents << "\"/>\n";
        }
        os  << "</" << dataKind << ">\n";
        for (label r = 0; r < Pstream::nProcs(); ++r)
        {
            os  << "<Piece Source=\"" << pieceDir << '/' << kind << '_' << r
                << ".vtp\"/>\n";
        }
        os  << "</PPolyData>\n</VTKFile>\n";
    }
    commit(tmp, file);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::granularVTKWriter::granularVTKWriter
(
    const fileName& dir,
    const scalar startTime,
    const bool hydrodynamic
)
:
    dir_(dir),
    polyhedra_(readSeries(dir/"polyhedra.vtp.series", startTime)),
    spheres_(readSeries(dir/"spheres.vtp.series", startTime)),
    polyhedraPieces_(readSeries(dir/"polyhedra.pvtp.series", startTime)),
    spherePieces_(readSeries(dir/"spheres.pvtp.series", startTime)),
    hydrodynamic_(hydrodynamic)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::granularVTKWriter::writeParticles
(
    const granularSystem& system,
    const bool ownedOnly,
    const fileName& polyFile,
    const fileName& sphereFile,
    const loads& given
) const
{
    if
    (
        hydrodynamic_
     && (!given.hydrodynamicForce || !given.hydrodynamicTorque)
    )
    {
        FatalErrorInFunction
            << "the VTK files of " << dir_ << " carry the hydrodynamic force"
            << " and torque, but none were given" << exit(FatalError);
    }
    const label nVectors = arrays(false).size() - 1;

    // A particle's vectors, in the order of arrays()
    std::vector<vector> v(nVectors);
    const auto particleVectors = [&](const label i, const rigidParticle& p)
    {
        v[0] = p.velocity();
        v[1] = p.omega();
        const scalar byDt = given.Deltat > 0 ? 1/given.Deltat : 0;
        v[2] = byDt*p.contactImpulse();
        v[3] = byDt*p.contactAngularImpulse();
        if (hydrodynamic_)
        {
            const label g = system.globalIndex(i);
            v[4] = (*given.hydrodynamicForce)[g];
            v[5] = (*given.hydrodynamicTorque)[g];
        }
    };

    // Spheres: one point each
    DynamicList<point> centres;
    DynamicList<scalar> diameters;
    DynamicList<label> sphereIds;
    std::vector<DynamicList<vector>> sphereVectors(nVectors);

    // Polyhedra: their faces
    DynamicList<point> points;
    DynamicList<label> connectivity, offsets, faceIds;
    std::vector<DynamicList<vector>> faceVectors(nVectors);

    for (label i = 0; i < system.size(); ++i)
    {
        if (ownedOnly && system.ghost(i))
        {
            continue;
        }
        const rigidParticle& p = system.particle(i);
        particleVectors(i, p);
        if (const auto* s = isA<particleShapes::sphere>(p.shape()))
        {
            centres.append(p.position());
            diameters.append(2*s->radius());
            sphereIds.append(system.id(i));
            for (label k = 0; k < nVectors; ++k)
            {
                sphereVectors[k].append(v[k]);
            }
            continue;
        }
        // A face of the particle's surface: its cell data
        const auto addFaceData = [&]()
        {
            offsets.append(connectivity.size());
            faceIds.append(system.id(i));
            for (label k = 0; k < nVectors; ++k)
            {
                faceVectors[k].append(v[k]);
            }
        };
        if (const auto* c = isA<particleShapes::circle>(p.shape()))
        {
            // A 2D disc: drawn as a prism of nSides sides, one cell deep,
            // with the polyhedra (its rotation shows on the side faces)
            const label nSides = 36;
            const tensor R = p.R();
            const label start = points.size();
            for (label k = 0; k < 2*nSides; ++k)
            {
                const scalar a =
                    constant::mathematical::twoPi*(k % nSides)/nSides;
                const vector corner
                (
                    c->radius()*std::cos(a),
                    c->radius()*std::sin(a),
                    (k < nSides ? -0.5 : 0.5)*c->depth()
                );
                points.append(p.position() + (R & corner));
            }
            const auto addFace = [&](const labelList& f)
            {
                for (const label corner : f)
                {
                    connectivity.append(start + corner);
                }
                addFaceData();
            };
            labelList bottom(nSides), top(nSides);
            for (label k = 0; k < nSides; ++k)
            {
                bottom[k] = nSides - 1 - k;
                top[k] = nSides + k;
            }
            addFace(bottom);
            addFace(top);
            for (label k = 0; k < nSides; ++k)
            {
                const label k1 = (k + 1) % nSides;
                addFace(labelList({k, k1, nSides + k1, nSides + k}));
            }
            continue;
        }
        const auto* poly = isA<particleShapes::convexPolyhedron>(p.shape());
        if (!poly)
        {
            FatalErrorInFunction
                << "particle " << system.id(i) << ": shape "
                << p.shape().type() << " has no VTK form"
                << exit(FatalError);
        }
        const tensor R = p.R();
        const label start = points.size();
        for (const point& corner : poly->points())
        {
            points.append(p.position() + (R & corner));
        }
        for (const face& f : poly->faces())
        {
            for (const label corner : f)
            {
                connectivity.append(start + corner);
            }
            addFaceData();
        }
    }

    const std::vector<dataArray> vectorArrays(arrays(false));

    writePolyData
    (
        polyFile, points, "Polys", connectivity, offsets,
        "CellData", "id",
        [&](Ostream& os)
        {
            writeScalars(os, "Int32", "id", faceIds);
            for (label k = 0; k < nVectors; ++k)
            {
                writeVectors(os, vectorArrays[k + 1].name, faceVectors[k]);
            }
        }
    );

    // One vertex cell per sphere
    labelList verts(centres.size());
    labelList vertOffsets(centres.size());
    forAll(verts, i)
    {
        verts[i] = i;
        vertOffsets[i] = i + 1;
    }
    writePolyData
    (
        sphereFile, centres, "Verts", verts, vertOffsets,
        "PointData", "diameter",
        [&](Ostream& os)
        {
            writeScalars(os, "Int32", "id", sphereIds);
            writeScalars(os, "Float64", "diameter", diameters);
            for (label k = 0; k < nVectors; ++k)
            {
                writeVectors(os, vectorArrays[k + 1].name, sphereVectors[k]);
            }
        }
    );
}


void Foam::granularVTKWriter::write
(
    const granularSystem& system,
    const scalar t,
    const label index,
    const loads& given
)
{
    // The folder made at the first write, not before: a run refused at
    // start leaves no VTK folder behind
    mkDir(dir_);
    const word polyName("polyhedra_" + Foam::name(index) + ".vtp");
    const word sphereName("spheres_" + Foam::name(index) + ".vtp");
    writeParticles(system, false, dir_/polyName, dir_/sphereName, given);

    dropFrom(polyhedra_, t);
    dropFrom(spheres_, t);
    polyhedra_.append(Tuple2<word, scalar>(polyName, t));
    spheres_.append(Tuple2<word, scalar>(sphereName, t));
    writeSeries(dir_/"polyhedra.vtp.series", polyhedra_);
    writeSeries(dir_/"spheres.vtp.series", spheres_);
}


void Foam::granularVTKWriter::writePieces
(
    const granularSystem& part,
    const scalar t,
    const label index,
    const loads& given
)
{
    // This rank's piece: its own particles, not its ghosts
    const fileName pieceDir(dir_/"pieces_" + Foam::name(index));
    mkDir(pieceDir);
    const word rank(Foam::name(Pstream::myProcNo()));
    writeParticles
    (
        part, true,
        pieceDir/"polyhedra_" + rank + ".vtp",
        pieceDir/"spheres_" + rank + ".vtp",
        given
    );
    if (!Pstream::master())
    {
        return;
    }

    // The index of the pieces, and its series
    const word polyName("polyhedra_" + Foam::name(index) + ".pvtp");
    const word sphereName("spheres_" + Foam::name(index) + ".pvtp");
    writePieceIndex
    (
        dir_/polyName, pieceDir.name(), "polyhedra", "PCellData", "id",
        arrays(false)
    );
    writePieceIndex
    (
        dir_/sphereName, pieceDir.name(), "spheres", "PPointData", "diameter",
        arrays(true)
    );
    dropFrom(polyhedraPieces_, t);
    dropFrom(spherePieces_, t);
    polyhedraPieces_.append(Tuple2<word, scalar>(polyName, t));
    spherePieces_.append(Tuple2<word, scalar>(sphereName, t));
    writeSeries(dir_/"polyhedra.pvtp.series", polyhedraPieces_);
    writeSeries(dir_/"spheres.pvtp.series", spherePieces_);
}


// ************************************************************************* //

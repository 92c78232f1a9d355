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
    libFuzzer target of the particle-file reader: each input is read as a
    particle file (particleFileReader: the check for control characters,
    OpenFOAM's tokenizer and the check of the file's structure; then
    granularSystem::readParticles with its checks of the starting state)
    into a scene of spheres, cubes, tetrahedra and circles, a floor and a
    periodic direction. Bad input must end in an OpenFOAM error (thrown
    here, and caught); anything else (a crash, an abort, an address
    sanitizer report, a hang) is a finding. Built and run by tests/fuzz/run.

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "particleFileReader.H"
#include "testInput.H"
#include "error.H"

#include <cstdint>
#include <cstddef>
#include <string>

using namespace Foam;
using Foam::testInput::parse;

namespace
{

granularSystem& scene()
{
    static granularSystem* sys = []
    {
        FatalError.throwExceptions();
        FatalIOError.throwExceptions();
        const std::string coeffs =
            "en 0.9; muc 0.3; maxOverlapRatio 1e-3; impactVelocity 0.5;"
            " referenceDiameter 0.01; ks 1e4;";
        return new granularSystem
        (
            parse
            (
                "shapes { ball { type sphere; D 0.01; }"
                " box { type cube; edge 0.008; }"
                " tet { type tetrahedron; edge 0.01; }"
                " disc { type circle; D 0.01; depth 0.002; } }"
                " materials { glass { density 2500; } steel { density 7800; } }"
            ),
            parse
            (
                "contactLaw hookeanStaticFriction; domain { min (-0.1 -0.1 0);"
                " max (0.1 0.1 0.2); periodic (true false false); }"
                " walls { floor { point (0 0 0); normal (0 0 1);"
                " material wall; } }"
                " pairs { glass-glass {" + coeffs + "} glass-steel {"
              + coeffs + "} steel-steel {" + coeffs + "} glass-wall {"
              + coeffs + "} steel-wall {" + coeffs + "} }"
            )
        );
    }();
    return *sys;
}

} // End anonymous namespace


extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    granularSystem& sys = scene();
    const std::string text(reinterpret_cast<const char*>(data), size);
    try
    {
        const fileName name("fuzz/particles");
        sys.readParticles(particleFileReader::parse(text, name), name);
    }
    catch (const Foam::error&)
    {
        // Refused with a message: the expected end of bad input
    }
    return 0;
}


// ************************************************************************* //

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

#include "suspensionInput.H"
#include "OSspecific.H"
#include "error.H"

#include <algorithm>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * * //

std::map<Foam::scalar, std::vector<Foam::suspensionInput::sample>>
Foam::suspensionInput::readSeries(const fileName& dir)
{
    std::map<scalar, std::vector<sample>> steps;
    fileNameList starts(readDir(dir, fileName::DIRECTORY));
    std::sort
    (
        starts.begin(), starts.end(),
        [](const fileName& a, const fileName& b)
        {
            return readScalar(a) < readScalar(b);
        }
    );
    for (const fileName& start : starts)
    {
        const fileName file(dir/start/"particles.dat");
        if (!isFile(file))
        {
            continue;
        }
        // Steps of this file replace those of earlier ones from its start
        const scalar t0 = readScalar(start);
        steps.erase(steps.upper_bound(t0), steps.end());

        std::ifstream is(file);
        std::string line;
        label lineNo = 0;
        while (std::getline(is, line))
        {
            ++lineNo;
            if (line.empty() || line[0] == '#')
            {
                continue;
            }
            std::istringstream ls(line);
            scalar v[21];
            for (scalar& x : v)
            {
                if (!(ls >> x))
                {
                    FatalErrorInFunction
                        << file << " line " << lineNo << ": expected 21"
                        << " numbers (time id x y z qw qx qy qz Ux Uy Uz"
                        << " omegax omegay omegaz Fhx Fhy Fhz Thx Thy Thz)"
                        << exit(FatalError);
                }
            }
            sample s;
            s.id = label(v[1]);
            s.x = point(v[2], v[3], v[4]);
            s.V = vector(v[9], v[10], v[11]);
            s.omega = vector(v[12], v[13], v[14]);
            s.F = vector(v[15], v[16], v[17]);
            steps[v[0]].push_back(s);
        }
    }
    return steps;
}


Foam::scalar Foam::suspensionInput::sphereTerminalReynolds(const scalar Ga)
{
    const auto f = [&](const scalar Re)
    {
        return 24*Re*(1 + 0.15*std::pow(Re, 0.687)) - 4.0/3.0*sqr(Ga);
    };
    scalar lo = 0, hi = max(1.0, sqr(Ga));
    for (int i = 0; i < 200; ++i)
    {
        const scalar mid = 0.5*(lo + hi);
        (f(mid) > 0 ? hi : lo) = mid;
    }
    return 0.5*(lo + hi);
}


// ************************************************************************* //

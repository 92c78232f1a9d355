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
    mergeParticleSeries

Group
    grpPostProcessingUtilities

Description
    Merges the particle time series that dlmfdFoam writes rank by rank with
    particleDistribution owned (constant/collisionProperties) on several
    ranks into the file master mode writes:

        processor<r>/postProcessing/dlmfdParticles/<t>/particles.dat
            (each rank's own particles; every row led by the time index and
            the particle's global index)
    ->  postProcessing/dlmfdParticles/<t>/particles.dat
            (every particle, steps in order, particles by global index: the
            same bytes as master mode's file)

    for every start time <t> (one per run and restart). The ranks' files are
    read side by side, each already in (time index, global index) order, so
    the memory held is one row per rank. Every step must have each global
    index 0 ... N-1 exactly once, N the particles of the first step: a
    duplicate, a gap, a step missing on some rank (a rank's file ending
    early) or rows out of order stop the utility with the file and line,
    and no merged file is left behind.

Usage
    \b mergeParticleSeries [-case dir]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "OSspecific.H"
#include "fileNameList.H"

#include <fstream>
#include <functional>
#include <memory>
#include <queue>
#include <string>
#include <tuple>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The header's lead that a rank's file has and the merged file has not
const std::string rankLead("# timeIndex globalIndex ");

//- One rank's file read a row at a time
class rankSeries
{
    std::ifstream is_;
    fileName file_;
    label line_ = 0;

public:

    std::string header;
    label timeIndex = -1;
    label globalIndex = -1;
    std::string row;
    bool done = false;

    explicit rankSeries(const fileName& file)
    :
        is_(file),
        file_(file)
    {
        if (!is_.good())
        {
            FatalErrorInFunction
                << "cannot read " << file << exit(FatalError);
        }
        std::getline(is_, header);
        ++line_;
        if (header.compare(0, rankLead.size(), rankLead) != 0)
        {
            FatalErrorInFunction
                << file << " line 1: the header does not begin with \""
                << rankLead.c_str() << "\": not a rank's series of"
                << " particleDistribution owned" << exit(FatalError);
        }
        next();
    }

    const fileName& file() const
    {
        return file_;
    }

    label line() const
    {
        return line_;
    }

    //- Read the next row; done at the end of the file. A row that is
    //- not a rank's row, or out of order, ends the file with problem set
    //- (what the merge then reports)
    void next()
    {
        std::string text;
        if (!std::getline(is_, text))
        {
            done = true;
            return;
        }
        ++line_;
        const auto end1 = text.find(' ');
        const auto end2 =
            end1 == std::string::npos ? end1 : text.find(' ', end1 + 1);
        const auto digits = [&](const std::size_t b, const std::size_t e)
        {
            return
                e != std::string::npos && e > b
             && text.find_first_not_of("0123456789", b) >= e;
        };
        if (!digits(0, end1) || !digits(end1 + 1, end2))
        {
            fail
            (
                "\"" + text + "\" does not begin with a time index and a"
                " global index"
            );
            return;
        }
        const label step = std::stol(text.substr(0, end1));
        const label index = std::stol(text.substr(end1 + 1, end2 - end1 - 1));
        if
        (
            step < timeIndex
         || (step == timeIndex && index <= globalIndex)
        )
        {
            fail
            (
                "time index " + std::to_string(step) + ", global index "
              + std::to_string(index) + " after "
              + std::to_string(timeIndex) + ", "
              + std::to_string(globalIndex) + "; a rank writes its rows in"
                " (time index, global index) order"
            );
            return;
        }
        timeIndex = step;
        globalIndex = index;
        row = text.substr(end2 + 1);
    }

    //- What is wrong with the file, empty if nothing
    std::string problem;

private:

    void fail(const std::string& what)
    {
        problem =
            std::string(file_) + " line " + std::to_string(line_) + ": "
          + what;
        done = true;
    }
};


//- The processor<r> folders of the case, by r
fileNameList processorDirs(const fileName& root)
{
    std::vector<std::pair<label, fileName>> found;
    for (const fileName& d : readDir(root, fileName::DIRECTORY))
    {
        const std::string s(d);
        if (s.compare(0, 9, "processor") != 0 || s.size() == 9)
        {
            continue;
        }
        const std::string digits(s.substr(9));
        if (digits.find_first_not_of("0123456789") == std::string::npos)
        {
            found.emplace_back(std::stol(digits), d);
        }
    }
    std::sort(found.begin(), found.end());
    fileNameList dirs(label(found.size()));
    forAll(dirs, i)
    {
        dirs[i] = found[i].second;
    }
    return dirs;
}


//- Merge the ranks' files of one start time into file; returns the steps
//- and the particles of each
Pair<label> merge(const fileNameList& rankFiles, const fileName& file)
{
    std::vector<std::unique_ptr<rankSeries>> ranks;
    std::string problem;
    for (const fileName& f : rankFiles)
    {
        ranks.emplace_back(new rankSeries(f));
        if (problem.empty())
        {
            problem = ranks.back()->problem;
        }
    }
    const std::string header =
        "# " + ranks.front()->header.substr(rankLead.size());

    // The next row of the merged file: the least (time index, global
    // index) over the ranks
    using key = std::tuple<label, label, label>;
    std::priority_queue<key, std::vector<key>, std::greater<key>> heads;
    for (std::size_t r = 0; r < ranks.size(); ++r)
    {
        if (!ranks[r]->done)
        {
            heads.emplace(ranks[r]->timeIndex, ranks[r]->globalIndex, label(r));
        }
    }

    const fileName tmp(file + ".tmp");
    std::ofstream os(tmp);
    os  << header << '\n';
    label nSteps = 0, nParticles = -1, step = -1, expected = 0;
    const auto stepEnds = [&]()
    {
        if (step < 0)
        {
            return;
        }
        if (nParticles < 0)
        {
            nParticles = expected;
        }
        else if (expected != nParticles)
        {
            problem =
                "time index " + std::to_string(step) + " has "
              + std::to_string(expected) + " particles, the first step "
              + std::to_string(nParticles) + " (a rank's file ends early,"
                " or a particle is missing)";
        }
        ++nSteps;
    };
    while (!heads.empty() && problem.empty())
    {
        const label r = std::get<2>(heads.top());
        heads.pop();
        rankSeries& s = *ranks[r];
        if (s.timeIndex != step)
        {
            stepEnds();
            step = s.timeIndex;
            expected = 0;
        }
        if (s.globalIndex != expected)
        {
            problem =
                std::string(s.file()) + " line " + std::to_string(s.line())
              + ": time index " + std::to_string(step) + ", global index "
              + std::to_string(s.globalIndex) + " where "
              + std::to_string(expected) + " comes next ("
              + (s.globalIndex < expected ? "twice" : "a gap") + ")";
            break;
        }
        os  << s.row << '\n';
        ++expected;
        s.next();
        if (!s.problem.empty())
        {
            problem = s.problem;
        }
        else if (!s.done)
        {
            heads.emplace(s.timeIndex, s.globalIndex, r);
        }
    }
    if (problem.empty())
    {
        stepEnds();
    }
    os.close();
    if (!problem.empty() || !os)
    {
        rm(tmp);
        FatalErrorInFunction
            << "merging into " << file << ": "
            << (problem.empty() ? "cannot write" : problem.c_str())
            << "; nothing written" << exit(FatalError);
    }
    if (!mv(tmp, file))
    {
        rm(tmp);
        FatalErrorInFunction
            << "cannot rename " << tmp << " to " << file << exit(FatalError);
    }
    return Pair<label>(nSteps, nParticles);
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Merge the particle series that dlmfdFoam writes per rank with"
        " particleDistribution owned into postProcessing/dlmfdParticles"
    );
    argList::noParallel();
    argList::noFunctionObjects();

    #include "setRootCase.H"

    const fileName root(args.path());
    const fileNameList procs(processorDirs(root));
    const fileName series("postProcessing/dlmfdParticles");

    // The start times that some rank wrote a series for
    wordList times;
    for (const fileName& p : procs)
    {
        for (const fileName& t : readDir(root/p/series, fileName::DIRECTORY))
        {
            if (!times.found(t))
            {
                times.append(t);
            }
        }
    }
    if (times.empty())
    {
        FatalErrorInFunction
            << "no " << series.c_str() << "/<time>/particles.dat in the "
            << procs.size() << " processor folders of " << root
            << "; dlmfdFoam writes them with particleDistribution owned"
            << " (constant/collisionProperties) on several ranks"
            << exit(FatalError);
    }
    Foam::sort(times);

    for (const word& t : times)
    {
        fileNameList files;
        for (const fileName& p : procs)
        {
            const fileName f(root/p/series/t/"particles.dat");
            if (isFile(f))
            {
                files.append(f);
            }
        }
        mkDir(root/series/t);
        const fileName out(root/series/t/"particles.dat");
        const Pair<label> n = merge(files, out);
        Info<< (series/t/"particles.dat").c_str() << ": " << n.first() << " steps of "
            << n.second() << " particles from " << files.size()
            << " ranks" << endl;
    }

    Info<< "End" << endl;
    return 0;
}


// ************************************************************************* //

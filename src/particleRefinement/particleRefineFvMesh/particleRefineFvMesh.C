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

#include "particleRefineFvMesh.H"
#include "particleRefinementTargets.H"
#include "addToRunTimeSelectionTable.H"
#include "knownKeywords.H"
#include "volFields.H"
#include "mapPolyMesh.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(particleRefineFvMesh, 0);
    addToRunTimeSelectionTable(dynamicFvMesh, particleRefineFvMesh, IOobject);
}


// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * * //

namespace
{

// The periodic shifts of a body: 0 and +-period along each periodic
// direction
Foam::List<Foam::vector> periodicShifts(const Foam::vector& period)
{
    using namespace Foam;
    List<vector> shifts(1, Zero);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (period[d] > 0)
        {
            const label n = shifts.size();
            shifts.setSize(3*n);
            for (label i = 0; i < n; ++i)
            {
                shifts[n + i] = shifts[i];
                shifts[n + i][d] += period[d];
                shifts[2*n + i] = shifts[i];
                shifts[2*n + i][d] -= period[d];
            }
        }
    }
    return shifts;
}

} // End anonymous namespace



// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::particleRefineFvMesh::keywords()
{
    return wordList
    ({
        "dynamicFvMesh", "dynamicFvMeshLibs", "maxRefinement",
        "refineInterval", "shellWidth", "wakeLength", "wakeRadius",
        "bufferLayers", "unrefineMargin", "maxCells", "correctFluxes",
        "dumpLevel"
    });
}


void Foam::particleRefineFvMesh::readCoefficients()
{
    const IOdictionary dict
    (
        IOobject
        (
            "dynamicMeshDict",
            time().constant(),
            *this,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const fileName file(time().globalPath()/time().constant()/"dynamicMeshDict");
    knownKeywords::require(dict, keywords(), word::null, file);

    // A value out of its range stops with the file, keyword, value and
    // what is allowed
    auto check = [&](const word& key, const scalar value, const bool ok,
                     const char* allowed)
    {
        if (!ok)
        {
            FatalIOErrorInFunction(dict)
                << file << ": " << key << " " << value << " is not allowed: "
                << allowed << exit(FatalIOError);
        }
    };
    maxLevel_ = dict.get<label>("maxRefinement");
    check("maxRefinement", maxLevel_, maxLevel_ >= 1, "an integer >= 1");
    refineInterval_ = dict.getOrDefault<label>("refineInterval", 1);
    check
    (
        "refineInterval", refineInterval_, refineInterval_ >= 1,
        "an integer >= 1 (time steps)"
    );
    shellWidth_ = dict.getOrDefault<scalar>("shellWidth", 0.5);
    check("shellWidth", shellWidth_, shellWidth_ >= 0, ">= 0");
    wakeLength_ = dict.getOrDefault<scalar>("wakeLength", 4);
    check("wakeLength", wakeLength_, wakeLength_ >= 0, ">= 0");
    wakeRadius_ = dict.getOrDefault<scalar>("wakeRadius", 0.75);
    check("wakeRadius", wakeRadius_, wakeRadius_ >= 0, ">= 0");
    bufferLayers_ = dict.getOrDefault<label>("bufferLayers", 4);
    check("bufferLayers", bufferLayers_, bufferLayers_ >= 1, "an integer >= 1");
    unrefineMargin_ = dict.getOrDefault<scalar>("unrefineMargin", 0.5);
    check("unrefineMargin", unrefineMargin_, unrefineMargin_ >= 0, ">= 0");
    maxCells_ = dict.getOrDefault<label>("maxCells", labelMax/2);
    check("maxCells", maxCells_, maxCells_ > 0, "an integer > 0");
}


Foam::scalarList Foam::particleRefineFvMesh::levelReach() const
{
    // In units of the base cell h0: bufferLayers of its own cells (level
    // L - j: h0/2^(L - j)) added to the finer ones'
    scalarList reach(maxLevel_ + 1, scalar(0));
    for (label j = 1; j <= maxLevel_; ++j)
    {
        reach[j] = reach[j - 1] + bufferLayers_*std::pow(2.0, j - maxLevel_);
    }
    return reach;
}


const Foam::particleRefinementTargets&
Foam::particleRefineFvMesh::targets() const
{
    const particleRefinementTargets* bodies =
        findObject<particleRefinementTargets>
        (
            particleRefinementTargets::typeName
        );
    if (!bodies || !bodies->valid())
    {
        FatalErrorInFunction
            << "constant/dynamicMeshDict: dynamicFvMesh " << typeName
            << " refines around the particles dlmfdFoam gives it; this run"
            << " gave none (a case without constant/dlmfdProperties, or"
            << " another solver): use dynamicRefineFvMesh or staticFvMesh"
            << exit(FatalError);
    }
    return *bodies;
}


Foam::labelList Foam::particleRefineFvMesh::targetLevels
(
    const particleRefinementTargets& bodies,
    const scalar margin
) const
{
    const labelList& level = meshCutter().cellLevel();
    const pointField& C = cellCentres();
    const scalarField& V = cellVolumes();
    labelList target(nCells(), 0);

    const scalarList reach(levelReach());

    // Each cell's base-mesh size, once for all bodies and images
    scalarField h0(nCells());
    forAll(h0, c)
    {
        h0[c] = std::cbrt(V[c])*std::pow(2.0, level[c]);
    }

    const List<vector> shifts(periodicShifts(bodies.period()));
    const scalar travelSteps = 2*refineInterval_*bodies.deltaT();

    forAll(bodies.centres(), b)
    {
        const scalar R = bodies.radii()[b];
        const scalar Db = 2*R;
        const vector& Vb = bodies.velocities()[b];
        const vector W = Vb - bodies.fluidVelocity();
        const scalar magW = mag(W);
        // Behind the body, along its velocity relative to the fluid
        const vector w = magW > SMALL ? -W/magW : vector::zero;
        const scalar shell =
            R + (shellWidth_ + margin)*Db + mag(Vb)*travelSteps;
        const scalar wakeL =
            magW > SMALL && wakeLength_ > 0 ? R + (wakeLength_ + margin)*Db : 0;
        const scalar wakeR = (wakeRadius_ + margin)*Db;

        for (const vector& s : shifts)
        {
            const point X = bodies.centres()[b] + s;
            forAll(C, c)
            {
                // Beyond this along any axis no level is refined
                const scalar outer =
                    max(shell, wakeL + wakeR) + reach[maxLevel_]*h0[c];
                const vector r = C[c] - X;
                if
                (
                    mag(r.x()) > outer || mag(r.y()) > outer
                 || mag(r.z()) > outer
                )
                {
                    continue;
                }
                scalar dist = max(scalar(0), mag(r) - shell);
                if (wakeL > 0)
                {
                    const scalar along = r & w;
                    const scalar across = mag(r - along*w);
                    const scalar ds =
                        along < 0 ? -along : max(scalar(0), along - wakeL);
                    const scalar dr = max(scalar(0), across - wakeR);
                    dist = min(dist, std::sqrt(sqr(ds) + sqr(dr)));
                }
                const scalar inCells = dist/h0[c];
                for (label j = 0; j <= maxLevel_; ++j)
                {
                    if (inCells <= reach[j])
                    {
                        target[c] = max(target[c], maxLevel_ - j);
                        break;
                    }
                }
            }
        }
    }
    return target;
}


Foam::bitSet Foam::particleRefineFvMesh::bodyCells() const
{
    bitSet cells(nCells());
    const volScalarField* owner =
        findObject<volScalarField>("ghostOwner");
    const volVectorField* source =
        findObject<volVectorField>("lambdaSource");
    forAll(cells, c)
    {
        if
        (
            (owner && (*owner)[c] >= 0)
         || (source && magSqr((*source)[c]) > 0)
        )
        {
            cells.set(c);
        }
    }
    return cells;
}


bool Foam::particleRefineFvMesh::refineTowardsTargets(const bool protect)
{
    const labelList target(targetLevels(targets(), 0));
    const labelList& level = meshCutter().cellLevel();

    bitSet candidate(nCells());
    const bitSet inBody(protect ? bodyCells() : bitSet(nCells()));
    label nLeft = 0;
    forAll(target, c)
    {
        if (target[c] > level[c])
        {
            if (inBody.test(c))
            {
                ++nLeft;
            }
            else
            {
                candidate.set(c);
            }
        }
    }
    nLeft = returnReduce(nLeft, sumOp<label>());
    if (nLeft)
    {
        Info<< typeName << ": " << nLeft << " cells of a body below the"
            << " finest level left as they are (a body reached cells the"
            << " look-ahead had not refined: raise shellWidth or lower"
            << " refineInterval)" << endl;
    }

    if (globalData().nTotalCells() >= maxCells_)
    {
        return false;
    }

    // The bodies' cells, protected for the 2:1 cascade too
    const bitSet keptProtection(protectedCell_);
    if (protect)
    {
        protectedCell_.resize(nCells());
        protectedCell_ |= inBody;
    }
    const labelList cells(selectRefineCells(maxCells_, maxLevel_, candidate));
    protectedCell_ = keptProtection;

    if (returnReduce(cells.size(), sumOp<label>()) == 0)
    {
        return false;
    }
    refine(cells);
    return true;
}


bool Foam::particleRefineFvMesh::unrefineAwayFromTargets(const bitSet& keep)
{
    // Cells whose level the hysteresis band's target keeps
    const labelList target(targetLevels(targets(), unrefineMargin_));
    const labelList& level = meshCutter().cellLevel();
    bitSet marked(keep);
    marked.resize(nCells());
    forAll(target, c)
    {
        if (target[c] >= level[c])
        {
            marked.set(c);
        }
    }

    const bitSet keptProtection(protectedCell_);
    protectedCell_.resize(nCells());
    protectedCell_ |= bodyCells();
    // Every split point is a candidate (below the level 1): the marked
    // cells and the protected ones hold theirs
    const labelList points
    (
        selectUnrefinePoints(1, marked, scalarField(nPoints(), 0))
    );
    protectedCell_ = keptProtection;

    if (returnReduce(points.size(), sumOp<label>()) == 0)
    {
        return false;
    }

    // (the mapping gives a merged cell its cells' volume-weighted mean:
    // momentum is kept; the links' per-cell momentum, which is not a
    // density, sits in cells bodyCells() protects)
    unrefine(points);
    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleRefineFvMesh::particleRefineFvMesh(const IOobject& io)
:
    dynamicRefineFvMesh(io),
    maxLevel_(1),
    refineInterval_(1),
    shellWidth_(0.5),
    wakeLength_(4),
    wakeRadius_(0.75),
    unrefineMargin_(0.5),
    bufferLayers_(4),
    maxCells_(labelMax/2),
    started_(false),
    largestBaseCell_(0)
{
    readCoefficients();
    {
        const labelList& level = meshCutter().cellLevel();
        const scalarField& V = cellVolumes();
        forAll(V, c)
        {
            largestBaseCell_ = max
            (
                largestBaseCell_, std::cbrt(V[c])*std::pow(2.0, level[c])
            );
        }
        reduce(largestBaseCell_, maxOp<scalar>());
    }

    // A mesh refined already (a restart) has had its initial refinement:
    // its first update is any other's, so that the restart is exact
    label finest = 0;
    for (const label l : meshCutter().cellLevel())
    {
        finest = max(finest, l);
    }
    started_ = returnReduce(finest, maxOp<label>()) > 0;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::particleRefineFvMesh::update()
{
    bool changed = false;
    if (!started_)
    {
        // The initial refinement: the bodies start in cells of the
        // finest level (nothing to do on a restart, whose mesh is refined)
        for (label pass = 0; pass < maxLevel_; ++pass)
        {
            if (!refineTowardsTargets(false))
            {
                break;
            }
            changed = true;
        }
        started_ = true;
    }
    else if (time().timeIndex() % refineInterval_ == 0)
    {
        if (refineTowardsTargets(true))
        {
            changed = true;
        }
        if (unrefineAwayFromTargets(bitSet(nCells())))
        {
            changed = true;
        }
        ++nRefinementIterations_;
        if ((nRefinementIterations_ % 10) == 0)
        {
            // Unrefinement leaves holes in the refinement history
            const_cast<refinementHistory&>(meshCutter().history()).compact();
        }
    }

    topoChanging(changed);
    if (changed)
    {
        moving(false);
    }
    return changed;
}


Foam::scalar Foam::particleRefineFvMesh::bodyReach
(
    const scalar R,
    const scalar speed,
    const scalar deltaT
) const
{
    // targetLevels' shell and wake with the larger of its two margins
    // (unrefinement's), and the coarser levels around them
    const scalar Db = 2*R;
    const scalar margin = unrefineMargin_;
    const scalar shell =
        R + (shellWidth_ + margin)*Db + speed*2*refineInterval_*deltaT;
    const scalar wake =
        wakeLength_ > 0
      ? R + (wakeLength_ + margin)*Db + (wakeRadius_ + margin)*Db
      : 0;
    return max(shell, wake) + levelReach()[maxLevel_]*largestBaseCell_;
}


// ************************************************************************* //

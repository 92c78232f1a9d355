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

#include "fictitiousDomain.H"
#include "OStringStream.H"
#include "bodyExchange.H"
#include "fvmDdt.H"
#include "hexCellCheck.H"
#include "fictitiousDomainParts.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The treatment the dictionary selects, a retired option refused first
// (with what replaced it, rather than as an unknown model)
Foam::autoPtr<Foam::surfaceTreatment> selectTreatment
(
    const Foam::fvMesh& mesh,
    const Foam::dictionary& dict
)
{
    Foam::fictitiousDomain::refuseRetired(dict, dict.name());
    return Foam::surfaceTreatment::New(mesh, dict);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fictitiousDomain::reach() const
{
    return treatment_->reach();
}


Foam::scalar Foam::fictitiousDomain::cellSize(const scalar V) const
{
    // In 2D the cells are one layer deep: the in-plane size
    if (twoD_)
    {
        return std::sqrt(V/mesh_.bounds().span().z());
    }
    return std::cbrt(V);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fictitiousDomain::fictitiousDomain
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    treatment_(selectTreatment(mesh, dict)),
    search_(mesh),
    twoD_(mesh.nSolutionD() == 2),
    images_(search_, mesh.bounds()),
    owners_(mesh.nCells()),
    source_
    (
        IOobject
        (
            "lambdaSource",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimAcceleration, Zero)
    ),
    deviation_
    (
        IOobject
        (
            "ghostDeviation",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    ),
    ghostOwner_
    (
        IOobject
        (
            "ghostOwner",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("none", dimless, -1)
    ),
    mirror_
    (
        IOobject
        (
            "ghostMirror",
            mesh.time().timeName(),
            mesh,
            treatment_->mirrorsWallVelocity()
          ? IOobject::READ_IF_PRESENT : IOobject::NO_READ,
            treatment_->mirrorsWallVelocity()
          ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    ),
    stepStart_(),
    owed_(),
    results_(),
    traffic_(),
    perRank_()
{
    // Before anything is solved or written: a mesh the coupling is not
    // validated on stops here, not by diverging later
    hexCellCheck::require(mesh, "DLM/FD");
    if (twoD_ && mesh.geometricD()[2] > 0)
    {
        FatalErrorInFunction
            << "a 2D mesh must have its empty direction along z (the"
            << " planar particles move in the x-y plane); its solution"
            << " directions are " << mesh.solutionD() << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::fictitiousDomain::keywords() const
{
    wordList known({"surfaceTreatment"});
    known.append(treatment_->keywords());
    return known;
}


Foam::List<Foam::fictitiousDomainRetired>
Foam::fictitiousDomain::retiredKeywords()
{
    // The ghost cells with the wall links are more accurate on every row
    // of the validation table where these options ran beside them
    // (CHANGELOG.md, benchmarks/validationTable/removedOptions.md)
    const string ghost
    (
        "remove the entry: the ghost cells (surfaceTreatment ghostCells, the"
        " only treatment) hold the surface"
    );
    const string noCutCells
    (
        "remove the entry: no fluid cell is forced; the wall's shear reaches"
        " the cut cells through ghostShear link (the default) or viscous"
    );
    const string noPenalty
    (
        "remove the entry: the fluid step carries the last multipliers'"
        " force (the only fluid-step force)"
    );
    return List<fictitiousDomainRetired>
    ({
        {"surfaceTreatment", "fluidStencil", ghost},
        {"surfacePoints", "", ghost},
        {"surfacePointSpacing", "", ghost},
        {"surfaceStencilRadius", "", ghost},
        {"surfacePointRetraction", "", ghost},
        {"tolerance", "", ghost + " with one direct solve per body (no CG)"},
        {"maxIterations", "", ghost + " with one direct solve per body (no CG)"},
        {"ghostCutCells", "", noCutCells},
        {"fluidStepForce", "", noPenalty},
        {"penaltyFactor", "", noPenalty}
    });
}


void Foam::fictitiousDomain::refuseRetired
(
    const dictionary& dict,
    const fileName& file
)
{
    for (const fictitiousDomainRetired& r : retiredKeywords())
    {
        const entry* e = dict.findEntry(r.keyword, keyType::LITERAL);
        if (!e)
        {
            continue;
        }
        // The value as written (a word for every retired one)
        string value;
        if (e->isStream())
        {
            OStringStream os;
            const ITstream& is = e->stream();
            forAll(is, i)
            {
                os  << (i ? " " : "") << is[i];
            }
            value = os.str();
        }
        if (!r.value.empty() && value != r.value)
        {
            continue;
        }
        const std::string written(value.empty() ? "" : " " + value);
        FatalIOErrorInFunction(dict)
            << file << ": fictitiousDomain/" << r.keyword
            << written.c_str()
            << " is no longer read (retired with the options it served); "
            << r.replacement.c_str() << exit(FatalIOError);
    }
}


Foam::string Foam::fictitiousDomain::describe() const
{
    return treatment_->describe();
}


void Foam::fictitiousDomain::discardStoredState(const fileName& particleFile)
{
    const bool stored =
        gMax(mag(source_.primitiveField())) > 0
     || gMax(mag(deviation_.primitiveField())) > 0;
    if (stored)
    {
        Info<< "DLM/FD: " << source_.name() << " and " << deviation_.name()
            << " of time " << mesh_.time().timeName() << " set to zero:"
            << " the particles come from " << particleFile
            << ", not from the solver's uniform/particles of that time"
            << endl;
    }
    source_ == dimensionedVector(source_.dimensions(), Zero);
    deviation_ == dimensionedVector(deviation_.dimensions(), Zero);
    ghostOwner_ == dimensionedScalar("none", dimless, -1);
    mirror_ == dimensionedVector(mirror_.dimensions(), Zero);
}


void Foam::fictitiousDomain::updateMesh()
{
    search_.rebuild();
    owners_ = cellOwnership(mesh_.nCells());
    if (perRank_.on)
    {
        updateHolders();
    }

    // The step's per-cell state is made again by the next step
    stepStart_.index = -1;
    stepStart_.source.clear();
    stepStart_.ddtCoeff.clear();
    stepStart_.deviation.clear();
    stepStart_.owner.clear();

    // A refined cell takes its parent's owner; cells merged into one take
    // one of theirs or a mean, which is no body's index when they held
    // different ones: the refinement must keep the bodies' cells at one
    // level
    // (a mean of equal owners may differ from them by round-off: such an
    // owner is set back to the index)
    forAll(ghostOwner_, c)
    {
        const scalar o = ghostOwner_[c];
        const scalar index = std::round(o);
        if (mag(o - index) > 1e-9 || index < -1)
        {
            FatalErrorInFunction
                << "cell " << c << " at " << mesh_.C()[c]
                << " holds a ghost cell's owner " << o
                << " after the mesh changed: cells of different bodies (or"
                << " of a body and the fluid) were merged. The refinement"
                << " (constant/dynamicMeshDict) must not merge or refine the"
                << " cells of a body's surface layer"
                << exit(FatalError);
        }
        ghostOwner_[c] = index;
    }

    // The mapping leaves the boundary values as mapped: those of the
    // processor and cyclic patches (the neighbours' owners and forces the
    // links and the exchange read) evaluated again
    source_.correctBoundaryConditions();
    deviation_.correctBoundaryConditions();
    ghostOwner_.correctBoundaryConditions();
    mirror_.correctBoundaryConditions();
}


void Foam::fictitiousDomain::keepStepStart(const volVectorField& U)
{
    stepStart_.index = mesh_.time().timeIndex();
    stepStart_.source = source_.primitiveField();
    stepStart_.ddtCoeff =
        mesh_.time().deltaTValue()*fvm::ddt(U)().A()().primitiveField();
    stepStart_.deviation = deviation_.primitiveField();
    stepStart_.owner = ghostOwner_.primitiveField();
}


void Foam::fictitiousDomain::addOwed
(
    const UList<body>& bodies,
    const UList<vector>& momentum,
    const UList<vector>& moment
)
{
    if (momentum.size() != bodies.size() || moment.size() != bodies.size())
    {
        FatalErrorInFunction
            << "momentum for " << momentum.size() << " and moment for "
            << moment.size() << " bodies given for a list of "
            << bodies.size() << exit(FatalError);
    }
    forAll(momentum, b)
    {
        // (from zero: 0 + x is x)
        const label g = bodyPlaces::global(bodies, b);
        owed_.momentum.insert(g, Zero);
        owed_.moment.insert(g, Zero);
        owed_.momentum[g] += momentum[b];
        owed_.moment[g] += moment[b];
    }
}


void Foam::fictitiousDomain::rewindToStepStart()
{
    if (stepStart_.index != mesh_.time().timeIndex())
    {
        FatalErrorInFunction
            << "no state kept for time index " << mesh_.time().timeIndex()
            << ": keepStepStart() must come first in the step"
            << exit(FatalError);
    }
    deviation_.primitiveFieldRef() = stepStart_.deviation;
    ghostOwner_.primitiveFieldRef() = stepStart_.owner;
    deviation_.correctBoundaryConditions();
    ghostOwner_.correctBoundaryConditions();
}


void Foam::fictitiousDomain::localCellSums
(
    const UList<body>& bodies,
    scalarField& sumV,
    scalarField& count
) const
{
    // The volumes of the cells within each body's bounding radius
    const scalarField& V = mesh_.V();
    sumV.setSize(bodies.size());
    count.setSize(bodies.size());
    sumV = Zero;
    count = Zero;
    DynamicList<label> near;
    forAll(bodies, b)
    {
        const body& B = bodies[b];
        const scalar rb = B.shape->boundingRadius();
        const List<vector> shifts(images_.shifts(B.centre, rb));
        for (const vector& s : shifts)
        {
            near.clear();
            search_.cellsInBall(B.centre - s, rb, near);
            for (const label c : near)
            {
                sumV[b] += V[c];
            }
            count[b] += near.size();
        }
    }
}


Foam::scalarList Foam::fictitiousDomain::cellSizes
(
    const UList<body>& bodies,
    const scalarField& sumV,
    const scalarField& count
) const
{
    scalarList h(bodies.size());
    forAll(bodies, b)
    {
        const label particle = bodyPlaces::global(bodies, b);
        if (count[b] == 0)
        {
            FatalErrorInFunction
                << "particle " << particle << " at " << bodies[b].centre
                << " has no cell centre of the mesh within its bounding"
                << " radius " << bodies[b].shape->boundingRadius() << " m: it"
                << " is outside the mesh, or smaller than a cell"
                << exit(FatalError);
        }
        h[b] = cellSize(sumV[b]/count[b]);

        // A body must not meet itself across a period
        images_.checkClearance
        (
            particle, bodies[b].shape->boundingRadius() + this->reach()*h[b]
        );
    }
    return h;
}


void Foam::fictitiousDomain::startCandidates
(
    const UList<body>& bodies,
    candidates& cand
)
{
    // The claims of the last step are undone
    owners_.reset();

    const label n = bodies.size();
    scalarField sumV, count;
    localCellSums(bodies, sumV, count);
    if (perRank_.on)
    {
        shareAmongHolders
        (
            bodies, sumV, count, cand.solver, cand.masterHolds
        );
    }
    else
    {
        labelList nHere(n);
        forAll(count, b)
        {
            nHere[b] = label(count[b]);
        }
        // One reduction for both sums (element by element, in the same
        // order as two would)
        scalarField both(2*n);
        SubField<scalar>(both, n) = sumV;
        SubField<scalar>(both, n, n) = count;
        clockTime clock;
        reduce(both, sumOp<scalarField>());
        traffic_.commSeconds += clock.elapsedTime();
        sumV = SubField<scalar>(both, n);
        count = SubField<scalar>(both, n, n);
        cand.solver = bodyExchange::solvingRanks(nHere, traffic_.commSeconds);
    }
    cand.h = cellSizes(bodies, sumV, count);
    cand.shifts.setSize(n);
    cand.interior.setSize(n);
    cand.interiorShift.setSize(n);
    cand.near.setSize(n);
    cand.nearShift.setSize(n);
}


// ************************************************************************* //

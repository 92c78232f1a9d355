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
#include "linear.H"
#include "hexCellCheck.H"
#include "particleGeometry.H"
#include "Switch.H"
#include "smallDenseSolve.H"
#include "fictitiousDomainParts.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::fictitiousDomain::ghostShearModel>
Foam::fictitiousDomain::ghostShearModelNames
({
    {ghostShearModel::viscous, "viscous"},
    {ghostShearModel::link, "link"},
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fictitiousDomain::reach() const
{
    // The fits' largest radius about a surface point (with ghostShear
    // link, whose cells move rigidly, the holders' reach and the
    // clearance across a period keep this margin: the wall links reach
    // no further)
    return ghostFitRadius_;
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
    ghostFitRadius_(dict.getOrDefault<scalar>("ghostFitRadius", 1.5)),
    ghostShear_
    (
        ghostShearModelNames.getOrDefault
        (
            "ghostShear", dict, ghostShearModel::link
        )
    ),
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
            hasWallShearSource()
          ? IOobject::READ_IF_PRESENT : IOobject::NO_READ,
            hasWallShearSource() ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    ),
    stepStartSource_(),
    stepDdtCoeff_(),
    stepStartDeviation_(),
    stepStartOwner_(),
    stepStartIndex_(-1),
    results_(),
    commSeconds_(0),
    received_(),
    nSolves_(0),
    perRank_(false),
    holders_(),
    largestCellSize_(0),
    exchange_(),
    ownerBoxes_(),
    largestRadius_(0),
    holderPartners_()
{
    // A keyword of a retired option would be ignored in silence: refused
    // with what replaced it
    refuseRetired(dict, dict.name());

    // Before anything is solved or written: a mesh the coupling is not
    // validated on stops here, not by diverging later
    hexCellCheck::require(mesh, "DLM/FD");
    if (!(ghostFitRadius_ >= 1.5))
    {
        FatalIOErrorInFunction(dict)
            << "ghostFitRadius = " << ghostFitRadius_ << " is not"
            << " allowed; it must be >= 1.5 (in cell sizes)"
            << exit(FatalIOError);
    }
    // The default ghost cells move rigidly: nothing is fitted, so a fit
    // radius would be ignored
    if
    (
        ghostShear_ == ghostShearModel::link
     && dict.found("ghostFitRadius", keyType::LITERAL)
    )
    {
        FatalIOErrorInFunction(dict)
            << "fictitiousDomain/ghostFitRadius is read with ghostShear"
            << " viscous only; this dictionary selects ghostShear link,"
            << " which fits nothing. Remove the entry or select ghostShear"
            << " viscous" << exit(FatalIOError);
    }
    if (twoD_ && mesh.geometricD()[2] > 0)
    {
        FatalErrorInFunction
            << "a 2D mesh must have its empty direction along z (the"
            << " planar particles move in the x-y plane); its solution"
            << " directions are " << mesh.solutionD() << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::fictitiousDomain::keywords()
{
    return wordList({"surfaceTreatment", "ghostShear", "ghostFitRadius"});
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
    // The one treatment by name: a misspelt one lists it
    const word treatment
    (
        dict.getOrDefault<word>("surfaceTreatment", "ghostCells")
    );
    if (treatment != "ghostCells")
    {
        FatalIOErrorInFunction(dict)
            << file << ": fictitiousDomain/surfaceTreatment " << treatment
            << " is not a surface treatment; valid: 1 ( ghostCells )"
            << exit(FatalIOError);
    }
}


Foam::string Foam::fictitiousDomain::describe() const
{
    OStringStream os;
    os  << "surfaceTreatment ghostCells, ghostShear "
        << ghostShearModelNames[ghostShear_];
    if (ghostShear_ == ghostShearModel::viscous)
    {
        os  << ", ghostFitRadius " << ghostFitRadius_;
    }
    return os.str();
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


Foam::tmp<Foam::volVectorField> Foam::fictitiousDomain::wallShearSource
(
    const volScalarField& nu
) const
{
    tmp<volVectorField> tsrc
    (
        new volVectorField
        (
            IOobject("wallShearSource", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedVector(dimAcceleration, Zero)
        )
    );
    vectorField& src = tsrc.ref().primitiveFieldRef();
    const scalarField& V = mesh_.V();
    const surfaceScalarField nuf(linearInterpolate(nu));
    const surfaceScalarField& dc = mesh_.deltaCoeffs();
    const surfaceScalarField& magSf = mesh_.magSf();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& body = ghostOwner_.primitiveField();
    const vectorField& t = mirror_.primitiveField();

    // A face between a body's cell g (t_g) and a fluid cell c: the flux
    // nu |S_f| t_g/|d_f| into c, out of g
    forAll(nei, f)
    {
        const label o = own[f], n = nei[f];
        const bool oBody = body[o] >= 0, nBody = body[n] >= 0;
        if (oBody == nBody)
        {
            continue;
        }
        const label g = oBody ? o : n, c = oBody ? n : o;
        const vector F = nuf[f]*magSf[f]*dc[f]*t[g];
        src[c] += F/V[c];
        src[g] -= F/V[g];
    }

    // Across processor and periodic patches each side takes its own cell's
    // share, with the neighbour's values of the other side
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled())
        {
            continue;
        }
        const labelUList& fc = p.faceCells();
        const scalarField bodyNbr
        (
            ghostOwner_.boundaryField()[patchi].patchNeighbourField()
        );
        const vectorField tNbr
        (
            mirror_.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField& nup = nuf.boundaryField()[patchi];
        const scalarField& dcp = dc.boundaryField()[patchi];
        const scalarField& magSp = magSf.boundaryField()[patchi];
        forAll(fc, i)
        {
            const label l = fc[i];
            const bool lBody = body[l] >= 0, nBody = bodyNbr[i] >= 0;
            if (lBody == nBody)
            {
                continue;
            }
            const scalar coeff = nup[i]*magSp[i]*dcp[i]/V[l];
            if (lBody)
            {
                src[l] -= coeff*t[l];
            }
            else
            {
                src[l] += coeff*tNbr[i];
            }
        }
    }
    tsrc.ref().correctBoundaryConditions();
    return tsrc;
}


void Foam::fictitiousDomain::updateMesh()
{
    search_.rebuild();
    owners_ = cellOwnership(mesh_.nCells());
    if (perRank_)
    {
        updateHolders();
    }

    // The step's per-cell state is made again by the next step
    stepStartIndex_ = -1;
    stepStartSource_.clear();
    stepDdtCoeff_.clear();
    stepStartDeviation_.clear();
    stepStartOwner_.clear();

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
    stepStartIndex_ = mesh_.time().timeIndex();
    stepStartSource_ = source_.primitiveField();
    stepDdtCoeff_ =
        mesh_.time().deltaTValue()*fvm::ddt(U)().A()().primitiveField();
    stepStartDeviation_ = deviation_.primitiveField();
    stepStartOwner_ = ghostOwner_.primitiveField();
}


void Foam::fictitiousDomain::addReleased
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
        pendingMomentum_.insert(g, Zero);
        pendingMoment_.insert(g, Zero);
        pendingMomentum_[g] += momentum[b];
        pendingMoment_[g] += moment[b];
    }
}


void Foam::fictitiousDomain::rewindToStepStart()
{
    if (stepStartIndex_ != mesh_.time().timeIndex())
    {
        FatalErrorInFunction
            << "no state kept for time index " << mesh_.time().timeIndex()
            << ": keepStepStart() must come first in the step"
            << exit(FatalError);
    }
    deviation_.primitiveFieldRef() = stepStartDeviation_;
    ghostOwner_.primitiveFieldRef() = stepStartOwner_;
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
    if (perRank_)
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
        commSeconds_ += clock.elapsedTime();
        sumV = SubField<scalar>(both, n);
        count = SubField<scalar>(both, n, n);
        cand.solver = bodyExchange::solvingRanks(nHere, commSeconds_);
    }
    cand.h = cellSizes(bodies, sumV, count);
    cand.shifts.setSize(n);
    cand.interior.setSize(n);
    cand.interiorShift.setSize(n);
    cand.near.setSize(n);
    cand.nearShift.setSize(n);
}


// ************************************************************************* //

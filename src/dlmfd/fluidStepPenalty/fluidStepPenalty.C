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

#include "fluidStepPenalty.H"
#include "posedShape.H"
#include "periodicImages.H"
#include "fvmSup.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidStepPenalty::fluidStepPenalty
(
    const fvMesh& mesh,
    const dictionary& dict,
    const fictitiousDomain::surfaceTreatment treatment,
    const cellCentreSearch& search
)
:
    mesh_(mesh),
    on_(false),
    factor_(dict.getOrDefault<scalar>("penaltyFactor", 100)),
    search_(search),
    holder_(),
    arm_(),
    target_(),
    rate_(0),
    ddtCoeff_(1)
{
    const fileName file
    (
        mesh.time().globalPath()/mesh.time().constant()/"dlmfdProperties"
    );
    const word force = dict.getOrDefault<word>("fluidStepForce", "multipliers");
    if (force != "multipliers" && force != "penalty")
    {
        FatalIOErrorInFunction(dict)
            << file << ": fictitiousDomain/fluidStepForce " << force
            << " is not allowed; valid: 2" << nl << "(" << nl
            << "multipliers" << nl << "penalty" << nl << ")" << nl
            << "(multipliers: the last step's multiplier force, explicit;"
            << " penalty: an implicit penalty towards the bodies' predicted"
            << " motion)" << exit(FatalIOError);
    }
    on_ = force == "penalty";
    if (!(factor_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << file << ": fictitiousDomain/penaltyFactor " << factor_
            << " is not allowed; it must be > 0 (K dt; 100 by default)"
            << exit(FatalIOError);
    }
    // The outer loop's repeated constraint is not made for a penalty that
    // holds the bodies within the fluid step
    const label nOuter =
        mesh.solutionDict().optionalSubDict("PIMPLE")
       .getOrDefault<label>("nOuterCorrectors", 1);
    if (on_ && nOuter > 1)
    {
        FatalErrorInFunction
            << "system/fvSolution PIMPLE/nOuterCorrectors " << nOuter
            << " is not allowed with " << file
            << " fictitiousDomain/fluidStepForce penalty; it must be 1"
            << " (the penalty holds the bodies within the fluid step;"
            << " fluidStepForce multipliers takes more)" << exit(FatalError);
    }
    if (on_ && treatment != fictitiousDomain::surfaceTreatment::ghostCells)
    {
        FatalIOErrorInFunction(dict)
            << file << ": fictitiousDomain/fluidStepForce penalty needs"
            << " surfaceTreatment ghostCells, not "
            << fictitiousDomain::surfaceTreatmentNames[treatment]
            << " (the fluid stencils' multipliers act on fluid cells)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::fluidStepPenalty::keywords()
{
    return wordList({"fluidStepForce", "penaltyFactor"});
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::tmp<Foam::fvVectorMatrix> Foam::fluidStepPenalty::matrix
(
    const volVectorField& U,
    const UList<fictitiousDomain::body>& bodies,
    const volVectorField& deviation,
    const vector& period,
    const scalar dt,
    const scalar ddtCoeff
)
{
    const label nCells = mesh_.nCells();
    const vectorField& C = mesh_.C();
    rate_ = factor_/dt;
    residual_.clear();
    holder_.setSize(nCells);
    holder_ = -1;
    arm_.setSize(nCells);
    target_.setSize(nCells);
    scalarField d2(nCells, VGREAT);
    near_.setSize(nCells);
    near_ = -1;
    nearArm_.setSize(nCells);
    scalarField nearD2(nCells, VGREAT);

    // Each body's cells, at every periodic image of the cells that its
    // ball reaches (a cell at C counts at C + s)
    const boundBox cellBox(C, false);
    DynamicList<label> cells;
    forAll(bodies, b)
    {
        const fictitiousDomain::body& B = bodies[b];
        const posedShape S(*B.shape, B.centre, B.R);
        const scalar r = B.shape->boundingRadius();
        const List<vector> shifts
        (
            periodicImages::shifts(cellBox, period, B.centre, 2*r)
        );
        for (const vector& s : shifts)
        {
            cells.clear();
            search_.cellsInBall(B.centre - s, 2*r, cells);
            for (const label c : cells)
            {
                const vector arm = C[c] + s - B.centre;
                const scalar dist2 = magSqr(arm);
                if (dist2 < nearD2[c])
                {
                    nearD2[c] = dist2;
                    near_[c] = b;
                    nearArm_[c] = arm;
                }
                if (dist2 >= d2[c] || dist2 > sqr(r))
                {
                    continue;
                }
                point p;
                vector n;
                const scalar depth = S.depth(C[c] + s, p, n);
                if (depth > 0)
                {
                    d2[c] = dist2;
                    holder_[c] = b;
                    arm_[c] = arm;
                    target_[c] =
                        B.V + (B.omega ^ arm) + deviation.primitiveField()[c];
                }
            }
        }
    }

    // The cells out of every body's two radii go to the nearest centre
    // (the pressure correctors reach the whole domain)
    if (bodies.size())
    {
        forAll(near_, c)
        {
            if (near_[c] >= 0)
            {
                continue;
            }
            forAll(bodies, b)
            {
                const vector arm = periodicImages::nearestImage
                (
                    C[c] - bodies[b].centre, period
                );
                const scalar dist2 = magSqr(arm);
                if (dist2 < nearD2[c])
                {
                    nearD2[c] = dist2;
                    near_[c] = b;
                    nearArm_[c] = arm;
                }
            }
        }
    }

    ddtCoeff_ = ddtCoeff;

    // K (u - u_b) on the left-hand side: diagonal K V_c, source K u_b V_c
    volScalarField::Internal K
    (
        IOobject("penaltyRate", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimless/dimTime, Zero)
    );
    volVectorField::Internal Kub
    (
        IOobject("penaltyTarget", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(dimAcceleration, Zero)
    );
    forAll(holder_, c)
    {
        if (holder_[c] >= 0)
        {
            K[c] = rate_;
            Kub[c] = rate_*target_[c];
        }
    }
    return fvm::Sp(K, U) - Kub;
}


void Foam::fluidStepPenalty::momentum
(
    const volVectorField& U,
    const label nBodies,
    const scalar dt,
    List<vector>& momentum,
    List<vector>& moment
)
{
    momentum.setSize(nBodies);
    moment.setSize(nBodies);
    momentum = Zero;
    moment = Zero;
    if (!(rate_ > 0))
    {
        return;
    }
    const vectorField& u = U.primitiveField();
    const scalarField& V = mesh_.V();
    forAll(holder_, c)
    {
        const label b = holder_[c];
        if (b < 0 || b >= nBodies)
        {
            continue;
        }
        const vector p = dt/ddtCoeff_*V[c]*rate_*(target_[c] - u[c]);
        momentum[b] += p;
        moment[b] += arm_[c] ^ p;
    }
    // The lagged H's momentum, paid by the nearest body
    if (residual_.size() == holder_.size())
    {
        forAll(near_, c)
        {
            const label b = near_[c];
            if (b < 0 || b >= nBodies)
            {
                continue;
            }
            const vector p = -dt/ddtCoeff_*V[c]*residual_[c];
            momentum[b] += p;
            moment[b] += nearArm_[c] ^ p;
        }
    }
    rate_ = 0;
}


void Foam::fluidStepPenalty::constraintMomentum
(
    const vectorField& f,
    const scalar dt,
    List<vector>& momentum,
    List<vector>& moment
) const
{
    const scalarField& V = mesh_.V();
    forAll(near_, c)
    {
        const label b = near_[c];
        if (b < 0 || b >= momentum.size())
        {
            continue;
        }
        const vector p = dt*V[c]*f[c];
        momentum[b] += p;
        moment[b] += nearArm_[c] ^ p;
    }
}


// ************************************************************************* //

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

#include "dlmfdCoupling.H"
#include "knownKeywords.H"
#include "OStringStream.H"
#include "problemList.H"
#include "granularInput.H"
#include "planeWall.H"
#include "Time.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::dlmfdCoupling::densityRatio(const rigidParticle& p) const
{
    return p.mass()/(rhoFluid_*p.shape().volume());
}


Foam::tensor Foam::dlmfdCoupling::volumeInertia(const rigidParticle& p)
{
    const tensor R = p.R();
    return R & p.shape().volumeInertia() & R.T();
}


void Foam::dlmfdCoupling::setPeriodicity()
{
    // The directions the mesh's cyclic patches join (by their faces'
    // normals: a decomposed cyclic lives on as processorCyclic patches),
    // with their separations where this rank holds both sides
    vector across(Zero), separation(Zero);
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        const coupledPolyPatch* cyc = nullptr;
        if (isA<processorCyclicPolyPatch>(pp))
        {
            cyc = &refCast<const processorCyclicPolyPatch>(pp);
        }
        else if (isA<cyclicPolyPatch>(pp))
        {
            cyc = &refCast<const cyclicPolyPatch>(pp);
            if (!cyc->separated() && pp.size() && !cyc->parallel())
            {
                FatalErrorInFunction
                    << "cyclic patch " << pp.name() << " is a rotation;"
                    << " the particles know only periodic boxes"
                    << " (translational cyclics)" << exit(FatalError);
            }
            if (cyc->separated() && cyc->separation().size())
            {
                separation = max(separation, cmptMag(cyc->separation()[0]));
            }
        }
        if (!cyc)
        {
            continue;
        }
        for (const vector& Sf : pp.faceAreas())
        {
            across = max(across, cmptMag(Sf/mag(Sf)));
        }
    }
    reduce(across, maxOp<vector>());
    reduce(separation, maxOp<vector>());
    const vector meshSpan = mesh_.bounds().span();

    const FixedList<bool, 3>& periodic = granular_.periodic();
    const vector span = granular_.domain().span();
    vector period(Zero);
    const char* names[] = {"x", "y", "z"};
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const bool meshPeriodic = across[d] > 0.99;
        if (meshPeriodic != periodic[d])
        {
            FatalErrorInFunction
                << "direction " << names[d] << " is "
                << (periodic[d] ? "" : "not ") << "periodic in"
                << " constant/collisionProperties (domain periodic "
                << periodic << ") but the mesh has "
                << (meshPeriodic ? "" : "no ") << "cyclic patches across"
                << " it; make both periodic, or neither"
                << exit(FatalError);
        }
        if (periodic[d])
        {
            const scalar meshPeriod =
                separation[d] > 0 ? separation[d] : meshSpan[d];
            if (mag(meshPeriod - span[d]) > 1e-9*mag(span))
            {
                FatalErrorInFunction
                    << "direction " << names[d] << ": the mesh's cyclic"
                    << " patches have period " << meshPeriod << " m but"
                    << " the domain of constant/collisionProperties spans "
                    << span[d] << " m; they must be the same"
                    << exit(FatalError);
            }
            period[d] = span[d];
        }
    }
    fd_.setPeriodicity(period);
}


void Foam::dlmfdCoupling::checkPlanarParticles(const fileName& file) const
{
    if (mesh_.nSolutionD() != 2)
    {
        return;
    }
    // A 2D mesh is one cell deep along z: its particles are prisms
    // across that cell, their centres inside it
    const scalar zMin = mesh_.bounds().min().z();
    const scalar zMax = mesh_.bounds().max().z();
    problemList problems;
    const granularSystem& all = distribution_->scene();
    for (label i = 0; i < all.size(); ++i)
    {
        const rigidParticle& p = all.particle(i);
        const bool planar = p.shape().planar();
        const scalar z = p.position().z();
        if (planar && z >= zMin && z <= zMax)
        {
            continue;
        }
        OStringStream os;
        os  << "particle " << all.id(i) << " (" << p.shape().name()
            << ", " << p.shape().type() << ") at " << p.position();
        if (!planar)
        {
            os  << " is not a planar shape (circle, polygon): a 2D case"
                << " holds prisms one cell deep";
        }
        else
        {
            os  << " is off the case's plane: its z must lie between "
                << zMin << " and " << zMax << " m (the mesh's depth)";
        }
        problems.add(os.str());
    }
    if (problems.size())
    {
        FatalErrorInFunction
            << file << ": " << problems.size() << " particle(s) do not fit"
            << " the 2D mesh (one cell deep along z):" << nl
            << problems.str().c_str() << exit(FatalError);
    }
}


void Foam::dlmfdCoupling::checkSettings() const
{
    // A misspelt optional keyword would leave its default in force (the
    // file of the case's constant/ folder: in parallel the dictionary is
    // the master's reading, with no file name)
    const fileName propertiesFile
    (
        mesh_.time().globalPath()/mesh_.time().constant()/"dlmfdProperties"
    );
    knownKeywords::require
    (
        properties_,
        wordList({"fluidDensity", "seriesInterval", "fictitiousDomain"}),
        word::null, propertiesFile
    );
    if (output_.seriesInterval < 1)
    {
        FatalIOErrorInFunction(properties_)
            << propertiesFile << ": seriesInterval " << output_.seriesInterval
            << " is not allowed; it must be a whole number of time steps"
            << " >= 1 (1: a row of particles.dat every step)"
            << exit(FatalIOError);
    }
    knownKeywords::require
    (
        properties_, fd_.keywords(), "fictitiousDomain", propertiesFile
    );

    // The links' momentum, counted once per step, leaks inside the outer
    // loop (a free sphere's total momentum moved 0.09 % in 25 steps with
    // three outer correctors, 0.002 % with one: case.momentumIsConserved*)
    const label nOuter =
        mesh_.solutionDict().optionalSubDict("PIMPLE")
       .getOrDefault<label>("nOuterCorrectors", 1);
    const string refusal(fd_.treatment().outerCorrectorsRefusal());
    if (!refusal.empty() && nOuter > 1)
    {
        FatalErrorInFunction
            << "system/fvSolution PIMPLE/nOuterCorrectors " << nOuter
            << " is not allowed with " << propertiesFile
            << " fictitiousDomain/" << refusal.c_str() << exit(FatalError);
    }
}


void Foam::dlmfdCoupling::reportScene(const fileName& particleFile) const
{
    // The scales of Seyed-Ahmadi & Wachs (2021) for each particle, when
    // the fluid is Newtonian: u_g = sqrt(|m - 1| g D), t_g = D/u_g,
    // Ga = u_g D/nu
    scalar nu = -1;
    {
        const IOdictionary transport
        (
            dlmfdConstantDict(mesh_, "transportProperties")
        );
        if (transport.get<word>("transportModel") == "Newtonian")
        {
            nu = dimensionedScalar("nu", dimViscosity, transport).value();
        }
    }

    // (the whole scene: on the master alone with owned particles, which
    // stops the run for all)
    Info<< "DLM/FD: " << nParticles_ << " particles from "
        << particleFile << ", fluid density " << rhoFluid_ << " kg/m^3"
        << nl;
    const granularSystem& all = distribution_->scene();
    for (label i = 0; i < all.size(); ++i)
    {
        const rigidParticle& p = all.particle(i);
        const scalar m = densityRatio(p);
        const scalar D = p.shape().equivalentDiameter();
        const scalar ug = std::sqrt(mag(m - 1)*mag(g_)*D);
        Info<< "    particle " << all.id(i) << ": "
            << p.shape().name() << " (" << p.shape().type() << ", D = "
            << D << " m), m = " << m << ", "
            << rigidParticle::motionKindNames[p.motion()];
        if (nu > 0 && ug > 0)
        {
            Info<< ", Ga = " << ug*D/nu << ", u_g = " << ug << " m/s, t_g = "
                << D/ug << " s";
        }
        Info<< nl;
        if (p.motion() == rigidParticle::motionKind::free && !(m > 0))
        {
            FatalErrorInFunction
                << "particle " << all.id(i) << ": density ratio "
                << m << " is not allowed; it must be > 0"
                << exit(FatalError);
        }
    }
    Info<< "    walls " << all.walls().size() << ", contact law "
        << "sub-step T_c/N = " << all.maxSubStep() << " s" << nl
        << "    coupling: " << fd_.describe().c_str() << nl
        << "    periods " << fd_.period() << " m (0: not periodic); "
        << (Pstream::parRun() ? "granular step on " : "")
        << (
               distribution_->bodiesPerRank() ? "every one of "
             : Pstream::parRun() ? "the master of " : ""
           )
        << (
               Pstream::parRun()
             ? Foam::name(Pstream::nProcs()) + " ranks" : "serial"
           )
        << nl;
    all.effects().report(Info);
    Info<< endl;
}


void Foam::dlmfdCoupling::openSeries()
{
    // The time series: the master's whole scene, or with owned particles
    // on several ranks each rank's own particles in its processor folder,
    // each row led by the time index and the particle's global index (what
    // mergeParticleSeries sorts by to make the master's file)
    if (Pstream::master() || distribution_->writesPerRank())
    {
        const fileName dir
        (
            (
                distribution_->writesPerRank()
              ? mesh_.time().path() : mesh_.time().globalPath()
            )
           /"postProcessing"/"dlmfdParticles"/mesh_.time().timeName()
        );
        mkDir(dir);
        output_.series.reset(new OFstream(dir/"particles.dat"));
        output_.series().precision(10);
        output_.series()
            << (
                   distribution_->writesPerRank()
                 ? "# timeIndex globalIndex " : "# "
               )
            << "time id x y z qw qx qy qz Ux Uy Uz omegax omegay omegaz"
            << " Fhx Fhy Fhz Thx Thy Thz Fcx Fcy Fcz Tcx Tcy Tcz"
            << "  (SI units, world frame)" << nl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dlmfdCoupling::dlmfdCoupling
(
    const fvMesh& mesh,
    const sceneEffects& effects
)
:
    mesh_(mesh),
    properties_(dlmfdConstantDict(mesh, "dlmfdProperties")),
    rhoFluid_
    (
        granularInput::positive
        (
            properties_, "fluidDensity", "dlmfdProperties", dimDensity
        )
    ),
    g_(Zero),
    granular_
    (
        IOdictionary(dlmfdConstantDict(mesh, "particleProperties")),
        IOdictionary(dlmfdConstantDict(mesh, "collisionProperties")),
        effects
    ),
    nParticles_(0),
    fd_
    (
        mesh,
        properties_.optionalSubDict("fictitiousDomain")
    ),
    ddt_(),
    Fh_(),
    Th_(),
    output_
    (
        properties_.getOrDefault<label>("seriesInterval", 1),
        mesh.time().globalPath()/"VTK",
        mesh.time().value()
    ),
    costs_(),
    outer_(),
    distribution_()
{
    checkSettings();

    // Walls from the mesh's planar patches, where asked for
    granular_.addWallPatches(mesh);

    // Gravity (effect gravity: constant/g) acts in the predictor (the
    // fluid carries its own weight in the pressure): the granular
    // corrector has the contacts only
    g_ = granular_.readGravity(mesh);
    Info<< "Gravity " << g_ << " m/s^2" << nl;
    granular_.setGravity(Zero);

    // Periodic directions, as the mesh's cyclics and the domain say
    setPeriodicity();

    // The scene of the current time, read by the master, and handed out
    // once checked (with owned particles each rank its own and those near
    // it)
    distribution_ =
        particleDistribution::New(mesh_, granular_, fd_, costs_, g_);
    const fileName particleFile(distribution_->readScene(effects));
    nParticles_ =
        returnReduce(distribution_->scene().size(), maxOp<label>());
    checkPlanarParticles(particleFile);
    distribution_->distribute(effects);

    // The multipliers' force density (and the ghost cells' deviations)
    // belong with the particles the solver wrote at this time: with
    // particles placed anew (\<time\>/particles, not uniform/particles)
    // they would hold bodies where there are none (issue 20, finding e)
    if (particleFile.name() == "particles" && particleFile.path().name() != "uniform")
    {
        fd_.discardStoredState(particleFile);
    }
    Fh_.setSize(nParticles_, Zero);
    Th_.setSize(nParticles_, Zero);

    reportScene(particleFile);

    openSeries();
    if (mesh.time().timeIndex() == 0)
    {
        writeVTK();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dlmfdCoupling::write()
{
    const Time& runTime = mesh_.time();
    if (!runTime.writeTime())
    {
        return;
    }
    distribution_->gatherScene();
    if (Pstream::master())
    {
        distribution_->scene().writeParticles(runTime.timePath()/"uniform");
    }
    writeVTK();
}


void Foam::dlmfdCoupling::writeVTK()
{
    const Time& runTime = mesh_.time();
    // (the step just taken: none before the first)
    const granularVTKWriter::loads given
    {
        runTime.timeIndex() > 0 ? runTime.deltaTValue() : 0, &Fh_, &Th_
    };
    distribution_->writeVTK(output_.vtk, given);
}


Foam::string Foam::dlmfdCoupling::costLineNote() const
{
    return distribution_->costLineNote();
}


void Foam::dlmfdCoupling::reportExchange() const
{
    if (!Pstream::parRun())
    {
        return;
    }
    const scalar nSolves = max(fd_.nSolves(), label(1));
    const scalar nProcs = Pstream::nProcs();
    const exchangeTraffic& t = fd_.received();
    Info<< "DLM/FD work and exchange per solve (" << fd_.nSolves()
        << " solves), by a rank: largest, mean over the ranks" << nl;
    const auto line = [&](const char* what, const scalar total, const scalar n)
    {
        const scalar per = total/n;
        Info<< "    " << what << " "
            << returnReduce(per, maxOp<scalar>()) << ", "
            << returnReduce(per, sumOp<scalar>())/nProcs << nl;
    };
    line("bodies in the list   ", t.bodiesListed, nSolves);
    line("bodies with cells here", t.bodiesHere, nSolves);
    line("their cells          ", t.cellsHere, nSolves);
    line("bodies solved        ", t.bodiesSolved, nSolves);
    line("messages received    ", t.messages, nSolves);
    line("bytes received       ", t.bytes, nSolves);
    // The states after the granular step: per step, not per solve
    const scalar nSteps = max(costs_.nStateSteps, label(1));
    line("state messages per step", costs_.stateMessages, nSteps);
    line("state bytes per step ", costs_.stateBytes, nSteps);
    if (distribution_->bodiesPerRank())
    {
        line("particles held per step", costs_.mirrorParticles, nSteps);
    }
    Info<< endl;
}


// ************************************************************************* //

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
    The time step of Foam::dlmfdCoupling: the granular predictor, the
    fictitious-domain step within the PIMPLE outer loop (correct) and after
    it (evolve), the granular corrector and the particles' log line (the
    time series' rows: dlmfdCouplingSeries.C).

\*---------------------------------------------------------------------------*/

#include "dlmfdCoupling.H"
#include "OStringStream.H"
#include "Time.H"
#include "fvmDdt.H"
#include "linear.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::fictitiousDomain::body> Foam::dlmfdCoupling::predictedBodies
(
    vectorField& V0,
    vectorField& omega0
) const
{
    using motionKind = rigidParticle::motionKind;

    const scalar dt = mesh_.time().deltaTValue();
    const label n = granular_.size();
    V0.setSize(n);
    omega0.setSize(n);
    List<fictitiousDomain::body> bodies(n);
    for (label k = 0; k < n; ++k)
    {
        const rigidParticle& p = granular_.particle(k);
        fictitiousDomain::body& b = bodies[k];
        V0[k] = p.velocity();
        omega0[k] = p.omega();
        b.shape = &p.shape();
        b.index = granular_.globalIndex(k);
        // (the master, or with owned particles the owner)
        b.resultRank = distribution_->resultRank(p);
        b.R = p.R();
        b.free = p.motion() == motionKind::free;
        b.rotates = p.rotates();
        b.excessDensity = densityRatio(p) - 1;
        b.V = V0[k];
        b.omega = omega0[k];
        if (b.free)
        {
            b.V += dt*g_;
            if (!p.isotropic() && b.rotates)
            {
                const tensor J = volumeInertia(p);
                b.omega -= dt*(inv(J) & (omega0[k] ^ (J & omega0[k])));
            }
            if (p.planar())
            {
                b.V.z() = 0;
                b.omega.x() = 0;
                b.omega.y() = 0;
            }
        }
        // The predictor moves the body over the step, its orientation too
        // (a rotation by |omega*| dt about omega*), so that the constraint
        // is imposed where the body will be
        b.centre = p.position() + dt*b.V;
        b.R = predictedRotation(p.R(), b.omega, dt);
    }

    return bodies;
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::dlmfdCoupling::predictedRotation
(
    const tensor& R,
    const vector& omega,
    const scalar dt
)
{
    const scalar angle = mag(omega)*dt;
    if (!(angle > 0))
    {
        return R;
    }
    return quaternion(omega/mag(omega), angle).R() & R;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dlmfdCoupling::checkPressureCorrectors
(
    const volScalarField& nu,
    const label nCorrectors
)
{
    const scalar dt = mesh_.time().deltaTValue();
    const surfaceScalarField nuf(linearInterpolate(nu));
    const scalar viscous =
        dt
       *gMax
        (
            nuf.primitiveField()*sqr(mesh_.deltaCoeffs().primitiveField())
        );
    if
    (
        !output_.freeBodyRingingSaid
     && viscous > freeBodyViscousNumberMeasured
    )
    {
        // The lightest free body (the particles this rank holds)
        scalar lightest = GREAT;
        for (const rigidParticle& p : granular_.particles())
        {
            if (p.motion() == rigidParticle::motionKind::free)
            {
                lightest = min(lightest, densityRatio(p));
            }
        }
        reduce(lightest, minOp<scalar>());
        if (lightest < freeBodyDensityRatioMeasured)
        {
            // Four digits, whatever writePrecision the case sets
            OStringStream msg;
            msg.precision(4);
            msg << "time " << mesh_.time().timeName() << ": the viscous"
                << " number nu dt/h^2 of this step is " << viscous
                << " with free particles of density ratio down to "
                << lightest << ". Free bodies at m = 2 were measured to"
                << " ring above " << freeBodyViscousNumberMeasured
                << " and to diverge at 3.2 (a cube) and 6.4 (a sphere)"
                << " (benchmarks/validation/shearRotation); a time step of"
                << " at most " << dt*freeBodyViscousNumberMeasured/viscous
                << " s keeps below it. Said once.";
            WarningInFunction << msg.str().c_str() << endl;
            output_.freeBodyRingingSaid = true;
        }
    }
    if (nCorrectors >= 3)
    {
        return;
    }
    if (viscous > maxTwoCorrectorViscousNumber)
    {
        FatalErrorInFunction
            << "time " << mesh_.time().timeName() << ": the viscous number"
            << " nu dt/h^2 of this step is " << viscous << " (dt = " << dt
            << " s) with system/fvSolution PIMPLE nCorrectors "
            << nCorrectors << "; the coupled step is stable with fewer than"
            << " three pressure correctors only up to "
            << maxTwoCorrectorViscousNumber << " (a fixed body at Re 0.1"
            << " diverged at 25: benchmarks/ringing). Set nCorrectors 3"
            << " (measured stable to 142), or a time step of at most "
            << dt*maxTwoCorrectorViscousNumber/viscous << " s (deltaT, or"
            << " maxDeltaT with adjustTimeStep in system/controlDict)"
            << exit(FatalError);
    }
}


Foam::scalar Foam::dlmfdCoupling::ddtCoeff(const volVectorField& U)
{
    // dt times the time scheme's diagonal per volume, averaged (a matrix
    // assembled for it: once per time step)
    const label timeIndex = mesh_.time().timeIndex();
    if (ddt_.timeIndex != timeIndex)
    {
        ddt_.coeff =
            mesh_.time().deltaTValue()
           *gAverage(fvm::ddt(U)().A()().primitiveField());
        ddt_.timeIndex = timeIndex;
    }
    return ddt_.coeff;
}


Foam::tmp<Foam::fvVectorMatrix> Foam::dlmfdCoupling::surfaceTerms
(
    const volVectorField& U,
    const volScalarField& nu
)
{
    clockTime clock;
    const label n = granular_.size();
    // The bodies where and as they move now (the ghost cells' are the
    // predictor's, a step's travel apart at most)
    List<fictitiousDomain::body> bodies(n);
    for (label k = 0; k < n; ++k)
    {
        const rigidParticle& p = granular_.particle(k);
        bodies[k].shape = &p.shape();
        bodies[k].index = granular_.globalIndex(k);
        bodies[k].centre = p.position();
        bodies[k].R = p.R();
        bodies[k].V = p.velocity();
        bodies[k].omega = p.omega();
    }
    tmp<fvVectorMatrix> m = fd_.treatment().fluidStepTerms(U, nu, bodies, fd_);
    costs_.fdSeconds += clock.timeIncrement();
    return m;
}


void Foam::dlmfdCoupling::updateMesh()
{
    fd_.updateMesh();
}


void Foam::dlmfdCoupling::correct(volVectorField& U)
{
    clockTime clock;

    // The bodies where the predictor puts them, at every corrector: moved
    // with the last corrector's velocities instead, the outer loop did not
    // converge (cells entering and leaving the body) and the E2 sphere
    // settled 5 % faster at CFL 0.5
    vectorField V0, omega0;
    const List<fictitiousDomain::body> bodies(predictedBodies(V0, omega0));
    List<fictitiousDomain::body> held;
    const UList<fictitiousDomain::body>& solved =
        distribution_->bodiesHeld(bodies, held);

    const label index = mesh_.time().timeIndex();
    if (outer_.correctedIndex != index)
    {
        fd_.keepStepStart(U);
        outer_.correctedIndex = index;
        outer_.nCorrections = 0;
    }
    else
    {
        fd_.rewindToStepStart();
    }
    ++outer_.nCorrections;
    const scalar dt = mesh_.time().deltaTValue();
    const scalar commBefore = fd_.communicationSeconds();
    const List<fictitiousDomain::result>& res = fd_.solve(U, solved, dt, true);
    const scalar fdComm = fd_.communicationSeconds() - commBefore;
    costs_.commSeconds += fdComm;

    // How far the particles' velocities moved since the last corrector:
    // what the outer loop has left to converge (on the rank that takes
    // each body's result)
    scalar change = 0;
    outer_.lastV.setSize(granular_.size(), vector::max);
    const bodyPlaces places(bodies);
    forAll(res, k)
    {
        if (solved[k].resultRank != Pstream::myProcNo())
        {
            continue;
        }
        const label place = places(bodyPlaces::global(solved, k));
        const vector V = solved[k].V + res[k].dV;
        if (outer_.nCorrections > 1)
        {
            change = max(change, mag(V - outer_.lastV[place]));
        }
        outer_.lastV[place] = V;
    }
    change = distribution_->largestOverResults(change);

    Info<< "DLM/FD outer corrector " << outer_.nCorrections << ": ";
    if (outer_.nCorrections > 1)
    {
        Info<< "largest change of a particle velocity " << change << " m/s";
    }
    else
    {
        Info<< "particles constrained";
    }
    Info<< endl;
    costs_.fdSeconds += clock.timeIncrement() - fdComm;
}


void Foam::dlmfdCoupling::payFluidGain
(
    const volVectorField& U,
    const List<fictitiousDomain::body>& bodies,
    const UList<fictitiousDomain::body>& solved
)
{
    surfaceTreatment& treatment = fd_.treatment();
    if (!treatment.hasFluidGain())
    {
        return;
    }
    // What the fluid gained from the bodies in its step (the wall links),
    // the bodies pay; with owned particles among the holders of each body
    List<vector> gain(bodies.size(), Zero);
    List<vector> gainMoment(bodies.size(), Zero);
    treatment.fluidGain
    (
        U, mesh_.time().deltaTValue(), ddtCoeff(U), fd_, solved,
        distribution_->bodiesPerRank(), nParticles_, gain, gainMoment
    );
    fd_.addOwed(bodies, gain, gainMoment);
}


void Foam::dlmfdCoupling::takeResults
(
    const List<fictitiousDomain::body>& bodies,
    const UList<fictitiousDomain::body>& solved,
    const List<fictitiousDomain::result>& res,
    const vectorField& V0,
    const vectorField& omega0,
    List<vector>& V3s,
    List<vector>& omega3s,
    dlmfdStepReport& report
)
{
    const scalar dt = mesh_.time().deltaTValue();
    // (by place in bodies, as V0)
    const bodyPlaces places(bodies);
    // (a body whose result this rank did not take keeps no velocity: the
    // granular step sets only the taken ones)
    V3s.setSize(bodies.size(), vector::max);
    omega3s.setSize(bodies.size(), vector::max);
    forAll(solved, k)
    {
        const fictitiousDomain::body& b = solved[k];
        if (b.resultRank != Pstream::myProcNo())
        {
            continue;
        }
        const label i = bodyPlaces::global(solved, k);
        const label place = places(i);
        const fictitiousDomain::result& r = res[k];
        report.nPoints += r.nInterior + r.nSurface;
        report.nSurface += r.nSurface;
        report.nDropped += r.nSurfaceDropped;
        report.maxError = max(report.maxError, r.constraintError);

        const vector V3 = b.V + r.dV;
        const vector omega3 = b.omega + r.dOmega;
        if (report.corrected)
        {
            report.lastChange =
                max(report.lastChange, mag(V3 - outer_.lastV[place]));
        }
        const scalar vp = b.shape->volume();
        Fh_[i] = rhoFluid_*(vp*(V3 - V0[place])/dt - r.sumLambda);
        const tensor J = volumeInertia(granular_.particle(place));
        Th_[i] =
            rhoFluid_*((J & (omega3 - omega0[place]))/dt - r.sumMoment);

        // (set on the particles by the granular step)
        V3s[place] = V3;
        omega3s[place] = omega3;
    }
}


void Foam::dlmfdCoupling::carryInteriorFluid
(
    volVectorField& U,
    const UList<fictitiousDomain::body>& solved,
    const List<fictitiousDomain::result>& res
) const
{
    // The fluid carried by each free particle moves with it: its interior
    // cells, at their centres relative to the body at X*, which moved by
    // X^{n+1} - X* (less than half a period, however it was wrapped)
    vectorField& u = U.primitiveFieldRef();
    forAll(solved, k)
    {
        const fictitiousDomain::body& b = solved[k];
        const fictitiousDomain::result& r = res[k];
        if (!b.free || r.interiorCells.empty())
        {
            // (a rank that took a body's result but has none of its
            // cells, its owner at the step's start, needs no new state)
            continue;
        }
        const label g = bodyPlaces::global(solved, k);
        const label place = distribution_->place(g);
        if (place < 0)
        {
            FatalErrorInFunction
                << "t = " << mesh_.time().value() << ": rank "
                << Pstream::myProcNo() << " holds particle of global index "
                << g << " but its new state was not sent to it (the"
                << " particle travelled farther than the margin its state"
                << " is sent with)" << exit(FatalError);
        }
        const rigidParticle& p = granular_.particle(place);
        const vector moved = granular_.separation(p.position(), b.centre);
        forAll(r.interiorCells, j)
        {
            const vector arm = r.interiorCentres[j] - b.centre - moved;
            u[r.interiorCells[j]] = p.velocity() + (p.omega() ^ arm);
            if (r.interiorDeviation.size())
            {
                u[r.interiorCells[j]] += r.interiorDeviation[j];
            }
        }
    }
    U.correctBoundaryConditions();
}


void Foam::dlmfdCoupling::logStep(const dlmfdStepReport& report) const
{
    const granularSystem::statistics s = distribution_->stats();
    Info<< "DLM/FD: " << nParticles_ << " particles, " << report.nPoints
        << " points";
    // Only a treatment that reads the fluid near the surface fits it
    Info<< " (" << report.nSurface << " ghost cells";
    if (fd_.treatment().readsFluidNearSurface())
    {
        Info<< ", " << report.nDropped
            << " of them with no fluid cell in reach";
    }
    Info<< "), momentum balance " << report.maxError << " m/s";
    if (report.corrected)
    {
        Info<< "; the last of " << outer_.nCorrections + 1 << " outer"
            << " correctors changed the particle velocities by at most "
            << report.lastChange << " m/s";
    }
    Info<< "; granular " << report.nSub << " sub-steps";
    if (s.nInReach >= 0)
    {
        Info<< " (contacts of " << s.nInReach << " of " << nParticles_
            << " particles in reach)";
    }
    if (s.nFallbacks)
    {
        Info<< " (redone with every particle's contacts: one in reach"
            << " travelled farther than allowed)";
    }
    Info<< ", " << s.nContacts << " + " << s.nWallContacts << " wall contacts,"
        << " max overlap " << s.maxOverlapRatio << " D" << endl;
}


void Foam::dlmfdCoupling::evolve(volVectorField& U)
{
    const scalar dt = mesh_.time().deltaTValue();
    clockTime clock;

    // (2) Granular predictor and the bodies of the constraint
    vectorField V0, omega0;
    const List<fictitiousDomain::body> bodies(predictedBodies(V0, omega0));
    List<fictitiousDomain::body> held;
    const UList<fictitiousDomain::body>& solved =
        distribution_->bodiesHeld(bodies, held);
    dlmfdStepReport report;
    report.corrected = outer_.correctedIndex == mesh_.time().timeIndex();
    if (report.corrected)
    {
        // The outer correctors solved this step already: from its start
        fd_.rewindToStepStart();
    }

    // (3) Fictitious domain, distributed; its results on the master
    payFluidGain(U, bodies, solved);
    const scalar commBefore = fd_.communicationSeconds();
    const List<fictitiousDomain::result>& res = fd_.solve(U, solved, dt);
    const scalar fdComm = fd_.communicationSeconds() - commBefore;
    costs_.fdSeconds += clock.timeIncrement() - fdComm;
    costs_.commSeconds += fdComm;

    // (4) On the master, or with owned particles on each body's owner:
    // forces, torques and the granular corrector, contacts from X^n over
    // dt
    List<vector> V3s, omega3s;
    takeResults(bodies, solved, res, V0, omega0, V3s, omega3s, report);
    distribution_->granularStep(bodies, V3s, omega3s, report, clock);

    carryInteriorFluid(U, solved, res);
    costs_.fdSeconds += clock.timeIncrement();

    logStep(report);
    if (mesh_.time().timeIndex() % output_.seriesInterval == 0)
    {
        if (distribution_->writesPerRank())
        {
            distribution_->handOverForces(Fh_, Th_);
        }
        writeSeriesRows();
    }
    costs_.seriesSeconds += clock.timeIncrement();
}


// ************************************************************************* //

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
#include "granularInput.H"
#include "planeWall.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::IOobject constantDict(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name,
        mesh.time().constant(),
        mesh,
        Foam::IOobject::MUST_READ,
        Foam::IOobject::NO_WRITE
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::dlmfdCoupling::densityRatio(const label i) const
{
    const rigidParticle& p = granular_.particle(i);
    return p.mass()/(rhoFluid_*p.shape().volume());
}


Foam::tensor Foam::dlmfdCoupling::volumeInertia(const label i) const
{
    const rigidParticle& p = granular_.particle(i);
    const tensor R = p.R();
    return R & p.shape().volumeInertia() & R.T();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dlmfdCoupling::dlmfdCoupling(const fvMesh& mesh, const vector& g)
:
    mesh_(mesh),
    properties_(constantDict(mesh, "dlmfdProperties")),
    rhoFluid_
    (
        granularInput::positive
        (
            properties_, "fluidDensity", "dlmfdProperties", dimDensity
        )
    ),
    g_(g),
    granular_
    (
        IOdictionary(constantDict(mesh, "particleProperties")),
        IOdictionary(constantDict(mesh, "collisionProperties"))
    ),
    fd_
    (
        mesh,
        properties_.optionalSubDict("fictitiousDomain")
    ),
    Fh_(),
    Th_(),
    series_(),
    vtk_(mesh.time().path()/"VTK", mesh.time().value()),
    fdSeconds_(0),
    granularSeconds_(0)
{
    // Walls from the mesh's planar patches, where asked for
    granular_.addWallPatches(mesh);

    // Gravity acts in the predictor (the fluid carries its own weight in
    // the pressure): the granular corrector has the contacts only
    granular_.setGravity(Zero);

    const fileName particleFile(mesh.time().timePath()/"particles");
    if (!isFile(particleFile))
    {
        FatalErrorInFunction
            << "no particle file " << particleFile << nl
            << "    Place particles with placeParticles, or copy them from"
            << " 0.orig" << exit(FatalError);
    }
    granular_.readParticles(particleFile);
    Fh_.setSize(granular_.size(), Zero);
    Th_.setSize(granular_.size(), Zero);

    // The scales of seed 001 for each particle, when the fluid is
    // Newtonian: u_g = sqrt(|m - 1| g D), t_g = D/u_g, Ga = u_g D/nu
    scalar nu = -1;
    {
        const IOdictionary transport(constantDict(mesh, "transportProperties"));
        if (transport.get<word>("transportModel") == "Newtonian")
        {
            nu = dimensionedScalar("nu", dimViscosity, transport).value();
        }
    }

    Info<< "DLM/FD: " << granular_.size() << " particles from "
        << particleFile << ", fluid density " << rhoFluid_ << " kg/m^3"
        << nl;
    for (label i = 0; i < granular_.size(); ++i)
    {
        const rigidParticle& p = granular_.particle(i);
        const scalar m = densityRatio(i);
        const scalar D = p.shape().equivalentDiameter();
        const scalar ug = std::sqrt(mag(m - 1)*mag(g_)*D);
        Info<< "    particle " << granular_.id(i) << ": "
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
                << "particle " << granular_.id(i) << ": density ratio "
                << m << " is not allowed; it must be > 0"
                << exit(FatalError);
        }
    }
    Info<< "    walls " << granular_.walls().size() << ", contact law "
        << "sub-step T_c/N = " << granular_.maxSubStep() << " s" << nl
        << endl;

    if (Pstream::master())
    {
        const fileName dir
        (
            mesh.time().path()/"postProcessing"/"dlmfdParticles"
           /mesh.time().timeName()
        );
        mkDir(dir);
        series_.reset(new OFstream(dir/"particles.dat"));
        series_().precision(10);
        series_()
            << "# time id x y z qw qx qy qz Ux Uy Uz omegax omegay omegaz"
            << " Fhx Fhy Fhz Thx Thy Thz  (SI units, world frame)" << nl;
    }
    if (mesh.time().timeIndex() == 0)
    {
        vtk_.write(granular_, mesh.time().value(), 0);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dlmfdCoupling::evolve(volVectorField& U)
{
    using motionKind = rigidParticle::motionKind;

    const scalar dt = mesh_.time().deltaTValue();
    const label n = granular_.size();
    clockTime clock;

    // (2) Granular predictor and the bodies of the constraint
    vectorField V0(n), omega0(n);
    List<fictitiousDomain::body> bodies(n);
    for (label i = 0; i < n; ++i)
    {
        const rigidParticle& p = granular_.particle(i);
        fictitiousDomain::body& b = bodies[i];
        V0[i] = p.velocity();
        omega0[i] = p.omega();
        b.shape = &p.shape();
        b.R = p.R();
        b.free = p.motion() == motionKind::free;
        b.excessDensity = densityRatio(i) - 1;
        b.V = V0[i];
        b.omega = omega0[i];
        if (b.free)
        {
            b.V += dt*g_;
            if (!p.isotropic())
            {
                const tensor J = volumeInertia(i);
                b.omega -= dt*(inv(J) & (omega0[i] ^ (J & omega0[i])));
            }
            if (p.planar())
            {
                b.V.z() = 0;
                b.omega.x() = 0;
                b.omega.y() = 0;
            }
        }
        b.centre = p.position() + dt*b.V;
    }

    // (3) Fictitious domain
    const List<fictitiousDomain::result>& res = fd_.solve(U, bodies, dt);

    label nPoints = 0, nDropped = 0, maxIter = 0;
    scalar maxError = 0;
    for (label i = 0; i < n; ++i)
    {
        const fictitiousDomain::body& b = bodies[i];
        const fictitiousDomain::result& r = res[i];
        nPoints += r.nInterior + r.nSurface;
        nDropped += r.nSurfaceDropped;
        maxIter = max(maxIter, r.iterations);
        maxError = max(maxError, r.constraintError);

        const vector V3 = b.V + r.dV;
        const vector omega3 = b.omega + r.dOmega;
        const scalar vp = b.shape->volume();
        Fh_[i] = rhoFluid_*(vp*(V3 - V0[i])/dt - r.sumLambda);
        Th_[i] =
            rhoFluid_
           *((volumeInertia(i) & (omega3 - omega0[i]))/dt - r.sumMoment);

        if (b.free)
        {
            rigidParticle& p = granular_.particle(i);
            p.setVelocity(V3);
            p.setOmega(omega3);
        }
    }

    fdSeconds_ += clock.timeIncrement();

    // (4) Granular corrector: contacts from X^n over dt
    const label nSub = granular_.evolve(dt);

    // The fluid carried by each free particle moves with it
    vectorField& u = U.primitiveFieldRef();
    const vectorField& C = mesh_.C();
    for (label i = 0; i < n; ++i)
    {
        if (!bodies[i].free)
        {
            continue;
        }
        const rigidParticle& p = granular_.particle(i);
        for (const label c : res[i].interiorCells)
        {
            u[c] = p.velocity() + (p.omega() ^ (C[c] - p.position()));
        }
    }
    U.correctBoundaryConditions();
    granularSeconds_ += clock.timeIncrement();

    const granularSystem::statistics& s = granular_.stats();
    Info<< "DLM/FD: " << n << " particles, " << nPoints << " points ("
        << nDropped << " surface points without a stencil left out),"
        << " CG iterations <= " << maxIter << ", constraint error "
        << maxError << " m/s; granular " << nSub << " sub-steps, "
        << s.nContacts << " + " << s.nWallContacts << " wall contacts,"
        << " max overlap " << s.maxOverlapRatio << " D" << endl;

    if (series_.valid())
    {
        OFstream& os = series_();
        const scalar t = mesh_.time().value();
        for (label i = 0; i < n; ++i)
        {
            const rigidParticle& p = granular_.particle(i);
            const quaternion& q = p.orientation();
            const point& x = p.position();
            const vector& V = p.velocity();
            const vector& w = p.omega();
            os  << t << ' ' << granular_.id(i) << ' '
                << x.x() << ' ' << x.y() << ' ' << x.z() << ' '
                << q.w() << ' ' << q.v().x() << ' ' << q.v().y() << ' '
                << q.v().z() << ' '
                << V.x() << ' ' << V.y() << ' ' << V.z() << ' '
                << w.x() << ' ' << w.y() << ' ' << w.z() << ' '
                << Fh_[i].x() << ' ' << Fh_[i].y() << ' ' << Fh_[i].z() << ' '
                << Th_[i].x() << ' ' << Th_[i].y() << ' ' << Th_[i].z()
                << nl;
        }
        os.flush();
    }
}


void Foam::dlmfdCoupling::write()
{
    const Time& runTime = mesh_.time();
    if (!runTime.writeTime())
    {
        return;
    }
    if (Pstream::master())
    {
        granular_.writeParticles(runTime.timePath());
    }
    vtk_.write(granular_, runTime.value(), runTime.timeIndex());
}


// ************************************************************************* //

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

#include "suspensionScales.H"
#include "suspensionInput.H"
#include "granularInput.H"
#include "uniformDimensionedFields.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::suspensionScales::suspensionScales
(
    const fvMesh& mesh,
    const dictionary& options,
    granularSystem& granular
)
{
    const Time& runTime = mesh.time();
    const auto constantDict = [&](const word& name)
    {
        return IOdictionary
        (
            IOobject
            (
                name, runTime.constant(), mesh,
                IOobject::MUST_READ, IOobject::NO_WRITE
            )
        );
    };
    const IOdictionary dlmfdProperties(constantDict("dlmfdProperties"));
    rhoF = granularInput::positive
    (
        dlmfdProperties, "fluidDensity", "dlmfdProperties", dimDensity
    );
    const IOdictionary transport(constantDict("transportProperties"));
    if (transport.get<word>("transportModel") != "Newtonian")
    {
        FatalIOErrorInFunction(transport)
            << "transportModel " << transport.get<word>("transportModel")
            << ": the statistics need a Newtonian fluid (Re, Stokes drag)"
            << exit(FatalIOError);
    }
    nu = dimensionedScalar("nu", dimViscosity, transport).value();
    const uniformDimensionedVectorField gField
    (
        IOobject
        (
            "g", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    const vector g = gField.value();
    if (mag(g) == 0)
    {
        FatalErrorInFunction
            << "constant/g is zero: a settling suspension needs gravity"
            << exit(FatalError);
    }
    eg = g/mag(g);
    vert = findMax(cmptMag(g));
    const direction h1 = (vert + 1) % 3, h2 = (vert + 2) % 3;
    hx = min(h1, h2);
    hy = max(h1, h2);
    up = -eg;

    // The particles of the first time with a particle file
    const fileName particleFile = [&]()
    {
        for (const instant& t : runTime.times())
        {
            for (const fileName f : {"uniform/particles", "particles"})
            {
                const fileName file(runTime.path()/t.name()/f);
                if (isFile(file))
                {
                    return file;
                }
            }
        }
        FatalErrorInFunction
            << "no particle file (<time>/uniform/particles or"
            << " <time>/particles) in " << runTime.path()
            << exit(FatalError);
        return fileName();
    }();
    granular.readParticles(particleFile);
    Np = granular.size();
    if (Np < 2)
    {
        FatalErrorInFunction
            << particleFile << " has " << Np << " particles; a suspension"
            << " needs two or more" << exit(FatalError);
    }
    const rigidParticle& p0 = granular.particle(0);
    D = p0.shape().equivalentDiameter();
    vp = p0.shape().volume();
    m = p0.mass()/(rhoF*vp);
    for (label i = 1; i < Np; ++i)
    {
        const rigidParticle& p = granular.particle(i);
        if
        (
            mag(p.shape().equivalentDiameter() - D) > 1e-9*D
         || mag(p.mass() - p0.mass()) > 1e-9*p0.mass()
        )
        {
            FatalErrorInFunction
                << particleFile << ": particle " << granular.id(i)
                << " differs from particle " << granular.id(0) << " in"
                << " size or mass; the statistics are for one kind of"
                << " particle" << exit(FatalError);
        }
    }
    ug = std::sqrt(mag(m - 1)*mag(g)*D);
    tg = D/ug;
    Ga = ug*D/nu;
    mu = rhoF*nu;

    // The box, its periods and the solid fraction
    box = granular.domain();
    period = Zero;
    for (direction d = 0; d < 3; ++d)
    {
        if (granular.periodic()[d])
        {
            period[d] = box.span()[d];
        }
    }
    boxVolume = box.volume();
    phi = Np*vp/boxVolume;

    shapeType = p0.shape().type();
    const bool isSphere = shapeType == "sphere";
    if (!isSphere && !options.found("isolatedReynolds"))
    {
        FatalIOErrorInFunction(options)
            << "the particles are " << shapeType << "s: give"
            << " isolatedReynolds, the terminal Re of one isolated particle"
            << " at Ga = " << Ga << " (for the Richardson-Zaki comparison),"
            << " in system/suspensionStatisticsDict" << exit(FatalIOError);
    }
    ReT = options.getOrDefault<scalar>
    (
        "isolatedReynolds",
        isSphere ? suspensionInput::sphereTerminalReynolds(Ga) : 0
    );
    if (!(ReT > 0))
    {
        FatalIOErrorInFunction(options)
            << "isolatedReynolds " << ReT << " must be > 0"
            << exit(FatalIOError);
    }

    Info<< "Suspension: " << Np << " " << shapeType << "s, D = "
        << D << " m, m = " << m << ", Ga = " << Ga << ", phi = " << phi
        << ", u_g = " << ug << " m/s, t_g = " << tg << " s, periods "
        << period << nl << "    vertical axis " << label(vert)
        << ", horizontal " << label(hx) << " and " << label(hy) << nl;
}


// ************************************************************************* //

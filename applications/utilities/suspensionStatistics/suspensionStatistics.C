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
    suspensionStatistics

Group
    grpPostProcessingUtilities

Description
    The statistics of a settling suspension of seed 001 (Seyed-Ahmadi &
    Wachs 2021, section III), from a dlmfdFoam run: the particle series
    postProcessing/dlmfdParticles/\<start\>/particles.dat (every time step,
    restarts joined) and the fluid at the write times (U with
    \<time\>/uniform/particles; reconstruct a parallel run first).

    Units: velocities over u_g = sqrt(|m - 1| g D), times over t_g = D/u_g,
    lengths over D (D the particles' volume-equivalent diameter, m their
    density ratio; one kind of particle). "Vertical" is the axis of gravity,
    V_s = V.g/|g| the settling velocity (positive downwards); "horizontal"
    the two other axes.

    Written to postProcessing/suspensionStatistics/:
    - timeSeries.csv, every step: the mean settling velocity <V_s>, Re =
      <V_s> D/nu, the particle velocity variances along and across gravity
      over <V_s>^2 and their ratio (the anisotropy), the mean horizontal
      angular velocity Omega_h = |Omega - (Omega.e_g) e_g|, the mean
      hydrodynamic force along gravity over the Stokes drag 3 pi mu D <V_s>;
    - fluidStatistics.csv, every write time: the fluid velocity variance in
      a cube of edge controlVolume D (4 D) around each particle, cells
      inside particles excluded, pooled over all cubes, along and across
      gravity; the mean local solid fraction in the same cubes (the
      fraction of their cells inside a particle);
    - OmegaH_pdf.csv: the distribution of Omega_h t_g over the averaging
      window;
    - OmegaX_Vy_jointPdf.csv: the joint PDF of Omega_x t_g and V_y/u_g
      (the two horizontal axes, x the first: for gravity along z, x and y),
      and their Pearson coefficient in summary.csv;
    - pairDistribution.csv: P(r, theta), theta from the upward vertical,
      bins dr = 0.1 D and dtheta = pi/60, by the minimum image over the
      periodic directions up to half the shortest period, normalised by
      the mean number density (1 for an ideal gas);
      radialDistribution.csv: g(r) on the same radial bins;
    - summary.csv: time averages over the window, with the drag over the
      Stokes drag, total (F, as computed) and flow-induced (F_d = (1 -
      phi) F, eq 29), and the Richardson-Zaki comparison: <V_s>/V_t
      against k (1 - phi)^n, n from Garside and Al-Dibouni ((5.1 - n)/(n -
      2.7) = 0.1 Re_t^0.9), k = 0.85 after Di Felice, V_t and Re_t of the
      isolated particle at the same Ga (for spheres from the drag balance
      C_D Re^2 = 4/3 Ga^2 with Schiller-Naumann's C_D unless given).

Usage
    \b suspensionStatistics [-time ranges | -latestTime ...]

    system/suspensionStatisticsDict (optional, the defaults shown):
    \verbatim
    averagingStart      <half the last time>;   // [s] window start
    pairSampleInterval  10;     // every 10th step in P(r, theta), g(r)
    controlVolume       4;      // cube edge over D
    omegaBins           50;
    jointBins           40;
    isolatedReynolds    <Schiller-Naumann for spheres>; // needed for others
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "granularSystem.H"
#include "particleGeometry.H"
#include "cellCentreSearch.H"
#include "granularInput.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "uniformDimensionedFields.H"
#include "mathematicalConstants.H"
#include "suspensionInput.H"
#include "knownKeywords.H"

#include <map>
#include <vector>
#include <algorithm>

using namespace Foam;
using constant::mathematical::pi;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

using namespace Foam::suspensionInput;


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "The settling-suspension statistics of seed 001 from a dlmfdFoam"
        " run, to postProcessing/suspensionStatistics"
    );
    argList::noParallel();
    timeSelector::addOptions(true, false);

    #include "setRootCase.H"
    #include "createTime.H"

    const instantList times = timeSelector::select0(runTime, args);

    #include "createMesh.H"

    // Options
    IOdictionary options
    (
        IOobject
        (
            "suspensionStatisticsDict",
            runTime.system(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        ),
        dictionary()
    );
    // A misspelt option would leave its default in force
    knownKeywords::require
    (
        options,
        wordList
        ({
            "averagingStart", "pairSampleInterval", "controlVolume",
            "omegaBins", "jointBins", "isolatedReynolds"
        })
    );
    const label pairInterval =
        options.getOrDefault<label>("pairSampleInterval", 10);
    const scalar cvEdge = options.getOrDefault<scalar>("controlVolume", 4);
    const label omegaBins = options.getOrDefault<label>("omegaBins", 50);
    const label jointBins = options.getOrDefault<label>("jointBins", 40);
    if (pairInterval < 1 || !(cvEdge > 0) || omegaBins < 2 || jointBins < 2)
    {
        FatalIOErrorInFunction(options)
            << "pairSampleInterval " << pairInterval << ", controlVolume "
            << cvEdge << ", omegaBins " << omegaBins << ", jointBins "
            << jointBins << ": need pairSampleInterval >= 1, controlVolume"
            << " > 0, omegaBins and jointBins >= 2" << exit(FatalIOError);
    }

    // The particles: shapes, materials, the periodic box
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
    granularSystem granular
    (
        constantDict("particleProperties"),
        constantDict("collisionProperties")
    );
    const IOdictionary dlmfdProperties(constantDict("dlmfdProperties"));
    const scalar rhoF = granularInput::positive
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
    const scalar nu = dimensionedScalar("nu", dimViscosity, transport).value();
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
    const vector eg = g/mag(g);
    const direction vert = findMax(cmptMag(g));
    const direction h1 = (vert + 1) % 3, h2 = (vert + 2) % 3;
    const direction hx = min(h1, h2), hy = max(h1, h2);
    const vector up = -eg;

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
    const label Np = granular.size();
    if (Np < 2)
    {
        FatalErrorInFunction
            << particleFile << " has " << Np << " particles; a suspension"
            << " needs two or more" << exit(FatalError);
    }
    const rigidParticle& p0 = granular.particle(0);
    const scalar D = p0.shape().equivalentDiameter();
    const scalar vp = p0.shape().volume();
    const scalar m = p0.mass()/(rhoF*vp);
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
    const scalar ug = std::sqrt(mag(m - 1)*mag(g)*D);
    const scalar tg = D/ug;
    const scalar Ga = ug*D/nu;
    const scalar mu = rhoF*nu;

    // The box, its periods and the solid fraction
    const boundBox& box = granular.domain();
    vector period(Zero);
    for (direction d = 0; d < 3; ++d)
    {
        if (granular.periodic()[d])
        {
            period[d] = box.span()[d];
        }
    }
    const scalar boxVolume = box.volume();
    const scalar phi = Np*vp/boxVolume;

    const bool isSphere = p0.shape().type() == "sphere";
    if (!isSphere && !options.found("isolatedReynolds"))
    {
        FatalIOErrorInFunction(options)
            << "the particles are " << p0.shape().type() << "s: give"
            << " isolatedReynolds, the terminal Re of one isolated particle"
            << " at Ga = " << Ga << " (for the Richardson-Zaki comparison),"
            << " in system/suspensionStatisticsDict" << exit(FatalIOError);
    }
    const scalar ReT = options.getOrDefault<scalar>
    (
        "isolatedReynolds", isSphere ? sphereTerminalReynolds(Ga) : 0
    );
    if (!(ReT > 0))
    {
        FatalIOErrorInFunction(options)
            << "isolatedReynolds " << ReT << " must be > 0"
            << exit(FatalIOError);
    }

    Info<< "Suspension: " << Np << " " << p0.shape().type() << "s, D = "
        << D << " m, m = " << m << ", Ga = " << Ga << ", phi = " << phi
        << ", u_g = " << ug << " m/s, t_g = " << tg << " s, periods "
        << period << nl << "    vertical axis " << label(vert)
        << ", horizontal " << label(hx) << " and " << label(hy) << nl;

    // The particle series
    const auto steps =
        readSeries(runTime.path()/"postProcessing"/"dlmfdParticles");
    if (steps.size() < 2)
    {
        FatalErrorInFunction
            << "postProcessing/dlmfdParticles holds " << steps.size()
            << " steps; run dlmfdFoam first" << exit(FatalError);
    }
    const scalar tEnd = steps.rbegin()->first;
    const scalar tStart = options.getOrDefault<scalar>
    (
        "averagingStart", 0.5*tEnd
    );
    if (!(tStart < tEnd))
    {
        FatalIOErrorInFunction(options)
            << "averagingStart " << tStart << " s is not before the last"
            << " step " << tEnd << " s" << exit(FatalIOError);
    }
    Info<< "    " << label(steps.size()) << " steps to t = " << tEnd
        << " s (" << tEnd/tg << " t_g); averaging from " << tStart << " s ("
        << tStart/tg << " t_g)" << nl << endl;

    const fileName outDir
    (
        runTime.path()/"postProcessing"/"suspensionStatistics"
    );
    mkDir(outDir);

    // Time series, and the window's sums
    scalar sumVs = 0, sumVarZ = 0, sumVarH = 0, sumDrag = 0, sumOmegaH = 0;
    label nWindow = 0;
    std::vector<scalar> omegaH, omegaX, Vy;
    {
        csvFile ts
        (
            outDir/"timeSeries.csv",
            "t_tg,Vs_ug,Re,varV_vertical_Vs2,varV_horizontal_Vs2,"
            "anisotropy,OmegaH_tg,drag_over_Stokes"
        );
        for (const auto& step : steps)
        {
            const std::vector<sample>& s = step.second;
            const label n = s.size();
            const bool inWindow = step.first >= tStart;
            vector meanV(Zero);
            scalar meanOmegaH = 0, meanF = 0;
            for (const sample& p : s)
            {
                meanV += p.V;
                const scalar oh = mag(p.omega - (p.omega & eg)*eg);
                meanOmegaH += oh;
                meanF += p.F & up;
                if (inWindow)
                {
                    omegaH.push_back(oh*tg);
                    omegaX.push_back(p.omega[hx]*tg);
                    Vy.push_back(p.V[hy]/ug);
                }
            }
            meanV /= n;
            meanOmegaH /= n;
            meanF /= n;
            scalar varZ = 0, varH = 0;
            for (const sample& p : s)
            {
                const vector d = p.V - meanV;
                varZ += sqr(d[vert]);
                varH += 0.5*(sqr(d[hx]) + sqr(d[hy]));
            }
            varZ /= n;
            varH /= n;
            const scalar Vs = meanV & eg;
            const scalar Vs2 = max(sqr(Vs), VSMALL);
            const scalar drag = meanF/(3*pi*mu*D*Vs + VSMALL);
            ts() << step.first/tg << ',' << Vs/ug << ',' << Vs*D/nu << ','
                << varZ/Vs2 << ',' << varH/Vs2 << ','
                << varZ/max(varH, VSMALL) << ',' << meanOmegaH*tg << ','
                << drag << nl;

            if (inWindow)
            {
                ++nWindow;
                sumVs += Vs;
                sumVarZ += varZ;
                sumVarH += varH;
                sumDrag += meanF;
                sumOmegaH += meanOmegaH;
            }
        }
    }
    const scalar Vs = sumVs/nWindow;
    const scalar varZ = sumVarZ/nWindow, varH = sumVarH/nWindow;
    const scalar F = sumDrag/nWindow;
    const scalar FSt = 3*pi*mu*D*Vs;

    // Omega_h PDF
    {
        const scalar top = *std::max_element(omegaH.begin(), omegaH.end());
        const scalar w = max(top, SMALL)/omegaBins;
        labelList count(omegaBins, Zero);
        for (const scalar o : omegaH)
        {
            ++count[min(label(o/w), omegaBins - 1)];
        }
        csvFile os(outDir/"OmegaH_pdf.csv", "OmegaH_tg,pdf");
        forAll(count, b)
        {
            os() << (b + 0.5)*w << ','
                << count[b]/(w*scalar(omegaH.size())) << nl;
        }
    }

    // Joint PDF of Omega_x and V_y, and their Pearson coefficient
    scalar pearson = 0;
    {
        const label n = omegaX.size();
        scalar mx = 0, my = 0;
        for (label i = 0; i < n; ++i)
        {
            mx += omegaX[i];
            my += Vy[i];
        }
        mx /= n;
        my /= n;
        scalar sxy = 0, sxx = 0, syy = 0;
        for (label i = 0; i < n; ++i)
        {
            sxy += (omegaX[i] - mx)*(Vy[i] - my);
            sxx += sqr(omegaX[i] - mx);
            syy += sqr(Vy[i] - my);
        }
        pearson = sxy/std::sqrt(max(sxx*syy, VSMALL));

        const auto range = [](const std::vector<scalar>& v)
        {
            scalar a = 0;
            for (const scalar x : v)
            {
                a = max(a, mag(x));
            }
            return max(a, SMALL);
        };
        const scalar ax = range(omegaX), ay = range(Vy);
        const scalar wx = 2*ax/jointBins, wy = 2*ay/jointBins;
        List<labelList> count(jointBins, labelList(jointBins, Zero));
        for (label i = 0; i < n; ++i)
        {
            const label bx = min(label((omegaX[i] + ax)/wx), jointBins - 1);
            const label by = min(label((Vy[i] + ay)/wy), jointBins - 1);
            ++count[bx][by];
        }
        csvFile os(outDir/"OmegaX_Vy_jointPdf.csv", "OmegaX_tg,Vy_ug,pdf");
        for (label bx = 0; bx < jointBins; ++bx)
        {
            for (label by = 0; by < jointBins; ++by)
            {
                os() << -ax + (bx + 0.5)*wx << ',' << -ay + (by + 0.5)*wy
                    << ',' << count[bx][by]/(wx*wy*scalar(n)) << nl;
            }
        }
    }

    // Pair distribution P(r, theta) and g(r), minimum image
    {
        scalar rMax = GREAT;
        for (direction d = 0; d < 3; ++d)
        {
            rMax = min(rMax, 0.5*(period[d] > 0 ? period[d] : box.span()[d]));
        }
        const scalar dr = 0.1*D;
        const label nr = label(rMax/dr);
        const label nTheta = 60;
        const scalar dTheta = pi/nTheta;
        List<labelList> count(nr, labelList(nTheta, Zero));
        label nSamples = 0, k = 0;
        for (const auto& step : steps)
        {
            if (step.first < tStart || (k++ % pairInterval) != 0)
            {
                continue;
            }
            ++nSamples;
            const std::vector<sample>& s = step.second;
            for (size_t i = 0; i < s.size(); ++i)
            {
                for (size_t j = i + 1; j < s.size(); ++j)
                {
                    const vector d = granular.separation(s[j].x, s[i].x);
                    const scalar r = mag(d);
                    const label br = label(r/dr);
                    if (br >= nr || r == 0)
                    {
                        continue;
                    }
                    // From i to j and from j to i (theta and pi - theta)
                    const scalar c = max(-1.0, min(1.0, (d & up)/r));
                    const label bt = min(label(std::acos(c)/dTheta), nTheta - 1);
                    ++count[br][bt];
                    ++count[br][nTheta - 1 - bt];
                }
            }
        }
        const scalar density = Np/boxVolume;
        const scalar norm = scalar(Np)*density*max(nSamples, 1);
        csvFile pd(outDir/"pairDistribution.csv", "r_D,theta,P");
        csvFile rd(outDir/"radialDistribution.csv", "r_D,g");
        for (label br = 0; br < nr; ++br)
        {
            const scalar r0 = br*dr, r1 = r0 + dr;
            const scalar shell = 4*pi/3*(pow3(r1) - pow3(r0));
            label total = 0;
            for (label bt = 0; bt < nTheta; ++bt)
            {
                const scalar t0 = bt*dTheta, t1 = t0 + dTheta;
                const scalar vol =
                    2*pi/3*(pow3(r1) - pow3(r0))*(std::cos(t0) - std::cos(t1));
                pd() << (r0 + 0.5*dr)/D << ',' << t0 + 0.5*dTheta << ','
                    << count[br][bt]/(norm*vol) << nl;
                total += count[br][bt];
            }
            rd() << (r0 + 0.5*dr)/D << ',' << total/(norm*shell) << nl;
        }
        Info<< "Pair distribution: " << nSamples << " samples, r up to "
            << rMax/D << " D" << nl;
    }

    // The fluid at the write times: variance in the cubes around the
    // particles (solid cells excluded), local solid fraction
    scalar sumFluidZ = 0, sumFluidH = 0, sumPhiLoc = 0;
    label nFluid = 0;
    {
        csvFile fs
        (
            outDir/"fluidStatistics.csv",
            "t_tg,varU_vertical_ug2,varU_horizontal_ug2,phi_local"
        );
        const cellCentreSearch search(mesh);
        const scalar half = 0.5*cvEdge*D;
        for (const instant& t : times)
        {
            runTime.setTime(t, 0);
            const fileName pFile(runTime.timePath()/"uniform"/"particles");
            IOobject Uheader
            (
                "U", runTime.timeName(), mesh, IOobject::MUST_READ
            );
            if (!isFile(pFile) || !Uheader.typeHeaderOk<volVectorField>(true))
            {
                continue;
            }
            granular.readParticles(pFile);
            const volVectorField U(Uheader, mesh);
            const vectorField& C = mesh.C();
            const scalarField& V = mesh.V();

            // The periodic shifts of a ball of radius r about x
            const auto shifts = [&](const point& x, const scalar r)
            {
                return cellCentreSearch::periodicShifts
                (
                    mesh.bounds(), period, x, r
                );
            };

            // Cells inside a particle
            boolList solid(mesh.nCells(), false);
            DynamicList<label> near;
            for (label i = 0; i < granular.size(); ++i)
            {
                const rigidParticle& p = granular.particle(i);
                const scalar rb = p.shape().boundingRadius();
                for (const vector& s : shifts(p.position(), rb))
                {
                    near.clear();
                    search.cellsInBall(p.position() - s, rb, near);
                    for (const label c : near)
                    {
                        if
                        (
                            particleGeometry::contains
                            (
                                p.shape(), p.position(), p.R(), C[c] + s
                            )
                        )
                        {
                            solid[c] = true;
                        }
                    }
                }
            }

            // The cubes
            scalar w = 0, phiLoc = 0;
            vector su(Zero), su2(Zero);
            for (label i = 0; i < granular.size(); ++i)
            {
                const point& x = granular.particle(i).position();
                scalar cubeV = 0, solidV = 0;
                for (const vector& s : shifts(x, std::sqrt(3.0)*half))
                {
                    near.clear();
                    search.cellsInBall(x - s, std::sqrt(3.0)*half, near);
                    for (const label c : near)
                    {
                        const vector d = C[c] + s - x;
                        if (cmptMax(cmptMag(d)) > half)
                        {
                            continue;
                        }
                        cubeV += V[c];
                        if (solid[c])
                        {
                            solidV += V[c];
                            continue;
                        }
                        w += V[c];
                        su += V[c]*U[c];
                        su2 += V[c]*cmptMultiply(U[c], U[c]);
                    }
                }
                phiLoc += solidV/max(cubeV, VSMALL);
            }
            phiLoc /= granular.size();
            const vector mean = su/max(w, VSMALL);
            const vector var = su2/max(w, VSMALL) - cmptMultiply(mean, mean);
            const scalar vz = var[vert];
            const scalar vh = 0.5*(var[hx] + var[hy]);
            fs() << runTime.value()/tg << ',' << vz/sqr(ug) << ','
                << vh/sqr(ug) << ',' << phiLoc << nl;
            Info<< "Time " << runTime.timeName() << ": fluid variance "
                << vz/sqr(ug) << " (vertical), " << vh/sqr(ug)
                << " (horizontal) u_g^2, local solid fraction " << phiLoc
                << nl;
            if (runTime.value() >= tStart)
            {
                ++nFluid;
                sumFluidZ += vz;
                sumFluidH += vh;
                sumPhiLoc += phiLoc;
            }
        }
    }

    // Summary
    {
        const scalar a = 0.1*std::pow(ReT, 0.9);
        const scalar n = (5.1 + 2.7*a)/(1 + a);
        const scalar k = 0.85;
        const scalar Vt = ReT*nu/D;
        csvFile os(outDir/"summary.csv", "quantity,value");
        const auto row = [&](const char* name, const scalar v)
        {
            os() << name << ',' << v << nl;
            Info<< "    " << name << " = " << v << nl;
        };
        Info<< nl << "Over " << tStart/tg << " to " << tEnd/tg << " t_g:" << nl;
        row("averagingStart_tg", tStart/tg);
        row("averagingEnd_tg", tEnd/tg);
        row("steps", nWindow);
        row("particles", Np);
        row("Ga", Ga);
        row("densityRatio", m);
        row("solidFraction", phi);
        row("Vs_ug", Vs/ug);
        row("Re", Vs*D/nu);
        row("varV_vertical_Vs2", varZ/sqr(Vs));
        row("varV_horizontal_Vs2", varH/sqr(Vs));
        row("anisotropy", varZ/max(varH, VSMALL));
        row("OmegaH_tg", sumOmegaH/nWindow*tg);
        row("pearson_OmegaX_Vy", pearson);
        row("drag_over_Stokes", F/FSt);
        row("flowDrag_over_Stokes", (1 - phi)*F/FSt);
        row("fluidSamples", nFluid);
        if (nFluid)
        {
            row("varU_vertical_Vs2", sumFluidZ/nFluid/sqr(Vs));
            row("varU_horizontal_Vs2", sumFluidH/nFluid/sqr(Vs));
            row("phi_local", sumPhiLoc/nFluid);
        }
        row("isolatedReynolds", ReT);
        row("isolatedVs_ug", Vt/ug);
        row("RZ_exponent_n", n);
        row("RZ_prefactor_k", k);
        row("RZ_Vs_over_Vt", k*std::pow(1 - phi, n));
        row("measured_Vs_over_Vt", Vs/Vt);
    }

    Info<< nl << "Written " << outDir << nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //

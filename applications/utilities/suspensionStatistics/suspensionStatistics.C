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

    One class per statistic: settlingSeries (timeSeries.csv and the window's
    means), omegaHDistribution, rotationTranslationCorrelation,
    pairDistribution, fluidAgitation; what they are scaled by:
    suspensionScales; the particle series: suspensionInput. This file only
    reads the options and wires them.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "granularSystem.H"
#include "knownKeywords.H"
#include "suspensionInput.H"
#include "suspensionScales.H"
#include "settlingSeries.H"
#include "omegaHDistribution.H"
#include "rotationTranslationCorrelation.H"
#include "pairDistribution.H"
#include "fluidAgitation.H"
#include "mathematicalConstants.H"

using namespace Foam;
using constant::mathematical::pi;

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

    // The particles, the fluid, gravity and the box
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
    const suspensionScales sc(mesh, options, granular);

    // The particle series
    const suspensionInput::series steps = suspensionInput::readSeries
    (
        runTime.path()/"postProcessing"/"dlmfdParticles"
    );
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
        << " s (" << tEnd/sc.tg << " t_g); averaging from " << tStart
        << " s (" << tStart/sc.tg << " t_g)" << nl << endl;

    const fileName outDir
    (
        runTime.path()/"postProcessing"/"suspensionStatistics"
    );
    mkDir(outDir);

    // The statistics, each writing its own files
    const settlingSeries settling(sc, steps, tStart, outDir);
    omegaHDistribution(settling.omegaHSamples(), omegaBins).write(outDir);
    const rotationTranslationCorrelation correlation
    (
        settling.omegaXSamples(), settling.VySamples(), jointBins
    );
    correlation.write(outDir);
    pairDistribution(sc, granular, steps, tStart, pairInterval)
        .write(outDir, sc.D);
    const fluidAgitation fluid
    (
        sc, runTime, mesh, granular, times, tStart, cvEdge, outDir
    );

    // Summary: the window's means, and the Richardson-Zaki comparison
    {
        const scalar Vs = settling.Vs();
        const scalar FSt = 3*pi*sc.mu*sc.D*Vs;
        const scalar a = 0.1*std::pow(sc.ReT, 0.9);
        const scalar n = (5.1 + 2.7*a)/(1 + a);
        const scalar k = 0.85;
        const scalar Vt = sc.ReT*sc.nu/sc.D;
        suspensionInput::csvFile os(outDir/"summary.csv", "quantity,value");
        const auto row = [&](const char* name, const scalar v)
        {
            os() << name << ',' << v << nl;
            Info<< "    " << name << " = " << v << nl;
        };
        Info<< nl << "Over " << tStart/sc.tg << " to " << tEnd/sc.tg
            << " t_g:" << nl;
        row("averagingStart_tg", tStart/sc.tg);
        row("averagingEnd_tg", tEnd/sc.tg);
        row("steps", settling.nWindow());
        row("particles", sc.Np);
        row("Ga", sc.Ga);
        row("densityRatio", sc.m);
        row("solidFraction", sc.phi);
        row("Vs_ug", Vs/sc.ug);
        row("Re", Vs*sc.D/sc.nu);
        row("varV_vertical_Vs2", settling.varVertical()/sqr(Vs));
        row("varV_horizontal_Vs2", settling.varHorizontal()/sqr(Vs));
        row
        (
            "anisotropy",
            settling.varVertical()/max(settling.varHorizontal(), VSMALL)
        );
        row("OmegaH_tg", settling.omegaH()*sc.tg);
        row("pearson_OmegaX_Vy", correlation.pearson());
        row("drag_over_Stokes", settling.force()/FSt);
        row("flowDrag_over_Stokes", (1 - sc.phi)*settling.force()/FSt);
        row("fluidSamples", fluid.nTimes());
        if (fluid.nTimes())
        {
            row("varU_vertical_Vs2", fluid.varVertical()/sqr(Vs));
            row("varU_horizontal_Vs2", fluid.varHorizontal()/sqr(Vs));
            row("phi_local", fluid.solidFraction());
        }
        row("isolatedReynolds", sc.ReT);
        row("isolatedVs_ug", Vt/sc.ug);
        row("RZ_exponent_n", n);
        row("RZ_prefactor_k", k);
        row("RZ_Vs_over_Vt", k*std::pow(1 - sc.phi, n));
        row("measured_Vs_over_Vt", Vs/Vt);
    }

    Info<< nl << "Written " << outDir << nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //

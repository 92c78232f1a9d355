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
    galileoScales

Group
    grpPreProcessingUtilities

Description
    Sets up a case in the non-dimensional form of seed 001 (Seyed-Ahmadi &
    Wachs 2021, eqs 4-7): from the Galileo number Ga and the density ratio
    m, with the particle diameter D and the fluid density rho_f as units
    (1 by default), it writes constant/galileoScales, a dictionary that the
    case's own dictionaries include:

    \f[
        u_g = \sqrt{|m - 1| g D}, \quad t_g = D/u_g, \quad
        \nu = u_g D/Ga, \quad \rho_p = m \rho_f
    \f]

    with |g| = u_g^2/(|m - 1| D) chosen so that u_g = D/t_g = 1 when D = 1
    and t_g = 1: the velocities and times of the run are then in units of
    u_g and t_g, as in seed 001's figures.

    Entries written: nu (kinematic viscosity), g (gravity vector),
    fluidDensity, particleDensity, Ga, m, D, u_g, t_g. Use them as

    \verbatim
    // constant/transportProperties
    #include "galileoScales"
    transportModel Newtonian;
    nu          [0 2 -1 0 0 0 0] $nu;

    // constant/g
    #include "galileoScales"
    dimensions  [0 1 -2 0 0 0 0];
    value       $g;

    // constant/dlmfdProperties
    #include "galileoScales"
    fluidDensity $fluidDensity;

    // constant/particleProperties, materials
    solid { density $particleDensity; }
    \endverbatim

Usage
    \b galileoScales [-case dir]

    system/galileoScalesDict:
    \verbatim
    Ga                  70;
    m                   2;
    D                   1;          // optional, default 1 [m]
    fluidDensity        1;          // optional, default 1 [kg/m^3]
    gravityDirection    (0 0 -1);   // optional
    \endverbatim

    \table
        Property         | Description                      | Required | Default
        Ga               | Galileo number, > 0              | yes |
        m                | density ratio rho_p/rho_f, > 0, not 1 | yes |
        D                | particle diameter [m], > 0       | no  | 1
        fluidDensity     | rho_f [kg/m^3], > 0              | no  | 1
        gravityDirection | direction of gravity, non-zero   | no  | (0 0 -1)
    \endtable

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "knownKeywords.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

scalar positiveOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt
)
{
    const scalar value = dict.getOrDefault<scalar>(key, deflt);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << key << " = " << value << " is not allowed; it must be > 0"
            << exit(FatalIOError);
    }
    return value;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Write constant/galileoScales (nu, g, densities) from Ga and m,"
        " for a case in the non-dimensional form of seed 001"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    const IOdictionary dict
    (
        IOobject
        (
            "galileoScalesDict",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    // A misspelt optional keyword would leave its default in force
    knownKeywords::require
    (
        dict, wordList({"Ga", "m", "D", "fluidDensity", "gravityDirection"})
    );

    const scalar Ga = dict.get<scalar>("Ga");
    if (!(Ga > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Ga = " << Ga << " is not allowed; it must be > 0"
            << exit(FatalIOError);
    }
    const scalar m = dict.get<scalar>("m");
    if (!(m > 0) || m == 1)
    {
        FatalIOErrorInFunction(dict)
            << "m = " << m << " is not allowed; it must be > 0 and not 1"
            << " (u_g = sqrt(|m - 1| g D) is the velocity scale)"
            << exit(FatalIOError);
    }
    const scalar D = positiveOrDefault(dict, "D", 1);
    const scalar rhoFluid = positiveOrDefault(dict, "fluidDensity", 1);
    const vector direction =
        dict.getOrDefault<vector>("gravityDirection", vector(0, 0, -1));
    if (mag(direction) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "gravityDirection = " << direction << " is not allowed; it"
            << " must be non-zero" << exit(FatalIOError);
    }

    // Units: D and t_g = 1 s for D = 1 m, so u_g = D/t_g
    const scalar ug = D;            // [m/s] with t_g = 1 s
    const scalar tg = D/ug;
    const scalar g = sqr(ug)/(mag(m - 1)*D);
    const scalar nu = ug*D/Ga;

    const fileName file(runTime.path()/runTime.constant()/"galileoScales");
    const fileName tmp(file + ".tmp");
    {
        OFstream os(tmp);
        os.precision(17);
        IOobject::writeBanner(os);
        os  << "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
            << "    class       dictionary;\n    location    \"constant\";\n"
            << "    object      galileoScales;\n}\n";
        IOobject::writeDivider(os);
        os  << "\n// Written by galileoScales from system/galileoScalesDict:"
            << " include it, do not edit\n\n"
            << "Ga              " << Ga << ";\n"
            << "m               " << m << ";\n"
            << "D               " << D << ";      // [m]\n"
            << "u_g             " << ug << ";      // [m/s]\n"
            << "t_g             " << tg << ";      // [s]\n"
            << "nu              " << nu << ";      // [m^2/s]\n"
            << "g               " << g*direction/mag(direction)
            << ";      // [m/s^2]\n"
            << "fluidDensity    " << rhoFluid << ";      // [kg/m^3]\n"
            << "particleDensity " << m*rhoFluid << ";      // [kg/m^3]\n";
        IOobject::writeEndDivider(os);
    }
    Foam::mv(tmp, file);

    Info<< "Ga = " << Ga << ", m = " << m << ", D = " << D << " m: u_g = "
        << ug << " m/s, t_g = " << tg << " s, nu = " << nu << " m^2/s, |g| = "
        << g << " m/s^2, rho_f = " << rhoFluid << ", rho_p = " << m*rhoFluid
        << " kg/m^3" << nl << "Written " << file << nl << nl << "End" << nl
        << endl;

    return 0;
}


// ************************************************************************* //

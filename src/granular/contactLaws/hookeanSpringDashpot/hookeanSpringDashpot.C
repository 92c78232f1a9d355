/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Class
\*---------------------------------------------------------------------------*/

#include "hookeanSpringDashpot.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "granularInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(hookeanSpringDashpot, 0);
    addToRunTimeSelectionTable(contactLaw, hookeanSpringDashpot, dictionary);
}
}


namespace
{
    //- delta_max omega_0/v_0 = exp(-gamma_n t*) for damping ratio c
    Foam::scalar overlapFactor(const Foam::scalar c)
    {
        const Foam::scalar s = Foam::sqrt(1 - c*c);
        return Foam::exp(-c/s*Foam::atan2(s, c));
    }

}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactLaws::hookeanSpringDashpot::readCoeffs
(
    const dictionary& coeffs
)
{
    en_ = coeffs.get<scalar>("en");
    if (!(en_ > 0 && en_ <= 1))
    {
        FatalIOErrorInFunction(coeffs)
            << "pair " << pair_.name << ": en = " << en_
            << " is not allowed; 0 < en <= 1" << exit(FatalIOError);
    }
    const scalar lnE = log(en_);
    dampingRatio_ = -lnE/sqrt(sqr(constant::mathematical::pi) + sqr(lnE));

    muc_ = coeffs.get<scalar>("muc");
    if (!(muc_ >= 0))
    {
        FatalIOErrorInFunction(coeffs)
            << "pair " << pair_.name << ": muc = " << muc_
            << " is not allowed; muc >= 0" << exit(FatalIOError);
    }

    gammat_ = -1;
    if (coeffs.readIfPresent("gammat", gammat_) && !(gammat_ >= 0))
    {
        FatalIOErrorInFunction(coeffs)
            << "pair " << pair_.name << ": gammat = " << gammat_
            << " is not allowed; gammat >= 0 (or leave it out for"
            << " gamma_n)" << exit(FatalIOError);
    }

    const bool hasKn = coeffs.found("kn");
    const bool hasOverlap = coeffs.found("maxOverlapRatio");
    if (hasKn == hasOverlap)
    {
        FatalIOErrorInFunction(coeffs)
            << "pair " << pair_.name << ": give either kn or"
            << " maxOverlapRatio (with impactVelocity and"
            << " referenceDiameter); " << (hasKn ? "both are" : "neither is")
            << " given" << exit(FatalIOError);
    }

    if (hasKn)
    {
        kn_ = granularInput::positive
        (
            coeffs, "kn", "pair " + pair_.name, dimForce/dimLength
        );
    }
    else
    {
        const string owner("pair " + pair_.name);
        const scalar ratio =
            granularInput::positive(coeffs, "maxOverlapRatio", owner);
        const scalar v0 = granularInput::positive
        (
            coeffs, "impactVelocity", owner, dimVelocity
        );
        const scalar D = granularInput::positive
        (
            coeffs, "referenceDiameter", owner, dimLength
        );

        const scalar M = pair_.referenceMass(D);
        const scalar omega0 = v0*overlapFactor(dampingRatio_)/(ratio*D);
        kn_ = M*sqr(omega0);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::hookeanSpringDashpot::hookeanSpringDashpot
(
    const dictionary& coeffs,
    const materialPair& pair
)
:
    contactLaw(pair),
    kn_(0),
    en_(1),
    dampingRatio_(0),
    muc_(0),
    gammat_(-1)
{
    readCoeffs(coeffs);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::contactLaws::hookeanSpringDashpot::maxOverlap
(
    const scalar v0,
    const scalar M
) const
{
    return v0*overlapFactor(dampingRatio_)/sqrt(kn_/M);
}


Foam::scalar Foam::contactLaws::hookeanSpringDashpot::contactTime
(
    const scalar M
) const
{
    return
        constant::mathematical::pi
       /(sqrt(kn_/M)*sqrt(1 - sqr(dampingRatio_)));
}


Foam::vector Foam::contactLaws::hookeanSpringDashpot::regionTorque
(
    const vector& n,
    const vector& omegaRel,
    const scalar spread,
    const scalar M,
    const scalar Fn
) const
{
    const scalar r2 = sqr(spread);
    const scalar Fpos = max(Fn, scalar(0));

    // Twist: the tangential dashpot integrated over the region
    const scalar spin = omegaRel & n;
    scalar Ttwist = tangential_ ? -2*gammat(M)*M*r2*spin : 0;
    const scalar twistCap = muc_*Fpos*spread;
    if (mag(Ttwist) > twistCap)
    {
        Ttwist = sign(Ttwist)*twistCap;
    }

    // Rocking: the normal dashpot integrated over the region
    const vector rock = omegaRel - spin*n;
    vector Trock = -2*gamman(M)*M*r2*rock;
    const scalar rockCap = Fpos*spread;
    const scalar magTrock = mag(Trock);
    if (magTrock > rockCap)
    {
        Trock *= rockCap/magTrock;
    }

    return Ttwist*n + Trock;
}


Foam::vector Foam::contactLaws::hookeanSpringDashpot::force
(
    const scalar delta,
    const vector& n,
    const vector& Urel,
    const scalar M,
    const scalar,
    vector&
) const
{
    // One square root per contact: 2 gamma_n M = 2 zeta sqrt(k_n M), and
    // |F_n| is the magnitude of its component along the unit normal
    const scalar Un = Urel & n;
    const scalar twoGammanM = 2*dampingRatio_*sqrt(kn_*M);
    const scalar fn = kn_*delta - twoGammanM*Un;
    if (!tangential_)
    {
        return fn*n;
    }

    // Tangential dashpot, capped by Coulomb's limit (eq 22)
    const vector Fdt =
        -(gammat_ < 0 ? twoGammanM : 2*gammat_*M)*(Urel - Un*n);
    const scalar cap = muc_*mag(fn);
    const scalar magSqrFdt = magSqr(Fdt);

    return
        magSqrFdt > sqr(cap)
      ? fn*n + (cap/sqrt(magSqrFdt))*Fdt
      : fn*n + Fdt;
}


// ************************************************************************* //

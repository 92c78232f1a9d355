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

#include "hookeanStaticFriction.H"
#include "addToRunTimeSelectionTable.H"
#include "granularInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(hookeanStaticFriction, 0);
    addToRunTimeSelectionTable(contactLaw, hookeanStaticFriction, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::hookeanStaticFriction::hookeanStaticFriction
(
    const dictionary& coeffs,
    const materialPair& pair
)
:
    hookeanSpringDashpot(coeffs, pair),
    ks_
    (
        granularInput::positive
        (
            coeffs, "ks", "pair " + pair.name, dimForce/dimLength
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::contactLaws::hookeanStaticFriction::force
(
    const scalar delta,
    const vector& n,
    const vector& Urel,
    const scalar M,
    const scalar dt,
    vector& history
) const
{
    const vector Fn = normalForce(delta, n, Urel, M);
    const vector Vt = Urel - (Urel & n)*n;

    // Turn the history into the tangent plane of this step, same length
    const scalar magHistory = mag(history);
    history -= (history & n)*n;
    const scalar magInPlane = mag(history);
    if (magInPlane > VSMALL)
    {
        history *= magHistory/magInPlane;
    }
    history += Vt*dt;

    const vector Ftrial = -2*gammat(M)*M*Vt - ks_*history;
    const scalar magFtrial = mag(Ftrial);
    const scalar cap = muc()*kn()*delta;

    if (magFtrial <= cap)
    {
        return Fn + Ftrial;
    }

    // Sliding: the spring alone carries the capped force
    const vector Ft = (cap/magFtrial)*Ftrial;
    history = -Ft/ks_;
    return Fn + Ft;
}


// ************************************************************************* //

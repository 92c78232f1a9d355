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

#include "rigidMomentumBalance.H"
#include "smallDenseSolve.H"
#include "boolList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidMomentumBalance::rigidMomentumBalance
(
    const scalar mvp,
    const tensor& mJ,
    const vector& Vstar,
    const vector& omegaStar,
    const vector& owed,
    const vector& owedMoment
)
:
    KVV_(mvp*tensor::I),
    KVO_(Zero),
    KOV_(Zero),
    KOO_(mJ),
    rhsV_(mvp*Vstar - owed),
    rhsO_((mJ & omegaStar) - owedMoment)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rigidMomentumBalance::addRigidCell
(
    const vector& r,
    const scalar V,
    const vector& known
)
{
    KVV_ += V*tensor::I;
    KVO_ -= V*cross(r);
    KOV_ += V*cross(r);
    KOO_ += V*(magSqr(r)*tensor::I - (r*r));
    rhsV_ += V*known;
    rhsO_ += V*(r ^ known);
}


void Foam::rigidMomentumBalance::addAffineCell
(
    const vector& r,
    const scalar V,
    const tensor& P,
    const tensor& Q,
    const vector& E,
    const vector& u
)
{
    KVV_ += V*P;
    KVO_ += V*Q;
    KOV_ += V*(cross(r) & P);
    KOO_ += V*(cross(r) & Q);
    rhsV_ += V*(u - E);
    rhsO_ += V*(r ^ (u - E));
}


bool Foam::rigidMomentumBalance::solve
(
    const labelList& modes,
    vector& Vel,
    vector& omega
) const
{
    if (modes.empty())
    {
        return true;
    }
    const auto K = [&](const label a, const label b) -> scalar
    {
        if (a < 3)
        {
            return b < 3 ? KVV_(a, b) : KVO_(a, b - 3);
        }
        return b < 3 ? KOV_(a - 3, b) : KOO_(a - 3, b - 3);
    };
    scalarList y(6);
    for (direction d = 0; d < 3; ++d)
    {
        y[d] = Vel[d];
        y[3 + d] = omega[d];
    }
    const label nm = modes.size();
    List<scalarList> A(nm, scalarList(nm));
    scalarList rhs(nm);
    boolList unknown(6, false);
    for (const label a : modes)
    {
        unknown[a] = true;
    }
    forAll(modes, i)
    {
        const label a = modes[i];
        rhs[i] = a < 3 ? rhsV_[a] : rhsO_[a - 3];
        for (label b = 0; b < 6; ++b)
        {
            if (!unknown[b])
            {
                rhs[i] -= K(a, b)*y[b];
            }
        }
        forAll(modes, j)
        {
            A[i][j] = K(a, modes[j]);
        }
    }
    if (!smallDenseSolve(A, rhs))
    {
        return false;
    }
    forAll(modes, i)
    {
        y[modes[i]] = rhs[i];
    }
    Vel = vector(y[0], y[1], y[2]);
    omega = vector(y[3], y[4], y[5]);
    return true;
}


// ************************************************************************* //

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

#include "multiplierSolver.H"
#include "smallDenseSolve.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::multiplierSolver::multiplierSolver
(
    const scalar tolerance,
    const label maxIterations,
    const bool twoD
)
:
    tolerance_(tolerance),
    maxIterations_(maxIterations),
    twoD_(twoD)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::multiplierSolver::applyA
(
    const collocationSet& s,
    const scalar dt,
    const UList<vector>& x,
    vectorField& work,
    UList<vector>& y
)
{
    work = Zero;
    forAll(s.points, k)
    {
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            work[s.rowCell[e]] += s.rowWeight[e]*x[k];
        }
    }
    forAll(work, c)
    {
        work[c] *= dt*s.invVolume[c];
    }
    forAll(s.points, k)
    {
        vector sum(Zero);
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            sum += s.rowWeight[e]*work[s.rowCell[e]];
        }
        y[k] = sum;
    }
}


Foam::scalarField Foam::multiplierSolver::inverseDiagonal
(
    const collocationSet& s,
    const scalar dt
)
{
    scalarField invDiag(s.points.size());
    forAll(s.points, k)
    {
        scalar d = 0;
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            d += sqr(s.rowWeight[e])*s.invVolume[s.rowCell[e]];
        }
        invDiag[k] = 1/(dt*d);
    }
    return invDiag;
}



// To |r| <= tolerance max(|b|, normFloor): the floor keeps a right-hand side
// of round-off size (a fluid already moving with the body) from being
// chased into A's near null space
Foam::label Foam::multiplierSolver::conjugateGradient
(
    const collocationSet& s,
    const scalar dt,
    const UList<vector>& b,
    const scalar normFloor,
    const scalarField& invDiag,
    vectorField& x,
    scalar& residual
) const
{
    const label n = b.size();
    x.setSize(n);
    x = Zero;
    vectorField work(s.invVolume.size());

    vectorField r(b);
    scalar normB = 0;
    for (const vector& v : b)
    {
        normB += magSqr(v);
    }
    normB = max(std::sqrt(normB), normFloor);
    residual = 0;
    if (normB == 0)
    {
        return 0;
    }

    for (const vector& v : r)
    {
        residual += magSqr(v);
    }
    residual = std::sqrt(residual)/normB;
    if (residual <= tolerance_)
    {
        return 0;
    }

    vectorField z(n), p(n), Ap(n);
    forAll(z, k)
    {
        z[k] = invDiag[k]*r[k];
    }
    p = z;
    scalar rz = 0;
    forAll(r, k)
    {
        rz += r[k] & z[k];
    }

    for (label it = 1; it <= maxIterations_; ++it)
    {
        applyA(s, dt, p, work, Ap);
        scalar pAp = 0;
        forAll(p, k)
        {
            pAp += p[k] & Ap[k];
        }
        const scalar alpha = rz/pAp;
        scalar rr = 0;
        forAll(x, k)
        {
            x[k] += alpha*p[k];
            r[k] -= alpha*Ap[k];
            rr += magSqr(r[k]);
        }
        residual = std::sqrt(rr)/normB;
        if (residual <= tolerance_)
        {
            return it;
        }
        scalar rzNew = 0;
        forAll(z, k)
        {
            z[k] = invDiag[k]*r[k];
            rzNew += r[k] & z[k];
        }
        const scalar beta = rzNew/rz;
        rz = rzNew;
        forAll(p, k)
        {
            p[k] = z[k] + beta*p[k];
        }
    }
    return -1;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::multiplierSolver::solve
(
    const label particle,
    const rigidBody& B,
    collocationSet& s,
    const scalar dt,
    vectorField& f,
    outcome& out
) const
{
    const label n = s.points.size();
    vectorField& u = s.u;

    // Right-hand side g = V* + Omega* x r - B u_hat (in-plane in 2D)
    const auto Bu = [&](const label k)
    {
        vector sum(Zero);
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            sum += s.rowWeight[e]*u[s.rowCell[e]];
        }
        return sum;
    };
    const auto inPlane = [&](vector v)
    {
        if (twoD_)
        {
            v.z() = 0;
        }
        return v;
    };
    vectorField g(n);
    scalar velocityScale2 = 0;
    forAll(g, k)
    {
        const vector r = s.points[k] - B.centre;
        const vector rigid = B.V + (B.omega ^ r);
        const vector fluid = Bu(k);
        g[k] = inPlane(rigid - fluid);
        velocityScale2 += max(magSqr(rigid), magSqr(fluid));
    }

    scalar residual = 0;
    const scalarField invDiag(inverseDiagonal(s, dt));
    const auto cg = [&]
    (
        const UList<vector>& rhs,
        const scalar floor,
        vectorField& x
    )
    {
        const label it =
            conjugateGradient(s, dt, rhs, floor, invDiag, x, residual);
        if (it < 0)
        {
            FatalErrorInFunction
                << "particle " << particle << ": the fictitious-domain CG"
                << " did not reach the tolerance " << tolerance_ << " in "
                << maxIterations_ << " iterations (residual "
                << residual << "); raise maxIterations or tolerance"
                << " in constant/dlmfdProperties" << exit(FatalError);
        }
        out.iterations = max(out.iterations, it);
    };

    // The multipliers for the velocities as they are; the tolerance is
    // relative to the velocities at the points, not to their
    // difference from the rigid motion
    vectorField lambda;
    cg(g, std::sqrt(velocityScale2), lambda);

    vector w_V(Zero), w_Omega(Zero);
    if (B.free)
    {
        // The rigid modes: translations e_a, rotations e_a x r;
        // in 2D only x, y and the rotation about z
        const labelList modes
        (
            twoD_
          ? (B.rotates ? labelList{0, 1, 5} : labelList{0, 1})
          : (B.rotates ? labelList{0, 1, 2, 3, 4, 5} : labelList{0, 1, 2})
        );
        const auto mode = [&](const label a, const label k)
        {
            vector e(Zero);
            e[a % 3] = 1;
            return a < 3 ? e : (e ^ (s.points[k] - B.centre));
        };
        const label nm = modes.size();
        List<vectorField> Umodes(nm, vectorField(n));
        List<vectorField> Z(nm);
        forAll(modes, i)
        {
            forAll(Umodes[i], k)
            {
                Umodes[i][k] = inPlane(mode(modes[i], k));
            }
            cg(Umodes[i], 0, Z[i]);
        }

        // K = C^-1 + U^T Z; C^-1 = diag((m-1) v_p, (m-1) J)/dt
        const scalar vp = B.volume;
        const tensor& J = B.volumeInertia;
        List<scalarList> K(nm, scalarList(nm, scalar(0)));
        scalarList rhs(nm, scalar(0));
        forAll(modes, i)
        {
            const label a = modes[i];
            forAll(modes, j)
            {
                const label c = modes[j];
                scalar sum = 0;
                for (label k = 0; k < n; ++k)
                {
                    sum += Umodes[i][k] & Z[j][k];
                }
                K[i][j] = sum;
                if (a < 3 && c < 3 && a == c)
                {
                    K[i][j] += B.excessDensity*vp/dt;
                }
                else if (a >= 3 && c >= 3)
                {
                    K[i][j] += B.excessDensity*J(a - 3, c - 3)/dt;
                }
            }
            for (label k = 0; k < n; ++k)
            {
                rhs[i] += Umodes[i][k] & lambda[k];
            }
        }
        if (!smallDenseSolve(K, rhs))
        {
            FatalErrorInFunction
                << "particle " << particle << ": the rigid-mode system of"
                << " the fictitious-domain step is singular (m = "
                << 1 + B.excessDensity << ", " << n << " points);"
                << " the particle needs m > 0 and cells inside it"
                << exit(FatalError);
        }
        forAll(modes, i)
        {
            const label a = modes[i];
            forAll(lambda, k)
            {
                lambda[k] -= rhs[i]*Z[i][k];
            }
            if (a < 3)
            {
                w_V[a] = rhs[i];
            }
            else
            {
                w_Omega[a - 3] = rhs[i];
            }
        }
    }
    out.dV = -w_V;
    out.dOmega = -w_Omega;

    // The fluid in the body's cells, and the new force density
    f.setSize(u.size());
    f = Zero;
    forAll(s.points, k)
    {
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            f[s.rowCell[e]] += s.rowWeight[e]*lambda[k];
        }
        out.sumLambda += lambda[k];
        out.sumMoment += (s.points[k] - B.centre) ^ lambda[k];
    }
    forAll(f, i)
    {
        f[i] *= s.invVolume[i];
        u[i] += dt*f[i];
    }

    // What is left of the constraint
    const vector Vnew = B.V - w_V;
    const vector omegaNew = B.omega - w_Omega;
    forAll(s.points, k)
    {
        const vector r = s.points[k] - B.centre;
        out.constraintError = max
        (
            out.constraintError,
            mag(inPlane(Bu(k) - (Vnew + (omegaNew ^ r))))
        );
    }
}


// ************************************************************************* //

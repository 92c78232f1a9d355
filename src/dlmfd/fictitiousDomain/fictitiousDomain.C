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

#include "fictitiousDomain.H"
#include "particleGeometry.H"
#include "Switch.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

//- The collocation points of one body and the interpolation B from its
//- cells to them (rows in CSR over the body's local cell indices)
struct Foam::fictitiousDomain::collocationSet
{
    labelList cells;
    List<point> points;
    label nInterior = 0;
    labelList rowStart;
    labelList rowCell;
    scalarList rowWeight;
    scalarList invVolume;   // 1/V_c of the local cells
};



namespace
{

using namespace Foam;

//- Solve the small dense system a x = b (n <= 6) by Gauss elimination
//- with partial pivoting; false if it is singular to round-off
bool denseSolve(List<scalarList>& a, scalarList& b)
{
    const label n = b.size();
    scalar scale = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            scale = max(scale, mag(a[i][j]));
        }
    }
    for (label k = 0; k < n; ++k)
    {
        label p = k;
        for (label i = k + 1; i < n; ++i)
        {
            if (mag(a[i][k]) > mag(a[p][k]))
            {
                p = i;
            }
        }
        if (mag(a[p][k]) <= 1e-13*scale)
        {
            return false;
        }
        std::swap(a[p], a[k]);
        std::swap(b[p], b[k]);
        for (label i = k + 1; i < n; ++i)
        {
            const scalar f = a[i][k]/a[k][k];
            for (label j = k; j < n; ++j)
            {
                a[i][j] -= f*a[k][j];
            }
            b[i] -= f*b[k];
        }
    }
    for (label k = n - 1; k >= 0; --k)
    {
        scalar s = b[k];
        for (label j = k + 1; j < n; ++j)
        {
            s -= a[k][j]*b[j];
        }
        b[k] = s/a[k][k];
    }
    return true;
}


//- y = A x = dt B M^-1 B^T x
void applyA
(
    const fictitiousDomain::collocationSet& s,
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


//- The inverse diagonal of A, the Jacobi preconditioner
scalarField inverseDiagonal(const fictitiousDomain::collocationSet& s, const scalar dt)
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


//- Jacobi-preconditioned conjugate gradients on A x = b (x starts at 0),
//- to |r| <= tolerance max(|b|, normFloor): the floor keeps a right-hand
//- side of round-off size (a fluid already moving with the body) from
//- being chased into A's near null space; returns the iterations, -1 if
//- the tolerance was not reached
label conjugateGradient
(
    const fictitiousDomain::collocationSet& s,
    const scalar dt,
    const UList<vector>& b,
    const scalar tolerance,
    const label maxIterations,
    const scalar normFloor,
    const scalarField& invDiag,
    vectorField& x,
    scalar& residual
)
{
    const label n = b.size();
    x.setSize(n);
    x = Zero;
    vectorField work(s.cells.size());

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

    residual = 0;
    for (const vector& v : r)
    {
        residual += magSqr(v);
    }
    residual = std::sqrt(residual)/normB;
    if (residual <= tolerance)
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

    for (label it = 1; it <= maxIterations; ++it)
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
        if (residual <= tolerance)
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

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fictitiousDomain::cellSize(const scalar V) const
{
    // In 2D the cells are one layer deep: the in-plane size
    if (twoD_)
    {
        return std::sqrt(V/mesh_.bounds().span().z());
    }
    return std::cbrt(V);
}


bool Foam::fictitiousDomain::fitWeights
(
    const point& p,
    const UList<label>& cells,
    scalarList& weights
) const
{
    // u(c) ~ a + G.(x_c - p): weights of a by linear least squares,
    // w = X (X^T X)^-1 e_0, lengths scaled by the cell size
    const label nCoeff = twoD_ ? 3 : 4;
    if (cells.size() < nCoeff)
    {
        return false;
    }
    const vectorField& C = mesh_.C();
    const scalar h = cellSize(mesh_.V()[cells[0]]);

    List<scalarList> XtX(nCoeff, scalarList(nCoeff, scalar(0)));
    List<scalarList> rows(cells.size(), scalarList(nCoeff));
    forAll(cells, i)
    {
        const vector d = (C[cells[i]] - p)/h;
        rows[i][0] = 1;
        rows[i][1] = d.x();
        rows[i][2] = d.y();
        if (!twoD_)
        {
            rows[i][3] = d.z();
        }
        for (label a = 0; a < nCoeff; ++a)
        {
            for (label b = 0; b < nCoeff; ++b)
            {
                XtX[a][b] += rows[i][a]*rows[i][b];
            }
        }
    }
    scalarList e0(nCoeff, scalar(0));
    e0[0] = 1;
    if (!denseSolve(XtX, e0))
    {
        return false;
    }
    weights.setSize(cells.size());
    forAll(cells, i)
    {
        scalar w = 0;
        for (label a = 0; a < nCoeff; ++a)
        {
            w += rows[i][a]*e0[a];
        }
        weights[i] = w;
    }
    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fictitiousDomain::fictitiousDomain
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    surfacePoints_(dict.getOrDefault<Switch>("surfacePoints", true)),
    surfaceSpacing_(dict.getOrDefault<scalar>("surfacePointSpacing", 1)),
    stencilRadius_(dict.getOrDefault<scalar>("surfaceStencilRadius", 1.2)),
    retraction_(dict.getOrDefault<scalar>("surfacePointRetraction", 0)),
    tolerance_(dict.getOrDefault<scalar>("tolerance", 1e-10)),
    maxIterations_(dict.getOrDefault<label>("maxIterations", 1000)),
    search_(mesh),
    twoD_(mesh.nSolutionD() == 2),
    cellOwner_(mesh.nCells(), -1),
    ownerDist2_(mesh.nCells(), GREAT),
    ownerInside_(mesh.nCells(), false),
    touched_(),
    source_
    (
        IOobject
        (
            "lambdaSource",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimAcceleration, Zero)
    )
{
    if (!(surfaceSpacing_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "surfacePointSpacing = " << surfaceSpacing_ << " is not"
            << " allowed; it must be > 0 (in cell sizes)"
            << exit(FatalIOError);
    }
    if (!(stencilRadius_ >= 1))
    {
        FatalIOErrorInFunction(dict)
            << "surfaceStencilRadius = " << stencilRadius_ << " is not"
            << " allowed; it must be >= 1 (in cell sizes)"
            << exit(FatalIOError);
    }
    if (!(retraction_ >= 0 && retraction_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "surfacePointRetraction = " << retraction_ << " is not"
            << " allowed; 0 <= it < 1 (in cell sizes)" << exit(FatalIOError);
    }
    if (!(tolerance_ > 0 && tolerance_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "tolerance = " << tolerance_ << " is not allowed;"
            << " 0 < tolerance < 1 (relative residual of the CG solves)"
            << exit(FatalIOError);
    }
    if (maxIterations_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxIterations = " << maxIterations_ << " is not allowed;"
            << " it must be >= 1" << exit(FatalIOError);
    }
    if (twoD_ && mesh.geometricD()[2] > 0)
    {
        FatalErrorInFunction
            << "a 2D mesh must have its empty direction along z (the"
            << " planar particles move in the x-y plane); its solution"
            << " directions are " << mesh.solutionD() << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fictitiousDomain::claim
(
    const label c,
    const label b,
    const scalar d2,
    const bool inside
)
{
    if (cellOwner_[c] < 0)
    {
        touched_.append(c);
    }
    const bool wins =
        cellOwner_[c] < 0
     || (inside && !ownerInside_[c])
     || (inside == ownerInside_[c] && d2 < ownerDist2_[c]);
    if (wins)
    {
        cellOwner_[c] = b;
        ownerDist2_[c] = d2;
        ownerInside_[c] = inside;
    }
}


void Foam::fictitiousDomain::findCandidates
(
    const UList<body>& bodies,
    candidates& cand
)
{
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalar zPlane = twoD_ ? mesh_.bounds().centre().z() : 0;

    // The claims of the last step are undone
    for (const label c : touched_)
    {
        cellOwner_[c] = -1;
        ownerDist2_[c] = GREAT;
        ownerInside_[c] = false;
    }
    touched_.clear();

    List<DynamicList<label>>& interior = cand.interior;
    List<DynamicList<point>>& surface = cand.surface;
    List<List<labelList>>& stencils = cand.stencils;
    interior.setSize(bodies.size());
    surface.setSize(bodies.size());
    stencils.setSize(bodies.size());
    DynamicList<label> near;
    forAll(bodies, b)
    {
        const body& B = bodies[b];
        const particleShape& shape = *B.shape;
        const scalar rb = shape.boundingRadius();

        near.clear();
        search_.cellsInBall(B.centre, rb, near);
        if (near.empty())
        {
            FatalErrorInFunction
                << "particle " << b << " at " << B.centre << " has no"
                << " cell centre of the mesh within its bounding radius "
                << rb << " m: it is outside the mesh, or smaller than a"
                << " cell" << exit(FatalError);
        }
        scalar meanV = 0;
        for (const label c : near)
        {
            meanV += V[c];
        }
        const scalar h = cellSize(meanV/near.size());

        near.clear();
        search_.cellsInBall(B.centre, rb + 2*h, near);
        for (const label c : near)
        {
            if (particleGeometry::contains(shape, B.centre, B.R, C[c]))
            {
                interior[b].append(c);
                claim(c, b, magSqr(C[c] - B.centre), true);
            }
        }

        DynamicList<point> pts;
        if (surfacePoints_)
        {
            particleGeometry::surfacePoints
            (
                shape, B.centre, B.R, surfaceSpacing_*h, zPlane, pts
            );
            if (retraction_ > 0)
            {
                // Towards the centre by retraction h (in the plane in 2D)
                for (point& p : pts)
                {
                    vector d = p - B.centre;
                    if (twoD_)
                    {
                        d.z() = 0;
                    }
                    const scalar r = mag(d);
                    if (r > VSMALL)
                    {
                        p -= (min(retraction_*h, 0.5*r)/r)*d;
                    }
                }
            }
        }
        // Each surface point's velocity is the linear least-squares fit
        // of the fluid cells around it outside the body, extrapolated to
        // the point: the constraint puts the no-slip surface where the
        // body's surface is, without making those cells move rigidly
        // (a stencil across the surface did: the body acted half a cell
        // thicker)
        stencils[b].setSize(pts.size());
        DynamicList<label> ball;
        forAll(pts, k)
        {
            ball.clear();
            search_.cellsInBall(pts[k], stencilRadius_*h, ball);
            DynamicList<label> st;
            for (const label c : ball)
            {
                if (!particleGeometry::contains(shape, B.centre, B.R, C[c]))
                {
                    st.append(c);
                }
            }
            for (const label c : st)
            {
                claim(c, b, magSqr(C[c] - B.centre), false);
            }
            stencils[b][k].transfer(st);
        }
        surface[b].transfer(pts);
    }
}


void Foam::fictitiousDomain::assemble
(
    const label b,
    const candidates& cand,
    labelList& localIndex,
    collocationSet& s,
    result& res
) const
{
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const List<DynamicList<label>>& interior = cand.interior;
    const List<DynamicList<point>>& surface = cand.surface;
    const List<List<labelList>>& stencils = cand.stencils;

    // The body's points and B, with the cells it owns
    DynamicList<label> cells;
    DynamicList<point> points;
    DynamicList<label> rowStart, rowCell;
    DynamicList<scalar> rowWeight;
    const auto localOf = [&](const label c)
    {
        if (localIndex[c] < 0)
        {
            localIndex[c] = cells.size();
            cells.append(c);
        }
        return localIndex[c];
    };
    for (const label c : interior[b])
    {
        if (cellOwner_[c] != b)
        {
            continue;
        }
        rowStart.append(rowCell.size());
        rowCell.append(localOf(c));
        rowWeight.append(1);
        points.append(C[c]);
    }
    s.nInterior = points.size();

    DynamicList<label> st;
    scalarList w;
    forAll(surface[b], k)
    {
        st.clear();
        for (const label c : stencils[b][k])
        {
            if (cellOwner_[c] == b)
            {
                st.append(c);
            }
        }
        if (st.empty() || !fitWeights(surface[b][k], st, w))
        {
            ++res.nSurfaceDropped;
            continue;
        }
        rowStart.append(rowCell.size());
        forAll(st, i)
        {
            rowCell.append(localOf(st[i]));
            rowWeight.append(w[i]);
        }
        points.append(surface[b][k]);
    }
    rowStart.append(rowCell.size());
    for (const label c : cells)
    {
        localIndex[c] = -1;
    }

    s.cells.transfer(cells);
    s.points.transfer(points);
    s.rowStart.transfer(rowStart);
    s.rowCell.transfer(rowCell);
    s.rowWeight.transfer(rowWeight);
    s.invVolume.setSize(s.cells.size());
    forAll(s.cells, i)
    {
        s.invVolume[i] = 1/V[s.cells[i]];
    }
    res.nInterior = s.nInterior;
    res.interiorCells = SubList<label>(s.cells, s.nInterior);
    res.nSurface = s.points.size() - s.nInterior;
}


void Foam::fictitiousDomain::solveBody
(
    const label b,
    const body& B,
    const collocationSet& s,
    const scalar dt,
    vectorField& u,
    result& res
)
{
    const label n = s.points.size();

    // Right-hand side g = V* + Omega* x r - B u_hat (in-plane in 2D)
    const auto Bu = [&](const label k, const vectorField& field)
    {
        vector sum(Zero);
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            sum += s.rowWeight[e]*field[s.cells[s.rowCell[e]]];
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
        const vector fluid = Bu(k, u);
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
        const label it = conjugateGradient
        (
            s, dt, rhs, tolerance_, maxIterations_, floor, invDiag, x,
            residual
        );
        if (it < 0)
        {
            FatalErrorInFunction
                << "particle " << b << ": the fictitious-domain CG did"
                << " not reach the tolerance " << tolerance_ << " in "
                << maxIterations_ << " iterations (residual "
                << residual << "); raise maxIterations or tolerance"
                << " in constant/dlmfdProperties" << exit(FatalError);
        }
        res.iterations = max(res.iterations, it);
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
            twoD_ ? labelList{0, 1, 5} : labelList{0, 1, 2, 3, 4, 5}
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
        const scalar vp = B.shape->volume();
        const tensor J =
            B.R & B.shape->volumeInertia() & B.R.T();
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
        if (!denseSolve(K, rhs))
        {
            FatalErrorInFunction
                << "particle " << b << ": the rigid-mode system of the"
                << " fictitious-domain step is singular (m = "
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
    res.dV = -w_V;
    res.dOmega = -w_Omega;

    // The fluid in the body's cells, and the new force density
    vectorField spread(s.cells.size(), Zero);
    forAll(s.points, k)
    {
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            spread[s.rowCell[e]] += s.rowWeight[e]*lambda[k];
        }
        res.sumLambda += lambda[k];
        res.sumMoment += (s.points[k] - B.centre) ^ lambda[k];
    }
    forAll(s.cells, i)
    {
        const label c = s.cells[i];
        const vector f = spread[i]*s.invVolume[i];
        source_.primitiveFieldRef()[c] = f;
        u[c] += dt*f;
    }

    // What is left of the constraint
    const vector Vnew = B.V - w_V;
    const vector omegaNew = B.omega - w_Omega;
    forAll(s.points, k)
    {
        const vector r = s.points[k] - B.centre;
        res.constraintError = max
        (
            res.constraintError,
            mag(inPlane(Bu(k, u) - (Vnew + (omegaNew ^ r))))
        );
    }
}


const Foam::List<Foam::fictitiousDomain::result>&
Foam::fictitiousDomain::solve
(
    volVectorField& U,
    const UList<body>& bodies,
    const scalar dt
)
{
    // The fluid without the previous multipliers' force
    vectorField& u = U.primitiveFieldRef();
    u -= dt*source_.primitiveField();
    source_.primitiveFieldRef() = Zero;

    // Every body's candidate points, and the cells shared out
    candidates cand;
    findCandidates(bodies, cand);

    // Each body's problem on the cells it owns
    results_.setSize(bodies.size());
    labelList localIndex(mesh_.nCells(), -1);
    forAll(bodies, b)
    {
        result& res = results_[b];
        res = result();
        collocationSet s;
        assemble(b, cand, localIndex, s, res);
        if (s.points.size())
        {
            solveBody(b, bodies[b], s, dt, u, res);
        }
    }

    U.correctBoundaryConditions();
    source_.correctBoundaryConditions();
    return results_;
}

// ************************************************************************* //

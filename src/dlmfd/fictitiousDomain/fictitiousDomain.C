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
#include "smallDenseSolve.H"
#include "fictitiousDomainParts.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

Ostream& operator<<(Ostream& os, const fictitiousDomain::contribution& c)
{
    os  << c.body << token::SPACE << c.centres << token::SPACE << c.volumes
        << token::SPACE << c.u << token::SPACE << c.nInterior
        << token::SPACE << c.nCut
        << token::SPACE << c.deviation << token::SPACE << c.released
        << token::SPACE << c.releasedMoment
        << token::SPACE << c.surfacePoint << token::SPACE << c.stencilStart
        << token::SPACE << c.stencilCell;
    return os;
}


Istream& operator>>(Istream& is, fictitiousDomain::contribution& c)
{
    is  >> c.body >> c.centres >> c.volumes >> c.u >> c.nInterior
        >> c.nCut
        >> c.deviation >> c.released >> c.releasedMoment
        >> c.surfacePoint >> c.stencilStart >> c.stencilCell;
    return is;
}

} // End namespace Foam


namespace
{

using namespace Foam;

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


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::fictitiousDomain::surfaceTreatment>
Foam::fictitiousDomain::surfaceTreatmentNames
({
    {surfaceTreatment::fluidStencil, "fluidStencil"},
    {surfaceTreatment::ghostCells, "ghostCells"},
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fictitiousDomain::reach() const
{
    // Ghost cells: the fits' largest radius about a surface point;
    // surface stencils: their radius, and two cells for the inside search
    return treatment_ == surfaceTreatment::ghostCells
        ? ghostFitRadius_
        : max(scalar(2), stencilRadius_);
}


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
    const UList<point>& centres,
    const scalar h,
    scalarList& weights
) const
{
    // u(c) ~ a + G.(x_c - p): weights of a by linear least squares,
    // w = X (X^T X)^-1 e_0, lengths scaled by the cell size
    const label nCoeff = twoD_ ? 3 : 4;
    if (centres.size() < nCoeff)
    {
        return false;
    }

    List<scalarList> XtX(nCoeff, scalarList(nCoeff, scalar(0)));
    List<scalarList> rows(centres.size(), scalarList(nCoeff));
    forAll(centres, i)
    {
        const vector d = (centres[i] - p)/h;
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
    if (!smallDenseSolve(XtX, e0))
    {
        return false;
    }
    weights.setSize(centres.size());
    forAll(centres, i)
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


Foam::IOobject Foam::fictitiousDomain::ghostFieldIO
(
    const fvMesh& mesh,
    const word& name
) const
{
    // Read and written with the ghost cells only
    const bool ghost = treatment_ == surfaceTreatment::ghostCells;
    return IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        ghost ? IOobject::READ_IF_PRESENT : IOobject::NO_READ,
        ghost ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fictitiousDomain::fictitiousDomain
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    treatment_
    (
        surfaceTreatmentNames.getOrDefault
        (
            "surfaceTreatment", dict, surfaceTreatment::fluidStencil
        )
    ),
    ghostFitRadius_(dict.getOrDefault<scalar>("ghostFitRadius", 2.5)),
    forceCutCells_(dict.getOrDefault<Switch>("ghostCutCells", false)),
    surfacePoints_(dict.getOrDefault<Switch>("surfacePoints", true)),
    surfaceSpacing_(dict.getOrDefault<scalar>("surfacePointSpacing", 1)),
    stencilRadius_(dict.getOrDefault<scalar>("surfaceStencilRadius", 1.2)),
    retraction_(dict.getOrDefault<scalar>("surfacePointRetraction", 0)),
    tolerance_(dict.getOrDefault<scalar>("tolerance", 1e-10)),
    maxIterations_(dict.getOrDefault<label>("maxIterations", 1000)),
    search_(mesh),
    twoD_(mesh.nSolutionD() == 2),
    period_(Zero),
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
    ),
    deviation_
    (
        ghostFieldIO(mesh, "ghostDeviation"),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    ),
    ghostOwner_
    (
        ghostFieldIO(mesh, "ghostOwner"),
        mesh,
        dimensionedScalar("none", dimless, -1)
    ),
    results_(),
    commSeconds_(0)
{
    if (!(surfaceSpacing_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "surfacePointSpacing = " << surfaceSpacing_ << " is not"
            << " allowed; it must be > 0 (in cell sizes)"
            << exit(FatalIOError);
    }
    if (!(ghostFitRadius_ >= 1.5))
    {
        FatalIOErrorInFunction(dict)
            << "ghostFitRadius = " << ghostFitRadius_ << " is not"
            << " allowed; it must be >= 1.5 (in cell sizes)"
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

void Foam::fictitiousDomain::discardStoredState(const fileName& particleFile)
{
    const bool stored =
        gMax(mag(source_.primitiveField())) > 0
     || gMax(mag(deviation_.primitiveField())) > 0;
    if (stored)
    {
        Info<< "DLM/FD: " << source_.name() << " and " << deviation_.name()
            << " of time " << mesh_.time().timeName() << " set to zero:"
            << " the particles come from " << particleFile
            << ", not from the solver's uniform/particles of that time"
            << endl;
    }
    source_ == dimensionedVector(source_.dimensions(), Zero);
    deviation_ == dimensionedVector(deviation_.dimensions(), Zero);
    ghostOwner_ == dimensionedScalar("none", dimless, -1);
}


void Foam::fictitiousDomain::setPeriodicity(const vector& period)
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (period[d] < 0)
        {
            FatalErrorInFunction
                << "period " << period << " is not allowed: each component"
                << " must be > 0, or 0 for a direction that is not periodic"
                << exit(FatalError);
        }
    }
    period_ = period;
}


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


Foam::scalarList Foam::fictitiousDomain::cellSizes
(
    const UList<body>& bodies
) const
{
    // The mean volume of the cells within each body's bounding radius,
    // summed over the ranks
    const scalarField& V = mesh_.V();
    scalarField sumV(bodies.size(), Zero);
    scalarField count(bodies.size(), Zero);
    DynamicList<label> near;
    forAll(bodies, b)
    {
        const body& B = bodies[b];
        const scalar rb = B.shape->boundingRadius();
        const List<vector> shifts
        (
            cellCentreSearch::periodicShifts
            (
                mesh_.bounds(), period_, B.centre, rb
            )
        );
        for (const vector& s : shifts)
        {
            near.clear();
            search_.cellsInBall(B.centre - s, rb, near);
            for (const label c : near)
            {
                sumV[b] += V[c];
            }
            count[b] += near.size();
        }
    }
    clockTime clock;
    reduce(sumV, sumOp<scalarField>());
    reduce(count, sumOp<scalarField>());
    commSeconds_ += clock.elapsedTime();

    scalarList h(bodies.size());
    forAll(bodies, b)
    {
        if (count[b] == 0)
        {
            FatalErrorInFunction
                << "particle " << b << " at " << bodies[b].centre << " has"
                << " no cell centre of the mesh within its bounding radius "
                << bodies[b].shape->boundingRadius() << " m: it is outside"
                << " the mesh, or smaller than a cell" << exit(FatalError);
        }
        h[b] = cellSize(sumV[b]/count[b]);

        // A body must not meet itself across a period
        const scalar reach =
            bodies[b].shape->boundingRadius() + this->reach()*h[b];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (period_[d] > 0 && !(2*reach < period_[d]))
            {
                FatalErrorInFunction
                    << "particle " << b << ": its bounding radius with the"
                    << " stencils, " << reach << " m, is not below half the"
                    << " period " << period_[d] << " m in direction "
                    << label(d) << "; the periodic box must be longer than"
                    << " twice that" << exit(FatalError);
            }
        }
    }
    return h;
}


void Foam::fictitiousDomain::surfacePointsOf
(
    const body& B,
    const scalar h,
    DynamicList<point>& pts
) const
{
    pts.clear();
    if (!surfacePoints_)
    {
        return;
    }
    const scalar zPlane = twoD_ ? mesh_.bounds().centre().z() : 0;
    particleGeometry::surfacePoints
    (
        *B.shape, B.centre, B.R, surfaceSpacing_*h, zPlane, pts
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


void Foam::fictitiousDomain::startCandidates
(
    const UList<body>& bodies,
    candidates& cand
)
{
    // The claims of the last step are undone
    for (const label c : touched_)
    {
        cellOwner_[c] = -1;
        ownerDist2_[c] = GREAT;
        ownerInside_[c] = false;
    }
    touched_.clear();

    const label n = bodies.size();
    cand.h = cellSizes(bodies);
    cand.shifts.setSize(n);
    cand.interior.setSize(n);
    cand.interiorShift.setSize(n);
    cand.stencils.setSize(n);
    cand.stencilShifts.setSize(n);
}


void Foam::fictitiousDomain::findCandidates
(
    const UList<body>& bodies,
    candidates& cand
)
{
    startCandidates(bodies, cand);
    if (treatment_ == surfaceTreatment::ghostCells)
    {
        findGhostCandidates(bodies, cand);
        return;
    }

    const vectorField& C = mesh_.C();

    DynamicList<label> near;
    DynamicList<point> pts;
    forAll(bodies, b)
    {
        const body& B = bodies[b];
        const particleShape& shape = *B.shape;
        const scalar rb = shape.boundingRadius();
        const scalar h = cand.h[b];
        cand.shifts[b] = cellCentreSearch::periodicShifts
        (
            mesh_.bounds(), period_, B.centre, rb + reach()*h
        );
        const List<vector>& shifts = cand.shifts[b];

        // A cell at C counts at C + s: it is near the body at x when C is
        // near x - s
        forAll(shifts, si)
        {
            near.clear();
            search_.cellsInBall(B.centre - shifts[si], rb + 2*h, near);
            for (const label c : near)
            {
                const point x = C[c] + shifts[si];
                if (particleGeometry::contains(shape, B.centre, B.R, x))
                {
                    cand.interior[b].append(c);
                    cand.interiorShift[b].append(si);
                    claim(c, b, magSqr(x - B.centre), true);
                }
            }
        }

        // Each surface point's velocity is the linear least-squares fit
        // of the fluid cells around it outside the body, extrapolated to
        // the point: the constraint puts the no-slip surface where the
        // body's surface is, without making those cells move rigidly
        // (a stencil across the surface did: the body acted half a cell
        // thicker)
        surfacePointsOf(B, h, pts);
        cand.stencils[b].setSize(pts.size());
        cand.stencilShifts[b].setSize(pts.size());
        forAll(pts, k)
        {
            DynamicList<label> st, stShift;
            forAll(shifts, si)
            {
                near.clear();
                search_.cellsInBall
                (
                    pts[k] - shifts[si], stencilRadius_*h, near
                );
                for (const label c : near)
                {
                    const point x = C[c] + shifts[si];
                    if (!particleGeometry::contains(shape, B.centre, B.R, x))
                    {
                        st.append(c);
                        stShift.append(si);
                        claim(c, b, magSqr(x - B.centre), false);
                    }
                }
            }
            cand.stencils[b][k].transfer(st);
            cand.stencilShifts[b][k].transfer(stShift);
        }
    }
}


void Foam::fictitiousDomain::collect
(
    const label b,
    const candidates& cand,
    const vectorField& u,
    labelList& localIndex,
    contribution& con,
    labelList& cells
) const
{
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const List<vector>& shifts = cand.shifts[b];

    DynamicList<label> cellList;
    DynamicList<point> centres;
    const auto localOf = [&](const label c, const label si)
    {
        if (localIndex[c] < 0)
        {
            localIndex[c] = cellList.size();
            cellList.append(c);
            centres.append(C[c] + shifts[si]);
        }
        return localIndex[c];
    };

    forAll(cand.interior[b], i)
    {
        const label c = cand.interior[b][i];
        if (cellOwner_[c] == b)
        {
            localOf(c, cand.interiorShift[b][i]);
        }
    }
    con.nInterior = cellList.size();

    DynamicList<label> surfacePoint, stencilStart, stencilCell;
    label nSent = -1;
    if (treatment_ == surfaceTreatment::ghostCells)
    {
        // The fluid cells its surface cuts (claimed by it: the closest
        // surface), forced and written back; then the other fluid cells
        // near it (in no body), data only
        const labelList& near = cand.stencils[b][0];
        forAll(near, i)
        {
            const label c = near[i];
            if (cellOwner_[c] == b && !ownerInside_[c])
            {
                localOf(c, cand.stencilShifts[b][0][i]);
            }
        }
        con.nCut = cellList.size() - con.nInterior;
        nSent = cellList.size();
        forAll(near, i)
        {
            const label c = near[i];
            if (cellOwner_[c] < 0 || !ownerInside_[c])
            {
                localOf(c, cand.stencilShifts[b][0][i]);
            }
        }
    }
    else
    {
        forAll(cand.stencils[b], k)
        {
            const labelList& st = cand.stencils[b][k];
            const label start = stencilCell.size();
            forAll(st, i)
            {
                if (cellOwner_[st[i]] == b)
                {
                    stencilCell.append
                    (
                        localOf(st[i], cand.stencilShifts[b][k][i])
                    );
                }
            }
            if (stencilCell.size() > start)
            {
                surfacePoint.append(k);
                stencilStart.append(start);
            }
        }
    }
    stencilStart.append(stencilCell.size());

    for (const label c : cellList)
    {
        localIndex[c] = -1;
    }
    con.body = b;
    if (treatment_ == surfaceTreatment::ghostCells)
    {
        // A cell's deviation is this body's only if it held the cell
        con.deviation.setSize(con.nInterior);
        for (label i = 0; i < con.nInterior; ++i)
        {
            const label c = cellList[i];
            con.deviation[i] =
                label(ghostOwner_[c]) == b ? deviation_[c] : Zero;
        }
    }
    con.centres.transfer(centres);
    con.volumes.setSize(cellList.size());
    con.u.setSize(cellList.size());
    forAll(cellList, i)
    {
        con.volumes[i] = V[cellList[i]];
        con.u[i] = u[cellList[i]];
    }
    con.surfacePoint.transfer(surfacePoint);
    con.stencilStart.transfer(stencilStart);
    con.stencilCell.transfer(stencilCell);
    cells.transfer(cellList);
    if (nSent >= 0)
    {
        // Only the inside cells get a force back
        cells.setSize(nSent);
    }
}


void Foam::fictitiousDomain::assemble
(
    const body& B,
    const scalar h,
    const UList<const contribution*>& parts,
    collocationSet& s,
    result& res
) const
{
    // The cells, rank after rank
    label nCells = 0;
    for (const contribution* c : parts)
    {
        nCells += c->centres.size();
    }
    s.centres.setSize(nCells);
    s.invVolume.setSize(nCells);
    s.u.setSize(nCells);
    labelList offset(parts.size());
    nCells = 0;
    forAll(parts, r)
    {
        const contribution& c = *parts[r];
        offset[r] = nCells;
        forAll(c.centres, i)
        {
            s.centres[nCells] = c.centres[i];
            s.invVolume[nCells] = 1/c.volumes[i];
            s.u[nCells] = c.u[i];
            ++nCells;
        }
    }

    DynamicList<point> points;
    DynamicList<label> rowStart, rowCell;
    DynamicList<scalar> rowWeight;

    // Interior points: the centres of the cells inside
    forAll(parts, r)
    {
        for (label i = 0; i < parts[r]->nInterior; ++i)
        {
            rowStart.append(rowCell.size());
            rowCell.append(offset[r] + i);
            rowWeight.append(1);
            points.append(s.centres[offset[r] + i]);
        }
    }
    s.nInterior = points.size();

    // Surface points: the fit of their stencils, gathered from the ranks
    DynamicList<point> surface;
    surfacePointsOf(B, h, surface);
    List<DynamicList<label>> stencil(surface.size());
    forAll(parts, r)
    {
        const contribution& c = *parts[r];
        forAll(c.surfacePoint, j)
        {
            DynamicList<label>& st = stencil[c.surfacePoint[j]];
            for (label e = c.stencilStart[j]; e < c.stencilStart[j + 1]; ++e)
            {
                st.append(offset[r] + c.stencilCell[e]);
            }
        }
    }
    scalarList w;
    forAll(surface, k)
    {
        const List<point> centres(UIndirectList<point>(s.centres, stencil[k]));
        if (stencil[k].empty() || !fitWeights(surface[k], centres, h, w))
        {
            ++res.nSurfaceDropped;
            continue;
        }
        rowStart.append(rowCell.size());
        forAll(stencil[k], i)
        {
            rowCell.append(stencil[k][i]);
            rowWeight.append(w[i]);
        }
        points.append(surface[k]);
    }
    rowStart.append(rowCell.size());

    s.points.transfer(points);
    s.rowStart.transfer(rowStart);
    s.rowCell.transfer(rowCell);
    s.rowWeight.transfer(rowWeight);
    res.nInterior = s.nInterior;
    res.nSurface = s.points.size() - s.nInterior;
}


void Foam::fictitiousDomain::solveBody
(
    const label b,
    const body& B,
    collocationSet& s,
    const scalar dt,
    vectorField& f,
    result& res
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
        if (!smallDenseSolve(K, rhs))
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
    f.setSize(u.size());
    f = Zero;
    forAll(s.points, k)
    {
        for (label e = s.rowStart[k]; e < s.rowStart[k + 1]; ++e)
        {
            f[s.rowCell[e]] += s.rowWeight[e]*lambda[k];
        }
        res.sumLambda += lambda[k];
        res.sumMoment += (s.points[k] - B.centre) ^ lambda[k];
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
        res.constraintError = max
        (
            res.constraintError,
            mag(inPlane(Bu(k) - (Vnew + (omegaNew ^ r))))
        );
    }
}


void Foam::fictitiousDomain::gatherResults()
{
    // Each body was solved on one rank, zero elsewhere: sums give it
    constexpr label nValues = 17;
    scalarList values(nValues*results_.size(), Zero);
    forAll(results_, b)
    {
        const result& r = results_[b];
        scalar* v = &values[nValues*b];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            v[d] = r.dV[d];
            v[3 + d] = r.dOmega[d];
            v[6 + d] = r.sumLambda[d];
            v[9 + d] = r.sumMoment[d];
        }
        v[12] = r.nInterior;
        v[13] = r.nSurface;
        v[14] = r.nSurfaceDropped;
        v[15] = r.iterations;
        v[16] = r.constraintError;
    }
    Pstream::listCombineGather(values, plusEqOp<scalar>());
    if (!Pstream::master())
    {
        return;
    }
    forAll(results_, b)
    {
        result& r = results_[b];
        const scalar* v = &values[nValues*b];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            r.dV[d] = v[d];
            r.dOmega[d] = v[3 + d];
            r.sumLambda[d] = v[6 + d];
            r.sumMoment[d] = v[9 + d];
        }
        r.nInterior = label(v[12]);
        r.nSurface = label(v[13]);
        r.nSurfaceDropped = label(v[14]);
        r.iterations = label(v[15]);
        r.constraintError = v[16];
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
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const auto solverOf = [&](const label b) { return b % nProcs; };

    // The fluid without the previous multipliers' force
    vectorField& u = U.primitiveFieldRef();
    u -= dt*source_.primitiveField();
    source_.primitiveFieldRef() = Zero;


    // Every body's candidate points on this rank, and the cells shared out
    candidates cand;
    findCandidates(bodies, cand);

    results_.setSize(bodies.size());
    for (result& r : results_)
    {
        r = result();
    }

    // This rank's cells of each body, to the rank that solves it
    List<List<labelList>> sentCells(nProcs);
    List<labelList> sentBodies(nProcs);
    {
        List<DynamicList<labelList>> cellsTo(nProcs);
        List<DynamicList<label>> bodiesTo(nProcs);
        PstreamBuffers toSolvers(Pstream::commsTypes::nonBlocking);
        List<DynamicList<contribution>> outgoing(nProcs);
        labelList localIndex(mesh_.nCells(), -1);
        List<vector> released, releasedMoment;
        if (treatment_ == surfaceTreatment::ghostCells)
        {
            releasedDeviations(bodies, released, releasedMoment);
        }
        forAll(bodies, b)
        {
            contribution con;
            labelList cells;
            collect(b, cand, u, localIndex, con, cells);
            if (released.size())
            {
                con.released = released[b];
                con.releasedMoment = releasedMoment[b];
            }
            if (con.centres.empty() && con.released == vector::zero)
            {
                continue;
            }
            result& res = results_[b];
            res.interiorCells = SubList<label>(cells, con.nInterior);
            res.interiorCentres = SubList<point>(con.centres, con.nInterior);
            const label q = solverOf(b);
            bodiesTo[q].append(b);
            cellsTo[q].append(std::move(cells));
            outgoing[q].append(std::move(con));
        }
        // The deviations of the last step are in the contributions now;
        // this step sets those of the cells inside a body
        deviation_.primitiveFieldRef() = Zero;
        ghostOwner_.primitiveFieldRef() = -1;
        for (label q = 0; q < nProcs; ++q)
        {
            sentCells[q].transfer(cellsTo[q]);
            sentBodies[q].transfer(bodiesTo[q]);
            // One by one: a List of them would be checked for equal
            // elements, which contributions do not compare
            UOPstream os(q, toSolvers);
            os << outgoing[q].size();
            for (const contribution& con : outgoing[q])
            {
                os << con;
            }
        }
        clockTime clock;
        toSolvers.finishedSends();
        commSeconds_ += clock.timeIncrement();

        // The bodies this rank solves, from the cells of every rank
        List<List<contribution>> incoming(nProcs);
        for (label r = 0; r < nProcs; ++r)
        {
            UIPstream is(r, toSolvers);
            label size = 0;
            is >> size;
            incoming[r].setSize(size);
            for (contribution& con : incoming[r])
            {
                is >> con;
            }
        }
        List<DynamicList<const contribution*>> partsOf(bodies.size());
        List<DynamicList<labelPair>> whereFrom(bodies.size());
        forAll(incoming, r)
        {
            forAll(incoming[r], j)
            {
                const label b = incoming[r][j].body;
                partsOf[b].append(&incoming[r][j]);
                whereFrom[b].append(labelPair(r, j));
            }
        }

        // Solve, and send each rank the force density of its cells (and,
        // with ghost cells, their deviation from the rigid motion)
        const bool ghost = treatment_ == surfaceTreatment::ghostCells;
        List<List<vectorField>> forces(nProcs), deviations(nProcs);
        forAll(incoming, r)
        {
            forces[r].setSize(incoming[r].size());
            deviations[r].setSize(ghost ? incoming[r].size() : 0);
        }
        forAll(bodies, b)
        {
            if (solverOf(b) != me || partsOf[b].empty())
            {
                continue;
            }
            result& res = results_[b];
            vectorField f, dev;
            if (ghost)
            {
                solveGhostBody
                (
                    bodies[b], cand.h[b], partsOf[b], dt, f, dev, res
                );
            }
            else
            {
                collocationSet s;
                assemble(bodies[b], cand.h[b], partsOf[b], s, res);
                f.setSize(s.u.size(), Zero);
                if (s.points.size())
                {
                    solveBody(b, bodies[b], s, dt, f, res);
                }
            }
            label start = 0;
            for (const labelPair& rj : whereFrom[b])
            {
                const contribution& con = incoming[rj.first()][rj.second()];
                const label size =
                    ghost ? con.nInterior + con.nCut : con.u.size();
                forces[rj.first()][rj.second()] =
                    SubField<vector>(f, size, start);
                if (ghost)
                {
                    deviations[rj.first()][rj.second()] =
                        SubField<vector>(dev, size, start);
                }
                start += size;
            }
        }

        clock.timeIncrement();
        PstreamBuffers toOwners(Pstream::commsTypes::nonBlocking);
        for (label r = 0; r < nProcs; ++r)
        {
            UOPstream os(r, toOwners);
            os << forces[r] << deviations[r];
        }
        toOwners.finishedSends();
        commSeconds_ += clock.timeIncrement();
        vectorField& src = source_.primitiveFieldRef();
        for (label q = 0; q < nProcs; ++q)
        {
            List<vectorField> back, backDev;
            UIPstream is(q, toOwners);
            is >> back >> backDev;
            forAll(back, j)
            {
                const labelList& cells = sentCells[q][j];
                forAll(cells, i)
                {
                    src[cells[i]] = back[j][i];
                    u[cells[i]] += dt*back[j][i];
                }
            }
            forAll(backDev, j)
            {
                // The owner's bodies in the order it sent them
                const label b = sentBodies[q][j];
                // The body's own cells first, then the fluid cells it cut
                // (fluid: no deviation of the body's)
                const label nInside = results_[b].interiorCells.size();
                results_[b].interiorDeviation =
                    SubField<vector>(backDev[j], nInside);
                const labelList& cells = sentCells[q][j];
                for (label i = 0; i < nInside; ++i)
                {
                    deviation_[cells[i]] = backDev[j][i];
                    ghostOwner_[cells[i]] = b;
                }
            }
        }
    }

    {
        clockTime clock;
        gatherResults();
        commSeconds_ += clock.elapsedTime();
    }

    U.correctBoundaryConditions();
    source_.correctBoundaryConditions();
    deviation_.correctBoundaryConditions();
    ghostOwner_.correctBoundaryConditions();
    return results_;
}

// ************************************************************************* //

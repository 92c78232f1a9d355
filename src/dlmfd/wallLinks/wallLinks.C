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

#include "wallLinks.H"
#include "linear.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::FixedList<Foam::scalar, 3> Foam::wallLinks::slopeWeights
(
    const scalar d,
    const scalar hE,
    const scalar a
)
{
    // Along the line from the wall (y = 0) through c (y1 = d) to E (y2 =
    // d + hE), the face at yf = d - a: the derivative there of the
    // parabola through the three (Lagrange), or of the line through two
    FixedList<scalar, 3> w;
    if (!(hE > 0))
    {
        w[0] = -1/d;
        w[1] = 1/d;
        w[2] = 0;
        return w;
    }
    const scalar y1 = d, y2 = d + hE, yf = d - a;
    w[0] = ((yf - y1) + (yf - y2))/(y1*y2);
    w[1] = (yf + (yf - y2))/(y1*(y1 - y2));
    w[2] = (yf + (yf - y1))/(y2*(y2 - y1));
    return w;
}


Foam::vector Foam::wallLinks::oppositeVelocity
(
    const link& L,
    const vectorField& u,
    const PtrList<vectorField>& uNbr
) const
{
    const label fo = L.opposite;
    if (fo < 0)
    {
        return Zero;
    }
    if (fo < mesh_.nInternalFaces())
    {
        const label o = mesh_.faceOwner()[fo];
        return u[o == L.fluid ? mesh_.faceNeighbour()[fo] : o];
    }
    const label patchi = mesh_.boundaryMesh().whichPatch(fo);
    return uNbr[patchi][fo - mesh_.boundaryMesh()[patchi].start()];
}


Foam::PtrList<Foam::vectorField> Foam::wallLinks::neighbourVelocities
(
    const volVectorField& U
) const
{
    PtrList<vectorField> uNbr(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        if (mesh_.boundary()[patchi].coupled())
        {
            uNbr.set
            (
                patchi,
                U.boundaryField()[patchi].patchNeighbourField().ptr()
            );
        }
    }
    return uNbr;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

namespace
{
    // A list of the links' history: read and written with the links only
    Foam::IOobject historyIO
    (
        const Foam::fvMesh& mesh,
        const Foam::word& name,
        const bool on
    )
    {
        return Foam::IOobject
        (
            name, mesh.time().timeName(), "uniform", mesh,
            on ? Foam::IOobject::READ_IF_PRESENT : Foam::IOobject::NO_READ,
            on ? Foam::IOobject::AUTO_WRITE : Foam::IOobject::NO_WRITE
        );
    }
}


Foam::wallLinks::wallLinks(const fvMesh& mesh, const bool on)
:
    mesh_(mesh),
    links_(),
    historyMomentum_(historyIO(mesh, "wallLinkHistoryMomentum", on)),
    historyMoment_(historyIO(mesh, "wallLinkHistoryMoment", on)),
    historyIndex_(),
    lastPayIndex_(-1),
    places_()
{
    if (historyMomentum_.size() != historyMoment_.size())
    {
        FatalErrorInFunction
            << historyMomentum_.objectPath() << " has "
            << historyMomentum_.size() << " entries and "
            << historyMoment_.objectPath() << " " << historyMoment_.size()
            << "; both need one per particle" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::wallLinks::placeOf(const label global) const
{
    const label b = places_(global);
    if (b < 0)
    {
        FatalErrorInFunction
            << "a ghost cell belongs to particle " << global
            << " (global index), which this rank does not hold"
            << exit(FatalError);
    }
    return b;
}


void Foam::wallLinks::addCrossing
(
    const scan& s,
    link L,
    const point& a,
    const point& b,
    const label bi,
    const vector& S,
    const point& xf
)
{
    // A link from fluid cell c at a to the body cell's centre b through
    // the face with outward area S (from c) and centre xf
    const label bp = placeOf(bi);
    const scalar t = crossing(s.bodies[bp], s.images, a, b, L.uWall, L.arm);
    const vector e = (b - a)/mag(b - a);
    L.body = bp;
    L.d = t*mag(b - a);
    L.a = (xf - a) & e;
    // The third point: the fluid cell beyond c's opposite face, or
    // where the line meets that cell's body (a gap of one cell)
    point beyond;
    label beyondBody = -1;
    L.opposite = oppositeFace
    (
        L.fluid, S, s.owner, s.ownerNbr, s.deltaNbr, beyond, beyondBody
    );
    if (L.opposite >= 0 && beyondBody < 0)
    {
        L.hE = mag(beyond - a);
    }
    else if (L.opposite >= 0)
    {
        vector arm;
        L.hE = crossing
        (
            s.bodies[placeOf(beyondBody)], s.images, a, beyond, L.uFar, arm
        )*mag(beyond - a);
        L.farWall = true;
        L.opposite = -1;
    }
    links_.append(L);
}


bool Foam::wallLinks::addThrough
(
    const scan& s,
    link L,
    const point& a,
    const point& b,
    const label bi,
    const point& xf
)
{
    // Each side of a face between two fluid cells whose line passes
    // through a body: a link to its own wall, the line through the wall
    // and its centre
    const label bp = placeOf(bi);
    scalar tIn, tOut;
    vector uIn, uOut, armIn, armOut;
    if
    (
        !passesThrough
        (
            s.bodies[bp], s.images, a, b, tIn, tOut, uIn, uOut, armIn,
            armOut
        )
    )
    {
        return false;
    }
    const scalar Delta = mag(b - a);
    L.through = true;
    L.d = max(tIn, minFraction)*Delta;
    L.a = (xf - a) & (b - a)/Delta;
    L.uWall = uIn;
    L.arm = armIn;
    L.body = bp;
    links_.append(L);
    return true;
}


Foam::label Foam::wallLinks::addThroughAny
(
    const scan& s,
    const link& L,
    const point& a,
    const point& b,
    const FixedList<label, 2>& candidates,
    const point& xf
)
{
    for (const label bi : candidates)
    {
        if (bi < 0)
        {
            break;
        }
        if (addThrough(s, L, a, b, bi, xf))
        {
            return bi;
        }
    }
    return -1;
}


Foam::FixedList<Foam::label, 2> Foam::wallLinks::nearPair
(
    const scalar a,
    const scalar b
)
{
    // The two cells' near bodies, the lower index first (both sides of a
    // coupled face see the same pair)
    FixedList<label, 2> c({label(min(a, b)), label(max(a, b))});
    if (c[0] < 0 || c[0] == c[1])
    {
        c[0] = c[1];
        c[1] = -1;
    }
    return c;
}


Foam::tmp<Foam::volScalarField> Foam::wallLinks::nearBodies
(
    const scalarField& body
) const
{
    // The fluid cells within two faces of a body's cell, each with that
    // body (the nearest in hops, of two met at the same hop the lower
    // index: not the first in face order, which changes with the
    // decomposition; across coupled patches too, so that both sides of a
    // face agree)
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    tmp<volScalarField> tnear
    (
        new volScalarField
        (
            IOobject
            (
                "wallLinksNear",
                mesh_.time().timeName(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh_,
            dimensionedScalar("none", dimless, -1),
            calculatedFvPatchScalarField::typeName
        )
    );
    volScalarField& near = tnear.ref();
    scalarField& nearBody = near.primitiveFieldRef();
    for (int hop = 0; hop < 2; ++hop)
    {
        // A cell's mark: its body, or the body it reached by the last hop
        volScalarField mark
        (
            IOobject
            (
                "wallLinksMark",
                mesh_.time().timeName(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            near
        );
        forAll(body, celli)
        {
            if (body[celli] >= 0)
            {
                mark[celli] = body[celli];
            }
        }
        mark.correctBoundaryConditions();
        const scalarField reached(mark.primitiveField());
        const scalarField before(nearBody);
        const auto meet = [&](const label celli, const scalar m)
        {
            if
            (
                body[celli] < 0 && before[celli] < 0 && m >= 0
             && (nearBody[celli] < 0 || m < nearBody[celli])
            )
            {
                nearBody[celli] = m;
            }
        };
        forAll(nei, f)
        {
            meet(nei[f], reached[own[f]]);
            meet(own[f], reached[nei[f]]);
        }
        forAll(mesh_.boundary(), patchi)
        {
            const fvPatch& p = mesh_.boundary()[patchi];
            if (!p.coupled())
            {
                continue;
            }
            const scalarField markNbr
            (
                mark.boundaryField()[patchi].patchNeighbourField()
            );
            forAll(p.faceCells(), i)
            {
                meet(p.faceCells()[i], markNbr[i]);
            }
        }
    }
    near.correctBoundaryConditions();
    return tnear;
}


void Foam::wallLinks::addThroughLinks
(
    const scan& s,
    const volScalarField& near
)
{
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& Cf = mesh_.Cf().primitiveField();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& body = s.owner;
    const scalarField& nearBody = near.primitiveField();
    forAll(nei, f)
    {
        const label o = own[f], n = nei[f];
        if (body[o] >= 0 || body[n] >= 0)
        {
            continue;
        }
        link A;
        A.face = f;
        A.fluid = o;
        A.solid = n;
        const label bi = addThroughAny
        (
            s, A, C[o], C[n], nearPair(nearBody[o], nearBody[n]), Cf[f]
        );
        if (bi >= 0)
        {
            link B(A);
            B.fluid = n;
            B.solid = o;
            addThrough(s, B, C[n], C[o], bi, Cf[f]);
        }
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled())
        {
            continue;
        }
        const scalarField nearNbr
        (
            near.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField& bodyNbr = s.ownerNbr[patchi];
        const vectorField& delta = s.deltaNbr[patchi];
        forAll(p.faceCells(), i)
        {
            const label l = p.faceCells()[i];
            if (body[l] >= 0 || bodyNbr[i] >= 0)
            {
                continue;
            }
            // This side's row only; the other side adds its own
            link L;
            L.patch = patchi;
            L.patchFace = i;
            L.fluid = l;
            addThroughAny
            (
                s, L, C[l], C[l] + delta[i],
                nearPair(nearBody[l], nearNbr[i]), p.Cf()[i]
            );
        }
    }
}


void Foam::wallLinks::update
(
    const volScalarField& owner,
    const UList<body>& bodies,
    const periodicImages& images
)
{
    links_.clear();
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& Sf = mesh_.Sf().primitiveField();
    const vectorField& Cf = mesh_.Cf().primitiveField();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    // The owner field holds global indices (so do the marks of
    // nearBodies, which cross the ranks and decide ties by index): a
    // body's place in bodies is looked up where its motion is needed
    places_ = bodyPlaces(bodies);
    globalOf_.setSize(bodies.size());
    forAll(bodies, b)
    {
        globalOf_[b] = bodyPlaces::global(bodies, b);
    }
    scan s{bodies, images, owner.primitiveField(), {}, {}};
    s.ownerNbr.setSize(mesh_.boundary().size());
    s.deltaNbr.setSize(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (p.coupled())
        {
            s.ownerNbr.set
            (
                patchi,
                owner.boundaryField()[patchi].patchNeighbourField().ptr()
            );
            s.deltaNbr.set(patchi, p.delta().ptr());
        }
    }
    const scalarField& body = s.owner;

    // The faces between a fluid and a body cell
    forAll(nei, f)
    {
        const label o = own[f], n = nei[f];
        const bool oBody = body[o] >= 0, nBody = body[n] >= 0;
        if (oBody == nBody)
        {
            continue;
        }
        link L;
        L.face = f;
        L.solid = oBody ? o : n;
        L.fluid = oBody ? n : o;
        addCrossing
        (
            s, L, C[L.fluid], C[L.solid], label(body[L.solid]),
            oBody ? -Sf[f] : Sf[f], Cf[f]
        );
    }

    // Links between two fluid cells that pass through a body (an edge or
    // a corner cut off)
    addThroughLinks(s, nearBodies(body)());

    // The coupled faces whose other side is a body cell
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled())
        {
            continue;
        }
        const labelUList& fc = p.faceCells();
        const scalarField& bodyNbr = s.ownerNbr[patchi];
        const vectorField& delta = s.deltaNbr[patchi];
        forAll(fc, i)
        {
            // Only where this side is the fluid one: the other side's
            // rank has the body's cell, whose row keeps the Laplacian
            if (body[fc[i]] >= 0 || bodyNbr[i] < 0)
            {
                continue;
            }
            link L;
            L.patch = patchi;
            L.patchFace = i;
            L.fluid = fc[i];
            addCrossing
            (
                s, L, C[fc[i]], C[fc[i]] + delta[i], label(bodyNbr[i]),
                p.Sf()[i], p.Cf()[i]
            );
        }
    }
}


Foam::tmp<Foam::fvVectorMatrix> Foam::wallLinks::matrix
(
    const volVectorField& U,
    const volScalarField& nu
)
{
    tmp<fvVectorMatrix> tm
    (
        new fvVectorMatrix(U, U.dimensions()*dimVol/dimTime)
    );
    fvVectorMatrix& m = tm.ref();
    const surfaceScalarField nuf(linearInterpolate(nu));
    const surfaceScalarField K(nuf*mesh_.magSf());
    const surfaceScalarField& dc = mesh_.deltaCoeffs();
    const labelUList& own = mesh_.owner();
    scalarField& diag = m.diag();
    vectorField& source = m.source();
    scalarField& upper = m.upper();
    scalarField& lower = m.lower();

    for (link& L : links_)
    {
        const label c = L.fluid;
        scalar k, k0;
        if (L.face >= 0)
        {
            k = K[L.face];
            k0 = k*dc[L.face];
        }
        else
        {
            k = K.boundaryField()[L.patch][L.patchFace];
            k0 = k*dc.boundaryField()[L.patch][L.patchFace];
        }
        const FixedList<scalar, 3> w = slopeWeights(L.d, L.hE, L.a);
        L.coeffs = {k*w[0], k*w[1], k*w[2], k0};

        // c's row: minus the gain -k (w0 u_w + w1 u_c + w2 u_E) through
        // the face, less the Laplacian's k0 (u_c - u_g)
        diag[c] += L.coeffs[1] - k0;
        source[c] -= L.coeffs[0]*L.uWall;
        // Across a coupled patch the coefficient of the other side's cell
        // is minus the patch's boundaryCoeffs (the solvers' interfaces),
        // so the row stays implicit there too: the same matrix on any
        // decomposition and across cyclic patches
        if (L.face >= 0)
        {
            (own[L.face] == c ? upper[L.face] : lower[L.face]) += k0;
        }
        else
        {
            m.boundaryCoeffs()[L.patch][L.patchFace] -= k0*vector::one;
        }
        const label fo = L.opposite;
        if (L.farWall)
        {
            source[c] -= L.coeffs[2]*L.uFar;
        }
        else if (fo >= mesh_.nInternalFaces())
        {
            const label patchi = mesh_.boundaryMesh().whichPatch(fo);
            m.boundaryCoeffs()[patchi][fo - mesh_.boundaryMesh()[patchi].start()]
                -= L.coeffs[2]*vector::one;
        }
        else if (fo >= 0)
        {
            (own[fo] == c ? upper[fo] : lower[fo]) += L.coeffs[2];
        }
    }
    return tm;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Description
    The step of Foam::fictitiousDomain (solve): each rank's cells of a
    body collected for the rank that solves it, the bodies solved, their
    forces put back into the rank's cells; the messages themselves are
    Foam::bodyExchange's.

\*---------------------------------------------------------------------------*/

#include "fictitiousDomain.H"
#include "fictitiousDomainParts.H"
#include "bodyExchange.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fictitiousDomain::collect
(
    const label b,
    const label global,
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
        if (owners_.owner(c) == b)
        {
            localOf(c, cand.interiorShift[b][i]);
        }
    }
    con.nInterior = cellList.size();

    // The fluid cells near it (in no body) that its treatment reads
    // (readsFluidNearSurface; none otherwise), data only
    const labelList& near = cand.near[b];
    forAll(near, i)
    {
        const label c = near[i];
        if (owners_.owner(c) < 0 || !owners_.inside(c))
        {
            localOf(c, cand.nearShift[b][i]);
        }
    }

    for (const label c : cellList)
    {
        localIndex[c] = -1;
    }
    con.body = global;
    // A cell's deviation is this body's only if it held the cell
    con.deviation.setSize(con.nInterior);
    for (label i = 0; i < con.nInterior; ++i)
    {
        const label c = cellList[i];
        con.deviation[i] =
            label(ghostOwner_[c]) == global ? deviation_[c] : Zero;
    }
    con.centres.transfer(centres);
    con.volumes.setSize(cellList.size());
    con.u.setSize(cellList.size());
    forAll(cellList, i)
    {
        con.volumes[i] = V[cellList[i]];
        con.u[i] = u[cellList[i]];
    }
    cells.transfer(cellList);
    // Only the inside cells get a force back
    cells.setSize(con.nInterior);
}


void Foam::fictitiousDomain::removeLastForce
(
    volVectorField& U,
    const scalar dt
)
{
    // The fluid without the previous multipliers' force: within the outer
    // loop, without S^n and without the share of G - S^n the time scheme
    // gave it (the fluid step's ddt diagonal a/dt), so that the fluid's
    // momentum lost is the bodies' gain however G was chosen
    vectorField& u = U.primitiveFieldRef();
    if (stepStart_.index == mesh_.time().timeIndex())
    {
        const scalarField& a = stepStart_.ddtCoeff;
        const vectorField& G = source_.primitiveField();
        u -= dt*stepStart_.source + (dt/a)*(G - stepStart_.source);
    }
    else
    {
        u -= dt*source_.primitiveField();
    }
    source_.primitiveFieldRef() = Zero;
}


void Foam::fictitiousDomain::refuseOwedNotHeld() const
{
    // Momentum given to a body this rank does not hold would be lost
    forAllConstIters(owed_.momentum, iter)
    {
        const label g = iter.key();
        if
        (
            places_(g) < 0
         && (
                owed_.momentum[g] != vector::zero
             || owed_.moment[g] != vector::zero
            )
        )
        {
            FatalErrorInFunction
                << "the fluid of rank " << Pstream::myProcNo()
                << " gave particle " << g << " momentum "
                << owed_.momentum[g] << " outside the step, but the rank"
                << " does not hold it: its list of bodies must hold every"
                << " body near its cells (holds())" << exit(FatalError);
        }
    }
}


void Foam::fictitiousDomain::gatherContributions
(
    const UList<body>& bodies,
    const candidates& cand,
    const vectorField& u,
    List<DynamicList<labelList>>& cellsTo,
    List<DynamicList<label>>& bodiesTo,
    List<DynamicList<contribution>>& outgoing
)
{
    labelList localIndex(mesh_.nCells(), -1);
    List<vector> owed, owedMoment;
    owedForCellsLeft(bodies, owed, owedMoment);
    forAll(bodies, b)
    {
        contribution con;
        labelList cells;
        const label global = bodyPlaces::global(bodies, b);
        collect(b, global, cand, u, localIndex, con, cells);
        con.owed = owed[b];
        con.owedMoment = owedMoment[b];
        if (owed_.momentum.found(global))
        {
            // Momentum the fluid gained outside the step (the wall
            // links), by global index
            con.owed += owed_.momentum[global];
            con.owedMoment += owed_.moment[global];
        }
        if (con.centres.empty() && con.owed == vector::zero)
        {
            continue;
        }
        result& res = results_[b];
        res.interiorCells = SubList<label>(cells, con.nInterior);
        res.interiorCentres = SubList<point>(con.centres, con.nInterior);
        const label q = cand.solver[b];
        traffic_.received.bodiesHere += 1;
        traffic_.received.cellsHere += cells.size();
        bodiesTo[q].append(b);
        cellsTo[q].append(std::move(cells));
        outgoing[q].append(std::move(con));
    }
}


void Foam::fictitiousDomain::sortIncoming
(
    const List<List<contribution>>& incoming,
    List<DynamicList<const contribution*>>& partsOf,
    List<DynamicList<labelPair>>& whereFrom
) const
{
    forAll(incoming, r)
    {
        forAll(incoming[r], j)
        {
            // Sent by global index: the body's place here
            const label b = places_(incoming[r][j].body);
            if (b < 0)
            {
                FatalErrorInFunction
                    << "rank " << r << " sent the cells of particle "
                    << incoming[r][j].body << " (global index), which"
                    << " rank " << Pstream::myProcNo() << " does not hold"
                    << exit(FatalError);
            }
            partsOf[b].append(&incoming[r][j]);
            whereFrom[b].append(labelPair(r, j));
        }
    }
}


void Foam::fictitiousDomain::prependMasterParts
(
    const UList<body>& bodies,
    const candidates& cand,
    List<contribution>& masterParts,
    List<DynamicList<const contribution*>>& partsOf
) const
{
    // With bodies per rank, the master's share of a body it does not
    // hold comes first, as the master's part did with every body on
    // every rank (sent when its momentum was not zero)
    if (!perRank_.on || owed_.masterMomentum.empty())
    {
        return;
    }
    const label me = Pstream::myProcNo();
    forAll(bodies, b)
    {
        const label g = bodyPlaces::global(bodies, b);
        if
        (
            cand.solver[b] == me
         && !cand.masterHolds[b]
         && owed_.masterMomentum.found(g)
         && owed_.masterMomentum[g] != vector::zero
        )
        {
            contribution& con = masterParts[b];
            con.body = g;
            con.owed = owed_.masterMomentum[g];
            con.owedMoment = owed_.masterMoment[g];
            DynamicList<const contribution*> parts(1, &con);
            parts.append(partsOf[b]);
            partsOf[b].transfer(parts);
        }
    }
}


void Foam::fictitiousDomain::solveHere
(
    const UList<body>& bodies,
    const candidates& cand,
    const List<List<contribution>>& incoming,
    const List<DynamicList<const contribution*>>& partsOf,
    const List<DynamicList<labelPair>>& whereFrom,
    const scalar dt,
    DynamicList<label>& solved,
    List<List<vectorField>>& forces,
    List<List<vectorField>>& deviations
)
{
    // Solve, and for each rank the force density of its cells and their
    // deviation from the rigid motion
    const label me = Pstream::myProcNo();
    forces.setSize(incoming.size());
    deviations.setSize(incoming.size());
    forAll(incoming, r)
    {
        forces[r].setSize(incoming[r].size());
        deviations[r].setSize(incoming[r].size());
    }
    forAll(bodies, b)
    {
        if (cand.solver[b] != me || partsOf[b].empty())
        {
            continue;
        }
        solved.append(b);
        result& res = results_[b];
        vectorField f, dev;
        treatment_->solveBody
        (
            bodies[b], cand.h[b], partsOf[b], dt, f, dev, res
        );
        label start = 0;
        for (const labelPair& rj : whereFrom[b])
        {
            const contribution& con = incoming[rj.first()][rj.second()];
            const label size = con.nInterior;
            forces[rj.first()][rj.second()] =
                SubField<vector>(f, size, start);
            vectorField& d = deviations[rj.first()][rj.second()];
            d = SubField<vector>(dev, size, start);
            if (dev.size() > f.size())
            {
                // A treatment that mirrors the wall velocity: those after
                d.append(SubField<vector>(dev, size, f.size() + start));
            }
            start += size;
        }
    }
}


void Foam::fictitiousDomain::applyReturned
(
    const UList<body>& bodies,
    const List<List<labelList>>& sentCells,
    const List<labelList>& sentBodies,
    const List<List<vectorField>>& backAll,
    const List<List<vectorField>>& backDevAll,
    const scalar dt,
    vectorField& u
)
{
    vectorField& src = source_.primitiveFieldRef();
    forAll(backAll, q)
    {
        const List<vectorField>& back = backAll[q];
        const List<vectorField>& backDev = backDevAll[q];
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
            // The body's own cells
            const label nInside = results_[b].interiorCells.size();
            results_[b].interiorDeviation =
                SubField<vector>(backDev[j], nInside);
            const labelList& cells = sentCells[q][j];
            const bool mirrored = backDev[j].size() > cells.size();
            for (label i = 0; i < nInside; ++i)
            {
                deviation_[cells[i]] = backDev[j][i];
                ghostOwner_[cells[i]] = bodyPlaces::global(bodies, b);
                if (mirrored)
                {
                    mirror_[cells[i]] = backDev[j][cells.size() + i];
                }
            }
        }
    }
}


void Foam::fictitiousDomain::finishSolve
(
    const UList<body>& bodies,
    const UList<label>& solved
)
{
    traffic_.received.bodiesSolved += solved.size();
    labelList destination(solved.size()), solvedGlobal(solved.size());
    forAll(solved, k)
    {
        destination[k] = bodies[solved[k]].resultRank;
        solvedGlobal[k] = bodyPlaces::global(bodies, solved[k]);
    }
    bodyExchange::sendResults
    (
        solved, solvedGlobal, destination, places_, results_, traffic_.commSeconds,
        traffic_.received
    );
    ++traffic_.nSolves;
}


const Foam::List<Foam::fictitiousDomain::result>&
Foam::fictitiousDomain::solve
(
    volVectorField& U,
    const UList<body>& bodies,
    const scalar dt,
    const bool outerCorrector
)
{
    const label nProcs = Pstream::nProcs();

    if (outerCorrector && stepStart_.index != mesh_.time().timeIndex())
    {
        FatalErrorInFunction
            << "an outer corrector's solve needs keepStepStart() first in"
            << " the step" << exit(FatalError);
    }
    removeLastForce(U, dt);
    vectorField& u = U.primitiveFieldRef();

    places_ = bodyPlaces(bodies);
    traffic_.received.bodiesListed += bodies.size();

    // Every body's candidate cells on this rank, and the cells shared out
    candidates cand;
    findGhostCandidates(bodies, cand);

    results_.setSize(bodies.size());
    for (result& r : results_)
    {
        r = result();
    }

    // This rank's cells of each body, to the rank that solves it; the
    // bodies this rank solved
    DynamicList<label> solved;
    List<List<labelList>> sentCells(nProcs);
    List<labelList> sentBodies(nProcs);
    {
        List<DynamicList<labelList>> cellsTo(nProcs);
        List<DynamicList<label>> bodiesTo(nProcs);
        List<DynamicList<contribution>> outgoing(nProcs);
        gatherContributions(bodies, cand, u, cellsTo, bodiesTo, outgoing);
        if (perRank_.on)
        {
            refuseOwedNotHeld();
        }
        owed_.momentum.clear();
        owed_.moment.clear();
        // The deviations of the last step are in the contributions now;
        // this step sets those of the cells inside a body
        deviation_.primitiveFieldRef() = Zero;
        ghostOwner_.primitiveFieldRef() = -1;
        mirror_.primitiveFieldRef() = Zero;
        for (label q = 0; q < nProcs; ++q)
        {
            sentCells[q].transfer(cellsTo[q]);
            sentBodies[q].transfer(bodiesTo[q]);
        }

        // The bodies this rank solves, from the cells of every rank
        const List<List<contribution>> incoming
        (
            bodyExchange::toSolvers(outgoing, traffic_.commSeconds, traffic_.received)
        );
        List<DynamicList<const contribution*>> partsOf(bodies.size());
        List<DynamicList<labelPair>> whereFrom(bodies.size());
        sortIncoming(incoming, partsOf, whereFrom);
        List<contribution> masterParts(bodies.size());
        prependMasterParts(bodies, cand, masterParts, partsOf);
        owed_.masterMomentum.clear();
        owed_.masterMoment.clear();

        List<List<vectorField>> forces, deviations;
        solveHere
        (
            bodies, cand, incoming, partsOf, whereFrom, dt, solved, forces,
            deviations
        );

        // Each rank's force density and deviations back to it
        List<List<vectorField>> backAll, backDevAll;
        bodyExchange::toOwners
        (
            forces, deviations, backAll, backDevAll, traffic_.commSeconds,
            traffic_.received
        );
        applyReturned
        (
            bodies, sentCells, sentBodies, backAll, backDevAll, dt, u
        );
    }

    if (outerCorrector)
    {
        // The next corrector's force: what makes its fluid step reach
        // this solve's velocities, u* + (dt/a) (G' - G) = u
        const scalarField& a = stepStart_.ddtCoeff;
        vectorField& G = source_.primitiveFieldRef();
        G = stepStart_.source + a*(G - stepStart_.source);
    }
    finishSolve(bodies, solved);

    U.correctBoundaryConditions();
    source_.correctBoundaryConditions();
    deviation_.correctBoundaryConditions();
    ghostOwner_.correctBoundaryConditions();
    mirror_.correctBoundaryConditions();
    return results_;
}

// ************************************************************************* //

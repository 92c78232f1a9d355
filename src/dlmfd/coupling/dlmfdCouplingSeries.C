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
    The particles' time series of Foam::dlmfdCoupling: a row per particle
    and step written (the master's whole scene, or with owned particles each
    rank's own), and the hydrodynamic forces handed to a particle's new
    owner before its row.

\*---------------------------------------------------------------------------*/

#include "dlmfdCoupling.H"
#include "Time.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dlmfdCoupling::handOverForces()
{
    // A particle whose centre crossed into another box in the granular
    // step has a new owner, which writes its row: the forces go there from
    // the rank that took its result (its owner at the step's start)
    const label self = Pstream::myProcNo();
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    List<DynamicList<label>> moved(Pstream::nProcs());
    for (const labelPair& gr : owned_->lastDepartures()[0])
    {
        moved[gr.second()].append(gr.first());
    }
    forAll(moved, q)
    {
        if (moved[q].size())
        {
            List<vector> forces(2*moved[q].size());
            forAll(moved[q], k)
            {
                forces[2*k] = Fh_[moved[q][k]];
                forces[2*k + 1] = Th_[moved[q][k]];
            }
            UOPstream os(q, buffers);
            os << labelList(moved[q]) << forces;
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);
    forAll(recvSizes, q)
    {
        if (q != self && recvSizes[q] > 0)
        {
            UIPstream is(q, buffers);
            labelList particles;
            List<vector> forces;
            is >> particles >> forces;
            forAll(particles, k)
            {
                Fh_[particles[k]] = forces[2*k];
                Th_[particles[k]] = forces[2*k + 1];
            }
        }
    }
}


void Foam::dlmfdCoupling::writeSeriesRows()
{
    // (with owned particles each owner has its particles' hydrodynamic
    // forces, and writes their rows)
    if (!output_.series.valid())
    {
        return;
    }
    OFstream& os = output_.series();
    const scalar t = mesh_.time().value();
    const scalar dt = mesh_.time().deltaTValue();
    // (i: the global index)
    const auto row = [&](const label i)
    {
        const rigidParticle& p = granular_.particle(mirrorPlace(i));
        const quaternion& q = p.orientation();
        const point& x = p.position();
        const vector& V = p.velocity();
        const vector& w = p.omega();
        // The mean contact force and torque over the step: the contacts'
        // impulse of the granular step over its length
        const vector Fc(p.contactImpulse()/dt);
        const vector Tc(p.contactAngularImpulse()/dt);
        os  << t << ' ' << granular_.id(mirrorPlace(i)) << ' '
            << x.x() << ' ' << x.y() << ' ' << x.z() << ' '
            << q.w() << ' ' << q.v().x() << ' ' << q.v().y() << ' '
            << q.v().z() << ' '
            << V.x() << ' ' << V.y() << ' ' << V.z() << ' '
            << w.x() << ' ' << w.y() << ' ' << w.z() << ' '
            << Fh_[i].x() << ' ' << Fh_[i].y() << ' ' << Fh_[i].z() << ' '
            << Th_[i].x() << ' ' << Th_[i].y() << ' ' << Th_[i].z() << ' '
            << Fc.x() << ' ' << Fc.y() << ' ' << Fc.z() << ' '
            << Tc.x() << ' ' << Tc.y() << ' ' << Tc.z()
            << nl;
    };
    if (seriesPerRank())
    {
        const granularSystem& part = *ownedScene_.part;
        const label timeIndex = mesh_.time().timeIndex();
        for (label k = 0; k < part.size(); ++k)
        {
            if (!part.ghost(k))
            {
                const label i = part.globalIndex(k);
                os  << timeIndex << ' ' << i << ' ';
                row(i);
            }
        }
    }
    else
    {
        for (label i = 0; i < granular_.size(); ++i)
        {
            row(i);
        }
    }
    os.flush();
}


// ************************************************************************* //

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
    and step written (the master's whole scene, or with owned particles on
    several ranks each rank's own).

\*---------------------------------------------------------------------------*/

#include "dlmfdCoupling.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
        const label place = distribution_->place(i);
        const rigidParticle& p = granular_.particle(place);
        const quaternion& q = p.orientation();
        const point& x = p.position();
        const vector& V = p.velocity();
        const vector& w = p.omega();
        // The mean contact force and torque over the step: the contacts'
        // impulse of the granular step over its length
        const vector Fc(p.contactImpulse()/dt);
        const vector Tc(p.contactAngularImpulse()/dt);
        os  << t << ' ' << granular_.id(place) << ' '
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
    if (distribution_->writesPerRank())
    {
        const label timeIndex = mesh_.time().timeIndex();
        for (const label i : distribution_->ownParticles())
        {
            os  << timeIndex << ' ' << i << ' ';
            row(i);
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

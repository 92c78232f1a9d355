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
    Checks of a state: the one a run starts from (checkStart, when a
    particle file is read) and the one each step leaves (checkHealth).
    Both stop the run naming the particles, their positions and, for a
    step, the time; neither writes anything, so that the last write time
    keeps the last good state.

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "OStringStream.H"
#include "problemList.H"
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    std::string str(const point& x)
    {
        OStringStream os;
        os.precision(8);
        os << x;
        return os.str();
    }

    // A number for a message: six digits whatever writePrecision the case
    // sets (the default stream precision follows controlDict)
    std::string num(const scalar v)
    {
        OStringStream os;
        os.precision(6);
        os << v;
        return os.str();
    }

    bool finite(const vector& v)
    {
        return std::isfinite(v.x() + v.y() + v.z());
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::string Foam::granularSystem::describeContact
(
    const labelPair& contact
) const
{
    const label i = contact.first(), j = contact.second();
    if (i < 0)
    {
        return "no contact";
    }
    std::string s =
        "particle " + std::to_string(ids_[i]) + " at "
      + str(particles_[i].position());
    if (j >= 0)
    {
        s += " and particle " + std::to_string(ids_[j]) + " at "
           + str(particles_[j].position());
    }
    else
    {
        s += " and wall " + walls_[-1 - j].name;
    }
    return s;
}


void Foam::granularSystem::checkStart(const fileName& file)
{
    using motionKind = rigidParticle::motionKind;
    const char* axis[] = {"x", "y", "z"};
    problemList problems;

    // Outside the domain along a direction that is not periodic (periodic
    // ones wrap), and planar particles turned out of the x-y plane
    const point& lo = settings_.domain().min();
    const point& hi = settings_.domain().max();
    for (label i = 0; i < size(); ++i)
    {
        const rigidParticle& p = particles_[i];
        const point& x = p.position();
        for (direction d = 0; d < 3; ++d)
        {
            if (!settings_.periodic()[d] && !(x[d] >= lo[d] && x[d] <= hi[d]))
            {
                problems.add
                (
                    "particle " + std::to_string(ids_[i]) + " at " + str(x)
                  + " is outside the domain along " + axis[d] + " ("
                  + Foam::name(lo[d]) + " to " + Foam::name(hi[d])
                  + " m, domain of collisionProperties)"
                );
                break;
            }
        }
        const quaternion& q = p.orientation();
        if (p.shape().planar() && (mag(q.v().x()) + mag(q.v().y()) > 1e-9))
        {
            OStringStream os;
            os.precision(8);
            os  << "particle " << ids_[i] << " (planar shape "
                << p.shape().name() << ") at " << str(x).c_str()
                << " has orientation (" << q.w() << ' ' << q.v().x() << ' '
                << q.v().y() << ' ' << q.v().z() << "), which turns it out"
                << " of the x-y plane; planar shapes turn about z only:"
                << " (cos(a/2) 0 0 sin(a/2))";
            problems.add(os.str());
        }
    }

    // Overlaps beyond the limit: no run of the solver leaves one (it
    // stops first), so it is a placement error
    if (contactsOn_ && size())
    {
        contactGeometry c;
        for (label i = 0; i < size(); ++i)
        {
            if (particles_[i].motion() != motionKind::free)
            {
                continue;
            }
            forAll(walls_, w)
            {
                if
                (
                    wallTouches(i, w, c)
                 && c.overlap > settings_.overlapLimit()*Deq_[i]
                )
                {
                    OStringStream os;
                    os  << describeContact(labelPair(i, -1 - w)).c_str()
                        << " overlap by " << num(c.overlap/Deq_[i]).c_str()
                        << " D";
                    problems.add(os.str());
                }
            }
        }

        DynamicList<labelPair> pairs;
        search_.cells().findPairs(positions(), radius_, 0, pairs);
        point xjImage;
        for (const labelPair& ij : pairs)
        {
            const label i = ij.first(), j = ij.second();
            if
            (
                particles_[i].motion() != motionKind::free
             && particles_[j].motion() != motionKind::free
            )
            {
                continue;
            }
            const scalar D = min(Deq_[i], Deq_[j]);
            if
            (
                pairTouches(i, j, c, xjImage)
             && c.overlap > settings_.overlapLimit()*D
            )
            {
                OStringStream os;
                os  << describeContact(ij).c_str() << " overlap by "
                    << num(c.overlap/D).c_str() << " D (of the smaller)";
                problems.add(os.str());
            }
        }
    }

    if (problems.size())
    {
        FatalErrorInFunction
            << file << ": " << problems.size() << " problem(s) with the"
            << " particles' positions:" << nl << problems.str().c_str()
            << "    Overlaps beyond overlapLimit = "
            << num(settings_.overlapLimit()).c_str()
            << " D (collisionProperties) are refused: move the particles"
            << " apart (placeParticles keeps a gap), into the domain, or"
            << " turn planar ones about z only." << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::granularSystem::checkHealth(const scalar time) const
{
    for (const label i : integrator_.moving())
    {
        const rigidParticle& p = particles_[i];
        if
        (
            !finite(p.position()) || !finite(p.velocity())
         || !finite(p.omega())
        )
        {
            FatalErrorInFunction
                << "time " << time << ": particle " << ids_[i] << " ("
                << shapeName(i) << ") is no longer finite: position "
                << p.position() << ", velocity " << p.velocity()
                << ", angular velocity " << p.omega() << nl
                << "    The run stops here without writing: the last write"
                << " time holds the last good state." << nl
                << "    A force on it blew up: the fluid's (check the"
                << " Courant number and the DLM/FD solves) or a contact's"
                << " (subStepsPerContact)." << exit(FatalError);
        }
    }
    if (stats_.maxOverlapRatio > settings_.overlapLimit())
    {
        FatalErrorInFunction
            << "time " << time << ": "
            << describeContact(stats_.maxOverlapContact).c_str()
            << " overlap by " << stats_.maxOverlapRatio
            << " D, beyond overlapLimit = " << settings_.overlapLimit() << " D"
            << " (constant/collisionProperties): the contact exploded" << nl
            << "    The run stops here without writing: the last write"
            << " time holds the last good state." << nl
            << "    Causes: a law too soft for the impact speed (raise kn"
            << " or impactVelocity), too few subStepsPerContact, or a"
            << " fluid force beyond what the contact can hold."
            << exit(FatalError);
    }
}


// ************************************************************************* //

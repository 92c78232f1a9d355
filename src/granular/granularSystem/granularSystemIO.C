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
    Input of the granular system: constant/collisionProperties (contact
    settings, domain, walls, laws) and the particle state files,
    <time>/particles:

    \verbatim
    particles
    (
    //  id shape material motion position      orientation (w x y z)
    //     [velocity] [angular velocity, world] [force] [torque]
        (0 cube glass free (0.01 0.02 0.03) (1 0 0 0))
        (1 ball glass free (0.05 0.02 0.03) (1 0 0 0) (0 0 -0.1) (0 0 0))
    );
    contacts    // laws with history: ((i j) history) per contact, by the
                // particles' places in the file; j < 0 for wall -1-j
    (
        ((0 1) (1e-6 0 0))
    );
    \endverbatim

    Velocities, forces and torques are optional in a file written by hand
    (zero); the solver writes them all, with 17 digits, so that a restart
    continues exactly.

\*---------------------------------------------------------------------------*/

#include "granularSystem.H"
#include "particleFileReader.H"
#include "IFstream.H"
#include "OFstream.H"
#include "IOobject.H"
#include "OSspecific.H"
#include "Map.H"
#include "OStringStream.H"
#include "knownKeywords.H"
#include "granularInput.H"
#include "uniformDimensionedFields.H"
#include "objectRegistry.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- A vector "(x y z)"
    vector readVector(Istream& is)
    {
        vector v;
        is >> v;
        return v;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::granularSystem::readCollision(const dictionary& collisionDict)
{
    // A misspelt optional keyword would leave its default in force
    knownKeywords::require
    (
        collisionDict,
        wordList
        ({
            "contactLaw", "subStepsPerContact", "subCycling",
            "particleDistribution", "overlapLimit", "skin", "domain",
            "walls", "wallPatches", "pairs"
        })
    );

    // The scene's settings, each checked as it is read
    settings_ = collisionSettings(collisionDict);
    search_.setSkin(settings_.skin());
    const dictionary& domainDict = collisionDict.subDict("domain");

    if (const dictionary* wallsDict = collisionDict.findDict("walls"))
    {
        for (const word& name : wallsDict->toc())
        {
            knownKeywords::require
            (
                collisionDict, wordList({"point", "normal", "material"}),
                "walls/" + name
            );
            walls_.append(planeWall::read(name, wallsDict->subDict(name)));
            wallMaterial_.append
            (
                materials_.addWallMaterial(walls_.last().material)
            );
        }
    }

    // Periodicity: the domain's directions; a declaration must agree
    const string domainName = domainDict.name();
    const bool anyPeriodic = settings_.anyPeriodic();
    const FixedList<bool, 3>& periodic = settings_.periodic();
    if
    (
        effects_.settle("periodicity", anyPeriodic, domainName + " periodic")
     != anyPeriodic
    )
    {
        effects_.contradiction
        (
            "periodicity",
            "the domain of " + domainName + " has periodic "
          + (anyPeriodic ? "directions " : "none ")
          + "(periodic (" + Switch::name(periodic[0]) + ' '
          + Switch::name(periodic[1]) + ' ' + Switch::name(periodic[2])
          + "))"
        );
    }

    // Collisions: off builds no law at all
    const word lawName = collisionDict.get<word>("contactLaw");
    collisionMode_ = effects_.settleCollisions
    (
        lawName == "none"
      ? sceneEffects::collisionMode::off
      : sceneEffects::collisionMode::on,
        "contactLaw " + lawName
    );
    contactsOn_ = collisionMode_ != sceneEffects::collisionMode::off;
    if (contactsOn_ && lawName == "none")
    {
        effects_.contradiction
        (
            "collisions",
            collisionDict.name() + " has contactLaw none; name a law"
            " (hookeanSpringDashpot, hookeanStaticFriction) and its pairs"
        );
    }
    // Friction is settled before the laws are built: they are built with it
    if (contactsOn_)
    {
        effects_.settle("friction", true, "default");
    }
    buildLaws();

    if (!contactsOn_)
    {
        effects_.settle("friction", false, "collisions off");
        effects_.settle("frictionHistory", false, "collisions off");
        if (effects_.declared("friction") && effects_.on("friction"))
        {
            effects_.contradiction("friction", "collisions are off");
        }
        if
        (
            effects_.declared("frictionHistory")
         && effects_.on("frictionHistory")
        )
        {
            effects_.contradiction("frictionHistory", "collisions are off");
        }
        return;
    }

    const bool history = laws_->needsHistory();
    const bool friction = effects_.on("friction");
    if
    (
        effects_.settle("frictionHistory", history, "contactLaw " + lawName)
     != history
    )
    {
        effects_.contradiction
        (
            "frictionHistory",
            "contactLaw " + lawName + " of " + collisionDict.name()
          + (
                history
              ? " keeps a tangential history; declare it on, or use"
                " hookeanSpringDashpot"
              : " keeps none; use hookeanStaticFriction"
            )
        );
    }
    if (history && !friction)
    {
        effects_.contradiction
        (
            "friction",
            "contactLaw " + lawName + " is a friction law with history;"
            " without friction use hookeanSpringDashpot"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::granularSystem::readParticles(const fileName& file)
{
    readParticles(particleFileReader::read(file), file);
}


void Foam::granularSystem::readParticles
(
    const dictionary& dict,
    const fileName& file
)
{
    particles_.clear();
    ids_.clear();
    globalIndex_.clear();
    ghost_.clear();
    shapeOf_.clear();
    materialOf_.clear();

    ITstream& is = dict.lookup("particles");
    is.format(IOstream::ASCII);
    Map<label> seen;

    is.readBegin("particles");
    token t(is);
    while (t != token::END_LIST)
    {
        if (t != token::BEGIN_LIST)
        {
            FatalIOErrorInFunction(is)
                << "in " << file << " line " << t.lineNumber()
                << ": expected a particle (id shape material motion"
                << " (x y z) (w x y z) ...), found " << t.info()
                << exit(FatalIOError);
        }
        const label id = readLabel(is);
        const word shapeName(is);
        const word materialName(is);
        const word motionName(is);
        const label line = is.lineNumber();

        if (!rigidParticle::motionKindNames.found(motionName))
        {
            FatalIOErrorInFunction(is)
                << "in " << file << " line " << line << ": particle " << id
                << ": motion " << motionName << " is not one of "
                << rigidParticle::motionKindNames.sortedToc()
                << exit(FatalIOError);
        }
        if (!seen.insert(id, size()))
        {
            FatalIOErrorInFunction(is)
                << "in " << file << " line " << line << ": particle id "
                << id << " is given twice" << exit(FatalIOError);
        }

        const point x = readVector(is);

        is.readBegin("orientation");
        scalar q[4];
        for (scalar& qk : q)
        {
            qk = readScalar(is);
        }
        is.readEnd("orientation");
        const scalar magQ = std::sqrt(sqr(q[0]) + sqr(q[1]) + sqr(q[2]) + sqr(q[3]));
        if (!(magQ > SMALL))
        {
            FatalIOErrorInFunction(is)
                << "in " << file << " line " << line << ": particle " << id
                << ": orientation (" << q[0] << ' ' << q[1] << ' ' << q[2]
                << ' ' << q[3] << ") is not a rotation; give a unit"
                << " quaternion (w x y z), (1 0 0 0) for none"
                << exit(FatalIOError);
        }

        // Optional: velocity, angular velocity (world), force, torque and
        // the contacts' share of these two (a restart)
        FixedList<vector, 6> extra(Zero);
        label nExtra = 0;
        token next(is);
        while (next == token::BEGIN_LIST)
        {
            if (nExtra == 6)
            {
                FatalIOErrorInFunction(is)
                    << "in " << file << " line " << next.lineNumber()
                    << ": particle " << id << " has more than six vectors"
                    << " after its orientation (velocity, angular velocity,"
                    << " force, torque, contact force, contact torque)"
                    << exit(FatalIOError);
            }
            is.putBack(next);
            is >> extra[nExtra++];
            next = token(is);
        }
        if (next != token::END_LIST)
        {
            FatalIOErrorInFunction(is)
                << "in " << file << " line " << next.lineNumber()
                << ": particle " << id << ": expected ')' or a vector,"
                << " found " << next.info() << exit(FatalIOError);
        }

        const label i = addParticle
        (
            id, shapeName, materialName, x,
            quaternion(q[0], vector(q[1], q[2], q[3]))
        );
        rigidParticle& p = particles_[i];
        if (mag(magQ - 1) < 1e-14)
        {
            // Written by the solver: kept to the bit
            p.restoreOrientation(quaternion(q[0], vector(q[1], q[2], q[3])));
        }
        p.setMotion(rigidParticle::motionKindNames[motionName]);
        p.setVelocity(extra[0]);
        p.setOmega(extra[1]);
        p.setStartForces(extra[2], extra[3], extra[4], extra[5]);

        t = token(is);
    }

    updateParticleData();

    // Contact history, for the laws that keep one
    if (dict.found("contacts"))
    {
        // Text, also when the dictionary came from the master through a
        // binary stream (a vector would be read raw)
        ITstream& cs = dict.lookup("contacts");
        cs.format(IOstream::ASCII);
        // Read contact by contact, not as a List: a counted list
        // ("N(...)") would allocate N entries before reading them, and
        // OpenFOAM's List leaks them when an entry is malformed
        cs.readBegin("contacts");
        token t(cs);
        while (t != token::END_LIST)
        {
            if (t != token::BEGIN_LIST)
            {
                FatalIOErrorInFunction(cs)
                    << "in " << file << " line " << t.lineNumber()
                    << ": expected a contact ((i j) (x y z)), found "
                    << t.info() << exit(FatalIOError);
            }
            cs.readBegin("contact pair");
            const label i = readLabel(cs);
            const label j = readLabel(cs);
            cs.readEnd("contact pair");
            const vector history = readVector(cs);
            cs.readEnd("contact");
            if (i < 0 || i >= size() || j >= size())
            {
                FatalIOErrorInFunction(cs)
                    << "in " << file << " line " << cs.lineNumber()
                    << ": contact (" << i << ' ' << j << ") names a"
                    << " particle that is not in the file"
                    << exit(FatalIOError);
            }
            // A contact names its particles by their places in the file:
            // their global indices
            history_.set(i, j, history);
            t = token(cs);
        }
    }
    checkStart(file);
}


void Foam::granularSystem::writeParticles(const fileName& dir) const
{
    // The file lists the scene in global order, and its contacts name
    // particles by their places in it
    for (label i = 0; i < size(); ++i)
    {
        if (globalIndex_[i] != i)
        {
            FatalErrorInFunction
                << "writing " << dir/"particles" << ": particle " << ids_[i]
                << " of global index " << globalIndex_[i] << " is at place "
                << i << "; only a system holding the whole scene in global"
                << " order writes a particle file" << exit(FatalError);
        }
    }
    mkDir(dir);
    const fileName file(dir/"particles");
    const fileName tmp(file + ".tmp");
    {
        OFstream os(tmp);
        os.precision(17);
        IOobject::writeBanner(os);
        os  << "FoamFile\n{\n"
            << "    version     2.0;\n"
            << "    format      ascii;\n"
            << "    class       dictionary;\n"
            << "    location    \"" << dir.name() << "\";\n"
            << "    object      particles;\n"
            << "}\n";
        IOobject::writeDivider(os);
        os  << "\n// id shape material motion position (w x y z) velocity"
            << " omega force torque contactForce contactTorque\n"
            << "particles\n(\n";
        for (label i = 0; i < size(); ++i)
        {
            const rigidParticle& p = particles_[i];
            const quaternion& q = p.orientation();
            os  << '(' << ids_[i] << ' ' << shapeName(i) << ' '
                << materialName(i) << ' '
                << rigidParticle::motionKindNames[p.motion()] << ' '
                << p.position() << " ("
                << q.w() << ' ' << q.v().x() << ' ' << q.v().y() << ' '
                << q.v().z() << ") "
                << p.velocity() << ' ' << p.omega() << ' '
                << p.force() << ' ' << p.torque() << ' '
                << p.contactForce() << ' ' << p.contactTorque() << ")\n";
        }
        os  << ");\n";

        if (!history_.empty())
        {
            // Sorted, so that equal states write equal files; keyed by
            // global index, a particle's place in this file
            os  << "\ncontacts\n(\n";
            for (const auto& c : history_.entries())
            {
                os  << "((" << c.first.first() << ' ' << c.first.second()
                    << ") " << c.second << ")\n";
            }
            os  << ");\n";
        }
        IOobject::writeEndDivider(os);
        if (!os.good())
        {
            FatalErrorInFunction
                << "writing " << tmp << " failed" << exit(FatalError);
        }
    }
    // Atomic on POSIX: a reader sees the old file or the new one
    if (!Foam::mv(tmp, file))
    {
        FatalErrorInFunction
            << "cannot rename " << tmp << " to " << file << exit(FatalError);
    }
}




// * * * * * * * * * * * * * * * * Effects  * * * * * * * * * * * * * * * * //

const Foam::vector& Foam::granularSystem::readGravity
(
    const objectRegistry& db
)
{
    IOobject header
    (
        "g",
        db.time().constant(),
        db,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    const bool present =
        header.typeHeaderOk<uniformDimensionedVectorField>(true);
    if (!effects_.settle("gravity", present, "constant/g"))
    {
        // Off: the file, if any, must not ask for a weight
        if (present)
        {
            const vector g = uniformDimensionedVectorField(header).value();
            if (mag(g) > 0)
            {
                OStringStream why;
                why << "constant/g is " << g
                    << "; remove it or set it to (0 0 0)";
                effects_.contradiction("gravity", why.str());
            }
        }
        integrator_.setGravity(Zero);
        return integrator_.gravity();
    }
    if (!present)
    {
        effects_.contradiction("gravity", "the case has no constant/g");
    }
    integrator_.setGravity(uniformDimensionedVectorField(header).value());
    return integrator_.gravity();
}


// ************************************************************************* //

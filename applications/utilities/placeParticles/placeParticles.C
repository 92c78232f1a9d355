/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Application
    placeParticles

Group
    grpDlmfdUtilities

Description
    Places particles of one shape and material at random non-overlapping
    positions, with random orientations, in a box or a periodic domain,
    and writes them to <startTime>/particles (atomically; nothing is
    written if the target cannot be met).

    Random sequential addition: a random pose is kept if the particle lies
    inside the region's non-periodic faces and the walls and overlaps no
    particle kept before (bounding spheres first, then the true shapes
    through the narrow phase, across periodic boundaries by the minimum
    image). A planar shape (circle, polygon: a 2D case) is placed in the
    domain's mid-plane and turned about z only; its solid fraction is then
    the area fraction of the plane. The count is given, or follows from a target solid fraction of
    the region. When maxAttempts poses in a row are all rejected the
    utility stops, says how many it placed and the solid fraction reached.
    Random sequential addition jams well below the packings a pour
    reaches (5 mm cubes in pouringCubes: 1837 placed, phi = 0.164, before
    200 rejections in a row): higher targets need a packing run (pour them
    with granularFoam).

Usage
    \b placeParticles [OPTIONS]

    system/placeParticlesDict:
    \verbatim
    shape               cube;       // a shape of constant/particleProperties
    material            glass;
    number              2000;       // or: solidFraction 0.2;
    region              { min (0 0 0); max (0.1 0.1 0.2); } // default: domain
    randomOrientation   true;       // default true
    seed                1;          // default 1
    maxAttempts         100000;     // rejections in a row; default 1e5
    motion              free;       // free | fixed | prescribed
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "Random.H"
#include "mathematicalConstants.H"
#include "granularSystem.H"
#include "narrowPhase.H"
#include "knownKeywords.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- Uniformly random rotation (Shoemake 1992)
quaternion randomRotation(Random& rnd)
{
    const scalar u1 = rnd.sample01<scalar>();
    const scalar u2 = rnd.sample01<scalar>();
    const scalar u3 = rnd.sample01<scalar>();
    const scalar twoPi = constant::mathematical::twoPi;
    return quaternion
    (
        std::sqrt(u1)*std::cos(twoPi*u3),
        vector
        (
            std::sqrt(1 - u1)*std::sin(twoPi*u2),
            std::sqrt(1 - u1)*std::cos(twoPi*u2),
            std::sqrt(u1)*std::sin(twoPi*u3)
        )
    );
}

//- Uniformly random rotation about z (planar shapes in a 2D case)
quaternion randomRotationAboutZ(Random& rnd)
{
    const scalar halfAngle =
        constant::mathematical::pi*rnd.sample01<scalar>();
    return quaternion
    (
        std::cos(halfAngle), vector(0, 0, std::sin(halfAngle))
    );
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Place particles at random non-overlapping positions and"
        " orientations; writes <startTime>/particles"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    const auto readDict = [&](const word& name, const fileName& where)
    {
        return IOdictionary
        (
            IOobject
            (
                name, where, runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE
            )
        );
    };
    const IOdictionary particleProperties
    (
        readDict("particleProperties", runTime.constant())
    );
    const IOdictionary collisionProperties
    (
        readDict("collisionProperties", runTime.constant())
    );
    const IOdictionary dict(readDict("placeParticlesDict", runTime.system()));

    // A misspelt optional keyword would leave its default in force
    knownKeywords::require
    (
        dict,
        wordList
        ({
            "shape", "material", "number", "solidFraction", "region",
            "randomOrientation", "seed", "maxAttempts", "motion"
        })
    );
    if (dict.isDict("region"))
    {
        knownKeywords::require(dict, wordList({"min", "max"}), "region");
    }

    granularSystem granular(particleProperties, collisionProperties);

    const word shapeName(dict.get<word>("shape"));
    const word materialName(dict.get<word>("material"));
    const particleShape& shape =
        granular.shape(shapeName, "placeParticlesDict");
    granular.materials().particleMaterial
    (
        materialName, "placeParticlesDict", dict
    );
    const rigidParticle::motionKind motion =
        rigidParticle::motionKindNames.getOrDefault
        (
            "motion", dict, rigidParticle::motionKind::free
        );

    boundBox region(granular.domain());
    if (const dictionary* r = dict.findDict("region"))
    {
        region = boundBox(r->get<point>("min"), r->get<point>("max"));
        if (cmptMin(region.span()) <= 0)
        {
            FatalIOErrorInFunction(*r)
                << "region: max " << region.max() << " must exceed min "
                << region.min() << " in every direction" << exit(FatalIOError);
        }
    }
    // A planar shape (2D case): centres in the domain's mid-plane, turned
    // about z only; the solid fraction is an area fraction of the plane
    const bool planar = shape.planar();
    const scalar zPlane = granular.domain().centre().z();
    if (planar)
    {
        region.min().z() = granular.domain().min().z();
        region.max().z() = granular.domain().max().z();
        Info<< "Planar shape: centres at z = " << zPlane
            << ", turned about z only" << nl;
    }

    const FixedList<bool, 3>& periodic = granular.periodic();
    // Images are taken over the period: along a periodic direction the
    // region must be the whole domain
    for (direction d = 0; d < 3; ++d)
    {
        if
        (
            periodic[d]
         && (
                mag(region.min()[d] - granular.domain().min()[d]) > SMALL
             || mag(region.max()[d] - granular.domain().max()[d]) > SMALL
            )
        )
        {
            FatalIOErrorInFunction(dict)
                << "region " << region << " does not span the domain "
                << granular.domain() << " along the periodic direction "
                << vector::componentNames[d] << "; give the domain's extent"
                << " there (or leave region out)" << exit(FatalIOError);
        }
    }

    const bool hasNumber = dict.found("number");
    const bool hasPhi = dict.found("solidFraction");
    if (hasNumber == hasPhi)
    {
        FatalIOErrorInFunction(dict)
            << "give either number or solidFraction; "
            << (hasNumber ? "both are" : "neither is") << " given"
            << exit(FatalIOError);
    }
    label target = 0;
    if (hasNumber)
    {
        target = dict.get<label>("number");
        if (target < 1)
        {
            FatalIOErrorInFunction(dict)
                << "number = " << target << " is not allowed; it must be >= 1"
                << exit(FatalIOError);
        }
    }
    else
    {
        const scalar phi = dict.get<scalar>("solidFraction");
        if (!(phi > 0 && phi < 1))
        {
            FatalIOErrorInFunction(dict)
                << "solidFraction = " << phi
                << " is not allowed; 0 < solidFraction < 1"
                << exit(FatalIOError);
        }
        target = label(std::round(phi*region.volume()/shape.volume()));
        if (target < 1)
        {
            FatalIOErrorInFunction(dict)
                << "solidFraction = " << phi << " of the region "
                << region << " is less than one particle" << exit(FatalIOError);
        }
    }
    const bool randomOrientation =
        dict.getOrDefault<bool>("randomOrientation", true);
    const label seed = dict.getOrDefault<label>("seed", 1);
    const label maxAttempts = dict.getOrDefault<label>("maxAttempts", 100000);
    if (maxAttempts < 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxAttempts = " << maxAttempts << " must be >= 1"
            << exit(FatalIOError);
    }

    Info<< "Placing " << target << " x " << shapeName << " (" << materialName
        << ") in " << region << ", periodic " << periodic
        << ", seed " << seed << nl;

    // Accepted poses, hashed in cells of width 2 r
    const scalar r = shape.boundingRadius();
    const vector span = region.span();
    labelVector nCells;
    for (direction d = 0; d < 3; ++d)
    {
        nCells[d] = max(label(1), label(span[d]/(2*r)));
    }
    List<DynamicList<label>> cells(cmptProduct(nCells));
    const auto cellOf = [&](const point& x, const direction d)
    {
        return min
        (
            nCells[d] - 1,
            max(label(0), label((x[d] - region.min()[d])/span[d]*nCells[d]))
        );
    };
    const auto minImage = [&](vector dx)
    {
        for (direction d = 0; d < 3; ++d)
        {
            if (periodic[d])
            {
                dx[d] -= span[d]*std::round(dx[d]/span[d]);
            }
        }
        return dx;
    };

    DynamicList<point> xs;
    DynamicList<quaternion> qs;
    DynamicList<tensor> Rs;
    Random rnd(seed);
    label rejectedInARow = 0;
    label attempts = 0;

    while (xs.size() < target && rejectedInARow < maxAttempts)
    {
        ++attempts;
        point x;
        for (direction d = 0; d < 3; ++d)
        {
            const scalar margin = periodic[d] ? 0 : r;
            const scalar lo = region.min()[d] + margin;
            const scalar hi = region.max()[d] - margin;
            x[d] = hi > lo ? lo + (hi - lo)*rnd.sample01<scalar>() : 0.5*(lo + hi);
        }
        if (planar)
        {
            // In the mid-plane of the one-cell-deep domain
            x.z() = zPlane;
        }
        const quaternion q =
            !randomOrientation ? quaternion::I
          : planar ? randomRotationAboutZ(rnd)
          : randomRotation(rnd);
        const tensor R = q.R();
        const posedShape body{shape, x, R};

        bool ok = true;
        contactGeometry c;
        for (const planeWall& w : granular.walls())
        {
            if
            (
                w.distance(x) < r
             && narrowPhase::shapePlane(body, w.origin, w.normal, c)
            )
            {
                ok = false;
                break;
            }
        }

        const labelVector ijk(cellOf(x, 0), cellOf(x, 1), cellOf(x, 2));
        for (label dz = -1; dz <= 1 && ok; ++dz)
        for (label dy = -1; dy <= 1 && ok; ++dy)
        for (label dx = -1; dx <= 1 && ok; ++dx)
        {
            labelVector n(ijk + labelVector(dx, dy, dz));
            bool valid = true;
            for (direction d = 0; d < 3; ++d)
            {
                if (periodic[d])
                {
                    n[d] = (n[d] + nCells[d]) % nCells[d];
                }
                else if (n[d] < 0 || n[d] >= nCells[d])
                {
                    valid = false;
                }
            }
            if (!valid)
            {
                continue;
            }
            for (const label j : cells[n.x() + nCells.x()*(n.y() + nCells.y()*n.z())])
            {
                const vector dxij = minImage(x - xs[j]);
                if (magSqr(dxij) >= sqr(2*r))
                {
                    continue;
                }
                const posedShape other{shape, x - dxij, Rs[j]};
                if (narrowPhase::shapeShape(body, other, c))
                {
                    ok = false;
                    break;
                }
            }
        }

        if (!ok)
        {
            ++rejectedInARow;
            continue;
        }
        rejectedInARow = 0;
        cells[ijk.x() + nCells.x()*(ijk.y() + nCells.y()*ijk.z())].append(xs.size());
        xs.append(x);
        qs.append(q);
        Rs.append(R);
    }

    const scalar phiReached = xs.size()*shape.volume()/region.volume();
    if (xs.size() < target)
    {
        FatalIOErrorInFunction(dict)
            << "placed " << xs.size() << " of " << target << " particles"
            << " (solid fraction " << phiReached << " of the region) before "
            << maxAttempts << " random poses in a row were all rejected;"
            << " nothing written." << nl
            << "    Lower number or solidFraction, enlarge the region, raise"
            << " maxAttempts, or pour the particles with granularFoam"
            << exit(FatalIOError);
    }

    forAll(xs, i)
    {
        const label k = granular.addParticle(i, shapeName, materialName, xs[i], qs[i]);
        granular.particle(k).setMotion(motion);
    }
    granular.updated();
    granular.writeParticles(runTime.timePath());

    Info<< "Placed " << xs.size() << " particles in " << attempts
        << " attempts: solid fraction " << phiReached << " of the region"
        << nl << "Written " << runTime.timePath()/"particles" << nl
        << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //

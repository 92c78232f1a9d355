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
    Foam::narrowPhase::shapeShapeGJK: libccd's GJK and EPA on the world
    support functions of two posed shapes (the pairs with no closed form).

\*---------------------------------------------------------------------------*/

#include <ccd/ccd.h>
#include <cfenv>
#include <cmath>

#include "narrowPhase.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- libccd's support callback on a posedShape
    void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out)
    {
        const posedShape& body = *static_cast<const posedShape*>(obj);
        const point s =
            body.support(vector(dir->v[0], dir->v[1], dir->v[2]));
        ccdVec3Set(out, s.x(), s.y(), s.z());
    }

    //- libccd's centre callback: the centroid, inside every convex shape
    void ccdCentre(const void* obj, ccd_vec3_t* out)
    {
        const posedShape& body = *static_cast<const posedShape*>(obj);
        ccdVec3Set(out, body.centre.x(), body.centre.y(), body.centre.z());
    }
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::narrowPhase::shapeShapeGJK
(
    const posedShape& bi,
    const posedShape& bj,
    contactGeometry& contact
)
{
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccdSupport;
    ccd.support2 = ccdSupport;
    ccd.center1 = ccdCentre;
    ccd.center2 = ccdCentre;
    ccd.max_iterations = 1000;
    // Relative to the size of the pair: overlaps are 1e-3 D or less
    const scalar size = bi.shape.boundingRadius() + bj.shape.boundingRadius();
    ccd.epa_tolerance = 1e-12*size;
    ccd.dist_tolerance = 1e-12*size;
    ccd.mpr_tolerance = 1e-12*size;

    // GJK + EPA: the minimal separating translation. MPR is faster but
    // measures the depth along the line of centres, which for a sphere
    // near a cube's edge was measured 0.1 edge off the true depth.
    ccd_real_t depth;
    ccd_vec3_t dir, pos;

    // libccd divides by zero on degenerate polytopes (touching faces):
    // run it with the floating-point traps of OpenFOAM (FOAM_SIGFPE) held,
    // then restore them; a non-finite answer falls back to MPR
    fenv_t env;
    feholdexcept(&env);
    // MPR decides whether they intersect: libccd's GJK was seen to call
    // two cubes with centres 0.22 edge apart separate (2 of 15000 random
    // placements). EPA then gives the minimal separating translation.
    int status = ccdMPRIntersect(&bi, &bj, &ccd) ? 0 : -1;
    if (status == 0)
    {
        status = ccdGJKPenetration(&bi, &bj, &ccd, &depth, &dir, &pos);
        if (status != 0)
        {
            // EPA failed on an intersecting pair: MPR's depth
            status = ccdMPRPenetration(&bi, &bj, &ccd, &depth, &dir, &pos);
        }
    }
    const auto finite = [&]()
    {
        return
            std::isfinite(depth)
         && std::isfinite(dir.v[0]) && std::isfinite(dir.v[1])
         && std::isfinite(dir.v[2]) && std::isfinite(pos.v[0])
         && std::isfinite(pos.v[1]) && std::isfinite(pos.v[2]);
    };
    if (status == 0 && !finite())
    {
        status = ccdMPRPenetration(&bi, &bj, &ccd, &depth, &dir, &pos);
        if (status == 0 && !finite())
        {
            status = -1;
        }
    }
    feclearexcept(FE_ALL_EXCEPT);
    fesetenv(&env);

    if (status != 0 || !(depth > 0))
    {
        return false;
    }

    // libccd moves obj2 (j) along dir to separate: the normal from j to i
    // is -dir
    contact.set
    (
        point(pos.v[0], pos.v[1], pos.v[2]),
        -normalised(vector(dir.v[0], dir.v[1], dir.v[2])),
        depth
    );
    return true;
}


// ************************************************************************* //

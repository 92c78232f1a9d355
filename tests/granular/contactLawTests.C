/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Class
Description
    Unit tests of the contact laws of the granular library: forces against
    their closed forms, the Coulomb cap, the stiffness set from a target
    overlap, static friction, and the errors on bad coefficients.

    The head-on collision here integrates only the relative normal
    coordinate of the pair, with RK4 at T_c/2000, to check the law itself
    (not the granular time integrator): the restitution, duration and
    largest overlap it gives against eq 21 of seed 001.

\*---------------------------------------------------------------------------*/

#include "contactLaw.H"
#include "hookeanSpringDashpot.H"
#include "hookeanStaticFriction.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

const materialPair glassPair{"glass-glass", 2500, 2500};
const materialPair glassWall{"glass-wall", 2500, -1};

dictionary coeffs(const std::string& text)
{
    IStringStream is(text);
    dictionary dict(is);
    dict.name() = "constant/granularProperties.contact.glass-glass";
    return dict;
}

autoPtr<contactLaw> makeLaw
(
    const word& law,
    const std::string& text,
    const materialPair& pair = glassPair
)
{
    return contactLaw::New(law, coeffs(text), pair);
}

std::string errorOf(const word& law, const std::string& text)
{
    try
    {
        makeLaw(law, text);
    }
    catch (const IOerror& err)
    {
        return err.message();
    }
    return "";
}

//- Collide head-on at relative speed v0, integrating the overlap and the
//- normal relative velocity with classic RK4 at step dt, the step halved
//- down to dt*1e-9 at the separation (where the dashpot force jumps to
//- zero); gives the separation speed ratio, the contact duration and the
//- largest overlap (vertex of the parabola through the top samples)
void collide
(
    const contactLaw& law,
    const scalar M,
    const scalar v0,
    const scalar dt,
    scalar& restitution,
    scalar& duration,
    scalar& maxDelta
)
{
    const vector n(0, 0, 1);
    vector history(Zero);

    // d(delta)/dt = -u, du/dt = F.n/M, with u = Urel.n (< 0 approaching)
    auto accel = [&](scalar d, scalar u)
    {
        return d > 0 ? (law.force(d, n, u*n, M, dt, history) & n)/M : 0;
    };
    auto rk4 = [&](scalar& d, scalar& u, const scalar h)
    {
        const scalar k1d = -u, k1u = accel(d, u);
        const scalar k2d = -(u + 0.5*h*k1u);
        const scalar k2u = accel(d + 0.5*h*k1d, u + 0.5*h*k1u);
        const scalar k3d = -(u + 0.5*h*k2u);
        const scalar k3u = accel(d + 0.5*h*k2d, u + 0.5*h*k2u);
        const scalar k4d = -(u + h*k3u);
        const scalar k4u = accel(d + h*k3d, u + h*k3u);
        d += h/6*(k1d + 2*k2d + 2*k3d + k4d);
        u += h/6*(k1u + 2*k2u + 2*k3u + k4u);
    };

    // Start just inside contact
    scalar delta = v0*1e-12*dt, u = -v0, t = 1e-12*dt, h = dt;
    scalar d0 = 0, d1 = 0;
    maxDelta = 0;
    while (t < 1e3)
    {
        scalar d = delta, un = u;
        rk4(d, un, h);
        if (d <= 0)
        {
            if (h > 1e-9*dt)
            {
                h *= 0.5;
                continue;
            }
            duration = t + h*delta/(delta - d);
            restitution = un/v0;
            return;
        }
        d0 = d1;
        d1 = delta;
        delta = d;
        u = un;
        t += h;
        if (d1 >= d0 && d1 >= delta && h == dt)
        {
            maxDelta = d1 - sqr(delta - d0)/(8*(d0 - 2*d1 + delta));
        }
    }
    FAIL() << "no separation after " << t << " s";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * hookeanSpringDashpot * * * * * * * * * * * * //

TEST(hookeanSpringDashpot, headOnCollisionGivesRestitutionAndDuration)
{
    for (const scalar en : {0.1, 0.5, 0.9, 0.97, 1.0})
    {
        autoPtr<contactLaw> law = makeLaw
        (
            "hookeanSpringDashpot",
            "kn 2e4; en " + std::to_string(en) + "; muc 0.1;"
        );
        const scalar M = 1e-3;
        const scalar Tc = law->contactTime(M);

        scalar e, T, dmax;
        collide(law(), M, 0.3, Tc/2000, e, T, dmax);

        EXPECT_NEAR(e, en, 1e-4) << "en " << en;
        EXPECT_NEAR(T, Tc, 1e-4*Tc) << "en " << en;
    }
}


TEST(hookeanSpringDashpot, contactTimeAndDampingFollowEquation21)
{
    const scalar kn = 5e3, en = 0.8, M = 2e-3;
    autoPtr<contactLaw> law =
        makeLaw("hookeanSpringDashpot", "kn 5e3; en 0.8; muc 0.3;");

    // T_c = pi/Foam::sqrt(kn/M - gamma_n^2), gamma_n of eq 21; equivalently
    // kn = M (pi^2 + ln^2 en)/T_c^2 (doc/refdata/dem-analytic.md)
    const scalar Tc = law->contactTime(M);
    EXPECT_NEAR(kn, M*(sqr(pi) + sqr(Foam::log(en)))/sqr(Tc), 1e-9*kn);

    // Normal force at rest in contact is kn delta; the dashpot adds
    // -2 gamma_n M V_n
    vector h(Zero);
    const vector n(1, 0, 0);
    EXPECT_NEAR(law->force(1e-4, n, Zero, M, 0, h).x(), kn*1e-4, 1e-12);

    const scalar gn = -Foam::sqrt(kn/M)*Foam::log(en)/Foam::sqrt(sqr(pi) + sqr(Foam::log(en)));
    const vector F = law->force(1e-4, n, vector(-0.1, 0, 0), M, 0, h);
    EXPECT_NEAR(F.x(), kn*1e-4 + 2*gn*M*0.1, 1e-12);
}


TEST(hookeanSpringDashpot, tangentialForceIsCappedByCoulomb)
{
    const scalar kn = 1e4, M = 1e-3, delta = 1e-4;
    autoPtr<contactLaw> law = makeLaw
    (
        "hookeanSpringDashpot", "kn 1e4; en 1; muc 0.2; gammat 50;"
    );
    const vector n(0, 0, 1);
    vector h(Zero);

    // Slow slip: dashpot -2 gamma_t M V_t, below the cap
    const vector slow = law->force(delta, n, vector(0.1, 0, 0), M, 0, h);
    EXPECT_NEAR(slow.x(), -2*50*M*0.1, 1e-14);

    // Fast slip: capped at muc |F_n|, opposite to the slip
    const vector fast = law->force(delta, n, vector(0, -10, 0), M, 0, h);
    EXPECT_NEAR(fast.y(), 0.2*kn*delta, 1e-12);
    EXPECT_NEAR(fast.z(), kn*delta, 1e-12);
    EXPECT_EQ(fast.x(), 0);
}


TEST(hookeanSpringDashpot, stiffnessFromTargetOverlapGivesThatOverlap)
{
    // Seed 001: delta_max/D = 0.1 % at the impact speed
    const scalar D = 0.01, v0 = 0.4, ratio = 1e-3;

    for (const materialPair& pair : {glassPair, glassWall})
    {
        for (const scalar en : {0.5, 0.9, 1.0})
        {
            autoPtr<contactLaw> law = makeLaw
            (
                "hookeanSpringDashpot",
                "maxOverlapRatio 1e-3; impactVelocity 0.4;"
                " referenceDiameter 0.01; muc 0; en " + std::to_string(en)
                + ";",
                pair
            );
            const scalar M = pair.referenceMass(D);

            scalar e, T, dmax;
            collide(law(), M, v0, law->contactTime(M)/2000, e, T, dmax);

            EXPECT_NEAR(dmax/D, ratio, 1e-6*ratio)
                << pair.name << " en " << en;
        }
    }
}


TEST(contactLawInput, typoListsEveryLaw)
{
    const std::string msg = errorOf("hookeanSpringDashpt", "kn 1; en 1; muc 0;");
    for
    (
        const char* name
      : {"none", "hookeanSpringDashpot", "hookeanStaticFriction"}
    )
    {
        EXPECT_NE(msg.find(name), std::string::npos) << name << ": " << msg;
    }
}


TEST(contactLawInput, badCoefficientsAreNamed)
{
    const word law("hookeanSpringDashpot");
    EXPECT_NE(errorOf(law, "kn 1; en 0; muc 0;").find("0 < en <= 1"),
              std::string::npos);
    EXPECT_NE(errorOf(law, "kn 1; en 1.2; muc 0;").find("0 < en <= 1"),
              std::string::npos);
    EXPECT_NE(errorOf(law, "kn -1; en 1; muc 0;").find("kn"),
              std::string::npos);
    EXPECT_NE(errorOf(law, "kn 1; en 1; muc -0.1;").find("muc >= 0"),
              std::string::npos);
    EXPECT_NE(errorOf(law, "en 1; muc 0;").find("neither"),
              std::string::npos);
    EXPECT_NE
    (
        errorOf(law, "kn 1; maxOverlapRatio 1e-3; en 1; muc 0;").find("both"),
        std::string::npos
    );
    EXPECT_NE
    (
        errorOf("hookeanStaticFriction", "kn 1; en 1; muc 0; ks 0;")
            .find("ks"),
        std::string::npos
    );
}


// * * * * * * * * * * * * * * hookeanStaticFriction * * * * * * * * * * * * //

TEST(hookeanStaticFriction, springHoldsBelowCapAndSlidesAtCap)
{
    const scalar kn = 1e4, ks = 2e3, M = 1e-3, delta = 1e-4, dt = 1e-5;
    autoPtr<contactLaw> law = makeLaw
    (
        "hookeanStaticFriction", "kn 1e4; en 1; muc 0.5; gammat 0; ks 2e3;"
    );
    ASSERT_TRUE(law->needsHistory());
    const vector n(0, 0, 1);

    // Creep of 1e-3 m/s for 10 steps: spring force -ks * 1e-7 m
    vector h(Zero);
    vector F(Zero);
    for (label i = 0; i < 10; ++i)
    {
        F = law->force(delta, n, vector(1e-3, 0, 0), M, dt, h);
    }
    EXPECT_NEAR(h.x(), 1e-7, 1e-18);
    EXPECT_NEAR(F.x(), -ks*1e-7, 1e-15);

    // A long slip reaches the cap muc kn delta and the history stops there
    for (label i = 0; i < 10000; ++i)
    {
        F = law->force(delta, n, vector(1, 0, 0), M, dt, h);
    }
    EXPECT_NEAR(F.x(), -0.5*kn*delta, 1e-12);
    EXPECT_NEAR(h.x(), 0.5*kn*delta/ks, 1e-15);
}


TEST(hookeanStaticFriction, historyTurnsWithTheTangentPlane)
{
    autoPtr<contactLaw> law = makeLaw
    (
        "hookeanStaticFriction", "kn 1e4; en 1; muc 1; gammat 0; ks 1e3;"
    );
    vector h(3e-6, 0, 4e-6);    // partly along the new normal
    law->force(1e-3, vector(0, 0, 1), Zero, 1e-3, 1e-5, h);

    EXPECT_NEAR(h.z(), 0, 1e-20);
    EXPECT_NEAR(mag(h), 5e-6, 1e-18);
}


// ************************************************************************* //

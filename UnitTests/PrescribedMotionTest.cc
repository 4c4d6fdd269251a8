// Prescribed motion of fixed particles and walls (Walls/PrescribedMotion.h): exact rigid motion,
// and that moving boundaries move what they touch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ContactTestScenes.h"

using namespace talus;
using namespace talus::test;

namespace {

const LinearSpringDashpot grainLaw = LinearSpringDashpot::fromCollision(0.005, 0.5, 0.5).withFriction(0.5);
constexpr double grainRadius = 0.5;

// A sphere of radius 0.5 resting at height z on a floor z = 0 that follows `motion`, under g = 1.
void sphereOnMovingFloor(TestScene& s, const PrescribedMotion& motion, const Vec3& position) {
    s.scene().setGravity(Vec3(0, 0, -1));
    const auto species = s.scene().addSpecies("grain", unitMassDensity, grainLaw);
    s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species, static_cast<int>(s.scene().addMotion(motion)));
    s.scene().addParticle(position, grainRadius, species);
}

}  // namespace

// A fixed particle turning about the z axis through (1, 0, 0) at w = 2 for t = 1 must sit at the
// start point rotated by the angle w t = 2 (no drift off the circle: each step is an exact
// rotation), with the velocity w x (x - c) and the angular velocity w.
TEST(PrescribedMotion, FixedParticleTurnsExactlyOnItsCircle) {
    const double w = 2, endTime = 1, dt = 1e-4;
    const Vec3 centre(1, 0, 0), start(1.5, 0.2, 0.3);
    TestScene scene;
    scene.setup = [&](TestScene& s) {
        const auto species = s.scene().addSpecies("grain", unitMassDensity, grainLaw);
        PrescribedMotion turn;
        turn.angularVelocity = Vec3(0, 0, w);
        turn.centre = centre;
        s.scene().addFixedParticle(start, 0.1, species, static_cast<int>(s.scene().addMotion(turn)));
    };
    scene.runFor(dt, endTime);
    const double angle = w * scene.time();
    const Vec3 expected = centre + Eigen::AngleAxisd(angle, Vec3::UnitZ()) * (start - centre);
    const auto& p = scene.scene().particles();
    EXPECT_NEAR((p.position[0] - expected).norm(), 0, 1e-12);
    EXPECT_NEAR((p.velocity[0] - Vec3(0, 0, w).cross(expected - centre)).norm(), 0, 1e-12);
    EXPECT_EQ(p.angularVelocity[0], Vec3(0, 0, w));
    EXPECT_NEAR(scene.time(), endTime, 1e-12);
}

// A floor moving up at speed v carries a sphere resting on it: once the start-up oscillation
// has died out (damped contact, e = 0.5), the sphere moves at v too and rests on the floor at
// the static overlap m g / kn (the floor moves at constant speed, so the contact force is the
// weight; the wall contact uses the species law and the sphere's own mass).
TEST(PrescribedMotion, MovingFloorCarriesASphere) {
    const double v = 0.3, dt = 1e-4, endTime = 2;
    const double staticOverlap = sphereMass(grainRadius) / grainLaw.normalStiffness;
    PrescribedMotion lift;
    lift.velocity = Vec3(0, 0, v);
    TestScene scene;
    scene.setup = [&](TestScene& s) { sphereOnMovingFloor(s, lift, Vec3(0, 0, grainRadius - staticOverlap)); };
    scene.runFor(dt, endTime);
    const auto& p = scene.scene().particles();
    EXPECT_NEAR(p.velocity[0].z(), v, 1e-6);
    EXPECT_NEAR(scene.scene().walls()[0].point.z(), v * scene.time(), 1e-12);
    EXPECT_NEAR(p.position[0].z() - scene.scene().walls()[0].point.z(), grainRadius - staticOverlap, 1e-3 * staticOverlap);
}

// A plane wall turning about its own normal (a turntable, w along n) drags a sphere that starts at
// rest off the axis. The wall's velocity at the contact point, w x r, enters the tangential
// relative velocity; once friction has stopped the slip, the sphere rolls on the turning table at
// 2/7 of the table's speed under it, whatever happened before:
//   The friction F (in the plane) acts at b = -R n from the centre, so m dv/dt = F and
//   I dw_s/dt = b x F = -R n x (m dv/dt): I w_s + m R n x v is constant, zero from rest (gravity
//   and the normal force act along n through the centre: no torque, no push in the plane).
//   So w_s = -(m R / I) n x v in the plane, and the contact point moves at
//   v + w_s x b = v - R w_s x n = v + (m R^2 / I) v = (7/2) v  (I = 2/5 m R^2, v in the plane).
//   Rolling means that equals the table's velocity u = w x r there: v = (2/7) w x r.
// So the centre circles the axis at 2/7 of the table's rate (dr/dt = (2/7) w x r). Checked over
// the last second (the slip ends after about (2/7) |u| / (mu g) = 0.6): the overlap
// dn = m g / kn = 1e-5 R shortens the lever arm to R - dn/2, which makes the speed
// u / (1 + (5/2)(1 - dn/(2R))^2), (5/7) dn/R = 7e-6 above 2/7 u, and the tangential spring lets the
// contact creep only as fast as its stretch |F| / kt (1e-6) changes. Measured: 1.0e-5; the
// bound 1e-4. A wall speed off by 1% fails (measured: 1e-2), by a factor 0.5 or 2 by far.
TEST(PrescribedMotion, TurntableCarriesARollingSphereAtTwoSeventhsOfItsSpeed) {
    const double w = 0.5, dt = 1e-4, endTime = 3;
    const Vec3 tableSpin(0, 0, w);
    PrescribedMotion turn;
    turn.angularVelocity = tableSpin;
    TestScene scene;
    scene.setup = [&](TestScene& s) { sphereOnMovingFloor(s, turn, Vec3(2, 0, grainRadius)); };
    double worst = 0;
    scene.afterStep = [&](TestScene& s) {
        if (s.time() < endTime - 1) return;
        const auto& p = s.scene().particles();
        const Vec3 r(p.position[0].x(), p.position[0].y(), 0);
        const Vec3 rolling = 2.0 / 7.0 * tableSpin.cross(r);
        worst = std::max(worst, (p.velocity[0] - rolling).norm() / rolling.norm());
    };
    scene.runFor(dt, endTime);
    std::printf("[ measured ] sphere on a turntable: |v - (2/7) w x r| / |(2/7) w x r| up to %.2e in the last second\n",
                worst);
    EXPECT_LT(worst, 1e-4);
    EXPECT_NEAR((scene.scene().walls()[0].normal - Vec3::UnitZ()).norm(), 0, 1e-12);  // turning about itself
}

// Walls whose motion moves them only within their own surface (Wall::slidesInPlaceUnder): a drum's
// mantle and ends turning about its axis, a plane sliding along itself and turning about its normal;
// and walls that leave their place.
TEST(PrescribedMotion, WallsThatSlideInPlaceAreKnown) {
    Wall plane;  // z = 0
    Wall mantle;
    mantle.normal = Vec3::UnitY(), mantle.point = Vec3(0, 0.3, 0), mantle.radius = 0.1;
    Wall end;
    end.normal = Vec3::UnitY(), end.point = Vec3(0, -0.03, 0);
    const PrescribedMotion drum{.angularVelocity = Vec3(0, -2, 0)};
    EXPECT_TRUE(mantle.slidesInPlaceUnder(drum));
    EXPECT_TRUE(end.slidesInPlaceUnder(drum));
    EXPECT_FALSE(plane.slidesInPlaceUnder(drum));
    EXPECT_TRUE(plane.slidesInPlaceUnder({.velocity = Vec3(1, 2, 0), .angularVelocity = Vec3(0, 0, 3), .centre = Vec3(5, 1, 0)}));
    EXPECT_FALSE(plane.slidesInPlaceUnder({.velocity = Vec3(1, 2, 1e-6)}));
    EXPECT_TRUE(mantle.slidesInPlaceUnder({.velocity = Vec3(0, 0.5, 0)}));
    EXPECT_FALSE(mantle.slidesInPlaceUnder({.angularVelocity = Vec3(0, -2, 0), .centre = Vec3(0.01, 0, 0)}));
    EXPECT_FALSE(mantle.slidesInPlaceUnder({.angularVelocity = Vec3(0, 0, 1)}));
}

// A turning drum lists as wall candidates only the particles within reach of its mantle and ends,
// not every particle (the wall stays where it is); a floor that turns about its normal, listed so,
// and then starts to rise (the driver changes its motion) is listed anew: it throws up the sphere
// floating above it, which it would pass through with the old list (the sphere is at rest by then,
// so nothing else calls for a new list).
TEST(PrescribedMotion, WallsThatSlideInPlaceAreListedByDistanceWhileTheyDo) {
    TestScene drum;
    drum.setup = [](TestScene& s) {
        s.scene().setGravity(Vec3::Zero());
        const auto species = s.scene().addSpecies("grain", unitMassDensity, grainLaw);
        const int turning = static_cast<int>(s.scene().addMotion({.angularVelocity = Vec3(0, -0.5, 0)}));
        s.scene().addCylinderWall(Vec3::Zero(), Vec3::UnitY(), 10, species, turning);
        s.scene().addWall(Vec3::UnitY(), Vec3(0, -3, 0), species, turning);
        s.scene().addWall(-Vec3::UnitY(), Vec3(0, 3, 0), species, turning);
        // (Moving, so that the list is built anew after the walls' first step.)
        for (int k = 0; k < 5; ++k) s.scene().addParticle(Vec3(2 * k - 4, 0, 0), grainRadius, species, Vec3(0.5, 0, 0));
        s.scene().addParticle(Vec3(0, 0, -9.45), grainRadius, species, Vec3(0.5, 0, 0));  // (at the mantle)
    };
    drum.settings().skin = 0.1;
    drum.runFor(1e-4, 0.3);
    EXPECT_GT(drum.state().pairList.builds, 1u);
    EXPECT_EQ(drum.state().pairList.wallPairs.size(), 1u);
    EXPECT_EQ(drum.scene().particles().id[drum.state().pairList.wallPairs[0].particle], 5u);  // (the one at the mantle)

    TestScene floor;
    floor.setup = [](TestScene& s) {
        s.scene().setGravity(Vec3::Zero());
        const auto species = s.scene().addSpecies("grain", unitMassDensity, grainLaw);
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species,
                          static_cast<int>(s.scene().addMotion({.angularVelocity = Vec3(0, 0, 1)})));
        // (Drifting sideways until the floor starts to rise, so that the list is built anew while
        // the floor turns, without it; then at rest.)
        s.scene().addParticle(Vec3(0.3, 0, 2), grainRadius, species, Vec3(0.5, 0, 0));
    };
    floor.afterStep = [](TestScene& s) {
        if (s.time() > 0.5 && s.time() < 0.5 + 1.5e-4) {
            s.scene().motions()[0] = {.velocity = Vec3(0, 0, 1)};
            s.scene().particles().velocity[0] = Vec3::Zero();
        }
    };
    floor.settings().skin = 0.1;
    floor.runFor(1e-4, 3);
    EXPECT_GT(floor.state().pairList.builds, 2u);
    std::printf("[ measured ] the sphere leaves the rising floor at %.4f\n", floor.scene().particles().velocity[0].z());
    EXPECT_GT(floor.scene().particles().velocity[0].z(), 1.2);  // (1 + e = 1.5 for a wall of infinite mass)
}

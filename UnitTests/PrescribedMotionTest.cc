// Prescribed motion of fixed particles and walls (Walls/PrescribedMotion.h): exact rigid motion,
// and that moving boundaries move what they touch.
#include <gtest/gtest.h>

#include <cmath>

#include "ContactTestScenes.h"

using namespace talus;
using namespace talus::test;

namespace {

const LinearSpringDashpot grainLaw = LinearSpringDashpot::fromCollision(0.005, 0.5, 0.5).withFriction(0.5);
constexpr double grainRadius = 0.5;

// A sphere of radius 0.5 resting at height z on a floor z = 0 that follows `motion`, under g = 1.
void sphereOnMovingFloor(Scene& s, const PrescribedMotion& motion, const Vec3& position) {
    s.setGravity(Vec3(0, 0, -1));
    const auto species = s.addSpecies("grain", unitMassDensity, grainLaw);
    s.addWall(Vec3::UnitZ(), Vec3::Zero(), species, static_cast<int>(s.addMotion(motion)));
    s.addParticle(position, grainRadius, species);
}

}  // namespace

// A fixed particle turning about the z axis through (1, 0, 0) at w = 2 for t = 1 must sit at the
// start point rotated by the angle w t = 2 (no drift off the circle: each step is an exact
// rotation), with the velocity w x (x - c) and the angular velocity w.
TEST(PrescribedMotion, FixedParticleTurnsExactlyOnItsCircle) {
    const double w = 2, endTime = 1, dt = 1e-4;
    const Vec3 centre(1, 0, 0), start(1.5, 0.2, 0.3);
    Scene scene;
    scene.setup = [&](Scene& s) {
        const auto species = s.addSpecies("grain", unitMassDensity, grainLaw);
        PrescribedMotion turn;
        turn.angularVelocity = Vec3(0, 0, w);
        turn.centre = centre;
        s.addFixedParticle(start, 0.1, species, static_cast<int>(s.addMotion(turn)));
    };
    scene.run(dt, endTime);
    const double angle = w * scene.time();
    const Vec3 expected = centre + Eigen::AngleAxisd(angle, Vec3::UnitZ()) * (start - centre);
    const auto& p = scene.particles();
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
    Scene scene;
    scene.setup = [&](Scene& s) { sphereOnMovingFloor(s, lift, Vec3(0, 0, grainRadius - staticOverlap)); };
    scene.run(dt, endTime);
    const auto& p = scene.particles();
    EXPECT_NEAR(p.velocity[0].z(), v, 1e-6);
    EXPECT_NEAR(scene.walls()[0].point.z(), v * scene.time(), 1e-12);
    EXPECT_NEAR(p.position[0].z() - scene.walls()[0].point.z(), grainRadius - staticOverlap, 1e-3 * staticOverlap);
}

// A plane wall turning about its own normal (a turntable) drags a sphere resting off the axis
// by friction: the wall's velocity at the contact point, w x r, enters the tangential relative
// velocity, so the sphere must be set moving along w x r (it also rolls, so its centre need not
// co-rotate exactly). A wall at rest would leave it at rest.
TEST(PrescribedMotion, TurntableDragsASphereAlong) {
    const double w = 0.5, dt = 1e-4, endTime = 3;
    PrescribedMotion turn;
    turn.angularVelocity = Vec3(0, 0, w);
    Scene scene;
    scene.setup = [&](Scene& s) { sphereOnMovingFloor(s, turn, Vec3(2, 0, grainRadius)); };
    scene.run(dt, endTime);
    const auto& p = scene.particles();
    const Vec3 tableVelocity = Vec3(0, 0, w).cross(Vec3(p.position[0].x(), p.position[0].y(), 0));
    EXPECT_GT(p.velocity[0].dot(tableVelocity.normalized()), 0.1 * tableVelocity.norm());
    EXPECT_NEAR((scene.walls()[0].normal - Vec3::UnitZ()).norm(), 0, 1e-12);  // turning about itself
}

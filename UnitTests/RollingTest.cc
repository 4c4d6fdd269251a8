// A sphere on an incline (Theory/Chutes.md eq. (1) axes: x downslope, z normal to the plane,
// gravity g (sin a, 0, -cos a)) on a flat wall z = 0, driven through talus::Simulation.
//
// Rolling without slip: m x'' = m g sin a - F and I w' = F r with x' = r w, I = 2/5 m r^2, give
// x'' = g sin a / (1 + 2/5) = 5/7 g sin a and need the friction F = 2/7 m g sin a <= mu m g cos a,
// i.e. tan a <= 7/2 mu. Beyond that the sphere slides with F = mu m g cos a:
// x'' = g (sin a - mu cos a), and the contact point keeps slipping since its acceleration,
// g (sin a - mu cos a) - r (5/2 mu g cos a / r) = g (sin a - 7/2 mu cos a), is positive.
// The kernel's lever arm r - dn/2 (the branch vector ends at the middle of the overlap) differs
// from r by dn/(2r) = 2.5e-6 here: with the arm b, x' = b w and I w' = F b give
// x'' = g sin a / (1 + I / (m b^2)), (2/7) dn/r = 1.4e-6 below 5/7 g sin a (measured: 1.3e-6).
// The rolling check allows ten times that; the sliding one is exact but for round-off (the
// Coulomb force is constant), which over the 30000 steps adds up to
// at most 30000 ulp(1.5) = 7e-12 in the speed, 5e-12 of the acceleration (measured: 3e-12).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ContactTestScenes.h"

using namespace talus;
using namespace talus::test;

namespace {

constexpr double radius = 0.5;
constexpr double collisionTime = 0.005;
constexpr double timeStep = collisionTime / 50;

// Average downslope acceleration between t = 1 and t = 4 (600 collision times), after the
// tangential spring has loaded and its oscillation (damped by gt = gn, e = 0.5) has died out.
double downslopeAcceleration(double angle, double friction) {
    const double mass = sphereMass(radius);
    const auto law = LinearSpringDashpot::fromCollision(collisionTime, 0.5, mass).withFriction(friction);
    // Start at the static overlap m g cos a / kn, so that the normal spring does not bounce.
    const double overlap = mass * std::cos(angle) / law.normalStiffness;
    TestScene scene;
    scene.setup = [&](TestScene& s) {
        s.scene().setGravity(Vec3(std::sin(angle), 0, -std::cos(angle)));
        s.scene().setDomain(Vec3(-1, -1, -1), Vec3(10, 1, 1));
        const auto species = s.scene().addSpecies("solid", unitMassDensity, law);
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
        s.scene().addParticle(Vec3(0, 0, radius - overlap), radius, species);
    };
    const double start = 1, end = 4;
    double startVelocity = NAN;
    scene.afterStep = [&](TestScene& s) {
        if (std::abs(s.time() - start) < 0.5 * timeStep) startVelocity = s.scene().particles().velocity[0].x();
    };
    scene.runFor(timeStep, end);
    return (scene.scene().particles().velocity[0].x() - startVelocity) / (scene.time() - start);
}

}  // namespace

TEST(Incline, SphereRollsWithoutSlipAtFiveSevenths) {
    const double angle = degrees(20), friction = 0.5;  // tan 20 deg = 0.36 < 7/2 mu = 1.75
    const double expected = 5.0 / 7.0 * std::sin(angle);
    const double measured = downslopeAcceleration(angle, friction);
    std::printf("[ measured ] rolling: acceleration error %.2e\n", std::abs(measured / expected - 1));
    EXPECT_NEAR(measured / expected, 1, 1.5e-5);
}

TEST(Incline, SphereSlidesWithCoulombFriction) {
    const double angle = degrees(30), friction = 0.1;  // tan 30 deg = 0.58 > 7/2 mu = 0.35
    const double expected = std::sin(angle) - friction * std::cos(angle);
    const double measured = downslopeAcceleration(angle, friction);
    std::printf("[ measured ] sliding: acceleration error %.2e\n", std::abs(measured / expected - 1));
    EXPECT_NEAR(measured / expected, 1, 1e-10);
}

// The inside of a cylinder as a wall (Walls/Wall.h): a drum's mantle for spheres and for
// superquadrics (Theory/Superquadrics.md "Walls").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "TestHelpers.h"

using namespace talus;
using namespace talus::test;

TEST(CylinderWall, DistanceAndNormalAreThoseOfTheCylinder) {
    Wall drum;
    drum.point = Vec3(1, 2, 3);
    drum.normal = Vec3::UnitY();
    drum.radius = 2;
    const Vec3 x = drum.point + Vec3(0.6, 5, -0.8);  // 1 from the axis
    EXPECT_NEAR(drum.signedDistance(x), 1, 1e-15);
    EXPECT_LT((drum.normalAt(x) - Vec3(-0.6, 0, 0.8)).norm(), 1e-15);
    // The wall nearest to x is 2 (0.6, 0, -0.8) from the axis, its tangent plane normal to that
    // direction: a point 0.5 beyond x towards it lies 0.5 from the plane.
    EXPECT_NEAR(drum.tangentPlaneDistance(x + Vec3(0.3, 0, -0.4), x), 0.5, 1e-15);
}

namespace {

// Something resting at the bottom of a horizontal drum (axis along y through the origin,
// radius 2) under gravity -z: its lowest point sinks into the wall by m g / kn.
double restingHeight(bool ellipsoid, double& expected) {
    SceneSimulation s;
    const Superquadric shape = Superquadric::ellipsoid(0.6, 0.5, 0.3);  // lying along x, 0.3 high
    const double r = 0.3, mass = ellipsoid ? 6 / pi * shape.volume() : 6 / pi * 4.0 / 3.0 * pi * r * r * r;
    const LinearSpringDashpot law = LinearSpringDashpot::fromCollision(0.005, 0.3, mass).withFriction(0.5);
    s.setup = [&](SceneSimulation& sim) {
        sim.setGravity(Vec3(0, 0, -1));
        sim.setDomain(Vec3(-3, -2, -3), Vec3(3, 2, 3));
        sim.setPeriodic(false, true, false);
        const auto species = sim.addSpecies("grains", 6 / pi, law);
        sim.addCylinderWall(Vec3::Zero(), Vec3::UnitY(), 2, species);
        if (ellipsoid)
            sim.addSuperquadric(Vec3(0, 0, -1.6), sim.addShape(shape), species);
        else
            sim.addParticle(Vec3(0, 0, -1.6), r, species);
    };
    s.run(1e-4, 4);
    expected = -(2 - 0.3) - mass / law.normalStiffness;  // both are 0.3 high below the centre
    EXPECT_LT(s.particles().velocity[0].norm(), 1e-6);
    EXPECT_LT(std::abs(s.particles().position[0].x()), 1e-9);
    return s.particles().position[0].z();
}

}  // namespace

TEST(CylinderWall, SphereAndEllipsoidRestAtTheBottomOfADrum) {
    for (bool ellipsoid : {false, true}) {
        double expected = 0;
        const double z = restingHeight(ellipsoid, expected);
        std::printf("[ measured ] %s at the bottom of a drum: z = %.10f against %.10f\n",
                    ellipsoid ? "ellipsoid" : "sphere", z, expected);
        EXPECT_NEAR(z, expected, 1e-8);
    }
}

// A drum of radius Rd turning at w about its axis (y) carries a sphere (radius s, mass m,
// I = 2/5 m s^2) that starts at rest at the bottom; its wall moves at V = w Rd. With phi the angle
// of the sphere's centre from the bottom, in the sense the wall moves, e the unit vector along
// the circle of the centre (radius Rd - s) in that sense, u = v . e the centre's speed along it and
// a = (w_s x b) . e the spin's part of the contact point's speed (b = s from the centre towards
// the wall, along the radius):
//   m du/dt = F - m g sin(phi)   (F: the friction along e; the normal force is along b),
//   I dw_s/dt = b x F, so da/dt = (b x F) x b . e / I = s^2 F / I = (5/2) F / m,
// hence d(u - 2a/5)/dt = -g sin(phi), and from rest u - 2a/5 = -G(t), G = g int_0^t sin(phi) dt.
// Once friction has stopped the slip the contact point moves with the wall, u + a = V, and so
//   u = (2/7) V - (5/7) G(t)
// at every later time: 2/7 of the wall's speed, less what gravity took back on the way up (the
// drum test of Drivers/Drum follows the pendulum this leads to). G is summed from the positions
// (trapezoidal rule, error ~1e-9 here). Checked from t = 0.5 (the slip ends near
// (2/7) V / (mu g) = 0.14) to t = 1: the overlap dn = m g / kn = 7e-6 s shortens the lever arm
// to s - dn/2, which makes u (5/7) dn/s = 5e-6 faster, and the tangential spring lets the
// contact creep only as fast as its stretch |F| / kt changes. Measured: 5.9e-6 of 2V/7; the
// bound 1e-4. A wall speed off by 1% fails (measured: 1e-2), by a factor 0.5 or 2 by far.
TEST(CylinderWall, ARotatingDrumCarriesASphereAtTwoSeventhsOfItsSpeed) {
    SceneSimulation s;
    const double r = 0.3, mass = 6 / pi * 4.0 / 3.0 * pi * r * r * r, drumRadius = 2, w = 0.2, g = 1;
    const double wallSpeed = w * drumRadius;
    s.setup = [&](SceneSimulation& sim) {
        sim.setGravity(Vec3(0, 0, -g));
        sim.setDomain(Vec3(-3, -2, -3), Vec3(3, 2, 3));
        sim.setPeriodic(false, true, false);
        const auto species =
            sim.addSpecies("grains", 6 / pi, LinearSpringDashpot::fromCollision(0.005, 0.3, mass).withFriction(0.8));
        PrescribedMotion turning;
        turning.angularVelocity = Vec3(0, w, 0);
        sim.addCylinderWall(Vec3::Zero(), Vec3::UnitY(), drumRadius, species, static_cast<int>(sim.addMotion(turning)));
        sim.addParticle(Vec3(0, 0, -(drumRadius - r)), r, species);
    };
    // The wall at the bottom, (0, 0, -Rd), moves at (0, w, 0) x (0, 0, -Rd) = (-w Rd, 0, 0): phi
    // grows from the bottom towards -x, and e = (-cos(phi), 0, sin(phi)).
    double G = 0, lastSine = 0, worst = 0, carried = 0;
    s.afterStep = [&](SceneSimulation& sim) {
        const Vec3& x = sim.particles().position[0];
        const double phi = std::atan2(-x.x(), -x.z());
        G += 0.5 * g * (lastSine + std::sin(phi)) * sim.timeStep();
        lastSine = std::sin(phi);
        const double u = sim.particles().velocity[0].dot(Vec3(-std::cos(phi), 0, std::sin(phi)));
        if (sim.time() >= 0.5) worst = std::max(worst, std::abs(u + 5.0 / 7.0 * G - 2.0 / 7.0 * wallSpeed));
        carried = phi;
    };
    s.run(1e-4, 1);
    std::printf("[ measured ] sphere in a turning drum: carried to phi = %.4f, |u + 5G/7 - 2V/7| / (2V/7) up to %.2e "
                "(5G/7 = %.4f of 2V/7 = %.4f)\n",
                carried, worst / (2.0 / 7.0 * wallSpeed), 5.0 / 7.0 * G, 2.0 / 7.0 * wallSpeed);
    EXPECT_GT(carried, 0.01);  // carried up the side the wall moves to
    EXPECT_LT(worst, 1e-4 * 2.0 / 7.0 * wallSpeed);
    EXPECT_NEAR(s.walls()[0].point.norm(), 0, 1e-12);   // the axis stays put
    EXPECT_NEAR(std::abs(s.walls()[0].normal.y()), 1, 1e-12);
}

TEST(CylinderWall, BadRadiusIsNamed) {
    SceneSimulation s;
    s.setup = [](SceneSimulation& sim) {
        const auto species = sim.addSpecies("grains", 1, LinearSpringDashpot::fromCollision(0.005, 0.5, 1));
        sim.addCylinderWall(Vec3::Zero(), Vec3::UnitY(), -1, species);
    };
    expectError([&] { s.run(1e-4, 1e-3); }, {"cylinder wall", "radius must be positive"});
}

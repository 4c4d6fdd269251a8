// The inside of a cylinder as a wall (Walls/Wall.h): a drum's mantle for spheres and for
// superquadrics (SPEC.md 4-5).
#include <gtest/gtest.h>

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

TEST(CylinderWall, ARotatingDrumCarriesASphereAlong) {
    // A drum turning at 0.2 rad per time unit about its axis (y): the wall at the bottom,
    // r = (0, 0, -R), moves at omega x r = (0.2 y) x (-R z) = -0.2 R x; a sphere resting there with
    // friction is dragged along, towards -x.
    SceneSimulation s;
    const double r = 0.3, mass = 6 / pi * 4.0 / 3.0 * pi * r * r * r;
    s.setup = [&](SceneSimulation& sim) {
        sim.setGravity(Vec3(0, 0, -1));
        sim.setDomain(Vec3(-3, -2, -3), Vec3(3, 2, 3));
        sim.setPeriodic(false, true, false);
        const auto species =
            sim.addSpecies("grains", 6 / pi, LinearSpringDashpot::fromCollision(0.005, 0.3, mass).withFriction(0.8));
        PrescribedMotion turning;
        turning.angularVelocity = Vec3(0, 0.2, 0);
        sim.addCylinderWall(Vec3::Zero(), Vec3::UnitY(), 2, species, static_cast<int>(sim.addMotion(turning)));
        sim.addParticle(Vec3(0, 0, -1.7), r, species);
    };
    s.run(1e-4, 1);
    EXPECT_LT(s.particles().position[0].x(), -0.01);  // carried towards -x
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

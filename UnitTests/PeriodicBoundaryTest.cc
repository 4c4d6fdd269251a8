// Periodic boundaries: a contact across a periodic face (or corner) is the same contact as in
// the middle of the box, and wrapping keeps every position in [lo, hi).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "TestHelpers.h"

using namespace talus;
using test::SceneSimulation;

namespace {

const Vec3 boxLo(-2.0, 1.0, 0.5);
const Vec3 boxHi(6.0, 8.0, 10.5);

// Unit-mass spheres of radius 1/2 with friction, so that normal, damping and tangential
// forces and torques all act.
std::size_t addGlass(Simulation& s, double collisionTime) {
    return s.scene().addSpecies("glass", 6 / pi, LinearSpringDashpot::fromCollision(collisionTime, 0.7, 0.5).withFriction(0.5));
}

struct PairState {
    Vec3 force[2], torque[2], position[2];
};

// Two touching spheres (overlap 2% of the radius, oblique normal, sliding and spinning) whose
// contact point is at `middle`; all axes periodic. Returns their state after one time step.
PairState touchingPairAfterOneStep(const Vec3& middle) {
    const double tc = 0.01, dt = tc / 50;
    SceneSimulation s;
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setDomain(boxLo, boxHi);
        sim.scene().setPeriodic(true, true, true);
        sim.scene().setGravity(Vec3::Zero());
        sim.settings().timeStep = dt;
        const auto glass = addGlass(sim, tc);
        const Vec3 separation = Vec3(0.8, 0.5, -0.33).normalized() * (1.0 - 0.01);
        Vec3 a = middle + 0.5 * separation, b = middle - 0.5 * separation;
        sim.scene().domain().wrap(a);
        sim.scene().domain().wrap(b);
        sim.scene().addParticle(a, 0.5, glass, Vec3(-0.1, 0.2, 0.05), Vec3(1, -2, 0.5));
        sim.scene().addParticle(b, 0.5, glass, Vec3(0.05, -0.1, 0.3), Vec3(0, 3, -1));
    };
    s.solveOrThrow(test::stepsWithoutFiles(dt, 1));
    EXPECT_EQ(s.step(), 1u);
    PairState state;
    for (int k = 0; k < 2; ++k) {  // by id: the slots follow the space-filling curve
        const std::size_t slot = s.scene().slotOf(k);
        state.force[k] = s.scene().particles().force[slot];
        state.torque[k] = s.scene().particles().torque[slot];
        state.position[k] = s.scene().particles().position[slot];
    }
    return state;
}

// Equal to round-off: the two runs differ only in where the pair sits, so positions (of size
// ~10, rounded to 1.8e-15) carry rounding into an overlap of 1e-2: 2e-13 of the force per
// rounding. Measured: at most 1.1e-13; the bound 1e-11 leaves room for a few tens of roundings,
// while a contact missed or seen through a wrong image is off by the whole force.
void expectSameContact(const PairState& across, const PairState& inside) {
    const double scale = inside.force[0].norm();
    ASSERT_GT(scale, 0) << "the spheres should touch";
    double worst = 0;
    for (int k = 0; k < 2; ++k) {
        worst = std::max({worst, (across.force[k] - inside.force[k]).norm() / scale,
                          (across.torque[k] - inside.torque[k]).norm() / scale});
    }
    std::printf("[ measured ] across - inside: %.2e of the force\n", worst);
    EXPECT_LT(worst, 1e-11);
    EXPECT_LT((inside.force[0] + inside.force[1]).norm(), 1e-12 * scale) << "action equals reaction";
    EXPECT_GT(inside.torque[0].norm(), 0) << "tangential force should act";
}

void expectInsideBox(const Vec3& x) {
    for (int a = 0; a < 3; ++a) {
        EXPECT_GE(x[a], boxLo[a]) << "axis " << a << " of " << x.transpose();
        EXPECT_LT(x[a], boxHi[a]) << "axis " << a << " of " << x.transpose();
    }
}

const Vec3 centre = 0.5 * (boxLo + boxHi);

TEST(PeriodicBoundary, ContactAcrossEachFaceEqualsContactInside) {
    const PairState inside = touchingPairAfterOneStep(centre);
    for (int axis = 0; axis < 3; ++axis) {
        SCOPED_TRACE("face normal to axis " + std::to_string(axis));
        for (const Vec3& face : {boxLo, boxHi}) {
            Vec3 middle = centre;
            middle[axis] = face[axis];
            const PairState across = touchingPairAfterOneStep(middle);
            expectSameContact(across, inside);
            // The pair really straddles the face: the two centres lie at opposite ends of the box.
            EXPECT_GT(std::abs(across.position[0][axis] - across.position[1][axis]), 0.5 * (boxHi - boxLo)[axis]);
            expectInsideBox(across.position[0]);
            expectInsideBox(across.position[1]);
        }
    }
}

TEST(PeriodicBoundary, ContactAcrossCornerEqualsContactInside) {
    const PairState inside = touchingPairAfterOneStep(centre);
    for (const Vec3& corner : {boxHi, boxLo, Vec3(boxLo.x(), boxHi.y(), boxLo.z())}) {
        SCOPED_TRACE("corner " + std::to_string(corner.x()) + " " + std::to_string(corner.y()) + " " +
                     std::to_string(corner.z()));
        const PairState across = touchingPairAfterOneStep(corner);
        expectSameContact(across, inside);
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_GT(std::abs(across.position[0][axis] - across.position[1][axis]), 0.5 * (boxHi - boxLo)[axis]);
    }
}

// A fast particle crossing faces in every direction, several box lengths in a run. One particle
// per run, so that it cannot hit another at this speed.
TEST(PeriodicBoundary, WrappingKeepsPositionsInBox) {
    const double tc = 0.01, dt = tc / 50;
    for (const Vec3& velocity : {Vec3(1000.1, -700.3, 1200.7), Vec3(-555.5, 888.8, -1001.9)}) {
        SceneSimulation s;
        std::size_t checks = 0;
        s.setup = [&](SceneSimulation& sim) {
            sim.scene().setDomain(boxLo, boxHi);
            sim.scene().setPeriodic(true, true, true);
            sim.scene().setGravity(Vec3::Zero());
            sim.settings().timeStep = dt;
            sim.scene().addParticle(centre, 0.5, addGlass(sim, tc), velocity);
        };
        s.afterStep = [&](SceneSimulation& sim) {
            expectInsideBox(sim.scene().particles().position[0]);
            ++checks;
        };
        s.solveOrThrow(test::stepsWithoutFiles(dt, 200));
        EXPECT_EQ(checks, 200u);
        // It went the whole way: 200 steps of dt at this velocity, modulo the box.
        Vec3 expected = centre + 200 * dt * velocity;
        s.scene().domain().wrap(expected);
        // Each of the 200 drifts and wraps rounds a coordinate of size ~10 (1.8e-15): at most
        // a few 1e-13 in all (measured: 5e-14).
        const double error = (s.scene().particles().position[0] - expected).norm();
        std::printf("[ measured ] wrapped flight: %.2e from the expected point\n", error);
        EXPECT_LT(error, 1e-11);
    }
}

// Domain::wrap at the edges: exactly hi, a hair below lo (where x + L rounds up to hi), and
// jumps of several box lengths.
TEST(PeriodicBoundary, WrapHandlesEdgesAndLongJumps) {
    Domain domain;
    domain.lo = Vec3(0, -1, 2);
    domain.hi = Vec3(1, 3, 2.5);
    domain.periodic = {true, true, true};
    const std::vector<Vec3> positions = {domain.hi, domain.lo, Vec3(-1e-300, std::nextafter(-1.0, -2.0), std::nextafter(2.0, 0.0)),
                                         Vec3(7.25, 3 + 4 * 5.5, 2.5 + 0.5 * 9.3), Vec3(-7.25, -1 - 4 * 5.5, 2 - 11.1),
                                         Vec3(std::nextafter(1.0, 2.0), std::nextafter(-1.0, -2.0), 2.4999999)};
    for (Vec3 x : positions) {
        const Vec3 original = x;
        domain.wrap(x);
        for (int a = 0; a < 3; ++a) {
            EXPECT_GE(x[a], domain.lo[a]) << original.transpose();
            EXPECT_LT(x[a], domain.hi[a]) << original.transpose();
            // Same point modulo the period (to round-off of the jump).
            const double periods = (x[a] - original[a]) / domain.length(a);
            EXPECT_NEAR(periods, std::round(periods), 1e-9) << original.transpose();
        }
    }
    Domain open;  // open axes are left alone
    Vec3 far(-5, 7, 100);
    open.wrap(far);
    EXPECT_EQ(far, Vec3(-5, 7, 100));
}

}  // namespace

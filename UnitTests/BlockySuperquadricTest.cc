// A blocky superquadric (e1 = e2 = 0.3: a box with rounded edges) in whole simulations, driven
// through talus::Simulation: energy conservation of elastic frictionless bounces on a floor, and
// a restart written in the middle of a collision that continues bitwise as the uninterrupted run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "Contacts/SuperquadricContact.h"
#include "TestHelpers.h"

using namespace talus;
using namespace talus::test;

namespace {

const Superquadric blockyShape{0.5, 0.4, 0.3, 0.3, 0.3};
constexpr double density = 6 / pi;
constexpr double collisionTime = 0.01;

double blockyMass() { return density * blockyShape.volume(); }

// The largest departure of kinetic + rotational + gravitational energy from its start value, in
// flight (no contact, where no elastic energy is stored), relative to the start value, of a
// tilted, spinning block dropped on a floor (e = 1, no friction) for three bounces.
struct BounceResult {
    double worstEnergyError = 0;
    int contactSteps = 0, bounces = 0;
    double largestSpinChange = 0;
};

BounceResult bounce(double timeStep) {
    SceneSimulation s;
    BounceResult result;
    double startEnergy = NAN;
    bool inContact = false;
    Vec3 spinBefore = Vec3::Zero();
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(Vec3(0, 0, -1));
        sim.scene().setDomain(Vec3(-5, -5, 0), Vec3(5, 5, 5));
        const auto species = sim.scene().addSpecies("blocks", density, LinearSpringDashpot::fromCollision(collisionTime, 1, blockyMass()));
        sim.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
        sim.scene().addSuperquadric(Vec3(0, 0, 0.9), sim.scene().addShape(blockyShape), species,
                            Quat(Eigen::AngleAxisd(0.5, Vec3(0.4, 1, 0.3).normalized())), Vec3(0.1, 0, 0),
                            Vec3(0.5, -1, 2));
    };
    s.afterStep = [&](SceneSimulation& sim) {
        const Energies e = sim.energies();
        const double total = e.kinetic + e.rotational + e.gravitational;
        if (std::isnan(startEnergy)) startEnergy = total;
        const bool touching = sim.contactSummary().contacts > 0;
        if (touching && !inContact) spinBefore = sim.scene().particles().angularVelocity[0];
        if (!touching && inContact) {
            ++result.bounces;
            result.largestSpinChange =
                std::max(result.largestSpinChange, (sim.scene().particles().angularVelocity[0] - spinBefore).norm());
        }
        inContact = touching;
        if (!touching) result.worstEnergyError = std::max(result.worstEnergyError, std::abs(total - startEnergy));
        result.contactSteps += touching;
    };
    s.runFor(timeStep, 3.2);
    result.worstEnergyError /= std::abs(startEnergy);
    return result;
}

}  // namespace

// Nothing dissipates (e = 1: no dashpot; no friction), so the energy in flight stays at its start
// value up to the time integration's error: velocity Verlet with the superquadric contact
// stepped plainly (the spring force has a kink at the touch and the separation, and the normal
// turns with the block) and the rigid-body rotation of RigidBodyRotation.h, both of second
// order in dt. Measured 4.9e-4 at dt = tc/50 and 1.0e-4 at tc/100 (a fifth): the tolerance is
// set at tc/100 with a margin of two, and the error must fall by at least a factor three.
TEST(BlockySuperquadric, ElasticBouncesConserveEnergyToTheTimeStepError) {
    const BounceResult coarse = bounce(collisionTime / 50), fine = bounce(collisionTime / 100);
    std::printf("[ measured ] blocky superquadric, 3 s of bounces: energy error %.2e at tc/50, %.2e at tc/100 "
                "(%d bounces, %d contact steps, spin changed by up to %.2f)\n",
                coarse.worstEnergyError, fine.worstEnergyError, fine.bounces, fine.contactSteps, fine.largestSpinChange);
    EXPECT_GE(fine.bounces, 2);
    EXPECT_GT(fine.largestSpinChange, 0.1) << "the impacts must turn the block (off-centre contacts)";
    EXPECT_LT(fine.worstEnergyError, 2e-4);
    EXPECT_LT(fine.worstEnergyError, coarse.worstEnergyError / 3);
}

namespace {

// Two blocks and a floor, gravity on: block 0 falls onto the floor, block 1 (tilted and spinning)
// comes in along x and hits block 0 off-centre; both contacts last about 50 steps.
constexpr double restartTimeStep = collisionTime / 50;

void twoBlocks(SceneSimulation& sim) {
    sim.settings().timeStep = restartTimeStep;
    sim.scene().setGravity(Vec3(0, 0, -1));
    sim.scene().setDomain(Vec3(-3, -3, 0), Vec3(3, 3, 3));
    const auto species = sim.scene().addSpecies("blocks", density, LinearSpringDashpot::fromCollision(collisionTime, 1, blockyMass()));
    sim.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
    const std::size_t shape = sim.scene().addShape(blockyShape);
    sim.scene().addSuperquadric(Vec3(0, 0, 0.3 + 10.4 * 0.3 * restartTimeStep), shape, species, Quat::Identity(),
                        Vec3(0, 0, -0.3));
    // Block 1 touches block 0 (as placed) at the distance found by bisection on the contact
    // detection, and starts 20.7 steps of its approach further out.
    const Quat turned(Eigen::AngleAxisd(0.2, Vec3(0.2, 0.3, 1).normalized()));
    const Vec3 offset(0, 0.1, 0.05);
    double near = 0.5, far = 2;
    for (int k = 0; k < 60; ++k) {
        const double middle = 0.5 * (near + far);
        const bool touching = findSuperquadricContact({&blockyShape, Vec3::Zero(), Mat3::Identity()},
                                                      {&blockyShape, Vec3(middle, 0, 0) + offset, turned.toRotationMatrix()})
                                  .touching;
        (touching ? near : far) = middle;
    }
    sim.scene().addSuperquadric(Vec3(far + 20.7 * 0.5 * restartTimeStep, 0, 0.3) + offset, shape, species, turned,
                        Vec3(-0.5, 0, 0), Vec3(0.3, 0.2, -1));
}

}  // namespace

// DESIGN: a restart continues bitwise identically to the uninterrupted run. Written at step 40,
// in the middle of both contacts (the particle pair's history then holds its spring and the
// warm start of the contact point), continued to step 100, against 100 steps in one run.
TEST(BlockySuperquadric, RestartInTheMiddleOfACollisionContinuesBitwise) {
    SceneSimulation first;
    first.setup = twoBlocks;
    first.settings().name = "blocky_restart";
    first.settings().reorderParticles = false;
    first.solveOrThrow({"--end-time", std::to_string(40 * restartTimeStep), "--output-interval", "1"});
    ASSERT_EQ(first.contactSummary().contacts, 2u) << "the restart must fall inside both contacts";

    SceneSimulation restarted;
    restarted.settings().reorderParticles = false;
    restarted.solveOrThrow({"--restart", "blocky_restart.restart", "--end-time", std::to_string(100 * restartTimeStep),
                            "--files", "off"});
    SceneSimulation uninterrupted;
    uninterrupted.setup = twoBlocks;
    uninterrupted.settings().reorderParticles = false;
    uninterrupted.solveOrThrow(stepsWithoutFiles(restartTimeStep, 100));

    ASSERT_EQ(restarted.step(), 100u);
    expectSameContinuation(restarted, uninterrupted);
    // And the run moved: the blocks turned and bounced.
    EXPECT_GT((uninterrupted.scene().particles().angularVelocity[0]).norm(), 0.01);
    EXPECT_GT(uninterrupted.scene().particles().velocity[0].z(), 0);
}

// The deletion boundary (Kernel/Boundaries/DeletionBoundary.h): it removes exactly the particles
// past its plane, records their number, mass and volume per species, and keeps the totals across
// a restart. The scene owns it and applies it after every step (the driver calls nothing).
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

#include "Boundaries/DeletionBoundary.h"
#include "TestHelpers.h"

using namespace talus;

// Only the scene makes boundaries (Scene::addBoundary): one made elsewhere would never act.
static_assert(!std::is_default_constructible_v<Boundary::Made>);

namespace {

const double outflowStep = 1e-3;

// Ten spheres in a row along x at x = 0, 1, ..., 9, alternately of density 1 and 2, moving at
// speed 1 towards a deletion plane at x = 10.5 without touching each other; no gravity. After a
// time t the spheres that started beyond 10.5 - t are gone.
struct Outflow : test::SceneSimulation {
    DeletionBoundary& outlet = scene().addBoundary<DeletionBoundary>(*this, Vec3::UnitX(), Vec3(10.5, 0, 0), 2, "outlet");
    Outflow() {
        setup = [](SceneSimulation& s) {
            s.settings().timeStep = outflowStep;
            s.scene().setGravity(Vec3::Zero());
            const auto law = LinearSpringDashpot::fromCollision(0.05, 0.5, 0.5);
            s.scene().addSpecies("light", 1, law);
            s.scene().addSpecies("heavy", 2, law);
            for (int k = 0; k < 10; ++k) s.scene().addParticle(Vec3(k, 0, 0), 0.2 + 0.01 * k, k % 2, Vec3(1, 0, 0));
            s.scene().addFixedParticle(Vec3(12, 0, 0), 0.2, 0);  // fixed particles stay, even past the plane
        };
    }
};

double sphereVolume(double r) { return 4.0 / 3.0 * pi * r * r * r; }

}  // namespace

TEST(DeletionBoundary, RemovesExactlyWhatPassedAndRecordsIt) {
    Outflow run;
    run.solveOrThrow(test::stepsWithoutFiles(outflowStep, 5000));  // t = 5: spheres 6..9 have left
    EXPECT_EQ(run.outlet.count(), 4);
    EXPECT_EQ(run.scene().particles().size(), 7u);  // six mobile spheres and the fixed one
    double mass[2] = {0, 0}, volume[2] = {0, 0};
    for (int k = 6; k < 10; ++k) {
        const double v = sphereVolume(0.2 + 0.01 * k);
        mass[k % 2] += (k % 2 ? 2 : 1) * v;
        volume[k % 2] += v;
    }
    for (int s = 0; s < 2; ++s) {
        EXPECT_NEAR(run.outlet.mass(s), mass[s], 1e-15);
        EXPECT_NEAR(run.outlet.volume(s), volume[s], 1e-15);
    }
    EXPECT_NEAR(run.outlet.mass(), mass[0] + mass[1], 1e-15);
    EXPECT_NEAR(run.outlet.volume(), volume[0] + volume[1], 1e-15);
    // Conservation: what is left plus what left is what there was.
    double left = 0, total = 0;
    for (std::size_t i = 0; i < run.scene().particles().size(); ++i)
        if (!run.scene().particles().fixed[i]) left += run.scene().particles().mass[i];
    for (int k = 0; k < 10; ++k) total += (k % 2 ? 2 : 1) * sphereVolume(0.2 + 0.01 * k);
    EXPECT_NEAR(left + run.outlet.mass(), total, 1e-14);
    for (std::size_t i = 0; i < run.scene().particles().size(); ++i) {
        if (!run.scene().particles().fixed[i]) {
            EXPECT_LE(run.scene().particles().position[i].x(), 10.5);
        }
    }
}

TEST(DeletionBoundary, TotalsContinueAfterARestart) {
    Outflow first;
    first.solveOrThrow({"--name", "deletion_restart", "--end-time", std::to_string(3000 * outflowStep),
                        "--progress-interval", "1e9"});
    EXPECT_EQ(first.outlet.count(), 2);  // spheres 8 and 9
    Outflow restarted;
    restarted.solveOrThrow({"--restart", "deletion_restart.restart", "--end-time", std::to_string(5000 * outflowStep),
                            "--files", "off"});
    Outflow whole;
    whole.solveOrThrow(test::stepsWithoutFiles(outflowStep, 5000));
    EXPECT_EQ(restarted.outlet.count(), 4);
    EXPECT_EQ(restarted.outlet.mass(), whole.outlet.mass());
    EXPECT_EQ(restarted.outlet.volume(1), whole.outlet.volume(1));
}

TEST(DeletionBoundary, BadPlaneIsAClearError) {
    test::SceneSimulation s;
    test::expectError([&] { s.scene().addBoundary<DeletionBoundary>(s, Vec3::Zero(), Vec3::Zero(), 1); }, {"deletion boundary", "normal"});
}

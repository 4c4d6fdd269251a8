// The deletion boundary (Kernel/Boundaries/DeletionBoundary.h): it removes exactly the particles
// past its plane, records their number, mass and volume per species, and keeps the totals across
// a restart. The scene owns it and applies it after every step (the driver calls nothing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <utility>
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

namespace {

// A hopper that drains: 300 spheres (radius 0.25, mass 1/16) dropped as a loose lattice (4 x 4,
// 0.6 apart) into a 45-degree funnel (orifice radius 0.8 at z = 0), gravity 1; spheres 1 below
// the orifice leave.
struct DrainingHopper : test::SceneSimulation {
    DeletionBoundary& outlet = scene().addBoundary<DeletionBoundary>(*this, -Vec3::UnitZ(), Vec3(0, 0, -1), 1, "outlet");
    explicit DrainingHopper(bool relist) {
        settings().relist = relist;
        setup = [](SceneSimulation& s) {
            s.scene().setGravity(Vec3(0, 0, -1));
            s.scene().setDomain(Vec3(-4, -4, -1.5), Vec3(4, 4, 14));
            const auto grain =
                s.scene().addSpecies("grain", 6 / pi, LinearSpringDashpot::fromCollision(0.02, 0.5, 0.0625).withFriction(0.4));
            s.scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), {{0.8, 0}, {3, 2.2}, {3, 14}}, grain);
            std::mt19937_64 random(11);
            std::uniform_real_distribution<double> jitter(-0.02, 0.02);
            for (int k = 0; k < 300; ++k) {
                const double x = -0.9 + 0.6 * (k % 4), y = -0.9 + 0.6 * ((k / 4) % 4), z = 1 + 0.6 * (k / 16);
                s.scene().addParticle(Vec3(x + jitter(random), y + jitter(random), z), 0.25, grain);
            }
        };
    }
};

}  // namespace

// The list follows each removal instead of being built anew (PairList::followRemoval). After
// every removal of a drain of a few dozen spheres the list kept holds every pair of spheres that
// overlap and every sphere touching a wall, and each of its pairs that holds a touching history
// belongs to two spheres that touch (within a step's motion): a slot followed wrongly would give
// a history to the wrong pair or lose one. And the run gives the trajectories of the run that
// rebuilds at every removal (--relist off) to round-off for as long as the flow keeps round-off
// small (the first removals, up to t = 3; later differences of 1e-13 grow a thousandfold per
// unit of time in the dense flow, whichever run is right).
TEST(DeletionBoundary, FollowingRemovalsKeepsTheListAndChangesNoPhysics) {
    DrainingHopper following(true), rebuilding(false), longer(true);
    following.runFor(2e-3, 3);
    rebuilding.runFor(2e-3, 3);
    const PairList &a = following.state().pairList, &b = rebuilding.state().pairList;
    EXPECT_GT(following.outlet.count(), 2);
    EXPECT_EQ(following.outlet.count(), rebuilding.outlet.count());
    EXPECT_EQ(a.removedParticles, static_cast<std::uint64_t>(following.outlet.count()));
    EXPECT_EQ(b.removedParticles, 0u);
    const ParticleStore &p = following.scene().particles(), &q = rebuilding.scene().particles();
    ASSERT_EQ(p.size(), q.size());
    double worst = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        worst = std::max(worst, (p.position[i] - q.position[rebuilding.scene().slotOf(p.id[i])]).norm());
    std::printf("[ measured ] to t = 3: %.0f removals, largest difference of a position %.2e\n", following.outlet.count(), worst);
    EXPECT_LT(worst, 1e-10);

    std::uint64_t seen = 0;
    int checks = 0, overlapping = 0, onWalls = 0;
    longer.afterStep = [&](test::SceneSimulation& s) {
        const PairList& list = s.state().pairList;
        if (list.removedParticles == seen) return;
        seen = list.removedParticles;
        const ParticleStore& x = s.scene().particles();
        ASSERT_TRUE(list.valid);
        ASSERT_EQ(list.referencePosition.size(), x.size());
        std::set<std::pair<std::uint64_t, std::uint64_t>> listed;
        for (std::size_t k = 0; k < list.pairs.size(); ++k) {
            const auto [i, j] = list.pairs[k];
            ASSERT_LT(std::max(i, j), x.size());
            listed.insert(std::minmax(x.id[i], x.id[j]));
            if (list.history.get(k).isTouching()) {
                EXPECT_LT((x.position[i] - x.position[j]).norm(), x.radius[i] + x.radius[j] + 0.02)
                    << "ids " << x.id[i] << "-" << x.id[j];
            }
        }
        std::set<std::uint64_t> atWalls;
        for (const WallCandidate& c : list.wallPairs) atWalls.insert(x.id[c.particle]);
        for (std::size_t i = 0; i < x.size(); ++i) {
            for (std::size_t j = i + 1; j < x.size(); ++j)
                if ((x.position[i] - x.position[j]).norm() < x.radius[i] + x.radius[j]) {
                    EXPECT_TRUE(listed.count(std::minmax(x.id[i], x.id[j]))) << "ids " << x.id[i] << "-" << x.id[j];
                    ++overlapping;
                }
            for (const Wall& w : s.scene().walls())
                if (w.gapTo(x.position[i]).distance < x.radius[i]) {
                    EXPECT_TRUE(atWalls.count(x.id[i])) << "id " << x.id[i];
                    ++onWalls;
                }
        }
        ++checks;
    };
    longer.runFor(2e-3, 12);
    std::printf("[ measured ] to t = 12: %d removals checked (%d overlapping pairs, %d wall contacts found listed); "
                "%lu builds\n", checks, overlapping, onWalls, static_cast<unsigned long>(longer.state().pairList.builds));
    EXPECT_GT(checks, 10);
    EXPECT_GT(overlapping, 1000);
    EXPECT_GT(onWalls, 100);
}

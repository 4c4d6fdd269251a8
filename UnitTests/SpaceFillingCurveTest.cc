// The Morton order of Particles/SpaceFillingCurve.h, and reordering during a run
// (RunSettings::reorderParticles): the particles' slots change, their physics does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "Particles/SpaceFillingCurve.h"
#include "TestHelpers.h"

using namespace talus;

namespace {

// The key bit by bit, as the definition reads: bit b of x goes to bit 3b, of y to 3b+1, of z to
// 3b+2.
std::uint64_t mortonKeyBitByBit(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    std::uint64_t key = 0;
    for (int b = 0; b < 21; ++b) {
        key |= std::uint64_t((x >> b) & 1) << (3 * b);
        key |= std::uint64_t((y >> b) & 1) << (3 * b + 1);
        key |= std::uint64_t((z >> b) & 1) << (3 * b + 2);
    }
    return key;
}

}  // namespace

TEST(SpaceFillingCurve, MortonKeyInterleavesTheBits) {
    std::mt19937 random(3);
    std::uniform_int_distribution<std::uint32_t> cell(0, (1u << 21) - 1);
    for (int n = 0; n < 1000; ++n) {
        const std::uint32_t x = cell(random), y = cell(random), z = cell(random);
        ASSERT_EQ(mortonKey(x, y, z), mortonKeyBitByBit(x, y, z)) << x << " " << y << " " << z;
    }
    EXPECT_EQ(mortonKey(1, 0, 0), 1u);
    EXPECT_EQ(mortonKey(0, 1, 0), 2u);
    EXPECT_EQ(mortonKey(0, 0, 1), 4u);
    EXPECT_EQ(mortonKey((1u << 21) - 1, (1u << 21) - 1, (1u << 21) - 1), (std::uint64_t(1) << 63) - 1);
}

// The eight cells of a 2 x 2 x 2 block come in Z order, whatever order the positions had, and
// positions in one cell keep their order.
TEST(SpaceFillingCurve, OrderFollowsTheCurveAndIsStable) {
    const std::vector<Vec3> positions = {{1.5, 1.5, 1.5}, {0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}, {0.5, 1.5, 0.5},
                                         {0.2, 0.1, 0.3}, {1.5, 1.5, 0.5}, {0.5, 0.5, 1.5}, {1.5, 0.5, 1.5},
                                         {0.5, 1.5, 1.5}, {-7, 0.5, 0.5}};  // the last one is clamped to cell 0
    const std::vector<std::size_t> order = spaceFillingCurveOrder(positions, Vec3::Zero(), 1.0);
    const std::vector<std::size_t> expected = {1, 4, 9, 2, 3, 5, 6, 7, 8, 0};
    EXPECT_EQ(order, expected);
    std::vector<Vec3> sorted;
    for (std::size_t k : order) sorted.push_back(positions[k]);
    std::vector<std::size_t> identity(positions.size());
    for (std::size_t k = 0; k < identity.size(); ++k) identity[k] = k;
    EXPECT_EQ(spaceFillingCurveOrder(sorted, Vec3::Zero(), 1.0), identity);  // ordering twice changes nothing
    test::expectError([&] { spaceFillingCurveOrder(positions, Vec3::Zero(), 0.0); }, {"cell size"});
}

// A packing collapsing in a periodic box for 2000 steps, with and without reordering: the
// particles move to other slots, but each particle (found by its id) follows the same path up to
// the round-off of a different summation order of the contact forces.
TEST(SpaceFillingCurve, ReorderingChangesSlotsNotPhysics) {
    std::size_t contactSteps = 0;  // contacts summed over the steps of the reordered run
    auto run = [&contactSteps](bool reorder) {
        auto s = std::make_unique<test::SceneSimulation>();
        if (reorder) s->afterStep = [&contactSteps](test::SceneSimulation& sim) { contactSteps += sim.contactSummary().contacts; };
        s->setup = [reorder](test::SceneSimulation& sim) {
            const double tc = 0.01;
            sim.scene().setDomain(Vec3(0, 0, 0), Vec3(5, 5, 20));
            sim.scene().setPeriodic(true, true, false);
            sim.settings().timeStep = tc / 50;
            sim.settings().reorderParticles = reorder;
            sim.scene().setGravity(Vec3(0, 0, -10));
            const auto glass = sim.scene().addSpecies("glass", 1, LinearSpringDashpot::fromCollision(tc, 0.5, 0.5).withFriction(0.5));
            sim.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), glass);
            // A loose lattice (gaps 0.01 .. 0.15) that collapses at once, inserted in an order far
            // from the curve's.
            std::mt19937 random(7);
            std::uniform_real_distribution<double> jitter(-1, 1);
            for (int ix = 0; ix < 5; ++ix)
                for (int iy = 0; iy < 5; ++iy)
                    for (int iz = 0; iz < 6; ++iz)
                        sim.scene().addParticle(Vec3(4.5 - ix + 0.02 * jitter(random), 0.5 + iy + 0.02 * jitter(random),
                                             0.5 + iz + 0.02 * jitter(random)),
                                        0.46 + 0.015 * jitter(random), glass);
        };
        s->solveOrThrow(test::stepsWithoutFiles(0.01 / 50, 2000));
        return s;
    };
    const auto plain = run(false), reordered = run(true);
    std::size_t moved = 0;
    double largestDifference = 0;
    for (std::uint64_t id = 0; id < plain->scene().particles().size(); ++id) {
        const std::size_t a = plain->scene().slotOf(id), b = reordered->scene().slotOf(id);
        EXPECT_EQ(a, id);  // without reordering the slots stay
        moved += b != id;
        largestDifference = std::max(largestDifference, (plain->scene().particles().position[a] -
                                                         reordered->scene().particles().position[b]).norm());
    }
    EXPECT_GT(moved, plain->scene().particles().size() / 2);
    EXPECT_GT(reordered->state().pairList.builds, 1u);
    EXPECT_GT(contactSteps, 2000 * plain->scene().particles().size() / 5);  // collisions all along, not a gas
    EXPECT_LT(largestDifference, 1e-12);
    std::printf("reordering: %zu of %zu particles moved slots, %llu list builds, %zu contacts a step on average, "
                "largest position difference %.2e\n", moved, plain->scene().particles().size(),
                static_cast<unsigned long long>(reordered->state().pairList.builds), contactSteps / 2000,
                largestDifference);
}

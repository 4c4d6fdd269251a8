// The rank context (Parallel/RankContext.h) on one rank, as every run without mpirun has it: the
// sums and maxima over the ranks are the numbers themselves, ids are numbered in order, and the
// flags it takes refuse bad values. On more ranks it is exercised by the Parallel.* self-tests.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Parallel/Communicator.h"
#include "Parallel/RankContext.h"
#include "Simulation.h"
#include "TestHelpers.h"

namespace talus {
namespace {

// One rank: a sum or maximum over the ranks of one value is that value, to the bit (nothing is
// added to it; a wrong reduction would, for instance, double it), before and after the run starts.
TEST(RankContext, OneRankSumsAreTheNumbersThemselves) {
    RankContext ranks(singleRankCommunicator());
    EXPECT_EQ(ranks.rank(), 0);
    EXPECT_EQ(ranks.count(), 1);
    EXPECT_FALSE(ranks.isSplit());
    EXPECT_EQ(ranks.split(), nullptr);
    const double x = 0.1 + 0.2;  // (not a round number)
    EXPECT_EQ(ranks.sum(x), x);
    EXPECT_EQ(ranks.max(-x), -x);
    std::vector<double> values{x, -1e-300, 7};
    ranks.sum(values);
    EXPECT_EQ(values, (std::vector<double>{x, -1e-300, 7}));

    SimulationState state;
    state.particles.radius = {0.5, 0.25};
    ranks.start(state);
    ASSERT_NE(ranks.split(), nullptr);
    EXPECT_FALSE(ranks.isSplit());  // one rank: the scene is never split
    EXPECT_EQ(ranks.sum(x), x);
}

// Without a split a new particle takes the next id, as in the order of addParticle.
TEST(RankContext, OneRankNumbersNewParticlesInOrder) {
    RankContext ranks(singleRankCommunicator());
    SimulationState state;
    state.nextId = 5;
    EXPECT_EQ(ranks.idOfNewParticle(state), 5u);
    EXPECT_EQ(ranks.idOfNewParticle(state), 6u);
    EXPECT_EQ(state.nextId, 7u);
    EXPECT_FALSE(ranks.isSentAsGhost(0));
}

TEST(RankContext, RefusesANegativeRebalanceInterval) {
    RankContext ranks(singleRankCommunicator());
    test::expectError([&] { ranks.setRebalanceInterval(-1); }, {"--rebalance-interval", "negative"});
    EXPECT_NO_THROW(ranks.setRebalanceInterval(0));
}

// A simulation's own context is the one that Kernel/Sampling asks: after a run on one rank the
// mobile particles counted through it are the scene's, and a driver's particles have ids 0, 1.
TEST(RankContext, ASimulationsContextCountsItsParticles) {
    struct TwoSpheres : Simulation {
        void setupInitialConditions() override {
            scene().setDomain(Vec3(-1, -1, -1), Vec3(1, 1, 1));
            const std::size_t s = scene().addSpecies("glass", 2500, LinearSpringDashpot{100, 1, 20, 1, 0.5});
            scene().addParticle(Vec3(-0.5, 0, 0), 0.1, s);
            scene().addParticle(Vec3(0.5, 0, 0), 0.1, s);
        }
    } run;
    run.settings().name = "RankContextTwoSpheres";
    run.settings().timeStep = 1e-4;
    run.settings().endTime = 1e-3;
    run.solveOrThrow({"--files", "off"});
    EXPECT_EQ(run.ranks().rank(), 0);
    EXPECT_FALSE(run.ranks().isSplit());
    EXPECT_EQ(run.lastRun().mobileParticles, 2u);
    EXPECT_EQ(run.scene().particles().id, (std::vector<std::uint64_t>{0, 1}));
}

}  // namespace
}  // namespace talus

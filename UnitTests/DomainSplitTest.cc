// The domain split's balance (Parallel/DomainSplit.h): where the boundary between two ranks goes.
// A replicated balance (every rank holds the whole scene, as after a restart read) sends no
// message, so a stand-in communicator that says "rank 0 of 2" runs it in one process.
#include <gtest/gtest.h>

#include "Parallel/Communicator.h"
#include "Parallel/DomainSplit.h"

using namespace talus;

namespace {

class FirstOfTwoRanks final : public Communicator {
public:
    int rank() const override { return 0; }
    int size() const override { return 2; }
    void allReduce(double*, int, Reduction) override { ADD_FAILURE() << "a replicated balance sends no message"; }
    std::vector<Bytes> exchange(const std::vector<Bytes>& outgoing) override { return outgoing; }
    void startExchangeWith(const std::vector<int>&, const std::vector<Bytes>&, const std::vector<int>&,
                           std::vector<Bytes>&) override {}
    void finishExchange() override {}
    std::vector<Bytes> allGather(const Bytes& mine) override { return {mine, mine}; }
    std::vector<Bytes> gatherToRoot(const Bytes& mine) override { return {mine}; }
    [[noreturn]] void abort(int code) override { std::exit(code); }
};

void addParticle(ParticleStore& p, double x, bool fixed) {
    p.position.push_back(Vec3(x, 0.5, 0.5));
    p.fixed.push_back(fixed ? 1 : 0);
}

// The boundary along x between the two ranks' cells.
double boundaryOf(const ParticleStore& p) {
    FirstOfTwoRanks two;
    DomainSplit split(two);
    split.setGrid({2, 1, 1});
    Domain domain;
    domain.lo = Vec3::Zero(), domain.hi = Vec3(10, 1, 1);
    split.balance(p, domain, /*replicated*/ true);
    return split.boundaries(0).at(0);
}

}  // namespace

// 100 moving particles spread evenly over x in (0, 10) and 100 fixed ones crowded in (0, 2) (a
// base or a wall under one part of the scene): the boundary halves the moving particles (x = 5),
// where counting all 200 would put it at 1.67 (20 moving and 100 fixed below it, 80 moving above:
// four times the work on one rank).
TEST(DomainSplit, BalanceHalvesTheMovingParticlesWhateverTheFixedOnes) {
    ParticleStore p;
    for (int k = 0; k < 100; ++k) addParticle(p, 0.05 + 0.1 * k, false);
    for (int k = 0; k < 100; ++k) addParticle(p, 0.01 + 0.02 * k, true);
    const double boundary = boundaryOf(p);
    EXPECT_NEAR(boundary, 5, 0.05);
    int movingBelow = 0;
    for (std::size_t i = 0; i < p.size(); ++i) movingBelow += !p.fixed[i] && p.position[i].x() < boundary;
    EXPECT_EQ(movingBelow, 50);
}

// Fixed particles alone (a scene before its filling): they are what is split, in halves.
TEST(DomainSplit, BalanceHalvesFixedParticlesWhenNoneMoves) {
    ParticleStore p;
    for (int k = 0; k < 100; ++k) addParticle(p, 0.01 + 0.02 * k, true);
    EXPECT_NEAR(boundaryOf(p), 1, 0.02);
}

// A superquadric weighs as four spheres (DomainSplit::workOf): 80 moving spheres over x in (0, 8)
// and 20 moving superquadrics over (8, 10), whose work equals the spheres' (80 = 20 x 4): the
// boundary falls at x = 8, the spheres on one rank and the superquadrics on the other, where
// counting particles would put it at x = 5.
TEST(DomainSplit, BalanceWeighsASuperquadricAsFourSpheres) {
    ParticleStore p;
    for (int k = 0; k < 100; ++k) addParticle(p, 0.05 + 0.1 * k, false);
    p.enableShapes();
    for (int k = 80; k < 100; ++k) p.shape[static_cast<std::size_t>(k)] = 0;
    const double boundary = boundaryOf(p);
    EXPECT_NEAR(boundary, 8, 0.05);
    int below = 0;
    for (std::size_t i = 0; i < p.size(); ++i) below += p.position[i].x() < boundary;
    EXPECT_EQ(below, 80);
}

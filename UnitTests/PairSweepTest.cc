// The force loop's first pass (Contacts/PairSweep.h): the pairs it picks are exactly those a
// direct evaluation of the rule picks (nearest periodic image closer than ri + rj + closing, or
// a pending contact), in order, whether the AVX-512 lanes or the scalar loop decide.
#include <gtest/gtest.h>

#include <random>

#include "Contacts/PairSweep.h"

using namespace talus;

namespace {

// The rule written out independently: the nearest image by rounding, distances by the norm.
bool needsWorkDirectly(const Vec3& xi, const Vec3& xj, double ri, double rj, ContactHistory::State state,
                       const Vec3& box, const bool periodic[3], double closing) {
    Vec3 d = xi - xj;
    for (int a = 0; a < 3; ++a)
        if (periodic[a]) d[a] -= box[a] * std::round(d[a] / box[a]);
    return d.norm() < ri + rj + closing || state != ContactHistory::apart;
}

}  // namespace

TEST(PairSweep, PicksExactlyThePairsTheRuleNames) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    const Vec3 box(20, 10, 8);
    const bool periodic[3] = {true, true, false};
    Domain domain;
    domain.lo = Vec3::Zero();
    domain.hi = box;
    domain.periodic = {true, true, false};
    const PeriodicImage image(domain);
    for (std::size_t n : {1u, 7u, 8u, 9u, 500u}) {  // tails of the eight-lane loop included
        std::vector<Vec3> position(n);
        std::vector<double> radius(n);
        for (std::size_t i = 0; i < n; ++i) {
            position[i] = Vec3(unit(random) * box.x(), unit(random) * box.y(), unit(random) * box.z());
            radius[i] = 0.3 + 0.2 * unit(random);
        }
        // Pairs near each other (some across the periodic faces), far apart, and pending.
        std::vector<ParticlePair> pairs;
        std::vector<ContactHistory::State> states;
        for (std::size_t k = 0; k < 4 * n + 3; ++k) {
            const auto i = static_cast<std::uint32_t>(random() % n), j = static_cast<std::uint32_t>(random() % n);
            if (k % 3 == 0 && i != j) {  // j just inside or outside of touching i, across a face or not
                Vec3 offset = Vec3(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5).normalized();
                offset *= (radius[i] + radius[j]) * (0.9 + 0.2 * unit(random));
                Vec3 x = position[i] + offset;
                x.x() = std::fmod(x.x() + box.x(), box.x());
                x.y() = std::fmod(x.y() + box.y(), box.y());
                position[j] = x;
            }
            pairs.push_back({i, j});
            states.push_back(static_cast<ContactHistory::State>(random() % 7 == 0 ? 1 + random() % 2 : 0));
        }
        const double closing = 0.01;
        std::vector<std::uint32_t> active(pairs.size());
        const std::size_t picked = sweepPairs(pairs.data(), pairs.size(), position.data(), n, radius.data(),
                                              states.data(), image, closing, active.data());
        std::vector<std::uint32_t> expected;
        for (std::size_t k = 0; k < pairs.size(); ++k)
            if (needsWorkDirectly(position[pairs[k].i], position[pairs[k].j], radius[pairs[k].i], radius[pairs[k].j],
                                  states[k], box, periodic, closing))
                expected.push_back(static_cast<std::uint32_t>(k));
        active.resize(picked);
        EXPECT_EQ(active, expected) << n << " particles";
        if (n < 100) continue;
        EXPECT_GT(expected.size(), pairs.size() / 10) << "the test must include pairs that need work";
        EXPECT_LT(expected.size(), pairs.size() / 2) << "and pairs that do not";
    }
}

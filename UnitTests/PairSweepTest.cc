// The force loop's first pass (Contacts/PairSweep.h): the pairs it picks are exactly those a
// direct evaluation of the rule picks (nearest periodic image closer than the sum of the two
// radii as passed, here grown by a reach of each particle as the force loop grows them, or a
// pending contact), in order, with their separations to the bit, whether the AVX-512 lanes or
// the scalar loop decide (both forms are swept; without AVX-512 in the build both are the loop).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "Contacts/PairSweep.h"

using namespace talus;

namespace {

// The rule written out independently: the nearest image by rounding, distances by the norm.
Vec3 separationDirectly(const Vec3& xi, const Vec3& xj, const Vec3& box, const bool periodic[3]) {
    Vec3 d = xi - xj;
    for (int a = 0; a < 3; ++a)
        if (periodic[a]) d[a] -= box[a] * std::round(d[a] / box[a]);
    return d;
}
bool needsWorkDirectly(const Vec3& d, double ri, double rj, ContactHistory::State state) {
    return d.norm() < ri + rj || state != ContactHistory::apart;
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
    for (std::size_t n : {1u, 7u, 8u, 9u, 500u}) {  // 4n + 3 pairs: tails of the eight lanes and of a chunk
        std::vector<Vec3> position(n);
        std::vector<double> radius(n), grown(n);  // the sphere, and its reach within a step
        for (std::size_t i = 0; i < n; ++i) {
            position[i] = Vec3(unit(random) * box.x(), unit(random) * box.y(), unit(random) * box.z());
            radius[i] = 0.3 + 0.2 * unit(random);
            grown[i] = radius[i] + 0.01 * unit(random);
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
        std::vector<SweepPoint> points(n);  // (as the force loop passes them)
        for (std::size_t i = 0; i < n; ++i) points[i] = {position[i].x(), position[i].y(), position[i].z(), grown[i]};
        std::pair<std::vector<std::uint32_t>, std::vector<Vec3>> sweeps[2];
        std::size_t wrongParticles = 0;  // picked pairs whose particles are not the listed pair's
        for (const SweepForm form : {SweepForm::scalar, SweepForm::lanes}) {
            std::vector<std::uint32_t> picked;
            std::vector<Vec3> separations;
            SweptPairs swept;
            for (std::size_t begin = 0; begin < pairs.size(); begin += SweptPairs::capacity) {
                sweepPairs(pairs.data(), begin, std::min(pairs.size(), begin + SweptPairs::capacity), points.data(),
                           n, states.data(), image, swept, form);
                for (std::size_t a = 0; a < swept.count; ++a) {
                    if (!(swept.particles[a] == pairs[swept.pair[a]])) ++wrongParticles;
                    picked.push_back(swept.pair[a]);
                    separations.push_back(swept.separation(a));
                }
            }
            sweeps[form == SweepForm::lanes] = {picked, separations};
        }
        const auto& [picked, separations] = sweeps[1];
        EXPECT_EQ(sweeps[0].first, picked) << "the two forms pick the same pairs";
        EXPECT_EQ(sweeps[0].second, separations) << "with the same separations";
        EXPECT_EQ(wrongParticles, 0u) << "each picked pair comes with its particles";
        std::vector<std::uint32_t> expected;
        std::vector<Vec3> expectedSeparations;
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            const Vec3 d = separationDirectly(position[pairs[k].i], position[pairs[k].j], box, periodic);
            if (needsWorkDirectly(d, grown[pairs[k].i], grown[pairs[k].j], states[k])) {
                expected.push_back(static_cast<std::uint32_t>(k));
                expectedSeparations.push_back(d);
            }
        }
        EXPECT_EQ(picked, expected) << n << " particles";
        EXPECT_EQ(separations, expectedSeparations) << n << " particles";
        if (n < 100) continue;
        EXPECT_GT(expected.size(), pairs.size() / 10) << "the test must include pairs that need work";
        EXPECT_LT(expected.size(), pairs.size() / 2) << "and pairs that do not";
    }
}

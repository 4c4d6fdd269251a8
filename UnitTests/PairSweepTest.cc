// The force loop's first pass (Contacts/PairSweep.h): the pairs it picks are exactly those a
// direct evaluation of the rule picks (nearest periodic image closer than the sum of the two
// radii as passed, here grown by a reach of each particle as the force loop grows them, or a
// pending contact), in order, with their separations to the bit, whether the lanes (AVX-512, or
// AVX2 without it) or the scalar loop decide (both forms are swept; without either in the build
// both are the loop); from the whole list and from a near list.
#include <algorithm>
#include <limits>
#include <random>

#include "LaneFormTest.h"
#include "Contacts/PairSweepLanes.h"

using namespace talus;
using namespace talus::TALUS_LANES;

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

TALUS_LANE_TEST(PairSweep, PicksExactlyThePairsTheRuleNames) {
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
        const std::vector<SweepForm> forms = availableSweepForms();
        std::vector<std::pair<std::vector<std::uint32_t>, std::vector<Vec3>>> sweeps;
        std::size_t wrongParticles = 0;  // picked pairs whose particles are not the listed pair's
        for (const SweepForm form : forms) {
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
            sweeps.push_back({picked, separations});
        }
        const auto& [picked, separations] = sweeps[0];
        for (std::size_t f = 1; f < forms.size(); ++f) {
            EXPECT_EQ(sweeps[f].first, picked) << sweepFormName(forms[f]) << " picks the scalar loop's pairs";
            EXPECT_EQ(sweeps[f].second, separations) << sweepFormName(forms[f]) << ": the same separations";
        }
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
        // A near list (every pair but each third): its sweep in both forms picks the rule's pairs
        // among them.
        NearPairs near;
        for (std::size_t k = 0; k < pairs.size(); ++k)
            if (k % 3 != 1) near.pairs.push_back({pairs[k], static_cast<std::uint32_t>(k)});
        std::vector<std::uint32_t> expectedNear;
        std::vector<Vec3> expectedNearSeparations;
        for (std::size_t a = 0; a < expected.size(); ++a)
            if (expected[a] % 3 != 1)
                expectedNear.push_back(expected[a]), expectedNearSeparations.push_back(expectedSeparations[a]);
        for (const SweepForm form : forms) {
            std::vector<std::uint32_t> nearPicked;
            std::vector<Vec3> nearSeparations;
            SweptPairs swept;
            for (std::size_t begin = 0; begin < near.pairs.size(); begin += SweptPairs::capacity) {
                sweepNearPairs<true>(near, begin, std::min(near.pairs.size(), begin + SweptPairs::capacity),
                                     points.data(), states.data(), image, swept, form);
                for (std::size_t a = 0; a < swept.count; ++a) {
                    if (!(swept.particles[a] == pairs[swept.pair[a]])) ++wrongParticles;
                    nearPicked.push_back(swept.pair[a]);
                    nearSeparations.push_back(swept.separation(a));
                }
            }
            EXPECT_EQ(nearPicked, expectedNear) << n << " particles, near list, " << sweepFormName(form);
            EXPECT_EQ(nearSeparations, expectedNearSeparations) << n << " particles, near list";
        }
        EXPECT_EQ(wrongParticles, 0u) << "each picked pair of the near list comes with its particles";
        if (n < 100) continue;
        EXPECT_GT(expected.size(), pairs.size() / 10) << "the test must include pairs that need work";
        EXPECT_LT(expected.size(), pairs.size() / 2) << "and pairs that do not";
    }
}

// The growths in the flow's frame (sweepFrameVelocity, sweepPointsForStep): spheres moving
// together at a large velocity with small fluctuations. Every pair that the force loop must
// treat (touching, or apart but closing the gap within the step, as ContactForceLoop::pairContact
// tests it) is picked with the frame as with the speeds, and the frame picks far fewer of the
// others. The frame is the sampled mean velocity of the mobile spheres, zero without any or if
// it is not finite.
TALUS_LANE_TEST(PairSweep, FlowFrameKeepsEveryPairThatCanTouch) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(0, 1);
    const Vec3 box(12, 12, 12), common(3, -1, 0.5);
    Domain domain;
    domain.lo = Vec3::Zero();
    domain.hi = box;
    domain.periodic = {true, true, true};
    const PeriodicImage image(domain);
    const double dt = 2e-3, fluctuation = 0.2;
    // Spheres in pairs (2m, 2m + 1), the second at a gap of -0.01 to 0.02 from the first in a
    // random direction: touching, closing within the step, and apart by up to a few steps' travel
    // at the common speed (3.3 dt = 0.0066).
    ParticleStore p;
    const std::size_t n = 2000;
    p.forEachArray([n](auto& array) { array.resize(n); });
    std::vector<ParticlePair> pairs;
    for (std::size_t i = 0; i < n; i += 2) {
        p.position[i] = Vec3(unit(random) * box.x(), unit(random) * box.y(), unit(random) * box.z());
        const Vec3 direction = Vec3(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5).normalized();
        p.position[i + 1] = p.position[i] + (1 - 0.01 + 0.03 * unit(random)) * direction;
        pairs.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)});
    }
    for (std::size_t i = 0; i < n; ++i) {
        p.velocity[i] = common + fluctuation * Vec3(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5);
        p.radius[i] = 0.5;
        p.fixed[i] = 0;
    }
    const Vec3 frame = sweepFrameVelocity(p);
    EXPECT_LT((frame - common).norm(), fluctuation) << "the sample's mean is near the common velocity";
    const std::vector<ContactHistory::State> states(pairs.size(), ContactHistory::apart);
    auto pick = [&](const Vec3& u) {
        std::vector<SweepPoint> points;
        sweepPointsForStep(p, dt, u, points);
        std::vector<std::uint32_t> picked;
        SweptPairs swept;
        for (std::size_t begin = 0; begin < pairs.size(); begin += SweptPairs::capacity) {
            sweepPairs(pairs.data(), begin, std::min(pairs.size(), begin + SweptPairs::capacity), points.data(), n,
                       states.data(), image, swept, SweepForm::scalar);
            picked.insert(picked.end(), swept.pair, swept.pair + swept.count);
        }
        return picked;
    };
    const std::vector<std::uint32_t> inFrame = pick(frame), withSpeeds = pick(Vec3::Zero());
    std::size_t needed = 0, missed = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::uint32_t i = pairs[k].i, j = pairs[k].j;
        const Vec3 d = image.nearest(p.position[i] - p.position[j]);
        const double distance = d.norm(), gap = distance - p.radius[i] - p.radius[j];
        const double approach = -(p.velocity[i] - p.velocity[j]).dot(d / distance);  // > 0: closing
        if (!(gap < 0 || (approach > 0 && gap < approach * dt))) continue;
        ++needed;
        missed += !std::binary_search(inFrame.begin(), inFrame.end(), static_cast<std::uint32_t>(k));
    }
    std::printf("[ measured ] %zu listed pairs, %zu need work; picked %zu in the flow's frame, %zu with the speeds\n",
                pairs.size(), needed, inFrame.size(), withSpeeds.size());
    EXPECT_GT(needed, 50u) << "the test needs touching and closing pairs";
    EXPECT_EQ(missed, 0u) << "pairs that need work and were not picked in the flow's frame";
    EXPECT_TRUE(std::includes(withSpeeds.begin(), withSpeeds.end(), inFrame.begin(), inFrame.end()))
        << "the frame's picks are among those of the larger growths";
    EXPECT_LT(inFrame.size() - needed, (withSpeeds.size() - needed) / 4)
        << "the frame should pick far fewer pairs that need no work";

    ParticleStore none = p;
    for (auto& fixed : none.fixed) fixed = 1;
    EXPECT_EQ(sweepFrameVelocity(none), Vec3::Zero()) << "no mobile particles: no frame";
    ParticleStore blownUp = p;
    blownUp.velocity[0].x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(sweepFrameVelocity(blownUp), Vec3::Zero()) << "a non-finite mean: no frame";
}

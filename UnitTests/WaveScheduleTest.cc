// The wave schedule of Contacts/WaveSchedule.h: replayed here with its own bookkeeping, every
// advance must find all the pairs of the advancing particles computed at that step, and every
// pair computed with both particles at the same step, once per step of the wave.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "Contacts/WaveSchedule.h"

using namespace talus;

namespace {

struct Bed {
    Domain domain;
    std::vector<Vec3> x;
    std::vector<ParticlePair> pairs;  // grouped by i, j < i
    double separation = 0;            // the longest a listed pair can have
};

// Spheres of diameter about 1 at random in a box periodic along x and y, `layers` deep, with
// every pair closer than `separation` listed (nearest image), in the order of the given cells.
Bed randomBed(double lengthX, double lengthY, int layers, double separation, unsigned seed) {
    Bed b;
    b.domain.lo = Vec3(-3, 5, 0);
    b.domain.hi = b.domain.lo + Vec3(lengthX, lengthY, layers);
    b.domain.periodic = {true, true, false};
    b.separation = separation;
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const std::size_t n = static_cast<std::size_t>(lengthX * lengthY * layers);
    for (std::size_t k = 0; k < n; ++k)
        b.x.push_back(b.domain.lo + Vec3(unit(random) * lengthX, unit(random) * lengthY, unit(random) * layers));
    return b;
}

void listPairs(Bed& b) {
    b.pairs.clear();
    for (std::uint32_t i = 0; i < b.x.size(); ++i)
        for (std::uint32_t j = 0; j < i; ++j)
            if (b.domain.nearestImage(b.x[i] - b.x[j]).norm() < b.separation) b.pairs.push_back({i, j});
}

void putInOrder(Bed& b, const WaveCells& cells) {
    const std::vector<std::size_t> order = cells.order(b.x);
    std::vector<Vec3> sorted;
    for (std::size_t k : order) sorted.push_back(b.x[k]);
    b.x.swap(sorted);
    listPairs(b);
}

// Replays the schedule: true if every particle's first step starts (its drift: the region's
// driftRuns) once, before any of its pairs is computed, every pair is computed once at every step
// with both particles at that step, and every particle advances once a step, after all its pairs
// of that step.
::testing::AssertionResult replaysAsSteps(const std::vector<WaveRegion>& regions, const WaveSchedule& s, const Bed& b,
                                          std::size_t interiorPairs) {
    const std::size_t n = b.x.size();
    std::vector<int> step(n, 0), computedAt(b.pairs.size(), -1), pairsDone(n, 0), degree(n, 0);
    std::vector<bool> started(n, false);
    for (const ParticlePair& p : b.pairs) ++degree[p.i], ++degree[p.j];
    for (const WaveRegion& r : regions) {
        for (std::uint32_t k = r.driftBegin; k < r.driftEnd; ++k)
            for (std::uint32_t i = s.driftRuns()[k].begin; i < s.driftRuns()[k].end; ++i) {
                if (started[i] || step[i] != 0) return ::testing::AssertionFailure() << "particle " << i << " started twice";
                started[i] = true;
            }
        for (std::uint32_t u = r.runs; u < r.end; ++u) {
            const PlaceRun run = s.placeRuns()[u];
            for (std::uint32_t k = run.begin; k < run.end; ++k) {
                if ((k < interiorPairs) != (u < r.interiorEnd)) return ::testing::AssertionFailure() << "pair " << k << " in the wrong group";
                const ParticlePair& p = b.pairs[k];
                if (!started[p.i] || !started[p.j])
                    return ::testing::AssertionFailure() << "pair " << k << " computed before its particles started";
                if (step[p.i] != r.level || step[p.j] != r.level)
                    return ::testing::AssertionFailure() << "pair " << k << " computed at step " << r.level << " with its particles at "
                                                         << step[p.i] << " and " << step[p.j];
                if (computedAt[k] != r.level - 1) return ::testing::AssertionFailure() << "pair " << k << " computed twice or skipped";
                computedAt[k] = r.level;
                ++pairsDone[p.i], ++pairsDone[p.j];
            }
        }
        for (int run = 0; run < 2; ++run)
            for (std::uint32_t i = r.runBegin[run]; i < r.runEnd[run]; ++i) {
                if (!started[i]) return ::testing::AssertionFailure() << "particle " << i << " advanced before it started";
                if (step[i] != r.level) return ::testing::AssertionFailure() << "particle " << i << " advanced twice at a step";
                if (pairsDone[i] != degree[i] * (r.level + 1))
                    return ::testing::AssertionFailure() << "particle " << i << " advanced before all its pairs of step " << r.level;
                ++step[i];
            }
    }
    for (std::size_t i = 0; i < n; ++i)
        if (step[i] != s.levels()) return ::testing::AssertionFailure() << "particle " << i << " ended at step " << step[i];
    for (std::size_t k = 0; k < b.pairs.size(); ++k)
        if (computedAt[k] != s.levels() - 1) return ::testing::AssertionFailure() << "pair " << k << " not computed at every step";
    return ::testing::AssertionSuccess();
}

}  // namespace

TEST(WaveSchedule, EveryAdvanceFindsItsPairsComputedAtItsStep) {
    struct Case {
        double lengthX, lengthY;
        int levels, stripColumns;
    };
    // One strip (its seam with itself), several strips of unequal widths, waves of 1 to 8 steps.
    for (const Case c : {Case{12, 10, 1, 32}, Case{12, 10, 4, 32}, Case{20, 13, 4, 8}, Case{30, 41, 8, 16},
                         Case{17, 37, 3, 7}}) {
        Bed b = randomBed(c.lengthX, c.lengthY, 2, 1.2, 7);
        std::string why;
        const std::optional<WaveCells> cells = WaveCells::fit(b.domain, b.separation, c.levels, c.stripColumns, &why);
        ASSERT_TRUE(cells) << why;
        putInOrder(b, *cells);
        const std::size_t interior = b.pairs.size() / 3;  // (any split: the schedule keeps it)
        WaveSchedule s;
        ASSERT_TRUE(s.make(*cells, b.pairs, interior, b.x, b.x.size(), &why)) << why;
        EXPECT_TRUE(replaysAsSteps(s.regions(), s, b, interior)) << c.lengthX << " x " << c.lengthY << ", " << c.levels << " steps, "
                                                    << cells->strips() << " strips";
        // The same with the pairs in the schedule's order: a permutation that keeps the interior
        // pairs first, and fewer runs of places than the list's own order needs.
        std::vector<std::uint32_t> order;
        WaveSchedule ordered;
        ASSERT_TRUE(ordered.make(*cells, b.pairs, interior, b.x, b.x.size(), &why, {}, &order)) << why;
        ASSERT_EQ(order.size(), b.pairs.size());
        std::vector<bool> seen(order.size(), false);
        for (std::size_t k = 0; k < order.size(); ++k) {
            ASSERT_LT(order[k], order.size());
            ASSERT_FALSE(seen[order[k]]) << "place " << order[k] << " twice";
            seen[order[k]] = true;
            ASSERT_EQ(k < interior, order[k] < interior) << "place " << k;
        }
        Bed reordered = b;
        for (std::size_t k = 0; k < order.size(); ++k) reordered.pairs[k] = b.pairs[order[k]];
        EXPECT_TRUE(replaysAsSteps(ordered.regions(), ordered, reordered, interior))
            << c.lengthX << " x " << c.lengthY << ", " << c.levels << " steps, in the schedule's order";
        if (c.levels > 1) {
            EXPECT_LT(ordered.placeRuns().size(), s.placeRuns().size());
        }
    }
}

// The cells at a strip's edge advance next to the strip they border on, so that its side of them
// is still cached: each seam region (row u at level t) comes within a few regions after the
// interior region of the same row and level of the strip after the seam (for the seam between the
// last strip and the first, of the last; with one strip, of the strip itself), not in a wave of
// its own after all strips (as they once did: a hundred regions and more later here).
TEST(WaveSchedule, SeamsAdvanceBesideTheStripAfterThem) {
    for (const int stripColumns : {40, 12, 8}) {  // of 31 columns: one strip, two of 15-16, three of 10-11
        const Bed b = randomBed(40, 38, 1, 1.2, 11);
        const std::optional<WaveCells> cells = WaveCells::fit(b.domain, b.separation, 4, stripColumns);
        ASSERT_TRUE(cells);
        struct Visit {
            int row, first, across, level;
        };
        std::vector<Visit> visits;
        cells->forEachRegion([&](int u, int first, int across, int t) { visits.push_back({u, first, across, t}); });
        int seams = 0;
        for (std::size_t k = 0; k < visits.size(); ++k) {
            const Visit& v = visits[k];
            int beside = -1;  // the strip whose wave this seam region should go with, if it is one
            for (int q = 0; q < cells->strips(); ++q)
                if (v.first == (cells->stripStart(q + 1) - 1 - v.level) % cells->columns() && v.across == 2 * v.level + 2)
                    beside = std::min(q + 1, cells->strips() - 1);
            if (beside < 0) continue;
            ++seams;
            const int interiorFirst = cells->stripStart(beside) + v.level + 1;
            const auto interior = std::find_if(visits.begin(), visits.end(), [&](const Visit& w) {
                return w.row == v.row && w.level == v.level && w.first == interiorFirst;
            });
            ASSERT_NE(interior, visits.end()) << "row " << v.row << " level " << v.level;
            const auto at = static_cast<std::size_t>(interior - visits.begin());
            EXPECT_LT(at, k);
            // (A step of a strip's wave visits at most one interior and two seam regions a level;
            // the seams go a step behind.)
            EXPECT_LE(k - at, static_cast<std::size_t>(6 * cells->levels()))
                << "the seam of row " << v.row << " at level " << v.level << ", " << cells->strips() << " strips";
        }
        EXPECT_GT(seams, cells->rows());
    }
}

// The replay above catches a schedule that breaks the order of steps (so it can fail): the
// regions' order reversed.
TEST(WaveSchedule, TheReplayCatchesRegionsOutOfOrder) {
    Bed b = randomBed(20, 20, 1, 1.2, 3);
    const std::optional<WaveCells> cells = WaveCells::fit(b.domain, b.separation, 3, 8);
    ASSERT_TRUE(cells);
    putInOrder(b, *cells);
    WaveSchedule s;
    ASSERT_TRUE(s.make(*cells, b.pairs, 0, b.x, b.x.size()));
    ASSERT_TRUE(replaysAsSteps(s.regions(), s, b, 0));
    std::vector<WaveRegion> reversed = s.regions();
    std::reverse(reversed.begin(), reversed.end());
    EXPECT_FALSE(replaysAsSteps(reversed, s, b, 0));
    // The first steps' starts left out of a region; or put off to the next region of the first
    // level that starts any (caught for some regions: a region starts all the rows beside its
    // own, and its own pairs may not need some of them yet).
    std::size_t regionsWithStarts = 0, putOffCaught = 0;
    for (std::size_t k = 0; k < s.regions().size(); ++k) {
        if (s.regions()[k].driftBegin == s.regions()[k].driftEnd) continue;
        ++regionsWithStarts;
        std::vector<WaveRegion> without = s.regions();
        without[k].driftEnd = without[k].driftBegin;
        EXPECT_FALSE(replaysAsSteps(without, s, b, 0)) << "region " << k << " without its starts";
        for (std::size_t later = k + 1; later < without.size(); ++later)
            if (without[later].driftBegin != without[later].driftEnd) {
                without[later].driftBegin = s.regions()[k].driftBegin;
                putOffCaught += !replaysAsSteps(without, s, b, 0);
                break;
            }
    }
    EXPECT_GT(regionsWithStarts, 10u);
    EXPECT_GT(putOffCaught, regionsWithStarts / 2);
}

TEST(WaveSchedule, RefusesWhatItCannotSchedule) {
    Bed b = randomBed(20, 20, 1, 1.2, 5);
    std::string why;
    const std::optional<WaveCells> cells = WaveCells::fit(b.domain, b.separation, 4, 8, &why);
    ASSERT_TRUE(cells) << why;
    putInOrder(b, *cells);
    WaveSchedule s;
    // Particles out of the cells' order.
    std::vector<Vec3> shuffled = b.x;
    std::swap(shuffled.front(), shuffled.back());
    EXPECT_FALSE(s.make(*cells, b.pairs, 0, shuffled, shuffled.size(), &why));
    EXPECT_NE(why.find("order"), std::string::npos) << why;
    // A pair longer than a cell.
    Bed far = b;
    far.separation = 4;
    listPairs(far);
    EXPECT_FALSE(s.make(*cells, far.pairs, 0, far.x, far.x.size(), &why));
    EXPECT_NE(why.find("not neighbours"), std::string::npos) << why;
    // Boxes too small or not periodic along y.
    EXPECT_FALSE(WaveCells::fit(b.domain, 1.2, 9, 8, &why));
    EXPECT_NE(why.find("along x"), std::string::npos) << why;
    Domain open = b.domain;
    open.periodic[1] = false;
    EXPECT_FALSE(WaveCells::fit(open, 1.2, 2, 8, &why));
    EXPECT_NE(why.find("periodic"), std::string::npos) << why;
}

// HGrid: the pairs it finds are exactly those of the definition (distance < ri + rj + skin with
// the nearest periodic image, no pair of two fixed particles), whatever the size ratio,
// periodicity, skin and cell size ratio; each pair once; few levels for wide size ranges; a
// clear error for periodic boxes too short for a unique nearest image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "Contacts/HGrid.h"
#include "TestHelpers.h"

using namespace talus;

namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

struct Packing {
    ParticleStore particles;
    Domain domain;
};

// Appends a particle with the fields the HGrid reads (position, radius, fixed flag).
void addSphere(ParticleStore& p, const Vec3& position, double radius, bool fixed) {
    p.position.push_back(position);
    p.radius.push_back(radius);
    p.fixed.push_back(fixed ? 1 : 0);
}

// Random polydisperse spheres, radii log-uniform in [rmin, sizeRatio rmin], at the given solid
// fraction (counted as if they did not overlap), one in ten fixed. The box does not start at the
// origin and is not a cube, so that offsets and per-axis cell sizes matter. Along open axes some
// particles lie outside the box: the box only frames the output there.
Packing randomPacking(std::size_t count, double sizeRatio, std::array<bool, 3> periodic, unsigned seed,
                      double solidFraction = 0.3) {
    const double rmin = 0.5;
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Packing packing;
    std::vector<double> radii(count);
    double volume = 0;
    for (double& r : radii) {
        r = rmin * std::pow(sizeRatio, unit(random));
        volume += 4.0 / 3.0 * pi * r * r * r;
    }
    const Vec3 aspect(1.3, 1.0, 0.8);
    const double scale = std::cbrt(volume / solidFraction / aspect.prod());
    packing.domain.lo = Vec3(-3.25, 1.5, 0.125);
    packing.domain.hi = packing.domain.lo + scale * aspect;
    packing.domain.periodic = periodic;
    for (double r : radii) {
        Vec3 x;
        for (int a = 0; a < 3; ++a) {
            const double margin = periodic[a] ? 0.0 : 0.1 * packing.domain.length(a);
            x[a] = packing.domain.lo[a] - margin + (packing.domain.length(a) + 2 * margin) * unit(random);
            if (periodic[a]) x[a] = std::min(x[a], std::nextafter(packing.domain.hi[a], packing.domain.lo[a]));
        }
        addSphere(packing.particles, x, r, unit(random) < 0.1);
    }
    return packing;
}

bool withinReach(const Packing& packing, std::size_t i, std::size_t j, double skin) {
    const ParticleStore& p = packing.particles;
    const double reach = p.radius[i] + p.radius[j] + skin;
    return packing.domain.nearestImage(p.position[i] - p.position[j]).squaredNorm() < reach * reach;
}

// The definition itself, O(N^2).
std::vector<Pair> bruteForcePairs(const Packing& packing, double skin) {
    const ParticleStore& p = packing.particles;
    std::vector<Pair> pairs;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        for (std::uint32_t j = i + 1; j < p.size(); ++j)
            if (!(p.fixed[i] && p.fixed[j]) && withinReach(packing, i, j, skin)) pairs.push_back({i, j});
    return pairs;
}

// The HGrid's pairs as (min, max), sorted; fails the test if a pair is reported twice.
std::vector<Pair> gridPairs(const Packing& packing, double skin, HGrid& grid) {
    std::vector<ParticlePair> found;
    grid.findPairs(packing.particles, packing.domain, skin, found);
    std::vector<Pair> pairs;
    for (const ParticlePair& q : found) {
        EXPECT_NE(q.i, q.j) << "a particle paired with itself";
        pairs.push_back({std::min(q.i, q.j), std::max(q.i, q.j)});
    }
    std::sort(pairs.begin(), pairs.end());
    const auto twice = std::adjacent_find(pairs.begin(), pairs.end());
    EXPECT_EQ(twice, pairs.end()) << "pair (" << twice->first << ", " << twice->second << ") reported twice";
    return pairs;
}

// Levels needed to span diameters from the smallest to the largest with the grid's cell size ratio.
std::size_t levelsNeeded(const Packing& packing, double skin, double cellSizeRatio) {
    const auto [smallest, largest] = std::minmax_element(packing.particles.radius.begin(), packing.particles.radius.end());
    const double spread = (2 * *largest + skin) / (2 * *smallest + skin);
    return 1 + static_cast<std::size_t>(std::ceil(std::log(spread) / std::log(cellSizeRatio) - 1e-9));
}

std::string axesName(std::array<bool, 3> periodic) {
    std::string name;
    for (int a = 0; a < 3; ++a)
        if (periodic[a]) name += "xyz"[a];
    return name.empty() ? "none" : name;
}

struct GridCase {
    double sizeRatio;
    std::array<bool, 3> periodic;
    double skin;  // in units of the smallest radius
    double cellSizeRatio;
};

class HGridAgainstBruteForce : public testing::TestWithParam<GridCase> {};

TEST_P(HGridAgainstBruteForce, FindsExactlyThePairsOfTheDefinition) {
    const GridCase c = GetParam();
    const Packing packing = randomPacking(2500, c.sizeRatio, c.periodic, 1234 + static_cast<unsigned>(c.sizeRatio));
    const double skin = c.skin * 0.5;
    HGrid grid(c.cellSizeRatio);
    const std::vector<Pair> expected = bruteForcePairs(packing, skin);
    const std::vector<Pair> found = gridPairs(packing, skin, grid);
    ASSERT_GT(expected.size(), packing.particles.size() / 4) << "too dilute to test anything";
    EXPECT_EQ(found.size(), expected.size());
    std::vector<Pair> missing, extra;
    std::set_difference(expected.begin(), expected.end(), found.begin(), found.end(), std::back_inserter(missing));
    std::set_difference(found.begin(), found.end(), expected.begin(), expected.end(), std::back_inserter(extra));
    EXPECT_TRUE(missing.empty()) << missing.size() << " pairs missed, first (" << missing[0].first << ", "
                                 << missing[0].second << ")";
    EXPECT_TRUE(extra.empty()) << extra.size() << " pairs too many, first (" << extra[0].first << ", "
                               << extra[0].second << ")";
    EXPECT_LE(grid.levelCount(), levelsNeeded(packing, skin, c.cellSizeRatio));
    if (c.sizeRatio == 1) {
        EXPECT_EQ(grid.levelCount(), 1u);
    }
}

// Cells kept in arrays or hashed: the same pairs in the same order (the order sets the order of
// the force sums, so a run does not depend on which a level took).
TEST_P(HGridAgainstBruteForce, DenseAndHashedCellsListTheSamePairsInTheSameOrder) {
    const GridCase c = GetParam();
    const Packing packing = randomPacking(2500, c.sizeRatio, c.periodic, 99 + static_cast<unsigned>(c.sizeRatio));
    const double skin = c.skin * 0.5;
    HGrid dense(c.cellSizeRatio), hashed(c.cellSizeRatio);
    dense.denseCellsPerParticle = 1e9;
    hashed.denseCellsPerParticle = 0;
    std::vector<ParticlePair> fromDense, fromHashed;
    dense.findPairs(packing.particles, packing.domain, skin, fromDense);
    hashed.findPairs(packing.particles, packing.domain, skin, fromHashed);
    EXPECT_GT(dense.denseLevelCount(), 0u);
    EXPECT_EQ(hashed.denseLevelCount(), 0u);
    ASSERT_FALSE(fromDense.empty());
    EXPECT_TRUE(fromDense == fromHashed) << fromDense.size() << " pairs from arrays, " << fromHashed.size() << " hashed";
}

std::vector<GridCase> allGridCases() {
    std::vector<GridCase> cases;
    for (double sizeRatio : {1.0, 3.0, 20.0})
        for (std::array<bool, 3> periodic : {std::array<bool, 3>{false, false, false}, std::array<bool, 3>{true, false, false},
                                             std::array<bool, 3>{true, true, true}})
            for (double skin : {0.0, 0.4})
                for (double cellSizeRatio : {2.0, 1.37, 3.5}) cases.push_back({sizeRatio, periodic, skin, cellSizeRatio});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Packings, HGridAgainstBruteForce, testing::ValuesIn(allGridCases()),
                         [](const testing::TestParamInfo<GridCase>& info) {
                             const GridCase& c = info.param;
                             std::string name = "ratio" + std::to_string(static_cast<int>(c.sizeRatio)) + "_periodic_" +
                                                axesName(c.periodic) + (c.skin > 0 ? "_skin" : "_noSkin") + "_cells" +
                                                std::to_string(static_cast<int>(std::lround(100 * c.cellSizeRatio)));
                             return name;
                         });

// 20000 small and 20 large particles (1:20): too many for the O(N^2) definition, so the check
// is O(N x sample): every reported pair is within reach and not two fixed particles, and every
// partner of the large particles and of a random sample of small ones is reported.
TEST(HGrid, WideMixtureIsCorrectWithFewLevels) {
    const double rmin = 0.5, sizeRatio = 20, skin = 0.1;
    std::mt19937_64 random(77);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Packing packing;
    packing.domain.lo = Vec3::Zero();
    packing.domain.hi = Vec3(140, 130, 120);
    packing.domain.periodic = {true, true, true};
    auto anywhere = [&] {
        return Vec3(unit(random) * packing.domain.hi.x(), unit(random) * packing.domain.hi.y(), unit(random) * packing.domain.hi.z());
    };
    for (int k = 0; k < 20; ++k) addSphere(packing.particles, anywhere(), sizeRatio * rmin, k % 5 == 0);
    for (int k = 0; k < 20000; ++k) addSphere(packing.particles, anywhere(), rmin * (1 + 0.1 * unit(random)), k % 50 == 0);
    const ParticleStore& p = packing.particles;

    HGrid grid;
    const std::vector<Pair> found = gridPairs(packing, skin, grid);
    EXPECT_LE(grid.levelCount(), levelsNeeded(packing, skin, grid.cellSizeRatio()));
    // The small spheres' levels are sparse (about 80 cells of the box per particle) and hashed,
    // the large ones' dense: both kinds in one search.
    EXPECT_GT(grid.denseLevelCount(), 0u);
    EXPECT_LT(grid.denseLevelCount(), grid.levelCount());
    for (const Pair& q : found) {
        EXPECT_TRUE(withinReach(packing, q.first, q.second, skin)) << "(" << q.first << ", " << q.second << ") too far";
        EXPECT_FALSE(p.fixed[q.first] && p.fixed[q.second]) << "two fixed particles paired";
    }

    std::vector<std::uint32_t> checked;
    for (std::uint32_t i = 0; i < 20; ++i) checked.push_back(i);
    std::uniform_int_distribution<std::uint32_t> someSmall(20, static_cast<std::uint32_t>(p.size() - 1));
    for (int k = 0; k < 300; ++k) checked.push_back(someSmall(random));
    std::size_t partnersOfLarge = 0;
    for (std::uint32_t i : checked)
        for (std::uint32_t j = 0; j < p.size(); ++j) {
            if (i == j || (p.fixed[i] && p.fixed[j]) || !withinReach(packing, i, j, skin)) continue;
            partnersOfLarge += i < 20;
            const Pair q{std::min(i, j), std::max(i, j)};
            EXPECT_TRUE(std::binary_search(found.begin(), found.end(), q)) << "(" << q.first << ", " << q.second << ") missed";
        }
    EXPECT_GT(partnersOfLarge, 20u) << "the large particles should have small neighbours";
}

// Pairs across periodic faces and corners, placed by hand at the nearest-image limits.
TEST(HGrid, FindsPairsAcrossFacesAndCorners) {
    Packing packing;
    packing.domain.lo = Vec3(-1, -1, -1);
    packing.domain.hi = Vec3(9, 7, 5);
    packing.domain.periodic = {true, true, true};
    const Vec3 justBelowHi = packing.domain.hi - Vec3::Constant(1e-12);
    addSphere(packing.particles, justBelowHi, 0.5, false);
    addSphere(packing.particles, packing.domain.lo, 0.5, false);                                  // corner partner
    addSphere(packing.particles, Vec3(-1, 3, 2), 0.5, false);                                     // on the lower x face
    addSphere(packing.particles, Vec3(9 - 1.0 + 1e-9, 3, 2), 0.5, false);                         // just within reach across x
    addSphere(packing.particles, Vec3(3, -1 + 1.0 - 1e-9, 2), 0.5, false);                       // a plain near pair...
    addSphere(packing.particles, Vec3(3, -1, 2), 0.5, false);                                    // ...on the lower y face
    addSphere(packing.particles, Vec3(0, 2, 5 - 0.5 - 1e-9), 0.5, false);                         // just beyond reach across z
    addSphere(packing.particles, Vec3(0, 2, -1 + 0.5), 0.5, false);
    HGrid grid;
    EXPECT_EQ(gridPairs(packing, 0.0, grid), bruteForcePairs(packing, 0.0));
    EXPECT_EQ(gridPairs(packing, 0.0, grid), (std::vector<Pair>{{0, 1}, {2, 3}, {4, 5}}));
}

// The nearest image is unique only if no pair spans half a period (Theory/ContactLaws.md eq. (1)).
TEST(HGrid, RejectsPeriodicBoxShorterThanTwoInteractionDiameters) {
    const double skin = 0.2;
    for (int axis = 0; axis < 3; ++axis) {
        Packing packing;
        addSphere(packing.particles, Vec3::Constant(0.5), 0.25, false);
        addSphere(packing.particles, Vec3::Constant(1.0), 1.0, false);
        const double largestDiameter = 2 * 1.0 + skin;
        packing.domain.hi = Vec3::Constant(20);
        packing.domain.periodic[axis] = true;
        std::vector<ParticlePair> pairs;
        HGrid grid;
        packing.domain.hi[axis] = 2 * largestDiameter;  // exactly twice: allowed
        EXPECT_NO_THROW(grid.findPairs(packing.particles, packing.domain, skin, pairs));
        packing.domain.hi[axis] = std::nextafter(2 * largestDiameter, 0.0);
        test::expectError([&] { grid.findPairs(packing.particles, packing.domain, skin, pairs); },
                          {"periodic length along " + std::string(1, "xyz"[axis]), "interaction diameter"});
    }
}

TEST(HGrid, RejectsCellSizeRatioNotAboveOne) {
    test::expectError([] { HGrid grid(1.0); }, {"cell size ratio"});
}

}  // namespace

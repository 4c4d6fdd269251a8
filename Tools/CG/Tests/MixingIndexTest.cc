// Mixing index M and segregation index S (Theory/CoarseGraining.md eq. (13)-(16),
// Fields/MixingIndex.h) of synthetic packings whose values are known:
// - perfectly mixed: every particle of species 0 has a twin of species 1 at the same place, so
//   rho_0 = rho_1 and phi = 1/2 at every point: M = 1 (to rounding), S = 0;
// - another composition: three twins of species 1 per particle of species 0 give phi = 3/4
//   everywhere, M = -(1/4 ln 1/4 + 3/4 ln 3/4)/ln 2 = 0.811278 (M is normalised by phi = 1/2);
// - fully layered: species 0 in the lower half of N equally spaced layers, species 1 above; a
//   point sees both species only within w of both interface layers, a band of 2w - a around
//   the interface holding a fraction (2w - a)/(N a) of the mass, and -m/ln 2 <= 1 there, so
//   M < (2w - a)/(N a) = 1/N for w = a;
// - core and periphery: species 1 in a ball at the centre of a cubic lattice, species 0 around
//   it: with k = 1 the spheres are at the core (S = M - 1 < 0), with k = 0 at the periphery
//   (S = 1 - M > 0); M is the same for both.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/EvaluationPoints.h"
#include "Fields/MixingIndex.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

MixingIndices indicesOf(const ParticleFrame& frame, const std::string& coordinates, double width,
                        std::array<long, 3> count, Vec3 lo, Vec3 hi, int species) {
    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName(coordinates);
    setup.width = WidthMatrix::isotropic(width);
    setup.speciesDensity = {1.5, 1.5};
    CoarseGrainer grainer(setup);
    grainer.setFrame(frame, nullptr);
    const auto points = gridPoints(setup.coordinates, count, lo, hi);
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    return mixingIndices(grainer.layout(), points, sums, setup.coordinates, species);
}

// Random positions in [1, 5]^3, `twins` particles of species 1 at the place of each of species 0.
ParticleFrame twinPacking(int count, int twins) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> u(1, 5);
    std::vector<Vec3> x;
    std::vector<double> r;
    std::vector<int> s;
    for (int i = 0; i < count; ++i) {
        const Vec3 p{u(random), u(random), u(random)};
        for (int t = 0; t <= twins; ++t) {
            x.push_back(p);
            r.push_back(0.3);
            s.push_back(t == 0 ? 0 : 1);
        }
    }
    return makeFrame(x, r, DomainBox{{0, 0, 0}, {6, 6, 6}}, {}, s);
}

}  // namespace

TEST(MixingIndex, PerfectlyMixedIsOne) {
    const ParticleFrame frame = twinPacking(400, 1);
    for (const std::string coordinates : {"XYZ", "XZ", "Z"}) {
        const MixingIndices m = indicesOf(frame, coordinates, 1.0, {16, 16, 16}, {0, 0, 0}, {6, 6, 6}, 1);
        EXPECT_NEAR(m.mixing, 1, 1e-12) << coordinates;
        EXPECT_NEAR(m.segregation, 0, 1e-12) << coordinates;
    }
}

// One kind alone: phi = 0 or 1 everywhere, so M = 0; no kind can be at the core or the periphery
// of a mixture that is not there, so S is NaN (not the 1 of "the periphery"), for either species.
TEST(MixingIndex, OneKindAloneHasNoSegregation) {
    std::vector<Vec3> x;
    std::vector<double> r;
    for (int i = 0; i < 5; ++i) x.push_back({1.0 + i, 3, 3}), r.push_back(0.3);
    const ParticleFrame frame = makeFrame(x, r, DomainBox{{0, 0, 0}, {6, 6, 6}}, {}, std::vector<int>(5, 0));
    for (int species : {0, 1}) {
        const MixingIndices m = indicesOf(frame, "XZ", 1.0, {12, 1, 12}, {0, 0, 0}, {6, 6, 6}, species);
        EXPECT_EQ(m.mixing, 0) << species;
        EXPECT_TRUE(std::isnan(m.segregation)) << species;
    }
}

TEST(MixingIndex, UniformCompositionThreeQuarters) {
    const ParticleFrame frame = twinPacking(200, 3);
    const double expected = -(0.25 * std::log(0.25) + 0.75 * std::log(0.75)) / std::numbers::ln2;
    const MixingIndices m = indicesOf(frame, "XYZ", 1.0, {16, 16, 16}, {0, 0, 0}, {6, 6, 6}, 1);
    EXPECT_NEAR(m.mixing, expected, 1e-12);
}

TEST(MixingIndex, FullyLayeredIsBelowTheInterfaceBand) {
    // 40 layers 0.25 apart, species 0 in the lower 20, w = a = 0.25; depth profile (Z).
    const int layers = 40;
    const double a = 0.25;
    std::vector<Vec3> x;
    std::vector<double> r;
    std::vector<int> s;
    for (int j = 0; j < layers; ++j) {
        x.push_back({0.5, 0.5, (j + 0.5) * a});
        r.push_back(0.1);
        s.push_back(j < layers / 2 ? 0 : 1);
    }
    const ParticleFrame frame = makeFrame(x, r, DomainBox{{0, 0, 0}, {1, 1, 10}}, {}, s);
    const MixingIndices m = indicesOf(frame, "Z", a, {1, 1, 4000}, {0, 0, -1}, {0, 0, 11}, 1);
    EXPECT_LT(m.mixing, 1.0 / layers);
    EXPECT_LT(m.mixing, 0.05);  // issue 5: "M < 0.05 for a fully layered one"
    EXPECT_GT(m.mixing, 0);     // the interface band is not empty
}

TEST(MixingIndex, SegregationSignFollowsCoreOrPeriphery) {
    // A cubic lattice 0.5 apart in [0, 8]^3, species 1 within 2.5 of the centre (4, 4, 4).
    std::vector<Vec3> x;
    std::vector<double> r;
    std::vector<int> s;
    for (int i = 0; i < 16; ++i) {
        for (int j = 0; j < 16; ++j) {
            for (int k = 0; k < 16; ++k) {
                const Vec3 p{0.25 + 0.5 * i, 0.25 + 0.5 * j, 0.25 + 0.5 * k};
                const double d = std::hypot(p[0] - 4, p[1] - 4, p[2] - 4);
                x.push_back(p);
                r.push_back(0.2);
                s.push_back(d < 2.5 ? 1 : 0);
            }
        }
    }
    const ParticleFrame frame = makeFrame(x, r, DomainBox{{0, 0, 0}, {8, 8, 8}}, {}, s);
    const MixingIndices core = indicesOf(frame, "XYZ", 0.75, {20, 20, 20}, {-1, -1, -1}, {9, 9, 9}, 1);
    const MixingIndices periphery = indicesOf(frame, "XYZ", 0.75, {20, 20, 20}, {-1, -1, -1}, {9, 9, 9}, 0);
    EXPECT_TRUE(core.speciesAtCore);
    EXPECT_FALSE(periphery.speciesAtCore);
    EXPECT_LT(core.segregation, 0);
    EXPECT_GT(periphery.segregation, 0);
    EXPECT_NEAR(core.mixing, periphery.mixing, 1e-12);  // m(phi) = m(1 - phi), up to rounding
    EXPECT_NEAR(core.segregation, core.mixing - 1, 1e-15);
    EXPECT_NEAR(periphery.segregation, 1 - periphery.mixing, 1e-15);
    // The centre of mass of the symmetric lattice is its middle.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(core.centre[k], 4, 1e-9);
    // Mostly segregated: only a shell of width ~w at the ball's surface mixes.
    EXPECT_LT(core.mixing, 0.5);
}

TEST(MixingIndex, BadSpeciesIsNamed) {
    const ParticleFrame frame = twinPacking(10, 1);
    try {
        indicesOf(frame, "Z", 1, {1, 1, 10}, {0, 0, 0}, {6, 6, 6}, 2);
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "--mixing: species 2 is not one of the 2 species (0 to 1)");
    }
}

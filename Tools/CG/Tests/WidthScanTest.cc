// Automatic width selection (Theory/CoarseGraining.md "Choosing the widths", Fields/WidthScan.h) on
// a packing whose concentration is known analytically, and the plateau rule on hand-made values.
//
// The packing: a jittered simple cubic lattice of spacing 1 in a box 24 x 2 x 16, periodic in x
// and y, coarse-grained in XZ. Layers k = 0..7 (centres z = k + 1/2) form the lower part: in
// even layers every second site along x holds a small particle (species 1, radius 0.4), all
// other sites large ones (species 0, radius 0.5), equal densities; layers k >= 8 are all large.
// So the lower part has 1/4 of its sites small and its small-particle concentration (by mass) is
//   phi0 = (1/4)(0.4/0.5)^3 / ((1/4)(0.4/0.5)^3 + 3/4) = 0.128 / 0.878 = 0.1457858769...
// At the point z = 3.5 (the centre of odd layer 3, all large):
//   - wz < 1 (one layer in the kernel) gives phi = 0 there, and wz near 1 swings between the
//     layers: too narrow is biased and noisy;
//   - the large layers start at z = 8.5 (jitter 0.15): a kernel with wz < 5 - 0.15 sees only
//     the lower part; wider ones mix in the large particles and phi falls (too wide is biased);
//   - along x the pattern has period 2, so wx must be about 2 or more to average it.
// Between these limits the bias in z is that of the layer sums: for a kernel wide along x (which
// averages the x pattern) phi(wz) = sum_k W(s_k) ms_k / sum_k W(s_k) m_k over the layers k with
// the 1-D Lucy weights W(s) = 1 - 6s^2 + 8s^3 - 3s^4, s_k = |z_k - 3.5|/wz, and per layer the
// small mass ms_k = 0.5 x 0.512 in even lower layers (else 0), the total m_k = 0.5 x 0.512 + 0.5
// there (else 1): layeredPhi() below, independent of the library. The chosen widths must lie
// where |phi(wz) - phi0| <= 0.005, with wx > 2, and the value there match phi0.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "CGTestHelpers.h"
#include "Fields/WidthScan.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

constexpr double phi0 = 0.128 / 0.878;

double layeredPhi(double wz) {
    double small = 0, total = 0;
    for (int k = 0; k < 16; ++k) {
        const double s = std::abs(k + 0.5 - 3.5) / wz;
        if (s >= 1) continue;
        const double w = 1 - 6 * s * s + 8 * s * s * s - 3 * s * s * s * s;
        const bool mixed = k < 8 && k % 2 == 0;
        small += w * (mixed ? 0.5 * 0.512 : 0.0);
        total += w * (mixed ? 0.5 * 0.512 + 0.5 : 1.0);
    }
    return small / total;
}

ParticleFrame layeredPacking(unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    std::vector<Vec3> position;
    std::vector<double> radius;
    std::vector<int> species;
    for (int i = 0; i < 24; ++i) {
        for (int j = 0; j < 2; ++j) {
            for (int k = 0; k < 16; ++k) {
                const bool small = k < 8 && k % 2 == 0 && i % 2 == 0;
                position.push_back({i + 0.5 + jitter(random), j + 0.5 + jitter(random), k + 0.5 + jitter(random)});
                radius.push_back(small ? 0.4 : 0.5);
                species.push_back(small ? 1 : 0);
            }
        }
    }
    return makeFrame(position, radius, DomainBox{{0, 0, 0}, {24, 2, 16}}, {}, species);
}

WidthScanRequest layeredRequest() {
    WidthScanRequest request;
    request.setup.coordinates = Coordinates::fromName("XZ");
    request.setup.periodic = {true, true, false};
    request.setup.speciesDensity = {1.0, 1.0};
    request.axes = {0, 2};
    request.widths = {logSpacedWidths(0.2, 50, 13), logSpacedWidths(0.2, 12, 16)};
    request.points = {{12.0, 0, 3.5}, {5.3, 0, 3.5}};
    // derivedColumns: Density, VolumeFraction, 3 momentum, 3 velocity, 6 kinetic stress,
    // Density_s0, Density_s1, Concentration_s0, Concentration_s1.
    request.field = 2 + 3 + 3 + 6 + 2 + 1;
    request.fractionField = true;
    request.tolerance = 0.05;
    request.minParticles = 10;
    request.minWidth = 0.975;  // the mean diameter: (1/8) 0.8 + (7/8) 1.0 (1/8 of the sites small)
    return request;
}

}  // namespace

TEST(WidthScan, LogSpacedWidthsAndBadRanges) {
    const std::vector<double> w = logSpacedWidths(0.1, 1000, 5);
    ASSERT_EQ(w.size(), 5u);
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(w[i], std::pow(10.0, i - 1), 1e-12 * w[i]);
    EXPECT_THROW(logSpacedWidths(0, 1, 5), InputError);
    EXPECT_THROW(logSpacedWidths(2, 1, 5), InputError);
    EXPECT_THROW(logSpacedWidths(1, 2, 1), InputError);
}

// The rule alone: two points whose values change by 0.2 per grid step except on known blocks.
TEST(WidthScan, PlateauIsTheLargestRectangleInsensitiveAtEveryPoint) {
    const std::array<std::vector<double>, 2> widths{logSpacedWidths(1, 1e6, 7), logSpacedWidths(1, 1e4, 5)};  // 1 decade per step
    auto scanWithFlatBlock = [&](long a0, long a1, long b0, long b1) {
        PointScan scan;
        for (long i = 0; i < 7; ++i) {
            for (long j = 0; j < 5; ++j) {
                const bool flat = i >= a0 && i <= a1 && j >= b0 && j <= b1;
                scan.value.push_back(flat ? 0.5 : 0.2 * double(i + 3 * j) + 1.0);  // off the block: steps of 0.2 per decade at least
                scan.trusted.push_back(true);
            }
        }
        return scan;
    };
    // Point 0 flat on i 1..5, j 1..3; point 1 flat on i 2..6, j 0..2: common block i 2..5, j 1..2.
    // Only cells whose every neighbour is on the block are insensitive (a neighbour off the block
    // differs by >= 0.5 per decade), so the insensitive cells of point 0 are i 2..4, j 2, and of
    // point 1 i 3..5, j 1 (the edges of the scan grid have no outer neighbour):
    std::vector<PointScan> points{scanWithFlatBlock(1, 5, 1, 3), scanWithFlatBlock(2, 6, 0, 2)};
    for (PointScan& p : points) markSensitivity(widths, 0.05, true, p);
    EXPECT_TRUE(points[0].insensitive[3 * 5 + 2]);
    EXPECT_FALSE(points[0].insensitive[1 * 5 + 2]);
    EXPECT_TRUE(points[1].insensitive[5 * 5 + 1]);
    EXPECT_FALSE(points[1].insensitive[3 * 5 + 2]);  // its neighbour j = 3 is off point 1's block
    EXPECT_FALSE(largestCommonPlateau(widths, points).found);  // the two regions do not meet

    // With a tolerance above the steps every cell is insensitive: the whole grid, centre at the
    // geometric mean of the ends (10^3 and 10^2).
    for (PointScan& p : points) markSensitivity(widths, 10.0, true, p);
    const WidthPlateau all = largestCommonPlateau(widths, points);
    ASSERT_TRUE(all.found);
    EXPECT_EQ(all.pairs, 35);
    EXPECT_NEAR(all.chosen[0], 1e3, 1e-9);
    EXPECT_NEAR(all.chosen[1], 1e2, 1e-10);

    // One point flat on i 0..6, j 1..4: insensitive on j 2..4 (j = 1 borders j = 0) for all i:
    // the rectangle i 0..6, j 2..4 (21 pairs), centre 10^3, 10^3.
    std::vector<PointScan> one{scanWithFlatBlock(0, 6, 1, 4)};
    markSensitivity(widths, 0.05, true, one[0]);
    const WidthPlateau block = largestCommonPlateau(widths, one);
    ASSERT_TRUE(block.found);
    EXPECT_EQ(block.pairs, 21);
    EXPECT_EQ(block.second[0], 2);
    EXPECT_EQ(block.second[1], 4);
    EXPECT_NEAR(block.chosen[1], 1e3, 1e-9);

    // Untrusted pairs are never insensitive, and a field scale F divides the changes.
    one[0].trusted[0] = false;
    markSensitivity(widths, 0.05, false, one[0]);
    EXPECT_TRUE(std::isnan(one[0].sensitivity[0]));
    EXPECT_FALSE(one[0].insensitive[0]);
}

TEST(WidthScan, LayeredPackingChoosesWidthsInsideTheAnalyticWindow) {
    const std::vector<ParticleFrame> frames{layeredPacking(7)};
    const WidthScanRequest request = layeredRequest();
    long calls = 0;
    const WidthScanResult result = scanWidths(request, frames, {}, [&](long, long) { ++calls; });
    EXPECT_EQ(calls, 13 * 16);
    ASSERT_TRUE(result.plateau.found);
    const double wx = result.plateau.chosen[0], wz = result.plateau.chosen[1];
    std::printf("chosen wx = %.4g, wz = %.4g; plateau wx %.4g..%.4g, wz %.4g..%.4g (%ld pairs); phi = %.6f, %.6f (phi0 = %.6f)\n", wx, wz,
                request.widths[0][result.plateau.first[0]], request.widths[0][result.plateau.first[1]],
                request.widths[1][result.plateau.second[0]], request.widths[1][result.plateau.second[1]], result.plateau.pairs,
                result.chosenValue[0], result.chosenValue[1], phi0);
    EXPECT_LE(std::abs(layeredPhi(wz) - phi0), 0.005) << "wz = " << wz;
    EXPECT_GT(wx, 2.0);
    // Every wz of the plateau is in the window (a biased width is never part of it), and the
    // window is a real constraint: wz = 1.35 (layer alternation) and wz = 10 (large layers) are
    // out.
    for (long j = result.plateau.second[0]; j <= result.plateau.second[1]; ++j) {
        EXPECT_LE(std::abs(layeredPhi(request.widths[1][j]) - phi0), 0.005) << "wz = " << request.widths[1][j];
    }
    EXPECT_GT(std::abs(layeredPhi(1.35) - phi0), 0.01);
    EXPECT_GT(std::abs(layeredPhi(10.0) - phi0), 0.01);
    // The value: phi0 within the window's 0.005 plus 0.005 for the jitter and the x pattern.
    for (double phi : result.chosenValue) EXPECT_NEAR(phi, phi0, 0.01);

    // Too narrow: below the lattice spacing in both directions nothing is insensitive. Too wide:
    // at wx = 50, wz = 12 the kernel reaches the large layers and phi is biased low, to
    // layeredPhi(12) (wx = 50 covers the periodic x of 24 about uniformly).
    const double wideValue = layeredPhi(12);
    EXPECT_LT(wideValue, phi0 - 0.01);  // the bias the scan must see
    const long nb = 16;
    for (const PointScan& scan : result.points) {
        for (long i = 0; i < 13; ++i) {
            for (long j = 0; j < nb; ++j) {
                if (request.widths[0][i] < 0.5 && request.widths[1][j] < 0.5) {
                    EXPECT_FALSE(scan.insensitive[i * nb + j]);
                }
            }
        }
        EXPECT_NEAR(scan.value[12 * nb + nb - 1], wideValue, 0.005);
    }
}

// The relative path of the rule (a field that is not a fraction, F = the point's largest value):
// the density of the same packing. Per site (one per unit volume) the even lower layers hold
// 0.5 x 0.512 + 0.5 large masses, the odd lower and all upper layers 1, with m_large = pi/6
// (density 1, diameter 1). For a kernel wide along x the density at z = 3.5 is the layer sum
// rho(wz) = sum_k (5/4)/wz W(s_k) m_k with the 1-D Lucy kernel (W as above), which also sees the
// bottom of the packing (no layer below z = 0: rho falls once the kernel reaches past z = -0.5,
// wz > 4) and the large layers above. layeredDensity() is that sum; the chosen wz must be where
// it is within 1% of the mean density of the lower part, rho0 = (0.5 x 0.512 + 0.5 + 1)/2 x pi/6,
// and the measured density within 2% of rho0.
TEST(WidthScan, LayeredPackingDensityUsesARelativeScale) {
    const double large = std::numbers::pi / 6;
    const double rho0 = (0.5 * 0.512 + 0.5 + 1.0) / 2 * large;
    auto layeredDensity = [&](double wz) {
        double rho = 0;
        for (int k = 0; k < 16; ++k) {
            const double s = std::abs(k + 0.5 - 3.5) / wz;
            if (s >= 1) continue;
            const bool mixed = k < 8 && k % 2 == 0;
            rho += 1.25 / wz * (1 - 6 * s * s + 8 * s * s * s - 3 * s * s * s * s) * (mixed ? 0.5 * 0.512 + 0.5 : 1.0) * large;
        }
        return rho;
    };
    const std::vector<ParticleFrame> frames{layeredPacking(7)};
    WidthScanRequest request = layeredRequest();
    request.field = 0;  // Density
    request.fractionField = false;
    // The density varies more with wz than phi: by layer alternation below wz = 3 and by the
    // bottom of the packing above wz = 4 (layeredDensity changes by 1.5% from wz = 4.03 to
    // 5.29, 0.13 per decade), so at 0.05 per decade only isolated pairs are insensitive and
    // no rectangle is common to both points; 0.1 per decade admits the flat stretch.
    request.tolerance = 0.1;
    const WidthScanResult result = scanWidths(request, frames, {});
    ASSERT_TRUE(result.plateau.found);
    const double wz = result.plateau.chosen[1];
    std::printf("density: chosen wx = %.4g, wz = %.4g; rho = %.6f, %.6f (rho0 = %.6f, analytic at wz %.6f); scale %.4f\n",
                result.plateau.chosen[0], wz, result.chosenValue[0], result.chosenValue[1], rho0, layeredDensity(wz),
                result.points[0].scale);
    EXPECT_LE(std::abs(layeredDensity(wz) - rho0), 0.01 * rho0) << "wz = " << wz;
    EXPECT_GT(result.plateau.chosen[0], 2.0);
    // F is the largest trusted density of the point, above rho0 (narrow kernels on a layer).
    EXPECT_GT(result.points[0].scale, rho0);
    for (double rho : result.chosenValue) EXPECT_NEAR(rho, rho0, 0.02 * rho0);
}

// Theory/CoarseGraining.md eq. (2): every coarse-graining function integrates to 1, is symmetric
// and non-negative, in 1, 2 and 3 dimensions, with isotropic, diagonal and rotated (full) width
// matrices.
//
// The kernel is evaluated as the density field of one particle of mass 1 at the origin (the
// code path of every field). The integral is computed in polar/spherical coordinates around the
// particle: along a direction omega the support ends at rho_max = R / |A omega| (A = B^-1, built
// here from the rotation and the widths, not by the library's inversion), the radial integrand
// is smooth on [0, rho_max] (a polynomial for Lucy: Gauss-Legendre is exact) and the angular
// integrand is smooth and periodic, so the quadrature converges to round-off.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"

using namespace talus::cg;
using namespace talus::cg::test;
using std::numbers::pi;

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
    return c;
}
Mat3 transpose(const Mat3& a) {
    Mat3 t{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) t[i][j] = a[j][i];
    return t;
}
Mat3 diagonalMatrix(double a, double b, double c) { return Mat3{{{a, 0, 0}, {0, b, 0}, {0, 0, c}}}; }
// Rotation by angle t about `axis`.
Mat3 rotation(int axis, double t) {
    Mat3 r = diagonalMatrix(1, 1, 1);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    r[i][i] = std::cos(t);
    r[i][j] = -std::sin(t);
    r[j][i] = std::sin(t);
    r[j][j] = std::cos(t);
    return r;
}

enum class WidthKind { Isotropic, Diagonal, Rotated };

struct Case {
    KernelShape shape;
    int dimension;
    WidthKind kind;
};

std::string caseName(const testing::TestParamInfo<Case>& info) {
    const char* kinds[] = {"Isotropic", "Diagonal", "Rotated"};
    return kernelShapeName(info.param.shape) + std::to_string(info.param.dimension) + "D" + kinds[int(info.param.kind)];
}

// The kernel of a case: its width matrix B and A = B^-1 (on the resolved axes).
struct KernelOfCase {
    std::string coordinates;
    std::array<double, 9> b{};
    Mat3 a{};
};

KernelOfCase kernelOf(const Case& c) {
    KernelOfCase k;
    k.coordinates = c.dimension == 1 ? "Z" : c.dimension == 2 ? "XZ" : "XYZ";
    Mat3 r = diagonalMatrix(1, 1, 1);
    Mat3 widths = diagonalMatrix(0.7, 0.7, 0.7);
    if (c.kind != WidthKind::Isotropic) widths = diagonalMatrix(0.5, 1.3, 0.8);
    if (c.kind == WidthKind::Rotated) {
        // In 2-D (x, z) a rotation about y keeps B's restriction to x, z a rotated diagonal.
        r = c.dimension == 2 ? rotation(1, 0.6) : multiply(rotation(2, 0.4), multiply(rotation(0, 0.9), rotation(1, -0.3)));
        if (c.dimension == 1) r = diagonalMatrix(1, 1, 1);
    }
    const Mat3 b = multiply(r, multiply(widths, transpose(r)));
    const Mat3 inverse = diagonalMatrix(1 / widths[0][0], 1 / widths[1][1], 1 / widths[2][2]);
    k.a = multiply(r, multiply(inverse, transpose(r)));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) k.b[3 * i + j] = b[i][j];
    return k;
}

CoarseGrainer grainerFor(const Case& c, const KernelOfCase& k) {
    CoarseGrainingSetup setup;
    setup.shape = c.shape;
    setup.coordinates = Coordinates::fromName(k.coordinates);
    setup.width = c.kind == WidthKind::Isotropic  ? WidthMatrix::isotropic(0.7)
                  : c.kind == WidthKind::Diagonal ? WidthMatrix::diagonal(0.5, 1.3, 0.8)
                                                  : WidthMatrix::full(k.b);
    setup.speciesDensity = {6 / pi};  // radius 0.5: mass 1
    CoarseGrainer grainer(setup);
    // Averaged directions of length 1, so that the field is the kernel itself.
    DomainBox box{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}};
    grainer.setFrame(makeFrame({{0, 0, 0}}, {0.5}, box), nullptr);
    return grainer;
}

class KernelNormalisation : public testing::TestWithParam<Case> {};

}  // namespace

TEST_P(KernelNormalisation, IntegratesToOneAndIsSymmetricAndNonNegative) {
    const Case c = GetParam();
    const KernelOfCase k = kernelOf(c);
    const CoarseGrainer grainer = grainerFor(c, k);
    const double cutoff = c.shape == KernelShape::Gauss ? 3.0 : 1.0;
    const std::vector<int> axes = Coordinates::fromName(k.coordinates).kernelAxes();

    // Directions omega and their angular weights.
    std::vector<Vec3> directions;
    std::vector<double> angularWeight;
    if (c.dimension == 1) {
        directions = {{0, 0, 1}, {0, 0, -1}};
        angularWeight = {1, 1};
    } else if (c.dimension == 2) {
        const int m = 256;  // trapezoid rule: exponential for smooth periodic integrands
        for (int i = 0; i < m; ++i) {
            const double phi = 2 * pi * i / m;
            directions.push_back({std::cos(phi), 0, std::sin(phi)});
            angularWeight.push_back(2 * pi / m);
        }
    } else {
        const GaussLegendre theta(96);
        const int m = 192;
        for (std::size_t i = 0; i < theta.node.size(); ++i) {
            const double t = 0.5 * pi * (theta.node[i] + 1);
            for (int j = 0; j < m; ++j) {
                const double phi = 2 * pi * j / m;
                directions.push_back({std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)});
                angularWeight.push_back(0.5 * pi * theta.weight[i] * std::sin(t) * 2 * pi / m);
            }
        }
    }
    const GaussLegendre radial(24);
    std::vector<Vec3> points;
    std::vector<double> weights;
    for (std::size_t d = 0; d < directions.size(); ++d) {
        const Vec3& w = directions[d];
        double aw2 = 0;
        for (int i : axes) {
            double s = 0;
            for (int j : axes) s += k.a[i][j] * w[j];
            aw2 += s * s;
        }
        const double rhoMax = cutoff / std::sqrt(aw2);
        for (std::size_t n = 0; n < radial.node.size(); ++n) {
            const double rho = 0.5 * rhoMax * (radial.node[n] + 1);
            points.push_back({rho * w[0], rho * w[1], rho * w[2]});
            weights.push_back(angularWeight[d] * 0.5 * rhoMax * radial.weight[n] * std::pow(rho, c.dimension - 1));
        }
        // Just outside the support the kernel is zero.
        points.push_back({1.0001 * rhoMax * w[0], 1.0001 * rhoMax * w[1], 1.0001 * rhoMax * w[2]});
        weights.push_back(0);
    }
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    const int fields = grainer.layout().count();
    double integral = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double value = sums[p * fields + FieldSums::density];
        ASSERT_GE(value, 0.0) << "negative at point " << p;
        if (weights[p] == 0) {
            EXPECT_EQ(value, 0.0) << "outside the support";
        }
        integral += weights[p] * value;
    }
    EXPECT_NEAR(integral, 1.0, 1e-10);
    RecordProperty("integral_minus_one", std::to_string(integral - 1));
    std::printf("[ kernel ] %s %dD: integral - 1 = %.3e\n", kernelShapeName(c.shape).c_str(), c.dimension, integral - 1);

    // Symmetry W(r) = W(-r), bitwise, at random points in and around the support.
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-2.5, 2.5);
    std::vector<Vec3> plus, minus;
    for (int i = 0; i < 500; ++i) {
        Vec3 r{0, 0, 0};
        for (int axis : axes) r[axis] = coordinate(random);
        plus.push_back(r);
        minus.push_back({-r[0], -r[1], -r[2]});
    }
    std::vector<double> atPlus, atMinus;
    grainer.evaluate(plus, atPlus);
    grainer.evaluate(minus, atMinus);
    for (std::size_t i = 0; i < plus.size(); ++i) {
        EXPECT_EQ(atPlus[i * fields], atMinus[i * fields]);
        EXPECT_GE(atPlus[i * fields], 0.0);
    }
}

INSTANTIATE_TEST_SUITE_P(
    AllKernels, KernelNormalisation,
    testing::ValuesIn([] {
        std::vector<Case> cases;
        for (KernelShape shape : {KernelShape::Lucy, KernelShape::Gauss, KernelShape::Heaviside})
            for (int d = 1; d <= 3; ++d)
                for (WidthKind kind : {WidthKind::Isotropic, WidthKind::Diagonal, WidthKind::Rotated})
                    if (!(d == 1 && kind == WidthKind::Rotated)) cases.push_back({shape, d, kind});
        return cases;
    }()),
    caseName);

// The normalisations written in Theory/CoarseGraining.md eq. (2) and KernelProfile.h, value at the
// centre.
TEST(KernelProfile, CentreValuesAreTheNormalisations) {
    EXPECT_DOUBLE_EQ(KernelProfile(KernelShape::Lucy, 1).value(0), 5.0 / 4.0);
    EXPECT_DOUBLE_EQ(KernelProfile(KernelShape::Lucy, 2).value(0), 5.0 / pi);
    EXPECT_DOUBLE_EQ(KernelProfile(KernelShape::Lucy, 3).value(0), 105.0 / (16 * pi));
    EXPECT_DOUBLE_EQ(KernelProfile(KernelShape::Heaviside, 3).value(0), 3.0 / (4 * pi));
    // The Gauss kernel cut at 3 sigma is slightly above the untruncated 1/sqrt(2 pi)^d.
    EXPECT_GT(KernelProfile(KernelShape::Gauss, 1).value(0), 1 / std::sqrt(2 * pi));
    EXPECT_NEAR(KernelProfile(KernelShape::Gauss, 1).value(0), 1 / std::sqrt(2 * pi) / std::erf(3 / std::sqrt(2.0)), 1e-15);
    EXPECT_EQ(KernelProfile(KernelShape::Lucy, 3).value(1.0), 0.0);
    EXPECT_EQ(KernelProfile(KernelShape::Gauss, 3).value(9.0), 0.0);
}

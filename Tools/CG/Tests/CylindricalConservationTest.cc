// Cylindrical coordinates (Fields/CylindricalCoarseGrainer.h), test (a) of issue 5: the fields
// are angular averages of a normalised 3-D (RZ) or cross-section 2-D (R) kernel, so
//   int rho(r, s) 2 pi r dr ds = total mass,  int p_s 2 pi r dr ds = total axial momentum,
//   int nu 2 pi r dr ds = total particle volume
// (R: the same with ds replaced by the box length L along the axis), exactly, for every kernel,
// also for particles on the axis (ri = 0), near it (ri below the width: part of the circles of
// small r lie wholly inside the support) and across a periodic end of the axis.
//
// The integral is nested Gauss-Legendre quadrature (CGTestHelpers.h) whose panels end where the
// field is not smooth: in s at s_i +- R wa (and the box ends), and in r at the edges of each
// support, r = ri +- wp sqrt(R^2 - ((s - si)/wa)^2), and where the whole circle enters it,
// r = -ri + wp sqrt(...) (the arc inside the support stops growing there), and at the centres
// r = ri, s = si, where Lucy's q^3 term makes the angular average non-analytic (|x - xi|^3
// averaged over a circle through xi has a dr^4 log|dr| term).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

struct ConservationCase {
    const char* name;
    KernelShape shape;
    const char* coordinates;  // "RZ" or "R"
    double wp, wa;            // widths across and along the axis (y)
    bool periodicAxis;
};

class CylindricalConservation : public testing::TestWithParam<ConservationCase> {};

TEST_P(CylindricalConservation, DensityVolumeAndAxialMomentumIntegrateToTotals) {
    const ConservationCase& c = GetParam();
    // Drum axis along y through (1, *, -2); particles on the axis, near it, and farther out;
    // near the ends y = 0 and y = 6 of the box when the axis is periodic.
    const Vec3 centre{1, 0, -2};
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0, 1), velocity(-1, 1);
    const std::vector<double> ri{0.0, 0.25, 0.7, 1.6, 3.1};
    std::vector<Vec3> x, v;
    std::vector<double> radius;
    double mass = 0, volume = 0, axialMomentum = 0;
    const double density = 2.0;
    for (std::size_t i = 0; i < ri.size(); ++i) {
        const double angle = 2 * std::numbers::pi * unit(random);
        const double y = c.periodicAxis ? (i % 2 == 0 ? 0.2 * unit(random) : 6 - 0.2 * unit(random)) : 2 + 2 * unit(random);
        x.push_back({centre[0] + ri[i] * std::cos(angle), y, centre[2] + ri[i] * std::sin(angle)});
        v.push_back({velocity(random), velocity(random), velocity(random)});
        radius.push_back(0.2 + 0.2 * unit(random));
        const double m = density * sphereVolume(radius.back());
        mass += m;
        volume += sphereVolume(radius.back());
        axialMomentum += m * v.back()[1];
    }
    const DomainBox box{{-6, 0, -9}, {8, 6, 5}};
    const ParticleFrame frame = makeFrame(x, radius, box, v);

    CoarseGrainingSetup setup;
    setup.shape = c.shape;
    setup.coordinates = Coordinates::fromName(c.coordinates);
    setup.coordinates.setAxis(1, centre);
    setup.width = WidthMatrix::diagonal(c.wp, c.wa, c.wp);
    setup.periodic = {false, c.periodicAxis, false};
    setup.speciesDensity = {density};
    CoarseGrainer grainer(setup);
    grainer.setFrame(frame, nullptr);

    const double R = KernelProfile(c.shape, 3).cutoff();
    const bool rz = setup.coordinates.resolves(2);
    const GaussLegendre rule(24);
    // Axial nodes: s over the box (periodic) or over the supports; one node at 0 for R.
    std::vector<double> sNodes{0.0}, sWeights{box.length(1)};
    if (rz) {
        std::vector<double> breaks;
        for (const Vec3& p : x) {
            for (double shift : {-6.0, 0.0, 6.0}) {
                breaks.push_back(p[1] + shift);
                breaks.push_back(p[1] + shift - R * c.wa);
                breaks.push_back(p[1] + shift + R * c.wa);
            }
        }
        const double lo = c.periodicAxis ? 0.0 : 2 - R * c.wa - 1, hi = c.periodicAxis ? 6.0 : 4 + R * c.wa + 1;
        rule.panels(lo, hi, breaks, sNodes, sWeights);
    }
    std::vector<Vec3> points;
    std::vector<double> weights;
    std::vector<double> rNodes, rWeights;
    const double rMax = 3.1 + R * c.wp + 1;
    for (std::size_t a = 0; a < sNodes.size(); ++a) {
        std::vector<double> breaks;
        for (std::size_t i = 0; i < x.size(); ++i) {
            for (double shift : {-6.0, 0.0, 6.0}) {
                const double ds = rz ? (sNodes[a] - x[i][1] - shift) / c.wa : 0.0;
                if (R * R - ds * ds <= 0) continue;
                const double half = c.wp * std::sqrt(R * R - ds * ds);
                breaks.push_back(ri[i]);
                breaks.push_back(ri[i] - half);
                breaks.push_back(ri[i] + half);
                breaks.push_back(half - ri[i]);  // the whole circle inside the support below it
            }
        }
        rule.panels(0.0, rMax, breaks, rNodes, rWeights);
        for (std::size_t b = 0; b < rNodes.size(); ++b) {
            points.push_back({rNodes[b], 0.0, sNodes[a]});
            weights.push_back(sWeights[a] * rWeights[b] * 2 * std::numbers::pi * rNodes[b]);
        }
    }
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    const int fields = grainer.layout().count();
    double integralMass = 0, integralVolume = 0, integralAxial = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        integralMass += weights[p] * sums[p * fields + FieldSums::density];
        integralVolume += weights[p] * sums[p * fields + FieldSums::volumeFraction];
        integralAxial += weights[p] * sums[p * fields + FieldSums::momentum + 2];
    }
    EXPECT_NEAR(integralMass / mass, 1.0, 1e-8) << c.name;
    EXPECT_NEAR(integralVolume / volume, 1.0, 1e-8) << c.name;
    EXPECT_NEAR(integralAxial, axialMomentum, 1e-8 * mass) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    Kernels, CylindricalConservation,
    testing::Values(ConservationCase{"LucyRZ", KernelShape::Lucy, "RZ", 1.0, 1.0, false},
                    ConservationCase{"GaussRZ", KernelShape::Gauss, "RZ", 0.4, 0.4, false},
                    ConservationCase{"HeavisideRZ", KernelShape::Heaviside, "RZ", 0.9, 0.9, false},
                    ConservationCase{"LucyRZAnisotropic", KernelShape::Lucy, "RZ", 0.8, 1.7, false},
                    ConservationCase{"LucyRZPeriodicAxis", KernelShape::Lucy, "RZ", 1.2, 1.5, true},
                    ConservationCase{"GaussRZPeriodicAxis", KernelShape::Gauss, "RZ", 0.5, 0.6, true},
                    ConservationCase{"LucyR", KernelShape::Lucy, "R", 1.1, 1.0, false},
                    ConservationCase{"GaussR", KernelShape::Gauss, "R", 0.35, 1.0, false},
                    ConservationCase{"HeavisideR", KernelShape::Heaviside, "R", 0.8, 1.0, false}),
    [](const testing::TestParamInfo<ConservationCase>& info) { return std::string(info.param.name); });

}  // namespace

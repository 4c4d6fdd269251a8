// Regions of the filling (Kernel/Boundaries/Region.h): volumes against the formulas of a box, a
// cylinder and an annulus; the inside test at the analytic boundaries (a sphere touching a face
// from inside is held, one a hair further out is not); candidates that cover the region
// uniformly (the share of them inside is the ratio of the volumes); bad regions named.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "Boundaries/Region.h"
#include "TestHelpers.h"

using namespace talus;
using test::expectError;

namespace {

Domain openDomain() {
    Domain d;
    d.lo = Vec3::Constant(-100), d.hi = Vec3::Constant(100);
    return d;
}

// 10^-9: far above the round-off of the coordinates used here (about 10^-15), far below the
// distances tested.
constexpr double hair = 1e-9;

TEST(Region, VolumesAreTheFormulas) {
    const Domain open = openDomain();
    EXPECT_DOUBLE_EQ(Box(Vec3(1, 2, 3), Vec3(4, 6, 9)).volume(open), 3 * 4 * 6);
    // pi R^2 L and pi (Ro^2 - Ri^2) L.
    EXPECT_DOUBLE_EQ(Cylinder(Vec3(1, 0, 2), 1, 5, 2).volume(open), pi * 4 * 5);
    EXPECT_DOUBLE_EQ(Annulus(Vec3(0, 0, -1), 2, 2, 1, 3).volume(open), pi * (9 - 1) * 2);
    // Along a periodic axis a region that covers the period counts one period (x: 10, not 12).
    Domain periodic = open;
    periodic.lo.x() = 0, periodic.hi.x() = 10, periodic.periodic[0] = true;
    EXPECT_DOUBLE_EQ(Box(Vec3(-1, 0, 0), Vec3(11, 1, 1)).volume(periodic), 10);
    EXPECT_DOUBLE_EQ(Cylinder(Vec3(-1, 0, 0), 0, 12, 1).volume(periodic), pi * 10);
}

TEST(Region, BoxHoldsASphereExactlyUpToItsFaces) {
    const Domain open = openDomain();
    const Box box(Vec3(0, 0, 0), Vec3(4, 3, 2));
    const double r = 0.5;
    EXPECT_TRUE(box.holds(Vec3(0.5, 1.5, 1), r, open));         // touching x = 0
    EXPECT_TRUE(box.holds(Vec3(2, 2.5, 1.5), r, open));         // touching y = 3 and z = 2
    EXPECT_FALSE(box.holds(Vec3(0.5 - hair, 1.5, 1), r, open));
    EXPECT_FALSE(box.holds(Vec3(2, 2.5 + hair, 1), r, open));
    EXPECT_FALSE(box.holds(Vec3(2, 1.5, 1.5 + hair), r, open));
    EXPECT_TRUE(box.holds(Vec3(0, 0, 0), 0, open));  // a centre on the corner
    // Covering a periodic axis, the box has no faces along it.
    Domain periodic = open;
    periodic.lo.x() = 0, periodic.hi.x() = 4, periodic.periodic[0] = true;
    EXPECT_TRUE(box.holds(Vec3(0.1, 1.5, 1), r, periodic));
}

TEST(Region, CylinderAndAnnulusHoldASphereBetweenTheirRadii) {
    const Domain open = openDomain();
    // Axis along z through (1, 2), from z = 0 to 4; outer radius 3, inner 1.
    const Cylinder cylinder(Vec3(1, 2, 0), 2, 4, 3);
    const Annulus annulus(Vec3(1, 2, 0), 2, 4, 1, 3);
    const double r = 0.5;
    const Vec3 diagonal = Vec3(1, 1, 0).normalized();
    const auto at = [&](double rho, double z) { return Vec3(Vec3(1, 2, z) + rho * diagonal); };
    // The outer face: rho + r <= 3.
    EXPECT_TRUE(cylinder.holds(at(2.5 - hair, 2), r, open));
    EXPECT_FALSE(cylinder.holds(at(2.5 + hair, 2), r, open));
    EXPECT_TRUE(annulus.holds(at(2.5 - hair, 2), r, open));
    EXPECT_FALSE(annulus.holds(at(2.5 + hair, 2), r, open));
    // The inner face of the annulus: rho - r >= 1; the cylinder holds the axis.
    EXPECT_TRUE(annulus.holds(at(1.5 + hair, 2), r, open));
    EXPECT_FALSE(annulus.holds(at(1.5 - hair, 2), r, open));
    EXPECT_TRUE(cylinder.holds(at(0, 2), r, open));
    EXPECT_FALSE(annulus.holds(at(0, 2), r, open));
    // The ends: z - r >= 0 and z + r <= 4, unless the cylinder covers a periodic z.
    EXPECT_TRUE(cylinder.holds(at(1, 0.5 + hair), r, open));
    EXPECT_FALSE(cylinder.holds(at(1, 0.5 - hair), r, open));
    EXPECT_FALSE(annulus.holds(at(2, 3.5 + hair), r, open));
    Domain periodic = open;
    periodic.lo.z() = 0, periodic.hi.z() = 4, periodic.periodic[2] = true;
    EXPECT_TRUE(annulus.holds(at(2, 3.9), r, periodic));
}

// Candidates of margin 0 cover a set that holds the region, uniformly: the share of them inside
// is the region's volume over that set's, pi/4 for a cylinder in the box around it and
// pi (Ro^2 - Ri^2) / (4 Ro^2) for an annulus, 1 for a box. With N = 10^5 draws the share has a
// standard deviation sqrt(p (1 - p) / N) <= 0.0016; the tolerance is 5 of them. With margin m
// every candidate lies in the region shrunk by m (the box) or in the box around the cylinder of
// radius R - m.
TEST(Region, CandidatesCoverTheRegionUniformly) {
    const Domain open = openDomain();
    std::mt19937_64 random(3);
    const int n = 100000;
    const auto shareInside = [&](const Region& region) {
        int inside = 0;
        for (int i = 0; i < n; ++i) inside += region.holds(region.randomPoint(0, open, random), 0, open);
        return double(inside) / n;
    };
    EXPECT_EQ(shareInside(Box(Vec3(0, 0, 0), Vec3(1, 2, 3))), 1.0);
    EXPECT_NEAR(shareInside(Cylinder(Vec3(0, 0, 0), 1, 2, 1.5)), pi / 4, 0.008);
    EXPECT_NEAR(shareInside(Annulus(Vec3(0, 0, 0), 0, 2, 1, 2)), pi * (4 - 1) / 16, 0.008);

    const Box box(Vec3(0, 0, 0), Vec3(2, 2, 2));
    const Cylinder cylinder(Vec3(0, 0, 0), 1, 4, 2);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 x = box.randomPoint(0.5, open, random);
        ASSERT_TRUE(x.minCoeff() >= 0.5 && x.maxCoeff() <= 1.5) << x.transpose();
        const Vec3 y = cylinder.randomPoint(0.5, open, random);
        ASSERT_TRUE(std::abs(y.x()) <= 1.5 && std::abs(y.z()) <= 1.5 && y.y() >= 0.5 && y.y() <= 3.5) << y.transpose();
    }
}

TEST(Region, BadRegionsNameTheParameter) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectError([] { Box(Vec3(0, 0, 0), Vec3(1, 0, 1)); }, {"box region", "upper corner (1, 0, 1)", "lower corner"});
    expectError([] { Box(Vec3(0, 0, 0), Vec3(-1, 1, 1)); }, {"box region", "upper corner"});
    expectError([] { Cylinder(Vec3::Zero(), 1, 2, -1); }, {"cylinder region", "radius must be positive, got -1"});
    expectError([&] { Cylinder(Vec3::Zero(), 1, 2, nan); }, {"cylinder region", "radius must be positive"});
    expectError([] { Cylinder(Vec3::Zero(), 1, 0, 1); }, {"cylinder region", "length must be positive, got 0"});
    expectError([] { Cylinder(Vec3::Zero(), 3, 1, 1); }, {"cylinder region", "axis must be 0 (x), 1 (y) or 2 (z), got 3"});
    expectError([] { Annulus(Vec3::Zero(), 1, 1, -0.5, 1); }, {"annulus region", "inner radius must not be negative"});
    expectError([] { Annulus(Vec3::Zero(), 1, 1, 2, 2); }, {"annulus region", "inner radius 2", "less than the outer radius 2"});
    expectError([] { Annulus(Vec3::Zero(), 1, 1, 1, -3); }, {"cylinder region", "radius must be positive"});
    // Particles that cannot fit (bounding radius 0.6, diameter 1.2).
    const Domain open = openDomain();
    expectError([&] { Box(Vec3::Zero(), Vec3(2, 1, 2)).checkFits(0.6, open); },
                {"box region", "1 wide along y", "largest particle diameter 1.2"});
    expectError([&] { Cylinder(Vec3::Zero(), 1, 2, 0.5).checkFits(0.6, open); },
                {"cylinder region", "radius 0.5", "bounding radius 0.6"});
    expectError([&] { Cylinder(Vec3::Zero(), 1, 1, 2).checkFits(0.6, open); },
                {"cylinder region: length", "1 wide along y", "largest particle diameter 1.2"});
    expectError([&] { Annulus(Vec3::Zero(), 1, 2, 1, 2).checkFits(0.6, open); },
                {"annulus region", "outer radius - inner radius = 1", "largest particle diameter 1.2"});
    Box(Vec3::Zero(), Vec3(2, 1.2, 2)).checkFits(0.6, open);  // exactly fits: no error
}

}  // namespace

// The depth average and shape factor of DepthAverage.h on depth profiles of known velocity fields.
#include <gtest/gtest.h>

#include <cmath>

#include "DepthAverage.h"

using namespace talus;

namespace {

// One sphere of mass m at the centre of each slab k = 0 .. n-1 of thickness 0.25 (z = (k + 1/2)
// 0.25), moving downslope at velocity(z).
template <class F>
DepthProfile profileOf(int n, F velocity, double m = 1) {
    ParticleStore p;
    for (int k = 0; k < n; ++k) {
        const double z = (k + 0.5) * 0.25;
        p.position.push_back(Vec3(1, 1, z)); p.velocity.push_back(Vec3(velocity(z), 0, 0));
        p.angularVelocity.push_back(Vec3::Zero()); p.force.push_back(Vec3::Zero()); p.torque.push_back(Vec3::Zero());
        p.radius.push_back(0.1); p.mass.push_back(m); p.invMass.push_back(1 / m); p.invInertia.push_back(1);
        p.species.push_back(0); p.id.push_back(p.id.size()); p.fixed.push_back(0); p.motion.push_back(-1);
    }
    DepthProfile profile(0.25, 0.25 * n + 1, 10, 10, 1);
    profile.add(p);
    profile.add(p);  // (two samples of the same field: the same averages)
    return profile;
}

}  // namespace

// A plug flow has alpha = 1.
TEST(DepthAverage, PlugFlowHasShapeFactorOne) {
    const DepthAverage a = depthAverage(profileOf(40, [](double) { return 2.5; }));
    EXPECT_DOUBLE_EQ(a.velocity, 2.5);
    EXPECT_NEAR(a.shapeFactor, 1, 1e-14);
}

// A linear profile u = z over n equal slabs at z_k = (k + 1/2) b: <u> = n b / 2 and
// <u^2> = b^2 (sum of (k + 1/2)^2) / n = b^2 (n^2/3 - 1/12), so alpha = (4/3) (1 - 1/(4 n^2)):
// 1.333125 for n = 40 (4/3 for a continuous linear profile, the discrete sum a little less).
TEST(DepthAverage, LinearProfileHasShapeFactorFourThirds) {
    const int n = 40;
    const DepthAverage a = depthAverage(profileOf(n, [](double z) { return z; }));
    EXPECT_DOUBLE_EQ(a.velocity, n * 0.25 / 2);
    EXPECT_NEAR(a.shapeFactor, 4.0 / 3.0 * (1 - 1.0 / (4.0 * n * n)), 1e-12);
}

// A Bagnold profile u ~ 1 - (1 - z/h)^(3/2) without slip has alpha = 5/4 in the continuum
// (over the depth u integrates to 3/5 h u_s and u^2 to 9/20 h u_s^2, u_s at the surface, and
// (9/20) / (3/5)^2 = 5/4); 400 slabs of 0.25 over h = 100 come within 1e-4 of it.
TEST(DepthAverage, BagnoldProfileHasShapeFactorFiveQuarters) {
    const DepthAverage a = depthAverage(profileOf(400, [](double z) { return 1 - std::pow(1 - z / 100, 1.5); }));
    EXPECT_NEAR(a.shapeFactor, 1.25, 1e-4);
}

// No flow (an arrested layer, or no spheres): no shape factor.
TEST(DepthAverage, NoFlowHasNoShapeFactor) {
    EXPECT_TRUE(std::isnan(depthAverage(profileOf(10, [](double) { return 0.0; })).shapeFactor));
    EXPECT_TRUE(std::isnan(depthAverage(profileOf(0, [](double) { return 1.0; })).shapeFactor));
}

// The change along the trend over 31 samples (k = 0 ... 30, m = 15, sum (k - m)^2 = 2 (1^2 + ...
// + 15^2) = 2480): a line u_k = 3 + 0.5 k changes by 0.5 x 30 = 15 exactly. Added to it, an
// alternation +-1 and a bump of +5 at both ends change nothing (sum (k - m) e_k = 0: the terms of
// k and 30 - k cancel), although the bump is all that the end samples see; one sample 1 too high
// at the end moves the slope by (30 - 15) / 2480, the change by 30 times that.
TEST(DepthAverage, ChangeAlongTrend) {
    std::vector<double> line, alternating, ends;
    for (int k = 0; k <= 30; ++k) {
        line.push_back(3 + 0.5 * k);
        alternating.push_back(line.back() + (k % 2 == 0 ? 1 : -1));
        ends.push_back(line.back() + (k == 0 || k == 30 ? 5 : 0));
    }
    EXPECT_NEAR(changeAlongTrend(line), 15, 1e-12);
    EXPECT_NEAR(changeAlongTrend(alternating), 15, 1e-12);
    EXPECT_NEAR(changeAlongTrend(ends), 15, 1e-12);
    std::vector<double> last = line;
    last.back() += 1;
    EXPECT_NEAR(changeAlongTrend(last), 15 + 30 * 15.0 / 2480, 1e-12);
    EXPECT_DOUBLE_EQ(changeAlongTrend({2.0}), 0);
}

// The chute base class (Kernel/Chute/Chute.h, Theory/Chutes.md "The rough base") and the chute
// diagnostics (Kernel/Chute/ChuteStatistics.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "Boundaries/Domain.h"
#include "Chute/Chute.h"
#include "Chute/ChuteStatistics.h"
#include "TestHelpers.h"

using namespace talus;

namespace {

// A chute with one species and the given base, set up in place (no run).
struct TestChute : Chute {
    std::size_t build(ChuteBase base, std::uint64_t seed, double length = 20, double width = 10) {
        setChuteGeometry({.length = length, .width = width, .height = 20, .periodicEnds = true});
        const auto glass = scene().addSpecies("glass", 6 / pi, LinearSpringDashpot::fromCollision(0.005, 0.88, 0.5));
        return addBase(base, 1.0, glass, seed);
    }
};

}  // namespace

TEST(Chute, AngleSetsGravityOfSpecMd2) {
    TestChute chute;
    chute.setChuteAngle(24);
    const double t = 24 * pi / 180;
    EXPECT_NEAR((chute.scene().gravity() - Vec3(std::sin(t), 0, -std::cos(t))).norm(), 0, 1e-15);
    EXPECT_NEAR(chute.chuteAngle(), 24, 1e-12);
    chute.setGravityMagnitude(9.81);
    EXPECT_NEAR(chute.scene().gravity().norm(), 9.81, 1e-12);
    EXPECT_NEAR(chute.chuteAngle(), 24, 1e-12);
    chute.setChuteAngle(-30);
    EXPECT_NEAR(chute.chuteAngle(), -30, 1e-12);
    for (double bad : {90.0, -90.0, 120.0, std::nan("")})
        test::expectError([&] { chute.setChuteAngle(bad); }, {"chute angle", "(-90, 90)"});
}

// Random sequential addition: no two base spheres overlap (across the periodic faces too), all
// centres lie within +-0.25 of z = 0, the same seed gives the same base, and the layer is nearly
// jammed: it covers more of the floor than 2-D random sequential addition of disks at jamming
// (0.547), which it can since the spheres may also shift in z.
TEST(Chute, DisorderedBaseIsJammedReproducibleAndOverlapFree) {
    TestChute a, b, c;
    const std::size_t n = a.build(ChuteBase::disordered, 7);
    EXPECT_EQ(b.build(ChuteBase::disordered, 7), n);
    c.build(ChuteBase::disordered, 8);
    const ParticleStore &p = a.scene().particles(), &q = b.scene().particles(), &r = c.scene().particles();
    ASSERT_EQ(p.size(), n);
    bool sameAsOtherSeed = r.size() == n;
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(p.position[i], q.position[i]);
        if (sameAsOtherSeed) sameAsOtherSeed = p.position[i] == r.position[i];
        EXPECT_TRUE(p.fixed[i]);
        EXPECT_LE(std::abs(p.position[i].z()), 0.25);
    }
    EXPECT_FALSE(sameAsOtherSeed);
    const PeriodicImage image(a.scene().domain());
    double closest = INFINITY;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            closest = std::min(closest, image.nearest(p.position[i] - p.position[j]).norm());
    EXPECT_GE(closest, 1.0 - 1e-12);
    const double coverage = n * pi / 4 / (20 * 10);
    std::printf("[ measured ] disordered base: %zu spheres on 20 x 10, coverage %.3f, closest centres %.6f\n", n,
                coverage, closest);
    EXPECT_GT(coverage, 0.547);
    EXPECT_LT(coverage, pi / (2 * std::sqrt(3.0)));  // below hexagonal close packing of disks
    // The safety floor lies below every base sphere.
    ASSERT_EQ(a.scene().walls().size(), 1u);
    EXPECT_LE(a.scene().walls()[0].point.z(), -0.75 + 1e-15);
}

TEST(Chute, OrderedBaseIsASquareLatticeNoCloserThanADiameter) {
    TestChute chute;
    EXPECT_EQ(chute.build(ChuteBase::ordered, 1, 10.5, 5), 10u * 5u);
    const ParticleStore& p = chute.scene().particles();
    const PeriodicImage image(chute.scene().domain());
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_EQ(p.position[i].z(), 0);
        for (std::size_t j = i + 1; j < p.size(); ++j)
            EXPECT_GE(image.nearest(p.position[i] - p.position[j]).norm(), 1.0);
    }
}

TEST(Chute, FlatBaseIsAWall) {
    TestChute chute;
    EXPECT_EQ(chute.build(ChuteBase::flat, 1), 0u);
    EXPECT_EQ(chute.scene().particles().size(), 0u);
    ASSERT_EQ(chute.scene().walls().size(), 1u);
    EXPECT_EQ(chute.scene().walls()[0].normal, Vec3::UnitZ());
}

TEST(Chute, BadGeometryAndBaseAreClearErrors) {
    TestChute chute;
    test::expectError([&] { chute.addBase(ChuteBase::disordered, 1, 0); }, {"setChuteGeometry before addBase"});
    test::expectError([&] { chute.setChuteGeometry({.length = -1}); }, {"chute length, width and height"});
    chute.setChuteGeometry({.length = 4, .width = 4});
    test::expectError([&] { chute.addBase(ChuteBase::ordered, 0, 0); }, {"base diameter"});
    test::expectError([&] { chute.addBase(ChuteBase::ordered, 5, 0); }, {"larger than the chute"});
    test::expectError([&] { chute.addBase(ChuteBase::disordered, 1, 0, 1, 2.0); }, {"roughness"});
}

// Bulk quantities against values computed by hand for three spheres of the two species.
TEST(ChuteStatistics, SnapshotOfKnownParticles) {
    ParticleStore p;
    auto add = [&](Vec3 x, Vec3 v, double r, std::uint32_t species, bool fixed) {
        const double m = fixed ? 0 : 1.0 * r * r * r;  // any masses: the test uses the store's
        p.position.push_back(x); p.velocity.push_back(v); p.angularVelocity.push_back(Vec3(0, 0, 2));
        p.force.push_back(Vec3::Zero()); p.torque.push_back(Vec3::Zero()); p.radius.push_back(r);
        p.mass.push_back(m); p.invMass.push_back(fixed ? 0 : 1 / m);
        p.invInertia.push_back(fixed ? 0 : 1 / (0.4 * m * r * r)); p.species.push_back(species);
        p.id.push_back(p.id.size()); p.fixed.push_back(fixed); p.motion.push_back(-1);
    };
    add(Vec3(1, 1, 1), Vec3(2, 0, 0), 0.5, 0, false);
    add(Vec3(2, 1, 3), Vec3(1, 0, 1), 0.25, 1, false);
    add(Vec3(0, 0, 0), Vec3(9, 9, 9), 0.5, 0, true);  // the base does not count
    const ChuteSnapshot s = measureChute(p, 4, 2, 1, 7.5);
    const double m1 = 0.125, m2 = 0.015625;
    EXPECT_DOUBLE_EQ(s.time, 7.5);
    EXPECT_DOUBLE_EQ(s.massFlux, (m1 * 2 + m2 * 1) / 8);
    EXPECT_DOUBLE_EQ(s.meanVelocity, (m1 * 2 + m2 * 1) / (m1 + m2));
    EXPECT_DOUBLE_EQ(s.height, 2 * (m1 * 1 + m2 * 3) / (m1 + m2));
    const double rotational = 0.5 * 4 * (0.4 * m1 * 0.25 + 0.4 * m2 * 0.0625);
    EXPECT_NEAR(s.kineticEnergy, (0.5 * m1 * 4 + 0.5 * m2 * 2 + rotational) / 8, 1e-15);
    EXPECT_DOUBLE_EQ(s.smallConcentration, 0.015625 / (0.125 + 0.015625));
    // One sphere of each kind: the large at z = 1, the small at z = 3 (small on top).
    EXPECT_DOUBLE_EQ(s.segregation, (1.0 - 3.0) / (s.height / 2));
}

// The segregation index of layers built to be mixed, segregated and inverted.
TEST(ChuteStatistics, SegregationIndexOfLayeredBeds) {
    // A column of 2n equal spheres at heights 0.5, 1.5, ...; which are small decides the index.
    auto bed = [](auto isSmall) {
        ParticleStore p;
        const int n = 10;
        for (int k = 0; k < 2 * n; ++k) {
            p.position.push_back(Vec3(0.5, 0.5, k + 0.5)); p.velocity.push_back(Vec3::Zero());
            p.angularVelocity.push_back(Vec3::Zero()); p.force.push_back(Vec3::Zero());
            p.torque.push_back(Vec3::Zero()); p.radius.push_back(0.5); p.mass.push_back(1);
            p.invMass.push_back(1); p.invInertia.push_back(10); p.species.push_back(isSmall(k, n) ? 1 : 0);
            p.id.push_back(p.id.size()); p.fixed.push_back(false); p.motion.push_back(-1);
        }
        return measureChute(p, 1, 1, 1, 0).segregation;
    };
    // Height 2 * mean z = 2n; small below: mean heights n/2 and 3n/2, index (3n/2 - n/2) / n = 1.
    EXPECT_NEAR(bed([](int k, int n) { return k < n; }), 1.0, 1e-14);
    EXPECT_NEAR(bed([](int k, int n) { return k >= n; }), -1.0, 1e-14);
    EXPECT_NEAR(bed([](int k, int) { return k % 4 == 0 || k % 4 == 3; }), 0.0, 1e-14);  // alternating pairs: mixed
    EXPECT_EQ(bed([](int, int) { return false; }), 0.0);  // one kind only
}

// A detector saved half-way and restored into another (as a restart does) decides as the
// original does from then on.
TEST(ChuteStatistics, PlateauDetectorStateRoundTrip) {
    PlateauDetector original(10, 0.01), restored(4, 0.5);
    auto sample = [](int k) { return std::vector<double>{k < 15 ? 1.0 + 0.01 * k : 1.15, 2.0}; };
    for (int k = 1; k <= 12; ++k) original.add(k, sample(k));
    restored.restore(original.state());
    EXPECT_EQ(restored.samples(), 12u);
    EXPECT_EQ(restored.state(), original.state());
    for (int k = 13; k <= 40; ++k) EXPECT_EQ(restored.add(k, sample(k)), original.add(k, sample(k))) << "sample " << k;
    EXPECT_TRUE(original.steady());
    EXPECT_EQ(restored.steadySince(), original.steadySince());
    test::expectError([&] { restored.restore({10, 0.01, 3}); }, {"at least 5 numbers"});
    test::expectError([&] { restored.restore({4, 0.01, 3, -1, 2, 1, 2, 3}); }, {"do not fit its window"});
}

TEST(ChuteStatistics, PlateauDetectorFindsAPlateauAndNotARamp) {
    PlateauDetector constant(10, 0.01), ramp(10, 0.01), late(10, 0.01);
    for (int k = 1; k <= 9; ++k) EXPECT_FALSE(constant.add(k, {3.0, -2.0}));
    EXPECT_TRUE(constant.add(10, {3.0, -2.0}));
    EXPECT_EQ(constant.steadySince(), 10);
    // A ramp of 0.2% of its value per sample changes by about 2% over a window of 10: never
    // steady at 1%.
    for (int k = 1; k <= 100; ++k) EXPECT_FALSE(ramp.add(k, {1.0 + 0.002 * k, 1.0}));
    // Growth that saturates, 1 - e^(-k/10): the line over the last 10 samples changes by about
    // 9 x (1/10) e^(-k/10), below 1% of the mean (about 1) once e^(-k/10) < 0.011, k > 45.
    double when = -1;
    for (int k = 1; k <= 200 && when < 0; ++k)
        if (late.add(k, {1 - std::exp(-k / 10.0), 5.0})) when = k;
    EXPECT_GT(when, 40);
    EXPECT_LT(when, 60);
    test::expectError([] { PlateauDetector(3, 0.01); }, {"window"});
}

TEST(ChuteStatistics, BatchMeansGiveTheStandardErrorOfIndependentBatches) {
    const std::vector<double> samples = {1, 1, 3, 3, 5, 5, 7, 7, 9, 9};  // batch means 1, 3, 5, 7, 9
    const MeanAndError r = batchMean(samples, 5);
    EXPECT_DOUBLE_EQ(r.mean, 5);
    EXPECT_DOUBLE_EQ(r.error, std::sqrt(10.0 / 5));  // sample variance of 1..9 step 2 is 10
}

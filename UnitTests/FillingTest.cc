// The filling (Kernel/Boundaries/Filling.h): particles of any shape stay inside their region and
// off each other (an annulus filled until it jams holds them only between its radii); a box fills
// to a packing fraction within one particle, or stops and says how far it got; kinds in turn
// alternate as the rule says, across calls too; the cylinder draws what the drum's filling drew
// before the two inserters became one; a triangle mesh across the region keeps the particles off
// it; bad kinds and particles that cannot fit are named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "Boundaries/Filling.h"
#include "TestHelpers.h"
#include "Walls/MeshContact.h"

using namespace talus;
using test::expectError;

namespace {

// A drum-like box: periodic along y (length 4), open along x and z.
void drumBox(Simulation& s) {
    s.scene().setDomain(Vec3(-5, 0, -5), Vec3(5, 4, 5));
    s.scene().setPeriodic(false, true, false);
}

std::size_t addGrains(Simulation& s, const std::string& name = "grains") {
    return s.scene().addSpecies(name, 6 / pi, LinearSpringDashpot::fromCollision(0.05, 0.5, 0.5));
}

// Largest overlap of bounding spheres r_i + r_j - |x_i - x_j| (nearest image) over all pairs, by
// brute force: independent of the filling's cell grid.
double largestOverlap(const Simulation& s) {
    const ParticleStore& p = s.scene().particles();
    double worst = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j)
            worst = std::max(worst, p.radius[i] + p.radius[j] -
                                        s.scene().domain().nearestImage(p.position[i] - p.position[j]).norm());
    return worst;
}

// Spheres and ellipsoids (bounding radius 0.6) in turn into an annulus of radii 1.5 and 3.5 about
// y, until one fails 2000 attempts. Every bounding sphere must lie between the radii (distance
// from the axis minus radius >= 1.5, plus radius <= 3.5), none may overlap another, and the
// filling must reach both faces (within a tenth of a radius): an annulus filled only near its
// middle would pass the first checks vacuously.
TEST(Filling, AnnulusHoldsParticlesOnlyBetweenItsRadii) {
    Simulation s;
    drumBox(s);
    const std::size_t spheres = addGrains(s, "spheres"), ellipsoids = addGrains(s, "ellipsoids");
    const int shape = static_cast<int>(s.scene().addShape(Superquadric::ellipsoid(0.6, 0.35, 0.35)));
    const double inner = 1.5, outer = 3.5;
    std::vector<int> inserted = {0, 0};
    const InsertionReport report = Filling(Annulus(Vec3::Zero(), 1, 4, inner, outer), 2000)
                                       .fillInTurn(s, {{.species = spheres, .radius = 0.4, .target = 1000},
                                                       {.species = ellipsoids, .shape = shape, .target = 1000}},
                                                   inserted);
    EXPECT_FALSE(report.complete) << "2000 particles cannot fit: " << report.describe();
    EXPECT_NE(report.describe().find("failed 2000 attempts in a row"), std::string::npos) << report.describe();
    const ParticleStore& p = s.scene().particles();
    ASSERT_EQ(p.size(), report.inserted);
    ASSERT_GT(p.size(), 40u) << report.describe();
    EXPECT_EQ(inserted[0] + inserted[1], static_cast<int>(p.size()));
    double innerGap = INFINITY, outerGap = INFINITY;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double rho = std::hypot(p.position[i].x(), p.position[i].z());
        EXPECT_GE(rho - p.radius[i], inner) << "particle " << i;
        EXPECT_LE(rho + p.radius[i], outer) << "particle " << i;
        innerGap = std::min(innerGap, rho - p.radius[i] - inner);
        outerGap = std::min(outerGap, outer - rho - p.radius[i]);
    }
    EXPECT_LT(innerGap, 0.04);
    EXPECT_LT(outerGap, 0.04);
    std::printf("[ measured ] %zu particles; nearest gaps to the inner and outer faces %.3g and %.3g\n", p.size(), innerGap,
                outerGap);
    EXPECT_LE(largestOverlap(s), 1e-12);
}

// A periodic box 8 x 8 x 8 of monodisperse spheres r = 0.5 (volume pi/6 each, 512 in all): the
// packing fraction 0.25 is reached and exceeded by less than one sphere, pi/6/512 = 0.00102, as
// counted here from the particles; 0.6 is beyond random sequential addition's jamming limit for
// spheres (about 0.38), so the filling stops and says how far it got.
TEST(Filling, BoxReachesAPackingFractionOrSaysHowFarItGot) {
    Simulation s;
    s.scene().setDomain(Vec3::Zero(), Vec3::Constant(8));
    s.scene().setPeriodic(true, true, true);
    const std::size_t grains = addGrains(s);
    const SizeDistribution one = SizeDistribution::byNumber().add(grains, 0.5);
    const Filling box(Box(Vec3::Zero(), Vec3::Constant(8)), 2000);
    const double sphere = pi / 6, volume = 512;
    InsertionReport report = box.fill(s, one, InsertionReport::Target::packingFraction, 0.25);
    ASSERT_TRUE(report.complete) << report.describe();
    const double reached = s.scene().particles().size() * sphere / volume;
    EXPECT_GE(reached, 0.25);
    EXPECT_LT(reached, 0.25 + sphere / volume);
    EXPECT_NEAR(report.packingFraction, reached, 1e-12);  // (summed in another order)

    report = box.fill(s, one, InsertionReport::Target::packingFraction, 0.6);
    EXPECT_FALSE(report.complete);
    EXPECT_LT(report.packingFraction, 0.45);
    EXPECT_NEAR(report.packingFraction, s.scene().particles().size() * sphere / volume, 1e-12);
    EXPECT_NE(report.describe().find("failed 2000 attempts in a row"), std::string::npos) << report.describe();
    EXPECT_LE(largestOverlap(s), 1e-12);
}

// A tilted plane of 200 triangles (z = 1.5 + 0.3 x over [0, 4]^2, a mesh wall) across a box
// [0, 4]^3 filled with spheres of radius 0.2 until 2000 tries in a row fail: no sphere reaches
// into a triangle (each distance by closestPointOnTriangle from the corners, every triangle,
// independent of the mesh's grid, which the filling asks), and the spheres pack up to the mesh
// from both sides (the nearest within a tenth of a radius), so the check is not vacuous.
TEST(Filling, AMeshAcrossTheRegionKeepsTheParticlesOffIt) {
    Simulation s;
    s.scene().setDomain(Vec3::Zero(), Vec3::Constant(4));
    const std::size_t grains = addGrains(s);
    std::vector<TriangleCorners> triangles;
    auto at = [](int i, int j) { return Vec3(0.4 * i, 0.4 * j, 1.5 + 0.12 * i); };
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) {
            triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    s.scene().addMeshWall(TriangleMesh(triangles), grains);
    const double r = 0.2;
    const InsertionReport report = Filling(Box(Vec3::Zero(), Vec3::Constant(4)), 2000)
                                       .fill(s, SizeDistribution::byNumber().add(grains, r),
                                             InsertionReport::Target::count, 5000);
    EXPECT_FALSE(report.complete);
    const ParticleStore& p = s.scene().particles();
    ASSERT_GT(p.size(), 300u) << report.describe();
    double nearestBelow = INFINITY, nearestAbove = INFINITY;
    for (std::size_t i = 0; i < p.size(); ++i) {
        double distance = INFINITY;
        for (const TriangleCorners& t : triangles)
            distance = std::min(distance, (p.position[i] - closestPointOnTriangle(p.position[i], t).point).norm());
        EXPECT_GE(distance, r) << "sphere " << i << " at " << p.position[i].transpose();
        const bool above = p.position[i].z() > 1.5 + 0.3 * p.position[i].x();
        (above ? nearestAbove : nearestBelow) = std::min(above ? nearestAbove : nearestBelow, distance - r);
    }
    std::printf("[ measured ] %zu spheres; nearest gaps to the mesh below and above it %.3g and %.3g\n", p.size(),
                nearestBelow, nearestAbove);
    EXPECT_LT(nearestBelow, 0.1 * r);
    EXPECT_LT(nearestAbove, 0.1 * r);
    EXPECT_LE(largestOverlap(s), 1e-12);
}

// The rule: the next particle is of the kind with the fewest inserted among those below their
// target, the first on ties. Targets 3 and 5 from nothing: 0 1 0 1 0 1 1 1; then, the targets
// raised to 4 and 5 with the counts kept, one more of kind 0.
TEST(Filling, KindsInTurnFollowTheRuleAcrossCalls) {
    Simulation s;
    drumBox(s);
    const std::size_t a = addGrains(s, "a"), b = addGrains(s, "b");
    const Filling drum(Cylinder(Vec3::Zero(), 1, 4, 4.5));
    std::vector<int> inserted = {0, 0};
    InsertionReport report = drum.fillInTurn(s, {{.species = a, .radius = 0.5, .target = 3},
                                                 {.species = b, .radius = 0.3, .target = 5}}, inserted);
    EXPECT_TRUE(report.complete);
    EXPECT_EQ(report.inserted, 8u);
    EXPECT_EQ(report.requested, 8);
    report = drum.fillInTurn(s, {{.species = a, .radius = 0.5, .target = 4}, {.species = b, .radius = 0.3, .target = 5}},
                             inserted);
    EXPECT_EQ(report.inserted, 1u);
    EXPECT_EQ(inserted, (std::vector<int>{4, 5}));
    std::vector<std::uint32_t> species = s.scene().particles().species;
    EXPECT_EQ(species, (std::vector<std::uint32_t>{0, 1, 0, 1, 0, 1, 1, 1, 0}));
}

// The drum's filling before the two inserters were joined, its code as it was (the order in which
// the compiler evaluates a constructor's arguments is its own; GCC goes right to left, z first):
// candidates in the square of half-width R - the largest bounding radius, std::uniform_real_
// distribution draws, a brute-force overlap test. The joint filling must place the same spheres
// at the same places, to the bit, so that the drum's output stays the same. (The reference holds
// for GCC with libstdc++, which the project builds with.)
#if defined(__GNUC__) && !defined(__clang__) && defined(__GLIBCXX__)
TEST(Filling, CylinderDrawsWhatTheDrumsFillingDrew) {
    const double radius = 3.8, length = 4;
    std::vector<Vec3> expected;
    std::vector<double> expectedRadius;
    {
        std::mt19937_64 random(11);
        std::uniform_real_distribution<double> unit(0, 1);
        const double ownRadius[2] = {0.5, 0.3}, reach = radius - 0.5;
        int counts[2] = {0, 0};
        for (int n = 0; n < 60; ++n) {
            const int kind = counts[1] < counts[0] ? 1 : 0;
            const double r = ownRadius[kind];
            for (int attempt = 0; attempt < 1000; ++attempt) {
                const Vec3 x(reach * (2 * unit(random) - 1), length * unit(random), reach * (2 * unit(random) - 1));
                if (std::hypot(x.x(), x.z()) > radius - r) continue;
                bool free = true;
                for (std::size_t i = 0; i < expected.size() && free; ++i) {
                    Vec3 d = x - expected[i];
                    d.y() -= length * std::round(d.y() / length);
                    free = d.norm() >= r + expectedRadius[i];
                }
                if (!free) continue;
                expected.push_back(x), expectedRadius.push_back(r);
                ++counts[kind];
                break;
            }
            ASSERT_EQ(expected.size(), static_cast<std::size_t>(n + 1)) << "the reference filling jammed";
        }
    }
    Simulation s;
    drumBox(s);
    const std::size_t a = addGrains(s, "a"), b = addGrains(s, "b");
    s.scene().random().seed(11);
    std::vector<int> inserted = {0, 0};
    Filling(Cylinder(Vec3::Zero(), 1, length, radius), 1000, Filling::CandidateMargin::largestRadius)
        .fillInTurn(s, {{.species = a, .radius = 0.5, .target = 30}, {.species = b, .radius = 0.3, .target = 30}}, inserted);
    const ParticleStore& p = s.scene().particles();
    ASSERT_EQ(p.size(), expected.size());
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_TRUE(test::sameBits(p.position[i], expected[i])) << "particle " << i;
}
#endif

TEST(Filling, BadKindsAndParticlesThatCannotFitAreNamed) {
    Simulation s;
    drumBox(s);
    const std::size_t grains = addGrains(s);
    const int shape = static_cast<int>(s.scene().addShape(Superquadric::ellipsoid(1.2, 0.3, 0.3)));
    const Filling narrow(Annulus(Vec3::Zero(), 1, 4, 2, 3));
    std::vector<int> inserted = {0};
    expectError([&] { narrow.fillInTurn(s, {{.species = grains, .shape = shape, .target = 1}}, inserted); },
                {"annulus region", "outer radius - inner radius = 1", "largest particle diameter 2.4"});
    expectError([&] { narrow.fillInTurn(s, {{.species = 5, .target = 1}}, inserted); },
                {"particle kind 0", "species 5 does not exist"});
    expectError([&] { narrow.fillInTurn(s, {{.species = grains, .shape = 4, .target = 1}}, inserted); },
                {"particle kind 0", "shape 4 does not exist"});
    expectError([&] { narrow.fillInTurn(s, {{.species = grains, .radius = -1, .target = 1}}, inserted); },
                {"particle kind 0", "radius must be positive"});
    std::vector<int> noCounts;
    expectError([&] { narrow.fillInTurn(s, {{.species = grains, .target = 1}}, noCounts); },
                {"one count of inserted particles per kind"});
    expectError([&] { Filling(Box(Vec3::Zero(), Vec3::Ones()), 0); }, {"maxAttemptsPerParticle", "at least 1"});
    EXPECT_EQ(s.scene().particles().size(), 0u) << "a rejected call must not insert anything";
}

}  // namespace

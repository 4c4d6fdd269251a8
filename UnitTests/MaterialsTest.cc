// Species from material properties (Species/Materials.h) in SI units: the effective moduli of a
// pair against the formulas worked out here, the species and pair laws a table adds, bad input
// named, and whole simulations at the millimetre scale of the open-source DEM comparison: an
// elastic impact lasts Hertz's classical duration, a damped one rebounds with the pair's
// restitution, and a sphere at rest on a wall sinks to Hertz's static overlap under its weight.
#include <gtest/gtest.h>

#include <cmath>

#include "ContactTestScenes.h"
#include "Species/Materials.h"

using namespace talus;
using namespace talus::test;

namespace {

// The materials of the comparison's README (SI): M1 glass-like beads and steel.
MaterialTable comparisonMaterials(double restitutionM1Steel) {
    MaterialTable t;
    t.add({"M1", 2500, 1e9, 0.2});
    t.add({"steel", 7200, 210e9, 0.2});
    t.setPair("M1", "M1", {.restitution = 0.5, .friction = 0.3});
    t.setPair("M1", "steel", {.restitution = restitutionM1Steel, .friction = 0.2});
    t.setPair("steel", "steel", {.restitution = 0.6, .friction = 0.5});
    return t;
}

}  // namespace

TEST(Materials, EffectiveModuliOfAPairAreTheReciprocalSums) {
    const MaterialTable t = comparisonMaterials(0.4);
    const HertzMindlin law = t.law("steel", "M1", 5.0);
    // 1/E* = (1 - 0.04)/1e9 + (1 - 0.04)/210e9; G = E/2.4; 1/G* = 1.8/G1 + 1.8/G2.
    const double expectedE = 1 / (0.96 / 1e9 + 0.96 / 210e9);
    const double expectedG = 1 / (1.8 / (1e9 / 2.4) + 1.8 / (210e9 / 2.4));
    EXPECT_NEAR(law.effectiveYoungsModulus / expectedE, 1, 1e-14);
    EXPECT_NEAR(law.effectiveShearModulus / expectedG, 1, 1e-14);
    EXPECT_EQ(law.restitution, 0.4);
    EXPECT_EQ(law.friction, 0.2);
    EXPECT_EQ(law.characteristicVelocity, 5.0);
    // A material with itself: E / (2 (1 - nu^2)) and G / (2 (2 - nu)).
    const HertzMindlin self = t.law("M1", "M1", 1.0);
    EXPECT_NEAR(self.effectiveYoungsModulus / (1e9 / (2 * 0.96)), 1, 1e-14);
    EXPECT_NEAR(self.effectiveShearModulus / (1e9 / 2.4 / (2 * 1.8)), 1, 1e-14);
}

TEST(Materials, TableAddsOneSpeciesPerMaterialAndEveryPairExplicitly) {
    const MaterialTable t = comparisonMaterials(0.4);
    SpeciesTable species;
    species.add("other", 1, HertzMindlin::fromMaterial(1e6, 0.3, 0.9));
    const std::vector<std::size_t> added = t.addTo(species, 2.0);
    ASSERT_EQ(added, (std::vector<std::size_t>{1, 2}));
    EXPECT_EQ(species[1].name, "M1");
    EXPECT_EQ(species[2].density, 7200);
    const auto pair = std::get<HertzMindlin>(species.pairLaw(2, 1));
    const HertzMindlin expected = t.law("M1", "steel", 2.0);
    EXPECT_EQ(pair.effectiveYoungsModulus, expected.effectiveYoungsModulus);
    EXPECT_EQ(pair.friction, 0.2);
    EXPECT_EQ(species.explicitPairs().size(), 1u);  // (M1, steel); each material's own law is its species'
    species.validate();
}

TEST(Materials, BadMaterialsAndMissingPairsAreNamed) {
    MaterialTable t;
    t.add({"M2", 2000, 0.5e9, 0.2});
    expectError([&] { t.add({"M2", 2000, 0.5e9, 0.2}); }, {"material 'M2'", "twice"});
    expectError([&] { t.add({"glass", 2500, -1, 0.2}); }, {"material 'glass'", "Young's modulus"});
    expectError([&] { t.add({"glass", 2500, 1e9, 0.5}); }, {"material 'glass'", "Poisson ratio"});
    expectError([&] { t.add({"glass", std::nan(""), 1e9, 0.2}); }, {"material 'glass'", "density"});
    expectError([&] { t.setPair("M2", "steel", {0.5, 0.3}); }, {"material 'steel'", "not in the table"});
    expectError([&] { t.setPair("M2", "M2", {0, 0.3}); }, {"('M2', 'M2')", "restitution"});
    t.add({"steel", 7200, 210e9, 0.2});
    t.setPair("M2", "M2", {0.4, 0.4});
    t.setPair("steel", "steel", {0.6, 0.5});
    SpeciesTable species;
    expectError([&] { t.addTo(species, 1.0); }, {"material pair ('M2', 'steel')", "setPair"});
}

// An M1 bead of diameter 2 mm hits a steel wall head-on at 5 m/s, the pair made elastic (e = 1):
// the contact lasts Hertz's tc = 2.868 (m*^2 / (R* E*^2 v))^(1/5) (Johnson 1985, eq. (11.24), the
// classical constant; the law's time-step check uses the beta-function form instead).
TEST(Materials, MillimetreBeadOnSteelLastsHertzsDuration) {
    const MaterialTable t = comparisonMaterials(1.0);
    const double radius = 1e-3, speed = 5;
    HeadOnCollision collision;
    collision.law = t.law("M1", "steel", speed);
    collision.radius = radius;
    collision.partnerRadius = 0;  // the wall
    collision.speed = speed;
    const double mass = sphereMass(radius);  // (the scene's density: only m* enters)
    const double E = std::get<HertzMindlin>(collision.law).effectiveYoungsModulus;
    const double duration = 2.868 * std::pow(mass * mass / (radius * E * E * speed), 0.2);
    collision.timeStep = duration / 200;
    collision.longestDuration = 1.5 * duration;
    const HeadOnResult r = collision.run();
    EXPECT_NEAR(r.contactDuration / duration, 1, 2e-3);  // (the constant's four digits, and dt)
    EXPECT_NEAR(r.restitution, 1, 1e-4);
}

TEST(Materials, MillimetreBeadReboundsWithThePairsRestitution) {
    const MaterialTable t = comparisonMaterials(0.4);
    HeadOnCollision collision;
    collision.law = t.law("M1", "steel", 5);
    collision.radius = 1e-3;
    collision.partnerRadius = 0;
    collision.speed = 5;
    const double E = std::get<HertzMindlin>(collision.law).effectiveYoungsModulus;
    const double elastic = 2.868 * std::pow(std::pow(sphereMass(1e-3), 2) / (1e-3 * E * E * 5), 0.2);
    collision.timeStep = elastic / 200;
    collision.longestDuration = 1.5 * elastic;
    EXPECT_NEAR(collision.run().restitution, 0.4, 4e-3);
}

// A 4 mm M2 bead (density 2000) released just above a steel floor under g = 9.8 m/s^2 settles,
// damped by the pair's restitution, to Hertz's static overlap: m g = 4/3 E* sqrt(R) d^(3/2).
TEST(Materials, MillimetreBeadRestsAtHertzsStaticOverlap) {
    MaterialTable t;
    t.add({"M2", 2000, 0.5e9, 0.2});
    t.add({"steel", 7200, 210e9, 0.2});
    t.setPair("M2", "M2", {0.4, 0.4});
    t.setPair("M2", "steel", {0.4, 0.2});
    t.setPair("steel", "steel", {0.6, 0.5});
    const double radius = 2e-3, g = 9.8;
    const double mass = 2000 * 4.0 / 3.0 * pi * radius * radius * radius;
    const HertzMindlin law = t.law("M2", "steel", 0.1);
    const double overlap = std::pow(3 * mass * g / (4 * law.effectiveYoungsModulus * std::sqrt(radius)), 2.0 / 3.0);
    TestScene scene;
    scene.setup = [&](TestScene& s) {
        s.scene().setGravity(Vec3(0, 0, -g));
        s.scene().setDomain(Vec3(-0.01, -0.01, 0), Vec3(0.01, 0.01, 0.01));
        const std::vector<std::size_t> species = t.addTo(s.scene().species(), 0.1);
        s.scene().addParticle(Vec3(0, 0, radius + 1e-5), radius, species[0]);
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species[1]);
    };
    // tc at the settling speed (~0.01 m/s) is about 2e-5 s; 0.05 s rings the bead down.
    scene.runFor(2e-7, 0.05);
    const double sunk = radius - scene.scene().particles().position[0].z();
    EXPECT_NEAR(sunk / overlap, 1, 1e-3) << "overlap " << sunk << " against Hertz " << overlap;
}

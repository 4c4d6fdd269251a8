// Species table: collision helpers of Theory/ContactLaws.md eq. (10)-(12) invert each other, mixing
// and validation.
#include <gtest/gtest.h>

#include <cmath>

#include "Species/SpeciesTable.h"

using namespace talus;

// kn, gn from (tc, e, m) must give back tc and e through the forward formulas of
// Theory/ContactLaws.md eq. (10)-(11).
TEST(LinearSpringDashpot, CollisionHelpersInvertEachOther) {
    for (double e : {0.1, 0.5, 0.88, 1.0}) {
        const double tc = 0.005, m = 0.37;
        const auto law = LinearSpringDashpot::fromCollision(tc, e, m);
        EXPECT_NEAR(law.collisionTime(m), tc, 1e-14);
        EXPECT_NEAR(law.restitution(m), e, 1e-13);
        EXPECT_DOUBLE_EQ(law.tangentialStiffness, 2.0 / 7.0 * law.normalStiffness);
        EXPECT_DOUBLE_EQ(law.tangentialDamping, law.normalDamping);
    }
}

// The thesis's table 3.C.1: kn = 2e5, gn = 25 between two unit masses (m* = 1/2) gives
// tc = 4.97e-3, e = 0.883.
TEST(LinearSpringDashpot, SeedTableParameters) {
    LinearSpringDashpot law{2e5, 25, 2.0 / 7.0 * 2e5, 25, 0.5};
    EXPECT_NEAR(law.collisionTime(0.5), 4.97e-3, 0.005e-3);
    EXPECT_NEAR(law.restitution(0.5), 0.883, 0.0005);
}

TEST(SpeciesTable, MixesUnlessPairIsSet) {
    SpeciesTable table;
    const auto a = table.add("a", 1, LinearSpringDashpot{100, 1, 20, 1, 0.5});
    const auto b = table.add("b", 2, LinearSpringDashpot{300, 3, 40, 3, 0.25});
    EXPECT_DOUBLE_EQ(std::get<LinearSpringDashpot>(table.pairLaw(a, b)).normalStiffness, 200);
    table.pair<LinearSpringDashpot>(b, a).friction = 0.375;
    EXPECT_DOUBLE_EQ(std::get<LinearSpringDashpot>(table.pairLaw(a, b)).friction, 0.375);
    const auto dense = table.table<LinearSpringDashpot>();
    EXPECT_DOUBLE_EQ(dense(a, b).friction, 0.375);
    EXPECT_DOUBLE_EQ(dense(b, a).friction, 0.375);
    EXPECT_DOUBLE_EQ(dense(b, b).friction, 0.25);
}

TEST(SpeciesTable, RejectsBadParametersByName) {
    SpeciesTable table;
    try {
        table.add("sand", -1, LinearSpringDashpot{100, 1, 20, 1, 0.5});
        FAIL() << "negative density accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("sand"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("density"), std::string::npos);
    }
    EXPECT_THROW(table.add("glass", 1, LinearSpringDashpot{0, 1, 20, 1, 0.5}), Error);
    table.add("a", 1, LinearSpringDashpot{100, 1, 20, 1, 0.5});
    table.add("b", 1, HertzMindlin::fromMaterial(1e6, 0.3, 0.9));
    EXPECT_THROW(table.validate(), Error);  // two kinds of law in one simulation
}

// Theory/ContactLaws.md "Bidisperse mixtures" bidisperse rule on the thesis's table 3.C.1 mixture
// (dL = 1, dS = 2^(-1/3), density 6/pi, so mL = 1, mS = 1/2): every pair type rebounds with the
// same e, and tc/sqrt(d) is the same for LL, SS and LS (d = (dL + dS)/2), each with its own reduced
// mass.
#include "Species/BidisperseRule.h"

TEST(BidisperseRule, SameRestitutionAndScaledCollisionTimes) {
    SpeciesTable table;
    const auto large = table.add("large", 6 / pi, LinearSpringDashpot{1, 0, 0, 0, 0.5});
    const auto small = table.add("small", 6 / pi, LinearSpringDashpot{1, 0, 0, 0, 0.25});
    const double dL = 1, dS = std::cbrt(0.5), tc = 4.97e-3, e = 0.883;
    applyBidisperseRule(table, {large, small, dL, dS, tc, e, 0.375});
    const double mL = 1, mS = 0.5;
    struct Pair {
        std::size_t a, b;
        double diameter, reducedMass, friction;
    };
    for (const Pair& p : {Pair{large, large, dL, mL / 2, 0.5}, Pair{small, small, dS, mS / 2, 0.25},
                          Pair{large, small, 0.5 * (dL + dS), mL * mS / (mL + mS), 0.375}}) {
        const auto law = std::get<LinearSpringDashpot>(table.pairLaw(p.a, p.b));
        EXPECT_NEAR(law.restitution(p.reducedMass), e, 1e-12);
        EXPECT_NEAR(law.collisionTime(p.reducedMass) / std::sqrt(p.diameter), tc / std::sqrt(dL), 1e-15);
        EXPECT_DOUBLE_EQ(law.friction, p.friction);
        EXPECT_DOUBLE_EQ(law.tangentialStiffness, 2.0 / 7.0 * law.normalStiffness);
    }
    // And the LL pair is the thesis's kn = 2e5, gn = 25 (to the 3 digits of tc and e given there).
    const auto ll = std::get<LinearSpringDashpot>(table.pairLaw(large, large));
    EXPECT_NEAR(ll.normalStiffness / 2e5, 1, 2e-3);
    EXPECT_NEAR(ll.normalDamping / 25, 1, 2e-3);
}

// The maser inflow boundary (Kernel/Boundaries/MaserBoundary.h, Theory/Maser.md eq. (3)): one-way
// forces across its downstream face, exact copies of every crossing, a first phase that is a plain
// periodic box to the last bit, totals that survive a restart, and clear errors.
#include <gtest/gtest.h>

#include <cmath>

#include "Boundaries/InsertionBoundary.h"
#include "Boundaries/MaserBoundary.h"
#include "TestHelpers.h"

using namespace talus;

namespace {

const LinearSpringDashpot grainLaw = LinearSpringDashpot::fromCollision(0.05, 0.5, 0.5);

// A maser box [-10, 0] along x, periodic in y over [0, 4]; no gravity. `arrange` adds the
// particles (after the species: chute 0, maser copy 1) and may activate the maser.
struct MaserScene : test::SceneSimulation {
    MaserBoundary& maser = scene().addBoundary<MaserBoundary>(*this, -10, 0, 3);
    std::function<void(MaserScene&)> arrange;
    MaserScene() {
        setup = [this](SceneSimulation&) {
            settings().timeStep = 1e-3;
            scene().setGravity(Vec3::Zero());
            scene().setDomain(Vec3(-10, 0, -2), Vec3(0, 4, 2));
            scene().setPeriodic(true, true, false);
            settings().maxInitialOverlapFraction = 0.5;  // the one-way test starts with overlaps
            scene().addSpecies("grain", 1, grainLaw);
            maser.maserSpecies(*this, 0);
            arrange(*this);
        };
    }
};

// The forces after initialisation (no step taken): contact forces alone, since g = 0.
void computeInitialForces(MaserScene& s) {
    s.solveOrThrow({"--end-time", "0", "--files", "off"});
}

}  // namespace

// A at the downstream face and B at the upstream face overlap by 0.02 through the face. In the
// first phase (a periodic box) they push each other apart; once the maser is active only B
// feels A (through A's image), with the same force as before, while A feels only the chute
// particle C in front of it, which feels A in return.
TEST(MaserBoundary, ForcesAcrossTheDownstreamFaceAreOneWay) {
    const Vec3 a(-0.48, 2, 0), b(-9.5, 2, 0), c(0.4, 2, 0);
    MaserScene periodic;
    periodic.arrange = [&](MaserScene& s) {
        s.scene().addParticle(a, 0.5, 1);
        s.scene().addParticle(b, 0.5, 1);
    };
    computeInitialForces(periodic);
    const Vec3 onB = periodic.scene().particles().force[periodic.scene().slotOf(1)];
    EXPECT_GT(onB.x(), 0);
    EXPECT_NEAR(onB.y(), 0, 1e-12);
    EXPECT_NEAR((periodic.scene().particles().force[periodic.scene().slotOf(0)] + onB).norm(), 0, 1e-12);

    MaserScene active;
    active.arrange = [&](MaserScene& s) {
        s.scene().addParticle(a, 0.5, 1);
        s.scene().addParticle(b, 0.5, 1);
        s.scene().addParticle(c, 0.5, 0);  // a chute particle just downstream of the face
        s.maser.activate(s, 10, /*seedChute*/ false);
    };
    computeInitialForces(active);
    const ParticleStore& p = active.scene().particles();
    const Vec3 onA = p.force[active.scene().slotOf(0)], onC = p.force[active.scene().slotOf(2)];
    EXPECT_EQ(p.force[active.scene().slotOf(1)], onB) << "B feels A's image as in the periodic box";
    EXPECT_GT(onC.x(), 0);
    EXPECT_LT(onA.x(), 0);
    EXPECT_EQ(onA, -onC) << "A feels C and nothing from B";
    EXPECT_EQ(active.state().pairList.oneWayPairs.size(), 1u);
}

// Past a tenth of the radius the pair stops being purely one way: at an overlap of 0.15 (30% of
// the radius 0.5) A feels (0.15 - 0.05) / 0.15 of the force on B, in the opposite direction.
TEST(MaserBoundary, DeepOverlapsAcrossTheFacePushBack) {
    MaserScene active;
    active.arrange = [](MaserScene& s) {
        s.scene().addParticle(Vec3(-0.4, 2, 0), 0.5, 1);
        s.scene().addParticle(Vec3(-9.55, 2, 0), 0.5, 1);
        s.maser.activate(s, 10, /*seedChute*/ false);
    };
    computeInitialForces(active);
    const Vec3 onA = active.scene().particles().force[active.scene().slotOf(0)], onB = active.scene().particles().force[active.scene().slotOf(1)];
    EXPECT_GT(onB.x(), 0);
    EXPECT_NEAR(onA.x(), -onB.x() * (0.15 - 0.05) / 0.15, 1e-9 * onB.x());
    EXPECT_EQ(active.contactSummary().oneWayReactions, 1u);
}

// Three maser spheres in separate lanes move downstream at constant speeds without touching
// anything. Sphere k starting at x0 with speed v has crossed the face floor((x0 + v t + 10) / 10)
// times by time t: that many copies of it, of the chute species, with its mass, must be in the
// chute, each at x >= 0 and moving with its velocity; the maser keeps its three spheres.
TEST(MaserBoundary, CopiesEveryCrossingExactlyOnce) {
    const double x0[3] = {-9.5, -5.2, -1.3}, v[3] = {1.0, 1.7, 2.3}, radius[3] = {0.3, 0.4, 0.5};
    MaserScene run;
    run.arrange = [&](MaserScene& s) {
        s.scene().addSpecies("other", 2, grainLaw);  // chute species 2, a second outflow class
        s.maser.maserSpecies(s, 2);          // maser species 3
        for (int k = 0; k < 3; ++k) s.scene().addParticle(Vec3(x0[k], 0.5 + 1.3 * k, 0), radius[k], k == 2 ? 3 : 1, Vec3(v[k], 0, 0));
        s.maser.activate(s, 200, /*seedChute*/ false);
    };
    const double t = 23.45;
    run.solveOrThrow(test::stepsWithoutFiles(1e-3, 23450));
    int expected[3], total = 0;
    for (int k = 0; k < 3; ++k) total += expected[k] = static_cast<int>(std::floor((x0[k] + v[k] * t + 10) / 10));
    ASSERT_GT(total, 5);
    EXPECT_EQ(run.maser.crossings(), total);
    EXPECT_EQ(run.maser.crossings(0), expected[0] + expected[1]);
    EXPECT_EQ(run.maser.crossings(2), expected[2]);
    const ParticleStore& p = run.scene().particles();
    int copies[3] = {0, 0, 0}, maserParticles = 0;
    double copiedMass = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.species[i] == 1 || p.species[i] == 3) {
            ++maserParticles;
            EXPECT_GE(p.position[i].x(), -10);
            EXPECT_LT(p.position[i].x(), 0);
            continue;
        }
        // A copy: which sphere it came from follows from its lane.
        const int k = static_cast<int>(std::lround((p.position[i].y() - 0.5) / 1.3));
        ++copies[k];
        copiedMass += p.mass[i];
        EXPECT_EQ(p.species[i], k == 2 ? 2u : 0u);
        EXPECT_EQ(p.radius[i], radius[k]);
        EXPECT_GE(p.position[i].x(), 0);
        EXPECT_EQ(p.velocity[i], Vec3(v[k], 0, 0));
    }
    EXPECT_EQ(maserParticles, 3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(copies[k], expected[k]) << "sphere " << k;
    EXPECT_DOUBLE_EQ(copiedMass, run.maser.createdMass());
    EXPECT_EQ(run.maser.backwardCrossings(), 0);
}

// Before activation the maser is a periodic box: a bidisperse flow in maser species (copies)
// with the maser registered follows the same flow in the original species bit for bit over
// 10^4 steps. (The copies' pair laws, the boundary's hook and the extra species could each
// break this.)
TEST(MaserBoundary, FirstPhaseIsAPlainPeriodicBoxBitForBit) {
    auto scene = [](test::SceneSimulation& s, MaserBoundary* maser) {
        s.settings().timeStep = 1e-4;
        const double angle = 24 * pi / 180;
        s.scene().setGravity(Vec3(std::sin(angle), 0, -std::cos(angle)));
        s.scene().setDomain(Vec3(-8, 0, -1), Vec3(0, 4, 12));
        s.scene().setPeriodic(true, true, false);
        const LinearSpringDashpot law{2e5, 25, 2.0 / 7.0 * 2e5, 25, 0.5};
        std::size_t large = s.scene().addSpecies("large", 6 / pi, law);
        std::size_t small = s.scene().addSpecies("small", 6 / pi, LinearSpringDashpot(law).withFriction(0.25));
        s.scene().species().setPair(large, small, LinearSpringDashpot(law).withFriction(0.375));
        if (maser) {
            large = maser->maserSpecies(s, large);
            small = maser->maserSpecies(s, small);
        }
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), large);
        s.scene().random().seed(7);
        InsertionBoundary box(Vec3(-8, 0, 0.5), Vec3(0, 4, 8),
                              SizeDistribution::byNumber().add(large, 0.5).add(small, 0.4, 2));
        ASSERT_TRUE(box.insertCount(s, 120).complete);
    };
    test::SceneSimulation plain;
    plain.setup = [&](test::SceneSimulation& s) { scene(s, nullptr); };
    test::SceneSimulation withMaser;
    MaserBoundary& maser = withMaser.scene().addBoundary<MaserBoundary>(withMaser, -8, 0, 2);
    withMaser.setup = [&](test::SceneSimulation& s) { scene(s, &maser); };
    const auto flags = test::stepsWithoutFiles(1e-4, 10000);
    plain.solveOrThrow(flags);
    withMaser.solveOrThrow(flags);
    EXPECT_GT(plain.energies().kinetic, 0);
    EXPECT_TRUE(test::sameBits(plain.scene().particles().position, withMaser.scene().particles().position));
    EXPECT_TRUE(test::sameBits(plain.scene().particles().velocity, withMaser.scene().particles().velocity));
    EXPECT_TRUE(test::sameBits(plain.scene().particles().angularVelocity, withMaser.scene().particles().angularVelocity));
}

// An active maser saved and restarted goes on exactly: the one-way box, its pairs and its totals
// are in the restart file.
TEST(MaserBoundary, RestartContinuesExactly) {
    auto arrange = [](MaserScene& s) {
        for (int k = 0; k < 3; ++k) s.scene().addParticle(Vec3(-8 + 3 * k, 0.5 + 1.3 * k, 0), 0.4, 1, Vec3(1 + 0.5 * k, 0, 0));
        s.scene().addParticle(Vec3(-9.6, 3.1, 0), 0.4, 1, Vec3(1, 0, 0));  // the fastest one catches up with it
        s.maser.activate(s, 100);  // seeded: the copies move on in the chute
    };
    MaserScene first;
    first.arrange = arrange;
    first.solveOrThrow({"--name", "maser_restart", "--end-time", "7", "--progress-interval", "1e9"});
    MaserScene restarted;
    restarted.arrange = arrange;
    restarted.solveOrThrow({"--restart", "maser_restart.restart", "--end-time", "15", "--files", "off"});
    MaserScene whole;
    whole.arrange = arrange;
    whole.solveOrThrow(test::stepsWithoutFiles(1e-3, 15000));
    EXPECT_GT(whole.maser.crossings(), first.maser.crossings());
    EXPECT_EQ(restarted.maser.crossings(), whole.maser.crossings());
    EXPECT_EQ(restarted.maser.createdMass(0), whole.maser.createdMass(0));
    EXPECT_TRUE(test::sameBits(restarted.scene().particles().position, whole.scene().particles().position));
    EXPECT_TRUE(test::sameBits(restarted.scene().particles().velocity, whole.scene().particles().velocity));
}

TEST(MaserBoundary, BadSetupsAreClearErrors) {
    test::SceneSimulation s;
    test::expectError([&] { s.scene().addBoundary<MaserBoundary>(s, 0, -1, 1); }, {"maser box", "downstream end"});
    MaserScene empty;
    empty.arrange = [](MaserScene& s) {
        s.scene().addParticle(Vec3(1, 1, 0), 0.5, 0);  // a chute particle only
        s.maser.activate(s, 10);
    };
    test::expectError([&] { computeInitialForces(empty); }, {"maser", "no particles"});
    MaserScene shortBox;
    shortBox.arrange = [](MaserScene& s) {
        s.scene().addParticle(Vec3(-5, 1, 0), 2.6, 1);  // diameter 5.2: the box of length 10 is under two
        s.maser.activate(s, 10);
    };
    test::expectError([&] { computeInitialForces(shortBox); }, {"maser", "longer than two diameters"});
    MaserScene noSpecies;
    noSpecies.arrange = [](MaserScene& s) {
        s.scene().addParticle(Vec3(-5, 1, 0), 0.5, 1);
        s.maser.activate(s, -3);
    };
    test::expectError([&] { computeInitialForces(noSpecies); }, {"maser", "chute must end downstream"});
    MaserScene shaped;
    shaped.arrange = [](MaserScene& s) {
        s.scene().addSuperquadric(Vec3(-5, 1, 0), s.scene().addShape(Superquadric::ellipsoid(0.5, 0.25, 0.25)), 1);
        s.maser.activate(s, 10);
    };
    test::expectError([&] { computeInitialForces(shaped); }, {"maser", "superquadric particles", "not supported"});
}

// Seeding: at activation the first box length of the chute gets a copy of every mobile particle
// of the box, shifted by the box length, of the chute species, with its velocity and spin; the
// box's fixed particles are not copied.
TEST(MaserBoundary, ActivationSeedsTheChuteWithTheBoxsFlow) {
    MaserScene run;
    run.arrange = [](MaserScene& s) {
        s.scene().addParticle(Vec3(-7, 1, 0), 0.4, 1, Vec3(0.5, 0, 0.1), Vec3(0, 2, 0));
        s.scene().addParticle(Vec3(-2, 3, 0), 0.3, 1, Vec3(0.2, 0, 0));
        s.scene().addFixedParticle(Vec3(-5, 2, -1), 0.5, 1);
        s.maser.activate(s, 30);
    };
    computeInitialForces(run);
    const ParticleStore& p = run.scene().particles();
    ASSERT_EQ(p.size(), 5u);
    EXPECT_EQ(run.maser.seeded(), 2);
    EXPECT_DOUBLE_EQ(run.maser.seededMass(), p.mass[run.scene().slotOf(0)] + p.mass[run.scene().slotOf(1)]);
    for (std::size_t k = 0; k < 2; ++k) {
        const std::size_t copy = run.scene().slotOf(3 + k), original = run.scene().slotOf(k);
        EXPECT_EQ(p.species[copy], 0u);
        EXPECT_EQ(p.position[copy], p.position[original] + Vec3(10, 0, 0));
        EXPECT_EQ(p.velocity[copy], p.velocity[original]);
        EXPECT_EQ(p.angularVelocity[copy], p.angularVelocity[original]);
        EXPECT_EQ(p.mass[copy], p.mass[original]);
    }
    EXPECT_EQ(run.maser.crossings(), 0);
}

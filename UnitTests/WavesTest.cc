// Several steps per pass (StepperTuning::setWaves, Contacts/WaveSchedule.h) change no physics: a
// chute advanced in waves follows the trajectory of single steps to round-off (the forces of a
// particle are summed in another order), through list builds, the periodic faces, fixed
// particles, wall candidates and the seams between strips.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "ContactTestScenes.h"
#include "IO/LammpsDataFile.h"
#include "Integration/Integrator.h"

using namespace talus;
using namespace talus::test;

namespace {

// The benchmark's chute (Theory/Chutes.md "The calibration chute (periodic)",
// Drivers/Benchmarks/PeriodicChuteBenchmark): a start file of the peers (the settled bed or the
// developed flow, 20 x 10, base spheres fixed) copied twice along y, 24 degrees, on a flat wall
// just below the base; one linear law for all pairs.
void benchmarkChute(TestScene& s, const std::string& file) {
    const LammpsData bed = readLammpsData(std::string(TALUS_SHARED_DIR) + "/peers/data/" + file);
    const Vec3 size = bed.hi - bed.lo;
    s.scene().setDomain(bed.lo, bed.lo + Vec3(size.x(), 2 * size.y(), size.z()));
    s.scene().setPeriodic(true, true, false);
    s.scene().setGravity(Vec3(std::sin(degrees(24)), 0, -std::cos(degrees(24))));
    const auto law = LinearSpringDashpot::fromCollision(0.005, 0.88, 0.25).withFriction(0.5);
    const auto grain = s.scene().addSpecies("grain", unitMassDensity, law);
    s.scene().addWall(Vec3::UnitZ(), Vec3(0, 0, -0.5), grain);
    for (int copy = 0; copy < 2; ++copy)
        for (const LammpsAtom& a : bed.atoms) {
            const Vec3 x = a.position + Vec3(0, copy * size.y(), 0);
            if (a.type == 1)
                s.scene().addFixedParticle(x, a.diameter / 2, grain);
            else
                s.scene().addParticle(x, a.diameter / 2, grain, a.velocity, a.angularVelocity);
        }
}

struct Difference {
    double position = 0, velocity = 0, angularVelocity = 0;
};

// The largest differences between two runs, particle by particle (by id: slots follow the order).
Difference largestDifference(const TestScene& a, const TestScene& b) {
    Difference d;
    const ParticleStore &p = a.scene().particles(), &q = b.scene().particles();
    EXPECT_EQ(p.size(), q.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::size_t j = b.scene().slotOf(p.id[i]);
        d.position = std::max(d.position, a.state().domain.nearestImage(p.position[i] - q.position[j]).norm());
        d.velocity = std::max(d.velocity, (p.velocity[i] - q.velocity[j]).norm());
        d.angularVelocity = std::max(d.angularVelocity, (p.angularVelocity[i] - q.angularVelocity[j]).norm());
    }
    return d;
}

// The slots whose position, velocity or spin differ in any bit between two runs (with the same
// particles in the same slots; every slot if their numbers differ).
std::uint64_t stepsInWaves(const TestScene& s) { return s.integrator().statistics().waves.stepsInWaves; }

std::size_t slotsThatDiffer(const TestScene& one, const TestScene& other) {
    const ParticleStore &a = one.scene().particles(), &b = other.scene().particles();
    if (a.size() != b.size()) return std::max(a.size(), b.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        differ += !(sameBits(a.position[i], b.position[i]) && sameBits(a.velocity[i], b.velocity[i]) &&
                    sameBits(a.angularVelocity[i], b.angularVelocity[i]));
    return differ;
}

void expectSameTrajectory(const std::string& file, int steps, int stripColumns, std::uint64_t leastBuilds) {
    const double dt = 1e-4;
    const int run = 1000;
    TestScene waves, single;
    waves.setup = single.setup = [file](TestScene& s) { benchmarkChute(s, file); };
    waves.settings().skin = 0.2, single.settings().skin = 0.2;
    waves.settings().stepper.setWaves(steps, stripColumns);
    single.settings().stepper.waves = StepperTuning::Waves::off;  // (compared with single steps)
    waves.runFor(dt, run * dt);
    single.runFor(dt, run * dt);
    const Difference d = largestDifference(waves, single);
    std::printf("[ measured ] %s, waves of %d steps, strips of %d columns: %llu of %d steps in waves, %llu list builds; "
                "largest difference from single steps: position %.2e, velocity %.2e, angular velocity %.2e\n",
                file.c_str(), steps, stripColumns, static_cast<unsigned long long>(stepsInWaves(waves)), run,
                static_cast<unsigned long long>(waves.state().pairList.builds), d.position, d.velocity,
                d.angularVelocity);
    EXPECT_GT(stepsInWaves(waves), static_cast<std::uint64_t>(run / 2)) << "most steps should be in waves";
    EXPECT_GE(waves.state().pairList.builds, leastBuilds) << "the test needs list builds between waves";
    EXPECT_GT(single.contactSummary().contacts, 2000u) << "and the spheres in contact";
    // Round-off grows through the collisions of 1000 steps; a pair computed at the wrong step, or
    // a particle advanced with a force missing, differs by more than 1e-6 (velocities of order 1).
    EXPECT_LT(d.position, 1e-9);
    EXPECT_LT(d.velocity, 1e-7);
    EXPECT_LT(d.angularVelocity, 1e-6);
}

}  // namespace

// (The box holds 16 x 16 cells: two strips of 8 columns, or one of 16.)
TEST(Waves, FourStepsInTwoStripsFollowSingleStepsInTheFlow) { expectSameTrajectory("chute_B_flowing.data", 4, 8, 3); }

TEST(Waves, EightStepsInOneStripFollowSingleStepsFromTheSettledBed) {
    expectSameTrajectory("chute_B_settled.data", 8, 16, 1);
}

// The schedule over the near list (NearPairs, made anew as the particles move) computes the
// pairs of the whole list's schedule that can touch, in the same order: the same trajectory to
// the bit, through the near list's remakes and a list build.
TEST(Waves, OverTheNearListFollowTheWholeListBitwise) {
    const double dt = 1e-4;
    TestScene overNear, overAll;
    overNear.setup = [](TestScene& s) { benchmarkChute(s, "chute_B_flowing.data"); };
    overAll.setup = [](TestScene& s) {
        benchmarkChute(s, "chute_B_flowing.data");
        s.settings().stepper.nearSkinFraction = 0;  // (no near list)
    };
    for (TestScene* s : {&overNear, &overAll}) s->settings().skin = 0.2, s->settings().stepper.setWaves(4, 8), s->runFor(dt, 1000 * dt);
    EXPECT_GT(overNear.state().pairList.near.makes, 2u) << "the test needs the near list remade between waves";
    EXPECT_EQ(overAll.state().pairList.near.makes, 0u);
    EXPECT_GE(overNear.state().pairList.builds, 3u);
    EXPECT_GT(stepsInWaves(overNear), 900u);
    EXPECT_EQ(stepsInWaves(overNear), stepsInWaves(overAll));
    EXPECT_EQ(slotsThatDiffer(overNear, overAll), 0u) << "particles whose state differs between the schedules";
}

// Where the list has no room left for the next wave, it is built anew ahead of it
// (WaveStepper::stepsNext): the flow goes on in waves through its list builds, rather than in
// single steps until each build (980 of 1000 steps here in waves).
TEST(Waves, TheListIsBuiltAnewAheadOfAWaveItCannotHold) {
    const double dt = 1e-4;
    TestScene s;
    s.setup = [](TestScene& scene) { benchmarkChute(scene, "chute_B_flowing.data"); };
    s.settings().skin = 0.2, s.settings().stepper.setWaves(4, 8), s.runFor(dt, 1000 * dt);
    EXPECT_GE(s.state().pairList.builds, 3u) << "the test needs list builds within the run";
    EXPECT_EQ(stepsInWaves(s), 1000u);
}

// ... but not where a new list would have no room for a wave either (a skin too thin for the
// speeds): single steps then rebuild as they need, as without waves, not before every step.
TEST(Waves, ASkinTooThinForWavesLeavesTheBuildsToSingleSteps) {
    const double dt = 1e-4;
    TestScene waves, single;
    waves.setup = single.setup = [](TestScene& scene) { benchmarkChute(scene, "chute_B_flowing.data"); };
    waves.settings().skin = 0.002, single.settings().skin = 0.002;
    waves.settings().stepper.setWaves(4, 8);
    single.settings().stepper.waves = StepperTuning::Waves::off;
    waves.runFor(dt, 200 * dt);
    single.runFor(dt, 200 * dt);
    EXPECT_EQ(stepsInWaves(waves), 0u);
    EXPECT_GT(single.state().pairList.builds, 10u) << "the test needs a skin that takes frequent builds";
    EXPECT_LE(waves.state().pairList.builds, single.state().pairList.builds + single.state().pairList.builds / 10);
}

// A driver's hook that moves the particles by hand between waves (each by up to 0.02 along each
// axis, so that pairs left out of the near list, 0.03 wide, come within reach): the next wave
// finds the positions changed and makes the near list anew (Simulation::checkPositionsFound),
// so the run follows the whole list's waves to the bit.
TEST(Waves, OverTheNearListFollowParticlesMovedByHand) {
    const double dt = 1e-4;
    const auto jiggle = [](TestScene& s) {
        if (s.state().step != 400) return;  // (a wave ends there: the hook runs once per wave)
        std::mt19937 random(3);
        std::uniform_real_distribution<double> within(-0.02, 0.02);
        ParticleStore& p = s.scene().particles();
        for (std::uint64_t id = 0; id < p.size(); ++id) {
            const std::size_t i = s.scene().slotOf(id);
            if (!p.fixed[i]) p.position[i] += Vec3(within(random), within(random), within(random));
        }
    };
    TestScene overNear, overAll;
    overNear.setup = [](TestScene& s) { benchmarkChute(s, "chute_B_flowing.data"); };
    overAll.setup = [](TestScene& s) {
        benchmarkChute(s, "chute_B_flowing.data");
        s.settings().stepper.nearSkinFraction = 0;  // (no near list)
    };
    for (TestScene* s : {&overNear, &overAll})
        s->afterStep = jiggle, s->settings().skin = 0.2, s->settings().stepper.setWaves(4, 8), s->runFor(dt, 600 * dt);
    EXPECT_GT(stepsInWaves(overNear), 500u);
    EXPECT_EQ(stepsInWaves(overNear), stepsInWaves(overAll));
    EXPECT_EQ(slotsThatDiffer(overNear, overAll), 0u) << "particles whose state differs between the lists";
}

// Two spheres set down overlapping on the settled bed fly apart faster than a wave predicts from
// the bed at rest, the lower into the bed: past the near list's allowance within the wave, the
// wave goes on over the whole list, to the bit as the whole list's waves do.
TEST(Waves, GoOnOverTheWholeListWhenAParticleOutrunsTheNearList) {
    const double dt = 1e-4;
    const auto scene = [](TestScene& s, double nearSkinFraction) {
        benchmarkChute(s, "chute_B_settled.data");
        s.settings().maxInitialOverlapFraction = s.settings().maxOverlapFraction = 0.5;
        // The top sphere of the bed near (5, 5); just above it (0.003 apart), the pair, one
        // above the other: the lower is driven into the bed.
        const ParticleStore& p = s.scene().particles();
        std::size_t top = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
            if (std::abs(p.position[i].x() - 5) < 1 && std::abs(p.position[i].y() - 5) < 1 &&
                p.position[i].z() > p.position[top].z())
                top = i;
        const std::size_t grain = 0;  // (benchmarkChute's one species)
        const Vec3 lower = p.position[top] + Vec3(0, 0, p.radius[top] + 0.5 + 0.003);
        s.scene().addParticle(lower, 0.5, grain);
        s.scene().addParticle(lower + Vec3(0, 0, 0.8), 0.5, grain);  // (overlapping by 40% of the radius)
        s.settings().stepper.nearSkinFraction = nearSkinFraction;
    };
    TestScene overNear, overAll;
    overNear.setup = [&](TestScene& s) { scene(s, 0.01); };
    overAll.setup = [&](TestScene& s) { scene(s, 0); };
    for (TestScene* s : {&overNear, &overAll}) s->settings().skin = 0.2, s->settings().stepper.setWaves(4, 8), s->runFor(dt, 200 * dt);
    EXPECT_GT(overNear.integrator().statistics().waves.offTheNearList, 0u) << "the test needs a wave to outrun the near list";
    EXPECT_GT(stepsInWaves(overNear), 100u);
    EXPECT_EQ(stepsInWaves(overNear), stepsInWaves(overAll));
    EXPECT_EQ(slotsThatDiffer(overNear, overAll), 0u) << "particles whose state differs between the lists";
}

namespace {

// The tangential springs and states of the listed pairs and wall candidates, by ids, that differ
// in any bit between two runs (all of them if their numbers differ).
std::size_t historiesThatDiffer(const TestScene& one, const TestScene& other) {
    const std::vector<CarriedHistory> a = one.state().pairList.carriedHistories(one.scene().particles());
    const std::vector<CarriedHistory> b = other.state().pairList.carriedHistories(other.scene().particles());
    if (a.size() != b.size()) return std::max(a.size(), b.size());
    std::size_t differ = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        differ += !(a[k].a == b[k].a && a[k].b == b[k].b && a[k].history.state == b[k].history.state &&
                    sameBits(a[k].history.spring, b[k].history.spring) &&
                    sameBits(a[k].history.lastNormalForce, b[k].history.lastNormalForce));
    return differ;
}

}  // namespace

// The top sphere of the settled bed thrown upwards at 200 (the bed's speeds are below 1; with
// dt = 1e-4 it moves 0.02 a step against half the list's reach, about 0.1) after the wave that
// ends at step 96: the next wave, predicted from the speeds of the one before, finds within its
// steps that the sphere has moved past the list's allowance. It is rolled back to its start and
// its 8 steps redone in single steps, which build the list anew. The run then equals to the bit
// a run that took single steps from step 96: the wave's start is put back to the bit (every
// array the wave changed that a single step reads, WaveUndo.h), so the redone steps are single
// steps from that state; the run compared with turns the drift pass off at step 96, which turns
// the waves off too but keeps their list order at each build, and steps pass by pass, which
// give the drift pass's trajectories to the bit (PairListTest.cc, DriftInOnePassChangesNothing).
TEST(Waves, AWaveThatOutrunsTheListIsRolledBackAndRedoneInSingleSteps) {
    const double dt = 1e-4;
    const int throwAt = 96, waveSteps = 8;
    std::uint64_t buildsAtThrow = 0;
    const auto throwTopSphere = [&](TestScene& s, bool thenSingleSteps) {
        if (s.state().step != throwAt) return;
        ParticleStore& p = s.scene().particles();
        std::size_t top = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
            if (p.position[i].z() > p.position[top].z()) top = i;
        p.velocity[top] = Vec3(0, 0, 200);
        if (thenSingleSteps) s.settings().stepper.driftPass = false;
        buildsAtThrow = s.state().pairList.builds;
    };
    TestScene rolledBack, singleSteps;
    rolledBack.setup = singleSteps.setup = [](TestScene& s) { benchmarkChute(s, "chute_B_settled.data"); };
    rolledBack.afterStep = [&](TestScene& s) { throwTopSphere(s, false); };
    singleSteps.afterStep = [&](TestScene& s) { throwTopSphere(s, true); };
    for (TestScene* s : {&rolledBack, &singleSteps}) {
        s->settings().skin = 0.2, s->settings().stepper.setWaves(waveSteps, 16);
        s->runFor(dt, (throwAt + waveSteps) * dt);
    }
    const WaveStepper::Statistics& waves = rolledBack.integrator().statistics().waves;
    EXPECT_EQ(waves.rolledBack, 1u);
    EXPECT_EQ(waves.stepsInWaves, static_cast<std::uint64_t>(throwAt)) << "every wave before the throw goes through";
    EXPECT_EQ(stepsInWaves(singleSteps), static_cast<std::uint64_t>(throwAt));
    EXPECT_GT(singleSteps.state().pairList.builds, buildsAtThrow) << "the test needs the steps after the throw to build the list";
    EXPECT_EQ(rolledBack.state().pairList.builds, singleSteps.state().pairList.builds);
    EXPECT_EQ(rolledBack.state().step, singleSteps.state().step);
    EXPECT_TRUE(sameBits(rolledBack.state().time, singleSteps.state().time));
    EXPECT_EQ(slotsThatDiffer(rolledBack, singleSteps), 0u) << "particles whose state differs from single steps";
    EXPECT_EQ(historiesThatDiffer(rolledBack, singleSteps), 0u) << "contact histories that differ from single steps";
    EXPECT_GT(rolledBack.state().pairList.carriedHistories(rolledBack.scene().particles()).size(), 1000u)
        << "the test needs contacts with springs";
}

// Strips eight columns wide per step of the wave unless a width is asked for (why that width:
// Documentation/TimeSkewing.md, "Strip width").
TEST(Waves, StripsFollowTheStepsUnlessAWidthIsGiven) {
    TestScene s;
    s.settings().stepper.setWaves(8);
    EXPECT_EQ(s.settings().stepper.stripColumns(), 64);
    s.settings().stepper.setWaves(12);
    EXPECT_EQ(s.settings().stepper.stripColumns(), 96);
    s.settings().stepper.setWaves(12, 40);
    EXPECT_EQ(s.settings().stepper.stripColumns(), 40);
    s.settings().stepper.setWaves(8);  // (the width asked for stays)
    EXPECT_EQ(s.settings().stepper.stripColumns(), 40);
}

TEST(Waves, RefuseBadSettings) {
    TestScene s;
    expectError([&] { s.settings().stepper.setWaves(0); }, {"waves of 1 to 255 steps"});
    expectError([&] { s.settings().stepper.setWaves(4, 0); }, {"strips of waves need at least one column"});
}

namespace {

// The benchmark's flow run 200 steps with an output at the end (flags: the first run's extra
// ones), restarted from its file to 400 (its settings those of the file and the defaults), and
// run 400 steps without a break; tuning: the first and the uninterrupted run's stepper settings.
// The restarted run must go on in waves and equal the uninterrupted one to the bit.
void expectRestartInWavesBitwise(const std::string& name, const std::function<void(StepperTuning&)>& tuning,
                                 const std::vector<std::string>& firstFlags) {
    const auto endOf = [](int steps) {
        std::ostringstream t;
        t.precision(17);
        t << steps * 1e-4;
        return t.str();
    };
    TestScene first, restarted, uninterrupted;
    first.setup = uninterrupted.setup = [](TestScene& s) { benchmarkChute(s, "chute_B_flowing.data"); };
    for (TestScene* s : {&first, &restarted, &uninterrupted}) s->settings().skin = 0.2, s->settings().progressInterval = 1e9;
    tuning(first.settings().stepper), tuning(uninterrupted.settings().stepper);
    first.settings().name = name;
    std::vector<std::string> flags{"--dt", endOf(1), "--end-time", endOf(200), "--vtu", "off", "--fstat", "off"};
    flags.insert(flags.end(), firstFlags.begin(), firstFlags.end());
    first.solveOrThrow(flags);
    restarted.solveOrThrow({"--restart", name + ".restart", "--end-time", endOf(400), "--files", "off"});
    flags = {"--dt", endOf(1), "--end-time", endOf(400), "--files", "off"};
    flags.insert(flags.end(), firstFlags.begin(), firstFlags.end());
    uninterrupted.solveOrThrow(flags);
    EXPECT_GT(stepsInWaves(first), 150u) << "the first run should take waves";
    EXPECT_GT(stepsInWaves(restarted), 150u) << "the restarted run should go on in waves";
    EXPECT_EQ(stepsInWaves(restarted) + stepsInWaves(first), stepsInWaves(uninterrupted));
    EXPECT_EQ(slotsThatDiffer(restarted, uninterrupted), 0u) << "particles whose state differs from the uninterrupted run";
}

}  // namespace

// A run in waves restarted from its file continues bitwise as the uninterrupted run: waves start
// at multiples of their steps, and the restart remakes the schedule of the list it kept.
TEST(Waves, RestartedRunContinuesBitwise) {
    expectRestartInWavesBitwise("waves_restart", [](StepperTuning& t) { t.setWaves(4, 8); }, {});
}

// The same with waves taken by default (--waves auto, here from 6000 particles, so that the 6400
// of the test take them): the restart file keeps the steps the run took, and the restarted run,
// whose tuning is the default again (--waves-from 20000), takes them as the saved run did.
TEST(Waves, RestartedAutomaticWavesContinueBitwise) {
    expectRestartInWavesBitwise("auto_waves_restart", [](StepperTuning&) {}, {"--waves-from", "6000"});
}

// Kernel/Sampling, the driver helpers: the sampling clock, whole-scene sums and extrema, running
// sums, timed events and the table form of SeriesFile, each on one rank (the sums on two ranks:
// SelfTests/Parallel, the maser chute's mass balance and RotatingDrum's count and mass).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "IO/SeriesFile.h"
#include "Sampling/ParticleSums.h"
#include "Sampling/RunningSums.h"
#include "Sampling/SamplingClock.h"
#include "Sampling/TimedEvents.h"
#include "TestHelpers.h"

namespace talus {
namespace {

using test::SceneSimulation;

// Three spheres in free flight (no gravity, apart: no contacts), of density 6/pi: mass d^3.
void threeSpheres(SceneSimulation& s) {
    s.scene().setDomain(Vec3(-10, -10, -10), Vec3(10, 10, 10));
    s.scene().setGravity(Vec3::Zero());
    const std::size_t sp = s.scene().addSpecies("a", 6 / pi, LinearSpringDashpot::fromCollision(0.5, 0.5, 0.5));
    s.scene().addParticle(Vec3(-2, 0, 0), 0.5, sp, Vec3(1, 0, 0));   // mass 1
    s.scene().addParticle(Vec3(2, 1, 0), 1.0, sp, Vec3(0, -1, 0));   // mass 8
    s.scene().addFixedParticle(Vec3(0, 5, 0), 0.5, sp);              // fixed, mass 1
}

// The first part of a restart test: `driver` runs with steps of 0.01 to `end` and writes
// NAME.restart (no .vtu frames, no progress lines).
void runUntil(SceneSimulation& driver, const std::string& name, double end) {
    driver.settings().name = name;
    driver.settings().timeStep = 0.01;
    driver.settings().endTime = end;
    driver.settings().progressInterval = 1e9;
    driver.solveOrThrow({"--vtu", "off"});
}

// Every 0.1 over (0, 1] with steps of 0.01: 10 samples, one at each multiple of 0.1 (to within
// half a step: the time is a sum of steps), none at t = 0.
struct ClockDriver : SceneSimulation {
    SamplingClock clock{*this, "test"};
    std::vector<double> sampled;
    ClockDriver() {
        setup = threeSpheres;
        afterStep = [this](SceneSimulation&) {
            if (clock.every(0.1)) sampled.push_back(time());
        };
    }
};

TEST(SamplingClock, OncePerIntervalAtTheMultiples) {
    ClockDriver d;
    d.runFor(0.01, 1.0);
    ASSERT_EQ(d.sampled.size(), 10u);
    for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(d.sampled[k], 0.1 * (k + 1), 0.005) << k;
    EXPECT_THROW(d.clock.every(0), Error);
}

// The next sample time is in the restart file: a run restarted at t = 0.55 samples at 0.6 ... 1.0
// as the uninterrupted run does, and its clock starts with the saved next sample time.
TEST(SamplingClock, KeptAcrossARestart) {
    ClockDriver first;
    first.setup = threeSpheres;
    runUntil(first, "clock_restart", 0.55);
    ASSERT_EQ(first.sampled.size(), 5u);
    ClockDriver restarted;
    restarted.solveOrThrow({"--restart", "clock_restart.restart", "--end-time", "0.55", "--files", "off"});
    EXPECT_DOUBLE_EQ(restarted.clock.nextSampleTime(), first.clock.nextSampleTime());
    EXPECT_NEAR(restarted.clock.nextSampleTime(), 0.6, 1e-12);
}

// Totals over all mobile spheres: count 2, mass 1 + 8, volume pi/6 (1 + 8), momentum
// (1, -8, 0), centre of mass (1 (-2, 0, 0) + 8 (2, 1, 0)) / 9, kinetic energy 1/2 + 8/2 (no
// rotation); over a box or a species; extrema of x.
TEST(ParticleSums, TotalsAndExtremaOfKnownSpheres) {
    SceneSimulation s;
    s.setup = threeSpheres;
    s.runFor(1e-3, 0);
    const Totals t = totalsOver(s);
    EXPECT_EQ(t.count, 2);
    EXPECT_DOUBLE_EQ(t.mass, 9);
    EXPECT_NEAR(t.volume, pi / 6 * 9, 1e-12);
    EXPECT_NEAR((t.momentum - Vec3(1, -8, 0)).norm(), 0, 1e-12);
    EXPECT_NEAR((t.centreOfMass() - Vec3(14.0 / 9, 8.0 / 9, 0)).norm(), 0, 1e-12);
    EXPECT_DOUBLE_EQ(t.kineticEnergy(), 4.5);
    EXPECT_EQ(t.rotationalEnergy, 0);
    EXPECT_NEAR(t.solidFraction(8000), pi / 6 * 9 / 8000, 1e-15);
    EXPECT_EQ(totalsOver(s, allParticles()).count, 3);
    EXPECT_EQ(totalsOver(s, both(allParticles(), inBox(Vec3(-1, -1, -1), Vec3(3, 6, 1)))).count, 2);
    const ParticleQuantity x = [](const ParticleStore& p, std::size_t i) { return p.position[i].x(); };
    EXPECT_DOUBLE_EQ(maxOver(s, mobileParticles(), x), 2);
    EXPECT_DOUBLE_EQ(minOver(s, mobileParticles(), x), -2);
    EXPECT_EQ(maxOver(s, inBox(Vec3(5, 5, 5), Vec3(6, 6, 6)), x), -INFINITY);
    EXPECT_DOUBLE_EQ(sumOver(s, ofSpecies(0), [](const ParticleStore& p, std::size_t i) { return p.mass[i]; }), 10);
}

// On one rank the gathered copy is the selected particles in slot order, bit for bit.
TEST(ParticleSums, GatherOnOneRankIsACopy) {
    SceneSimulation s;
    s.setup = threeSpheres;
    s.runFor(1e-3, 0.1);
    const ParticleStore g = gatherParticles(s);
    ASSERT_EQ(g.size(), 2u);
    std::size_t k = 0;
    for (std::size_t i = 0; i < s.scene().particles().size(); ++i) {
        if (s.scene().particles().fixed[i]) continue;
        EXPECT_EQ(g.id[k], s.scene().particles().id[i]);
        EXPECT_TRUE(test::sameBits(g.position[k], s.scene().particles().position[i]));
        ++k;
    }
}

// The step integral of m vx of a sphere in free flight over T: its momentum times T, 1 x 1 x 0.5;
// a number added each step: steps x number.
TEST(RunningSums, StepIntegralOfFreeFlight) {
    struct Driver : SceneSimulation {
        RunningSums sums{*this, "sums", 2};
        Driver() {
            setup = threeSpheres;
            afterStep = [this](SceneSimulation&) {
                sums.addStepIntegral(0, mobileParticles(), [](const ParticleStore& p, std::size_t i) {
                    return p.mass[i] * p.velocity[i].x();
                });
                sums.add(1, 2.0);
            };
        }
    } d;
    d.runFor(0.01, 0.5);
    EXPECT_NEAR(d.sums.totals()[0], 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(d.sums.totals()[1], 100);
}

// An event runs once, at the step that reaches its time; after a restart past it, not again,
// and a later one still runs.
struct EventDriver : SceneSimulation {
    TimedEvents& events = scene().addBoundary<TimedEvents>(*this, "events");
    std::vector<double> ranAt;
    EventDriver() {
        setup = threeSpheres;
        events.at(0.25, [this] { ranAt.push_back(time()); });
        events.at(0.75, [this] { ranAt.push_back(time()); });
    }
};

TEST(TimedEvents, RunOnceAndNotAgainAfterARestart) {
    EventDriver first;
    runUntil(first, "events_restart", 0.5);
    ASSERT_EQ(first.ranAt.size(), 1u);
    EXPECT_NEAR(first.ranAt[0], 0.25, 0.005);
    EventDriver restarted;
    restarted.solveOrThrow({"--restart", "events_restart.restart", "--end-time", "1", "--files", "off"});
    ASSERT_EQ(restarted.ranAt.size(), 1u);  // the one at 0.75 only
    EXPECT_NEAR(restarted.ranAt[0], 0.75, 0.005);
    EXPECT_TRUE(restarted.events.done(0));
}

// A table names its columns once and takes one value per column: integers as integers, numbers
// at the precision asked for; a row of the wrong length is an error naming the file.
TEST(SeriesFile, TableWithNamedColumns) {
    struct Driver : SceneSimulation {
        SeriesFile table{*this, "table", {"t", "count", "mass"}, "(a note)"};
        Driver() {
            setup = threeSpheres;
            afterStep = [this](SceneSimulation&) {
                if (step() == 1) table.write({0.125, std::size_t{3}, 1.0 / 3});
            };
        }
    } d;
    d.settings().name = "series_table";
    d.table.setPrecision(4);
    d.runFor(0.01, 0.02);
    std::ifstream in("series_table.table");
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "# t count mass (a note)\n0.125 3 0.3333\n");
    test::expectError([&] { d.table.write({1.0}); }, {"series file 'table': a row of 1 values for 3 columns"});
}

// A run saved before its first line (no file yet: a calibration point killed before its first
// sample) and then restarted starts the file anew: its header, then the restarted run's lines.
TEST(SeriesFile, RestartedBeforeItsFirstLine) {
    struct Driver : SceneSimulation {
        SeriesFile table{*this, "table", {"t"}, ""};
        Driver() {
            setup = threeSpheres;
            afterStep = [this](SceneSimulation&) {
                if (time() > 0.505) table.write({time()});
            };
        }
    };
    std::remove("series_late.table");
    Driver first;
    runUntil(first, "series_late", 0.3);
    Driver restarted;
    restarted.solveOrThrow({"--restart", "series_late.restart", "--end-time", "0.52", "--files", "off"});
    std::ifstream in("series_late.table");
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "# t\n0.51\n0.52\n");
}

}  // namespace
}  // namespace talus

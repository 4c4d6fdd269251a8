// The progress lines count the particle-steps of every step, also when a run reports them a few
// at a time (waves of steps, Documentation/TimeSkewing.md), and print on crossing every 64th step
// whatever the steps between reports; a run whose driver brings its end time forward ends there,
// and its progress lines count to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "IO/Progress.h"
#include "TestHelpers.h"

using namespace talus;

TEST(Progress, CountsEveryStepOfReportsAFewStepsApart) {
    std::ostringstream out;
    Progress progress(out, 1e9);
    progress.start("run", 0, 1, 100, 10);
    progress.update(0.01, 1, 10);   // a single step
    progress.update(0.09, 9, 10);   // a wave of 8
    progress.update(0.17, 17, 20);  // another, after particles were added
    EXPECT_EQ(progress.particleSteps(), 10 + 8 * 10 + 8 * 20);
}

TEST(Progress, PrintsOnCrossingTheSixtyFourthStepBetweenReports) {
    std::ostringstream out;
    Progress progress(out, 0);  // every time it reads the clock
    progress.start("run", 0, 1, 200, 10);
    const auto lines = [&] {
        std::size_t n = 0;
        for (char c : out.str()) n += c == '\n';
        return n;
    };
    // Waves of 8 from step 3 (a restarted run): reports at 3, 11, 19, ..., never at a multiple of
    // 64.
    progress.update(0.03, 3, 10);
    for (std::uint64_t k = 11; k <= 131; k += 8) progress.update(0.01 * static_cast<double>(k), k, 10);
    EXPECT_EQ(lines(), 1 + 2u) << out.str();  // the start line, and one each past steps 64 and 128
}

TEST(Progress, CountsToAnEndBroughtForward) {
    std::ostringstream out;
    Progress progress(out, 0);
    progress.start("run", 0, 1e9, 100000000000, 10);
    progress.update(0.64, 64, 10);
    EXPECT_NE(out.str().find("t = 0.64 / 1e+09 (  0.0%)"), std::string::npos) << out.str();
    progress.moveEnd(2, 200);
    progress.update(1.28, 128, 10);
    EXPECT_NE(out.str().find("t = 1.28 / 2 ( 64.0%)"), std::string::npos) << out.str();
}

// A driver that learns its end during the run (RotatingDrum --rotations) sets an earlier end
// time from its hook: the run stops there, at the step nearest to it, not at the end it started with.
TEST(Progress, ARunEndsAtTheEndTimeItsDriverBroughtForward) {
    test::SceneSimulation run;
    run.setup = [](test::SceneSimulation& s) {
        s.scene().addSpecies("grains", 1, LinearSpringDashpot::fromCollision(0.05, 0.5, 0.5));
        s.scene().addParticle(Vec3::Zero(), 0.5, 0);
    };
    run.afterStep = [](test::SceneSimulation& s) {
        if (s.time() >= 0.25) s.settings().endTime = std::min(s.settings().endTime, 0.5);
    };
    run.runFor(0.01, 100);
    EXPECT_NEAR(run.time(), 0.5, 1e-12);
    // An end brought forward to a time already passed: one more step, the run's last.
    test::SceneSimulation late;
    late.setup = run.setup;
    late.afterStep = [](test::SceneSimulation& s) {
        if (s.time() >= 0.25) s.settings().endTime = std::min(s.settings().endTime, 0.1);
    };
    late.runFor(0.01, 100);
    EXPECT_NEAR(late.time(), 0.26, 1e-12);
}

// Bad input of every kind gives a talus::Error whose message names what is wrong, never a crash
// and never a silent success: particle and species parameters, the time step, initial overlaps,
// blow-ups, command-line flags, and truncated or corrupted restart files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "Formats/RestartFormat.h"
#include "IO/RestartFile.h"
#include "TestHelpers.h"

using namespace talus;
using test::expectError;
using test::SceneSimulation;

namespace {

const double collisionTime = 0.01;
const double nan = std::numeric_limits<double>::quiet_NaN();

// Unit-mass spheres of radius 1/2 (density 6/pi), collision time 0.01 between two of them.
std::size_t addSand(Simulation& s) {
    return s.scene().addSpecies("sand", 6 / pi, LinearSpringDashpot::fromCollision(collisionTime, 0.8, 0.5).withFriction(0.4));
}

// A small scene: a floor and a leaning column of six spheres, near enough to be listed as pairs
// but not touching; dt is a safe tc/50.
void smallScene(SceneSimulation& s) {
    s.settings().timeStep = collisionTime / 50;
    const auto sand = addSand(s);
    s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), sand);
    for (int k = 0; k < 6; ++k) s.scene().addParticle(Vec3(0.1 * k, 0, 0.5 + 1.05 * k), 0.5, sand, Vec3(0.3, 0, 0));
}

// --- particles and species ---

TEST(BadInput, NonPositiveRadius) {
    for (double radius : {0.0, -0.5, nan}) {
        SceneSimulation s;
        const auto sand = addSand(s);
        expectError([&] { s.scene().addParticle(Vec3::Zero(), radius, sand); }, {"radius must be positive", "particle 0"});
        EXPECT_EQ(s.scene().particles().size(), 0u) << "a rejected particle must not be half added";
    }
}

TEST(BadInput, NonPositiveDensity) {
    for (double density : {0.0, -2.0}) {
        SceneSimulation s;
        expectError([&] { s.scene().addSpecies("basalt", density, LinearSpringDashpot{100, 1, 20, 1, 0.5}); },
                    {"basalt", "density must be positive"});
    }
}

TEST(BadInput, NonFinitePosition) {
    SceneSimulation s;
    const auto sand = addSand(s);
    expectError([&] { s.scene().addParticle(Vec3(0, nan, 0), 0.5, sand); }, {"particle 0", "position is not finite"});
    expectError([&] { s.scene().addParticle(Vec3(0, 0, INFINITY), 0.5, sand); }, {"position is not finite"});
    EXPECT_EQ(s.scene().particles().size(), 0u);
}

// --- the run ---

// Settings written by a driver are checked when solve starts, each error naming the setting and
// its flag; settings set in setupInitialConditions are checked before the run as well.
TEST(BadInput, SettingsOutOfRange) {
    struct Case {
        std::function<void(RunSettings&)> set;
        std::vector<std::string> parts;
    };
    const std::vector<Case> cases = {
        {[](RunSettings& c) { c.timeStep = -1e-4; }, {"settings().timeStep (--dt)", "must be positive", "-0.0001"}},
        {[](RunSettings& c) { c.timeStep = nan; }, {"settings().timeStep (--dt)", "must be positive"}},
        {[](RunSettings& c) { c.endTime = -1; }, {"settings().endTime (--end-time)", "must not be negative"}},
        {[](RunSettings& c) { c.outputInterval = -0.5; }, {"settings().outputInterval (--output-interval)"}},
        {[](RunSettings& c) { c.skin = -0.5; }, {"settings().skin (--skin)", "must not be negative"}},
        {[](RunSettings& c) { c.cellSizeRatio = 1; }, {"settings().cellSizeRatio (--cell-size-ratio)", "greater than 1"}},
        {[](RunSettings& c) { c.name = "two words"; }, {"settings().name (--name)", "one word"}},
        {[](RunSettings& c) { c.progressInterval = 0; }, {"settings().progressInterval (--progress-interval)"}},
        {[](RunSettings& c) { c.maxOverlapFraction = -1; }, {"settings().maxOverlapFraction (--max-overlap)"}},
        {[](RunSettings& c) { c.maxInitialOverlapFraction = 0; }, {"settings().maxInitialOverlapFraction"}},
        {[](RunSettings& c) { c.shapeTolerance = 0.1; }, {"settings().shapeTolerance (--shape-tolerance)", "[1e-15, 1e-3]"}},
        {[](RunSettings& c) { c.stepper.waveSteps = 0; }, {"settings().stepper.waveSteps (--wave-steps)", "1 to 255"}},
        {[](RunSettings& c) { c.stepper.nearSkinFraction = 1; },
         {"settings().stepper.nearSkinFraction (--near-skin-fraction)", "[0, 1)"}},
        {[](RunSettings& c) { c.stepper.waves = StepperTuning::Waves::on, c.stepper.waveSteps = 1; },
         {"settings().stepper.waves (--waves) on", "(--wave-steps) is 1"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.parts.front());
        for (bool inSetup : {false, true}) {
            SceneSimulation s;
            s.setup = [&](SceneSimulation& sim) {
                smallScene(sim);
                if (inSetup) c.set(sim.settings());
            };
            if (!inSetup) c.set(s.settings());
            expectError([&] { s.solveOrThrow({"--files", "off"}); }, c.parts);  // (no flag that overrides them)
        }
    }
    // The defaults pass, the automatic skin among them; no time step at all is named as such.
    SceneSimulation fine;
    fine.setup = smallScene;
    EXPECT_NO_THROW(fine.solveOrThrow(test::stepsWithoutFiles(collisionTime / 50, 1)));
    EXPECT_GT(fine.settings().skin, 0) << "the automatic skin is set at the start";
    SceneSimulation noStep;
    noStep.setup = [](SceneSimulation& sim) { addSand(sim); };
    expectError([&] { noStep.solveOrThrow({"--end-time", "1", "--files", "off"}); }, {"no time step", "settings().timeStep", "--dt"});
}

TEST(BadInput, TimeStepAboveATenthOfTheCollisionTime) {
    SceneSimulation s;
    s.setup = [](SceneSimulation& sim) {
        smallScene(sim);
        sim.settings().timeStep = collisionTime / 5;
    };
    const std::string message = expectError([&] { s.solveOrThrow(test::stepsWithoutFiles(collisionTime / 5, 1)); },
                                             {"time step", "shortest collision time", "sand"});
    // The message quotes the collision time itself (printed with the default 6 digits).
    std::ostringstream tc;
    tc << collisionTime;
    EXPECT_NE(message.find(tc.str()), std::string::npos) << message;
}

TEST(BadInput, InitialOverlapNamesBothParticles) {
    SceneSimulation s;
    s.setup = [](SceneSimulation& sim) {
        smallScene(sim);  // ids 0 to 5, not touching each other
        const std::size_t sand = 0;  // smallScene's only species
        sim.scene().addParticle(Vec3(5, 5, 5), 0.5, sand);                // id 6
        sim.scene().addParticle(Vec3(5, 5, 5 + 2 * 0.5 * 0.9), 0.5, sand);  // id 7, overlapping by 10% of r
    };
    expectError([&] { s.solveOrThrow(test::stepsWithoutFiles(collisionTime / 50, 1)); },
                {"initial conditions", "particle id 6", "particle id 7", "overlap"});
}

TEST(BadInput, VelocityBecomingNaNIsABlowUpNamingTheParticle) {
    SceneSimulation s;
    s.setup = [](SceneSimulation& sim) { smallScene(sim); };
    const std::uint64_t poisonedId = 4;
    s.afterStep = [&](SceneSimulation& sim) {
        if (sim.step() != 3) return;
        for (std::size_t i = 0; i < sim.scene().particles().size(); ++i)
            if (sim.scene().particles().id[i] == poisonedId) sim.scene().particles().velocity[i].x() = nan;
    };
    expectError([&] { s.solveOrThrow(test::stepsWithoutFiles(collisionTime / 50, 10)); },
                {"blow-up", "particle id " + std::to_string(poisonedId), "non-finite"});
    EXPECT_EQ(s.step(), 4u) << "the run must stop at the first step that sees the NaN";
}

// --- command line ---

TEST(BadInput, CommandLineFlags) {
    struct Case {
        std::vector<std::string> flags;
        std::vector<std::string> expected;
    };
    const std::vector<Case> cases = {
        {{"--bogus", "1"}, {"unknown flag", "--bogus"}},
        {{"--dt"}, {"--dt", "needs a value"}},
        {{"--end-time", "1", "--output-interval"}, {"--output-interval", "needs a value"}},
        {{"--dt", "abc"}, {"--dt", "'abc'", "not a finite number"}},
        {{"--dt", "1e-3x"}, {"--dt", "'1e-3x'"}},
        {{"--dt", ""}, {"--dt", "not a finite number"}},
        {{"--end-time=nan"}, {"--end-time", "'nan'"}},
        {{"--skin", "1e999"}, {"--skin", "'1e999'"}},
        {{"--dt", "-1"}, {"--dt", "must be positive"}},
        {{"--files", "maybe"}, {"--files", "'maybe'", "on or off"}},
        {{"--layers", "2.5"}, {"--layers", "'2.5'", "not an integer"}},
        {{"--layers", "99999999999"}, {"--layers", "not an integer"}},
        {{"--name", "two words"}, {"name", "one word"}},
        {{"stray"}, {"unexpected argument 'stray'"}},
        {{"--rank-grid", "2x2"}, {"--rank-grid", "'2x2'", "three positive whole numbers"}},
        {{"--waves", "sometimes"}, {"--waves", "auto, on or off", "'sometimes'"}},
        {{"--waves-from", "-5"}, {"--waves-from", "must not be negative"}},
        {{"--near-skin-fraction", "-0.1"}, {"--near-skin-fraction", "[0, 1)"}},
        {{"--shape-tolerance", "0"}, {"--shape-tolerance", "[1e-15, 1e-3]"}},
        {{"--sweep-frame", "moving"}, {"--sweep-frame", "flow or off", "'moving'"}},
        {{"--sweep", "vector"}, {"--sweep", "auto, scalar, lanes or gathers", "'vector'"}},
        {{"--rank-grid", "0x1x1"}, {"--rank-grid", "'0x1x1'"}},
        {{"--rank-grid", "2x1x1x"}, {"--rank-grid", "'2x1x1x'"}},
        {{"--rank-grid", "-1x1x1"}, {"--rank-grid", "'-1x1x1'"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.flags.front());
        SceneSimulation s;
        int layers = 3;
        s.run().addFlag("layers", "number of layers", layers);
        bool setUp = false;
        s.setup = [&](SceneSimulation& sim) {
            setUp = true;
            smallScene(sim);
        };
        expectError([&] { s.solveOrThrow(c.flags); }, c.expected);
        EXPECT_FALSE(setUp) << "bad flags must be rejected before the scene is built";
    }
}

// A rank grid that does not multiply to the number of ranks (one, here) stops the run at its
// start, naming the flag and both numbers.
TEST(BadInput, RankGridMustMatchTheRanks) {
    SceneSimulation s;
    s.setup = smallScene;
    expectError([&] { s.solveOrThrow({"--rank-grid", "2x1x1", "--end-time", "0.001", "--files", "off"}); },
                {"rank grid 2x1x1 has 2 cells", "the run has 1 ranks", "--rank-grid"});
}

// The other side of the checks above: unusual but valid values pass.
TEST(BadInput, UnusualButValidFlagsAreAccepted) {
    SceneSimulation s;
    int layers = 3;
    s.run().addFlag("layers", "number of layers", layers);
    s.setup = [](SceneSimulation& sim) { smallScene(sim); };
    s.solveOrThrow({"--dt=2e-4", "--end-time", "+4E-4", "--skin", "4.9406564584124654e-324", "--layers", "-7",
                    "--files=off", "--progress-interval", "0x1p-3"});
    EXPECT_EQ(s.step(), 2u);
    EXPECT_EQ(layers, -7);
    EXPECT_EQ(s.settings().skin, std::numeric_limits<double>::denorm_min());
    EXPECT_EQ(s.settings().progressInterval, 0.125);
}

// --- restart files ---

// A small run that writes its restart file; returns the file's path.
std::string writeValidRestart(const std::string& name) {
    SceneSimulation s;
    s.setup = [](SceneSimulation& sim) { smallScene(sim); };
    s.settings().name = name;
    s.settings().writeVtu = false;
    const double dt = collisionTime / 50;
    s.solveOrThrow({"--end-time", std::to_string(20 * dt), "--output-interval", std::to_string(10 * dt)});
    EXPECT_GT(s.state().pairList.pairs.size(), 0u) << "the corruption cases need a listed pair";
    return name + ".restart";
}

// Reads the restart file both ways a user can: the function and the --restart flag (continuing
// the run a few steps past where writeValidRestart stopped).
template <class Check>
void readBothWays(const std::string& path, Check&& check) {
    check([&] {
        SimulationState state;
        readRestartFile(path, state);
    });
    check([&] {
        SceneSimulation s;
        s.solveOrThrow({"--restart", path, "--files", "off", "--end-time", std::to_string(25 * collisionTime / 50)});
    });
}

// Every cut of the file is an error naming the file and a line, except the full file (and the
// file that lacks only its final newline, which has lost no data).
TEST(BadInput, TruncatedRestartFile) {
    const std::string full = test::readWholeFile(writeValidRestart("badinput_truncated"));
    ASSERT_GT(full.size(), 1000u);
    ASSERT_EQ(full.back(), '\n');
    const std::string path = "badinput_truncated_cut.restart";
    std::vector<std::size_t> cuts;
    for (std::size_t n = 0; n < 300; ++n) cuts.push_back(n);
    for (std::size_t n = 300; n < full.size() - 300; n += 37) cuts.push_back(n);
    for (std::size_t n = full.size() - 300; n < full.size() - 1; ++n) cuts.push_back(n);
    for (std::size_t n : cuts) {
        SCOPED_TRACE("cut at byte " + std::to_string(n) + " of " + std::to_string(full.size()));
        test::writeWholeFile(path, full.substr(0, n));
        // Only a few cuts also go through a whole Simulation, to keep the test quick.
        if (n % 10 == 0) readBothWays(path, [&](auto read) { expectError(read, {path, " line "}); });
        else expectError([&] { SimulationState state; readRestartFile(path, state); }, {path, " line "});
    }
    for (std::size_t n : {full.size() - 1, full.size()}) {
        test::writeWholeFile(path, full.substr(0, n));
        readBothWays(path, [](auto read) { EXPECT_NO_THROW(read()); });
    }
}

// The line number the reader must report for the byte at position `at`.
int lineOf(const std::string& text, std::size_t at) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// The start of the line that begins with `keyword` (a top-level keyword line).
std::size_t lineStarting(const std::string& text, const std::string& keyword) {
    const std::size_t at = text.find("\n" + keyword + " ");
    EXPECT_NE(at, std::string::npos) << keyword;
    return at + 1;
}

// Replaces the index-th whitespace-separated token of the line starting at lineStart.
std::string replaceToken(std::string text, std::size_t lineStart, int index, const std::string& replacement) {
    std::size_t at = lineStart;
    for (int k = 0;; ++k) {
        at = text.find_first_not_of(' ', at);
        const std::size_t end = text.find_first_of(" \n", at);
        if (k == index) return text.replace(at, end - at, replacement);
        at = end;
    }
}

TEST(BadInput, CorruptedRestartFile) {
    const std::string full = test::readWholeFile(writeValidRestart("badinput_corrupt"));
    const std::string path = "badinput_corrupt_bad.restart";
    const std::size_t timeLine = lineStarting(full, "time");
    const std::size_t wallsLine = lineStarting(full, "walls");
    const std::size_t firstWall = full.find('\n', wallsLine) + 1;
    const std::size_t firstSpecies = full.find('\n', lineStarting(full, "species")) + 1;
    const std::size_t particlesLine = lineStarting(full, "particles");
    const std::size_t firstParticle = full.find('\n', particlesLine) + 1;
    const std::size_t thirdParticle = full.find('\n', full.find('\n', firstParticle) + 1) + 1;
    const std::size_t pairlistLine = lineStarting(full, "pairlist");
    const std::size_t firstPair = full.find('\n', pairlistLine) + 1;
    // A particle line's fields: Formats/RestartFormat.h.
    const int speciesToken = formats::restart::particleSpecies;
    const std::string firstId = full.substr(full.find_first_not_of(' ', firstParticle),
                                            full.find(' ', full.find_first_not_of(' ', firstParticle)) -
                                                full.find_first_not_of(' ', firstParticle));
    struct Case {
        const char* what;
        std::string text;
        std::size_t lineStart;
        std::vector<std::string> expected;
    };
    const std::vector<Case> cases = {
        {"number replaced by text", replaceToken(full, timeLine, 1, "soon"), timeLine, {"bad number 'soon'", "time"}},
        {"number too large for a double", replaceToken(full, timeLine, 1, "1e999"), timeLine, {"bad number '1e999'"}},
        {"number with trailing text", replaceToken(full, firstParticle, 5, "1.5e"), firstParticle, {"bad number '1.5e'"}},
        {"keyword changed", replaceToken(full, lineStarting(full, "gravity"), 0, "gravitation"),
         lineStarting(full, "gravity"), {"expected 'gravity'", "'gravitation'"}},
        {"first keyword changed", replaceToken(full, 0, 0, "Mercury"), 0, {"expected 'Talus'"}},
        {"particle species out of range", replaceToken(full, thirdParticle, speciesToken, "1"), thirdParticle,
         {"species 1 is out of range"}},
        {"negative species", replaceToken(full, thirdParticle, speciesToken, "-1"), thirdParticle, {"species must not be negative, found -1"}},
        {"wall species out of range", replaceToken(full, firstWall, 6, "7"), firstWall, {"wall species 7"}},
        {"wall motion out of range", replaceToken(full, firstWall, 7, "0"), firstWall, {"wall motion out of range"}},
        {"fixed flag not 0 or 1", replaceToken(full, thirdParticle, formats::restart::fixed, "2"), thirdParticle,
         {"fixed flag 2"}},
        {"negative radius", replaceToken(full, thirdParticle, formats::restart::radius, "-0.5"), thirdParticle, {"radius must be positive"}},
        {"pair of a missing particle", replaceToken(full, firstPair, 1, "6"), firstPair, {"pair particle 6"}},
        {"particle count too large", replaceToken(full, particlesLine, 1, "7"), pairlistLine, {"bad count 'pairlist'"}},
        {"unsupported version", replaceToken(full, 0, 2, "99"), 0, {"format version 99"}},
        {"not a finite number", replaceToken(full, lineStarting(full, "gravity"), 3, "nan"),
         lineStarting(full, "gravity"), {"'nan'", "not a finite number"}},
        {"contact law parameter out of range", replaceToken(full, firstSpecies, 3, "0"), firstSpecies,
         {"normal stiffness must be positive"}},
        {"text after the end", full + "more\n", full.size(), {"unexpected text after 'end'"}},
        // Counts that are not whole numbers, or so large that reserving for them would fail
        // (std::bad_alloc, not a message) before the file has shown it lacks the lines.
        {"fractional count", replaceToken(full, particlesLine, 1, "2.5"), particlesLine,
         {"'2.5' for particle count is not a whole number"}},
        {"count written as a large real", replaceToken(full, particlesLine, 1, "1e30"), particlesLine,
         {"'1e30' for particle count is not a whole number"}},
        {"count beyond 64 bits", replaceToken(full, particlesLine, 1, "123456789012345678901234"), particlesLine,
         {"particle count 123456789012345678901234 is out of range"}},
        {"count of 2^32 - 1 particles", replaceToken(full, particlesLine, 1, "4294967295"), pairlistLine,
         {"bad count 'pairlist' for particle id"}},
        // Values no run can have: an inverted domain, a particle without mass, a negative
        // inverse mass, and two particles with one id.
        {"inverted domain", replaceToken(full, lineStarting(full, "domain"), 1, "99"), lineStarting(full, "domain"),
         {"domain: the upper corner must lie above the lower corner"}},
        {"zero mass", replaceToken(full, thirdParticle, formats::restart::mass, "0"), thirdParticle, {"mass must be positive"}},
        {"negative inverse mass", replaceToken(full, thirdParticle, formats::restart::inverseMass, "-2"), thirdParticle,
         {"inverse mass and inverse inertia must not be negative"}},
        {"an id twice", replaceToken(full, thirdParticle, formats::restart::id, firstId), thirdParticle,
         {"particle id " + firstId + " appears twice"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        ASSERT_NE(c.text, full);
        test::writeWholeFile(path, c.text);
        std::vector<std::string> expected = c.expected;
        expected.push_back("restart file " + path + " line " + std::to_string(lineOf(full, c.lineStart)) + ":");
        readBothWays(path, [&](auto read) { expectError(read, expected); });
    }
}

TEST(BadInput, MissingRestartFile) {
    readBothWays("badinput_no_such_file.restart", [](auto read) { expectError(read, {"badinput_no_such_file.restart"}); });
}

}  // namespace

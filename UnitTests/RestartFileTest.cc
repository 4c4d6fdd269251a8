// Restart files: writing then reading gives back every field of the run state bitwise, and a
// restarted run continues exactly as the uninterrupted one (Documentation/Architecture.md
// "Determinism").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "IO/RestartFile.h"
#include "TestHelpers.h"

using namespace talus;
using test::expectSameParticles;
using test::sameBits;
using test::SceneSimulation;

namespace {

const double collisionTime = 0.01;
const double timeStep = collisionTime / 50;
const double sceneTimeStep = timeStep;  // (for classes with a settings().timeStep of their own)

// A scene that uses every part of the state: three species with an explicit pair law and an
// edited mixed pair, a static floor and a lid that moves and turns, fixed particles (one moving),
// x and y periodic, tilted gravity, non-default run settings, and a block of mobile spheres
// pressed 1% into each other with random velocities, so that springs build up at once.
void richScene(SceneSimulation& s) {
    s.settings().timeStep = timeStep;
    s.scene().setDomain(Vec3(-4, -3.5, 0), Vec3(4, 3.5, 10));
    s.scene().setPeriodic(true, true, false);
    s.scene().setGravity(Vec3(0.05, -0.02, -1));
    s.settings().skin = 0.07;
    s.settings().progressInterval = 3.5;
    s.settings().maxOverlapFraction = 0.3;
    s.settings().maxInitialOverlapFraction = 0.04;
    const auto unitMass = [](double restitution) { return LinearSpringDashpot::fromCollision(collisionTime, restitution, 0.5); };
    const auto sand = s.scene().addSpecies("sand", 6 / pi, unitMass(0.8).withFriction(0.4));
    const auto glass = s.scene().addSpecies("glass", 1.3 * 6 / pi, unitMass(0.9).withFriction(0.2));
    const auto steel = s.scene().addSpecies("steel", 2 * 6 / pi, unitMass(0.7).withFriction(0.3));
    s.scene().species().setPair(sand, steel, unitMass(0.6).withFriction(0.55));
    s.scene().species().pair<LinearSpringDashpot>(glass, steel).friction = 0.25;

    const auto lidMotion = s.scene().addMotion({Vec3(0, 0, -0.01), Vec3(0, 0, 0.2), Vec3(0.3, -0.1, 3.0)});
    const auto conveyor = s.scene().addMotion({Vec3(0.1, 0, 0), Vec3::Zero(), Vec3::Zero()});
    // Neighbours 0.99 apart overlap by 1% of the radius, as do the block and the floor and lid.
    const double spacing = 0.99, bottom = 0.495, top = bottom + 2 * spacing;
    s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), steel);
    s.scene().addWall(-Vec3::UnitZ(), Vec3(0, 0, top + 0.495), glass, lidMotion);
    s.scene().addCylinderWall(Vec3(0.5, 0, 0), Vec3(0.1, 0, 1), 40, steel);  // a drum around it all, out of reach
    // A turning cone beside the block, pressed 1% into its nearest sphere (the one at (0.98, 0.02, 0.495):
    // 1.62 from the axis, where the cone's radius is 1.125), and a closed profile out of reach.
    s.scene().addRevolvedWall(Vec3(2.6, 0, 0), Vec3::UnitZ(), {{1.13, 0}, {1.1, 3}, {0.5, 4}}, sand, lidMotion);
    s.scene().addRevolvedWall(Vec3(0, 0, 8), Vec3::UnitX(), {{0.5, 0}, {1, 0.5}, {0.5, 1}, {0.5, 0}}, glass);
    for (int k = 0; k < 4; ++k)  // a row of fixed spheres along one side of the block
        s.scene().addFixedParticle(Vec3(-1 + spacing * (k - 1), 2 + spacing, bottom), 0.5, steel, k == 3 ? conveyor : -1);

    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> speed(-0.2, 0.2);
    const std::size_t species[] = {sand, glass, steel};
    for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
            for (int z = 0; z < 3; ++z) {
                const Vec3 position(-1 + spacing * x, 2 - spacing * y, bottom + spacing * z);
                const Vec3 velocity(speed(random), speed(random), speed(random));
                s.scene().addParticle(position, 0.5, species[(x + y + z) % 3], velocity, 10 * velocity);
            }
}

// Runs the rich scene for `steps` steps with all files on, then draws from the generator as a
// driver inserting particles would, so that its state is not the seed's.
void runRichScene(SceneSimulation& s, const std::string& name, int steps) {
    s.setup = richScene;
    s.settings().name = name;
    s.solveOrThrow({"--end-time", std::to_string(steps * timeStep), "--output-interval", std::to_string(20 * timeStep)});
    std::uniform_real_distribution<double> unit;
    for (int k = 0; k < 1001; ++k) unit(s.scene().random());
}

// Every parameter of the law (flags as 0 or 1), by its list of parameters (Species/ContactLaws.h).
std::vector<double> lawParameters(const ContactLaw& law) {
    std::vector<double> values;
    std::visit([&]<class Law>(const Law& l) { Law::parameters(l, [&](const char*, auto value) { values.push_back(value); }); },
               law);
    return values;
}

void expectSameLaw(const ContactLaw& a, const ContactLaw& b) {
    EXPECT_EQ(a.index(), b.index());
    EXPECT_TRUE(sameBits(lawParameters(a), lawParameters(b)));
}

void expectSameRandomGenerator(std::mt19937_64 a, std::mt19937_64 b) {
    EXPECT_TRUE(a == b);
    for (int k = 0; k < 1000; ++k) ASSERT_EQ(a(), b()) << "draw " << k;
}

void expectSameState(const SimulationState& a, const SimulationState& b) {
    const RunSettings &x = a.settings, &y = b.settings;
    EXPECT_EQ(x.name, y.name);
    EXPECT_TRUE(sameBits(std::vector<double>{x.timeStep, x.endTime, x.outputInterval, x.skin, x.cellSizeRatio,
                                             x.progressInterval, x.maxOverlapFraction, x.maxInitialOverlapFraction},
                         std::vector<double>{y.timeStep, y.endTime, y.outputInterval, y.skin, y.cellSizeRatio,
                                             y.progressInterval, y.maxOverlapFraction, y.maxInitialOverlapFraction}));
    EXPECT_EQ(std::vector<bool>({x.writeData, x.writeFstat, x.writeEne, x.writeVtu, x.writeRestart}),
              std::vector<bool>({y.writeData, y.writeFstat, y.writeEne, y.writeVtu, y.writeRestart}));
    EXPECT_TRUE(sameBits(a.time, b.time));
    EXPECT_EQ(a.step, b.step);
    EXPECT_TRUE(sameBits(a.gravity, b.gravity));
    EXPECT_TRUE(sameBits(a.domain.lo, b.domain.lo));
    EXPECT_TRUE(sameBits(a.domain.hi, b.domain.hi));
    EXPECT_EQ(a.domain.periodic, b.domain.periodic);

    ASSERT_EQ(a.species.size(), b.species.size());
    for (std::size_t k = 0; k < a.species.size(); ++k) {
        EXPECT_EQ(a.species[k].name, b.species[k].name);
        EXPECT_TRUE(sameBits(a.species[k].density, b.species[k].density));
        expectSameLaw(a.species[k].law, b.species[k].law);
    }
    ASSERT_EQ(a.species.explicitPairs().size(), b.species.explicitPairs().size());
    for (auto p = a.species.explicitPairs().begin(), q = b.species.explicitPairs().begin();
         p != a.species.explicitPairs().end(); ++p, ++q) {
        EXPECT_EQ(p->first, q->first);
        expectSameLaw(p->second, q->second);
    }

    ASSERT_EQ(a.motions.size(), b.motions.size());
    for (std::size_t k = 0; k < a.motions.size(); ++k) {
        EXPECT_TRUE(sameBits(a.motions[k].velocity, b.motions[k].velocity));
        EXPECT_TRUE(sameBits(a.motions[k].angularVelocity, b.motions[k].angularVelocity));
        EXPECT_TRUE(sameBits(a.motions[k].centre, b.motions[k].centre));
    }
    ASSERT_EQ(a.walls.size(), b.walls.size());
    for (std::size_t k = 0; k < a.walls.size(); ++k) {
        EXPECT_TRUE(sameBits(a.walls[k].normal, b.walls[k].normal));
        EXPECT_TRUE(sameBits(a.walls[k].point, b.walls[k].point));
        EXPECT_EQ(a.walls[k].species, b.walls[k].species);
        EXPECT_EQ(a.walls[k].motion, b.walls[k].motion);
        EXPECT_TRUE(sameBits(a.walls[k].radius, b.walls[k].radius));
        EXPECT_TRUE(sameBits(std::vector<double>(a.walls[k].profile.begin(), a.walls[k].profile.end()),
                             std::vector<double>(b.walls[k].profile.begin(), b.walls[k].profile.end())));
        EXPECT_TRUE(sameBits(a.walls[k].next[0], b.walls[k].next[0]) && sameBits(a.walls[k].next[1], b.walls[k].next[1]));
        EXPECT_EQ(a.walls[k].startJoined, b.walls[k].startJoined);
    }
    expectSameParticles(a.particles, b.particles);
    EXPECT_EQ(a.nextId, b.nextId);

    const PairList &l = a.pairList, &m = b.pairList;
    EXPECT_TRUE(l.pairs == m.pairs);
    EXPECT_TRUE(sameBits(l.history, m.history));
    EXPECT_TRUE(l.wallPairs == m.wallPairs);
    EXPECT_TRUE(sameBits(l.wallHistory, m.wallHistory));
    EXPECT_TRUE(sameBits(l.referencePosition, m.referencePosition));
    EXPECT_TRUE(sameBits(l.skin, m.skin));
    EXPECT_TRUE(sameBits(l.reach, m.reach));
    EXPECT_TRUE(sameBits(l.maxSpeed, m.maxSpeed));
    EXPECT_EQ(l.valid, m.valid);
    EXPECT_EQ(l.builds, m.builds);

    expectSameRandomGenerator(a.random, b.random);
    EXPECT_EQ(a.output.savedFrames, b.output.savedFrames);
    EXPECT_EQ(a.output.dataBytes, b.output.dataBytes);
    EXPECT_EQ(a.output.fstatBytes, b.output.fstatBytes);
    EXPECT_EQ(a.output.eneBytes, b.output.eneBytes);
    EXPECT_TRUE(sameBits(a.output.frameTimes, b.output.frameTimes));
}

std::size_t nonZeroSprings(const ContactHistories& history) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < history.size(); ++k) n += !history.get(k).spring.isZero(0);
    return n;
}

TEST(RestartFile, RunStateReadsBackBitwise) {
    SceneSimulation s;
    runRichScene(s, "restartfile_state", 60);
    const SimulationState& original = s.state();
    // The test is only as good as the state is rich: make sure it is.
    ASSERT_GT(nonZeroSprings(original.pairList.history), 10u);
    ASSERT_GT(nonZeroSprings(original.pairList.wallHistory), 2u);
    ASSERT_GT(original.output.savedFrames, 2u);
    ASSERT_FALSE(original.output.frameTimes.empty());
    ASSERT_EQ(original.species.explicitPairs().size(), 2u);

    const std::string path = "restartfile_state_copy.restart";
    writeRestartFile(path, original);
    SimulationState restored;
    readRestartFile(path, restored);
    expectSameState(original, restored);
}

// Values that "%.17g" and strtod must carry exactly: thirds, tiny, huge, subnormal, negative zero.
TEST(RestartFile, AwkwardNumbersReadBackBitwise) {
    SimulationState state;
    state.species.add("soft", 1.0 / 3.0, HertzMindlin::fromMaterial(1e7 / 3, 0.3, 0.9).withFriction(0.1 / 3));
    state.species.add("hard", 1e300, HertzMindlin::fromMaterial(std::sqrt(2.0) * 1e11, 0.25, 0.5));
    state.species.setPair(0, 1, HertzMindlin::fromMaterial(7e9, 0.2, 0.6));
    state.time = std::nextafter(1.0, 2.0);
    state.gravity = Vec3(-0.0, std::numeric_limits<double>::denorm_min(), -9.81);
    state.domain.lo = Vec3(-1e-310, -std::numeric_limits<double>::max(), 0.1);
    state.domain.hi = Vec3(1.0 / 3.0, std::numeric_limits<double>::max(), 0.7);
    ParticleStore& p = state.particles;
    p.position = {Vec3(0.1, 0.2, 0.3), Vec3(-0.0, 1e-300, 2.0 / 3.0)};
    p.velocity = {Vec3(1e-17, -1e17, std::numeric_limits<double>::min()), Vec3::Zero()};
    p.angularVelocity = p.force = p.torque = {Vec3(std::exp(1.0), -pi, 1e-5 / 7), Vec3(-0.0, 0.0, -0.0)};
    p.radius = {0.1, std::nextafter(0.5, 0.0)};
    p.mass = {1e-200, 4.0 / 3.0};
    p.invMass = {1e200, 0.75};
    p.invInertia = {0.0, 1.0 / 7.0};
    p.species = {0, 1};
    p.id = {0, 41};
    p.fixed = {0, 1};
    p.motion = {-1, -1};
    state.nextId = 42;
    state.pairList.pairs = {{0, 1}};
    state.pairList.history.push_back(ContactHistory{Vec3(1e-12 / 3, -0.0, 5e-324), -1e-300 / 3, ContactHistory::touching});
    state.pairList.referencePosition = p.position;
    state.pairList.skin = 0.01 / 3;
    const std::string path = "restartfile_awkward.restart";
    writeRestartFile(path, state);
    SimulationState restored;
    readRestartFile(path, restored);
    expectSameState(state, restored);
}

// Reading replaces the whole state, leaving nothing of what was there before.
TEST(RestartFile, ReadingReplacesThePreviousState) {
    SimulationState empty;
    empty.species.add("only", 1, LinearSpringDashpot{100, 1, 20, 1, 0.5});
    const std::string path = "restartfile_replace_empty.restart";
    writeRestartFile(path, empty);
    SceneSimulation s;
    runRichScene(s, "restartfile_replace", 5);
    readRestartFile(path, SimulationInternals::state(s));
    expectSameState(empty, s.state());
}

// Documentation/Architecture.md: a restart continues bitwise identically to an uninterrupted run.
TEST(RestartFile, RestartedRunContinuesBitwise) {
    SceneSimulation first;
    runRichScene(first, "restartfile_continue", 40);

    SceneSimulation restarted;
    restarted.solveOrThrow({"--restart", "restartfile_continue.restart", "--end-time", std::to_string(80 * timeStep),
                            "--files", "off"});
    SceneSimulation uninterrupted;
    uninterrupted.setup = richScene;
    uninterrupted.solveOrThrow(test::stepsWithoutFiles(timeStep, 80));

    ASSERT_EQ(restarted.step(), 80u);
    test::expectSameContinuation(restarted, uninterrupted);
}

// A driver's number flags and the values it keeps (Run::keepInRestart) come back on
// restart; a flag given again on the command line wins; a restart file that lacks one of them is
// refused, and names must be unique words.
struct KeepingDriver : SceneSimulation {
    double height = 1, counted = 0;
    int layers = 2;
    KeepingDriver() {
        run().addFlag("height", "a number flag", height);
        run().addFlag("layers", "an integer flag", layers);
        run().keepInRestart("steps.counted", counted);
        setup = [](SceneSimulation& s) {
            s.settings().timeStep = sceneTimeStep;
            s.scene().addSpecies("glass", 1, LinearSpringDashpot::fromCollision(collisionTime, 0.5, 0.5));
            s.scene().addParticle(Vec3::Zero(), 0.5, 0);
        };
        afterStep = [this](SceneSimulation&) { counted += 1; };
    }
};

TEST(RestartFile, KeepsTheDriversFlagsAndValues) {
    const std::string end10 = std::to_string(10 * timeStep), end20 = std::to_string(20 * timeStep);
    KeepingDriver first;
    first.solveOrThrow({"--name", "restartfile_kept", "--height", "2.5", "--layers", "7", "--end-time", end10,
                        "--progress-interval", "1e9"});
    ASSERT_EQ(first.counted, 10);

    KeepingDriver restarted;
    restarted.solveOrThrow({"--restart", "restartfile_kept.restart", "--end-time", end20, "--files", "off"});
    EXPECT_EQ(restarted.height, 2.5);
    EXPECT_EQ(restarted.layers, 7);
    EXPECT_EQ(restarted.counted, 20);  // 10 kept, 10 more counted

    KeepingDriver overridden;
    overridden.solveOrThrow({"--restart", "restartfile_kept.restart", "--height", "4", "--end-time", end20, "--files", "off"});
    EXPECT_EQ(overridden.height, 4);
    EXPECT_EQ(overridden.layers, 7);

    SceneSimulation other;
    double unknown = 0;
    other.run().keepInRestart("not.saved", unknown);
    test::expectError([&] { other.solveOrThrow({"--restart", "restartfile_kept.restart", "--files", "off"}); },
                      {"restartfile_kept.restart", "no value 'not.saved'"});
    test::expectError([&] { other.run().keepInRestart("not.saved", unknown); }, {"'not.saved' is taken"});
    test::expectError([&] { other.run().keepInRestart("two words", unknown); }, {"one word"});
}

}  // namespace

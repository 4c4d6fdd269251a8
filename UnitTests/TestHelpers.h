// Helpers shared by the unit tests: a simulation whose scene is given in place, and checks of
// talus::Error messages.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "Error.h"
#include "Simulation.h"

namespace talus {

// What tests change that drivers may not: the state of a simulation, mutable (a list's near-list
// fraction, a restart file read into it). Simulation names this struct its friend.
struct SimulationInternals {
    static SimulationState& state(Simulation& simulation) { return simulation.state_; }
};

}  // namespace talus

namespace talus::test {

// `count` particles in a store of their own for the passes over per-particle arrays: every
// coordinate, velocity, force and torque in (-2, 2), masses about 1, radii in (0.2, 0.4), and
// fixed ones among them (slots 2, 7, 12, ..., 8 and 43) with zero inverse mass and inertia.
inline ParticleStore someParticles(std::size_t count, unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> between(-2, 2);
    auto someVector = [&] { return Vec3(between(random), between(random), between(random)); };
    ParticleStore p;
    for (std::size_t i = 0; i < count; ++i) {
        p.position.push_back(someVector());
        p.velocity.push_back(someVector());
        p.angularVelocity.push_back(someVector());
        p.force.push_back(someVector());
        p.torque.push_back(someVector());
        p.radius.push_back(0.3 + 0.05 * between(random));
        p.mass.push_back(1 + between(random) * between(random));
        p.fixed.push_back(i % 5 == 2 || i == 8 || i == 43);
        p.invMass.push_back(p.fixed.back() ? 0 : 1 / p.mass.back());
        p.invInertia.push_back(p.fixed.back() ? 0 : 3 / p.mass.back());
    }
    return p;
}

// A driver whose setup and after-step hook are lambdas, so that each test states its scene
// next to its checks instead of in a class of its own.
class SceneSimulation : public Simulation {
public:
    std::function<void(SceneSimulation&)> setup;
    std::function<void(SceneSimulation&)> afterStep;

    // Runs from t = 0 to endTime with steps dt, writing no files and printing no progress.
    void runFor(double timeStep, double endTime) {
        settings().timeStep = timeStep;
        settings().endTime = endTime;
        settings().setFileOutput(false);
        settings().progressInterval = 1e9;
        solveOrThrow({});
    }

protected:
    void setupInitialConditions() override {
        if (setup) setup(*this);
    }
    void actionsAfterTimeStep() override {
        if (afterStep) afterStep(*this);
    }
};

// Flags that run exactly `steps` time steps of size dt from t = 0 without writing files.
inline std::vector<std::string> stepsWithoutFiles(double dt, int steps) {
    std::ostringstream endTime;
    endTime.precision(17);
    endTime << steps * dt;
    return {"--end-time", endTime.str(), "--files", "off"};
}

// Runs action, which must throw talus::Error whose message contains every one of parts;
// returns the message ("" when nothing was thrown) for further checks.
template <class Action>
std::string expectError(Action&& action, const std::vector<std::string>& parts) {
    try {
        action();
    } catch (const Error& e) {
        const std::string message = e.what();
        for (const std::string& part : parts)
            EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing from: " << message;
        return message;
    }
    ADD_FAILURE() << "no talus::Error thrown (expected a message containing '" << (parts.empty() ? "" : parts[0]) << "')";
    return "";
}

inline std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in) << "cannot read " << path;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void writeWholeFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    ASSERT_TRUE(out) << "cannot write " << path;
}

// Bitwise equality: a restart must give back the very same doubles (also -0 and the last bit).
inline bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
inline bool sameBits(const Vec3& a, const Vec3& b) {
    return sameBits(a.x(), b.x()) && sameBits(a.y(), b.y()) && sameBits(a.z(), b.z());
}
inline bool sameBits(const Quat& a, const Quat& b) { return sameBits(a.w(), b.w()) && sameBits(a.vec(), b.vec()); }
template <class Integer>
    requires std::is_integral_v<Integer>
bool sameBits(Integer a, Integer b) {
    return a == b;
}
inline bool sameBits(const ContactHistory& a, const ContactHistory& b) {
    return sameBits(a.spring, b.spring) && sameBits(a.lastNormalForce, b.lastNormalForce) && a.state == b.state &&
           sameBits(a.warmPoint, b.warmPoint) && sameBits(a.warmMultiplier, b.warmMultiplier) &&
           sameBits(a.rollingSpring, b.rollingSpring);
}
inline bool sameBits(const ContactHistories& a, const ContactHistories& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (!sameBits(a.get(k), b.get(k))) return false;
    return true;
}
template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (!sameBits(a[k], b[k])) return false;
    return true;
}

// Every per-particle array, found through forEachArray so that a field added later is compared
// without touching the tests that use it.
inline void expectSameParticles(ParticleStore a, ParticleStore b) {
    std::size_t arrayA = 0;
    a.forEachArray([&](auto& arrayOfA) {
        std::size_t arrayB = 0;
        b.forEachArray([&](auto& arrayOfB) {
            if constexpr (std::is_same_v<decltype(arrayOfA), decltype(arrayOfB)>) {
                if (arrayA == arrayB) {
                    EXPECT_TRUE(sameBits(arrayOfA, arrayOfB)) << "particle array " << arrayA;
                }
            }
            ++arrayB;
        });
        ++arrayA;
    });
    EXPECT_EQ(a.size(), b.size());
}

// A restarted run against the uninterrupted one at the same step: the time, every particle array,
// the pairs and their histories, bitwise.
inline void expectSameContinuation(const Simulation& restarted, const Simulation& uninterrupted) {
    EXPECT_TRUE(sameBits(restarted.time(), uninterrupted.time()));
    expectSameParticles(restarted.scene().particles(), uninterrupted.scene().particles());
    EXPECT_TRUE(restarted.state().pairList.pairs == uninterrupted.state().pairList.pairs);
    EXPECT_TRUE(sameBits(restarted.state().pairList.history, uninterrupted.state().pairList.history));
    EXPECT_TRUE(sameBits(restarted.state().pairList.wallHistory, uninterrupted.state().pairList.wallHistory));
}

}  // namespace talus::test

// --dt auto (Scene::automaticTimeStep, Theory/Integration.md "Choosing the time step"): the step is
// the shortest collision time of the scene over --steps-per-collision, the collision times worked
// out here again from the contact laws' parameters (the damped oscillator's half period for the
// linear law, the Hertzian impact's duration by numerical integration), over every pair the scene
// can form: its lightest and smallest particles of each species against each other and against
// walls of another species.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "TestHelpers.h"

using namespace talus;
using test::expectError;
using test::SceneSimulation;

namespace {

double sphereMass(double density, double radius) { return density * 4.0 / 3.0 * pi * radius * radius * radius; }

// Half the period of the damped oscillation m* x'' = -k x - g x' (the contact's duration).
double linearCollisionTime(const LinearSpringDashpot& law, double reducedMass) {
    const double damping = law.normalDamping / (2 * reducedMass);
    return pi / std::sqrt(law.normalStiffness / reducedMass - damping * damping);
}

// The elastic Hertzian impact at speed v: m* x'' = -4/3 E* sqrt(R*) x^(3/2). Energy gives
// x' = v sqrt(1 - (x / xmax)^(5/2)), so tc = 2 (xmax / v) int_0^1 dy / sqrt(1 - y^(5/2)), the
// integral by Simpson's rule after y = 1 - u^2 (which removes the square-root end).
double hertzCollisionTime(double youngs, double reducedMass, double effectiveRadius, double v) {
    const double xmax = std::pow(15 * reducedMass * v * v / (16 * youngs * std::sqrt(effectiveRadius)), 0.4);
    auto f = [](double u) {
        if (u == 0) return 2 / std::sqrt(2.5);  // (the limit)
        return 2 * u / std::sqrt(1 - std::pow(1 - u * u, 2.5));
    };
    const int n = 4000;
    double sum = f(0) + f(1);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * f(static_cast<double>(k) / n);
    return 2 * xmax / v * sum / (3.0 * n);
}

std::vector<std::string> autoStep(std::vector<std::string> more = {}) {
    std::vector<std::string> flags{"--dt", "auto", "--end-time", "0", "--files", "off"};
    flags.insert(flags.end(), more.begin(), more.end());
    return flags;
}

// Two mobile species of two sizes each, a wall of a third species, every pair law set apart from
// the others: the shortest of five collisions sets the step.
const LinearSpringDashpot heavyLaw{2e5, 25, 0, 0, 0.5}, lightLaw{5e4, 5, 0, 0, 0.5}, heavyLight{1e5, 2, 0, 0, 0.5},
    lightSteel{4e5, 1, 0, 0, 0.5}, heavySteel{4e5, 30, 0, 0, 0.5};
const double heavyDensity = 2, lightDensity = 1;

void linearScene(SceneSimulation& s) {
    Scene& scene = s.scene();
    const auto heavy = scene.addSpecies("heavy", heavyDensity, heavyLaw);
    const auto light = scene.addSpecies("light", lightDensity, lightLaw);
    const auto steel = scene.addSpecies("steel", 8, LinearSpringDashpot{1e7, 1, 0, 0, 0.5});
    scene.species().pair<LinearSpringDashpot>(heavy, light) = heavyLight;
    scene.species().pair<LinearSpringDashpot>(light, steel) = lightSteel;
    scene.species().pair<LinearSpringDashpot>(heavy, steel) = heavySteel;
    scene.addWall(Vec3::UnitZ(), Vec3::Zero(), steel);
    scene.addParticle(Vec3(0, 0, 2), 0.5, heavy);
    scene.addParticle(Vec3(3, 0, 2), 0.6, heavy);
    scene.addParticle(Vec3(6, 0, 2), 0.2, light);
    scene.addParticle(Vec3(9, 0, 2), 0.3, light);
}

double shortestLinearCollision() {
    const double mH = sphereMass(heavyDensity, 0.5), mL = sphereMass(lightDensity, 0.2);  // the lightest of each
    return std::min({linearCollisionTime(heavyLaw, mH / 2), linearCollisionTime(lightLaw, mL / 2),
                     linearCollisionTime(heavyLight, mH * mL / (mH + mL)), linearCollisionTime(lightSteel, mL),
                     linearCollisionTime(heavySteel, mH)});
}

}  // namespace

TEST(AutomaticTimeStep, LinearLawsTheShortestOfEveryPairOverTheStepsPerCollision) {
    const double tc = shortestLinearCollision();
    for (const double steps : {50.0, 200.0}) {
        SceneSimulation s;
        s.setup = linearScene;
        testing::internal::CaptureStdout();
        s.solveOrThrow(autoStep(steps == 50 ? std::vector<std::string>{} : std::vector<std::string>{"--steps-per-collision", "200"}));
        const std::string said = testing::internal::GetCapturedStdout();
        EXPECT_NEAR(s.settings().timeStep, tc / steps, 1e-12 * tc) << "--steps-per-collision " << steps;
        // The light sphere on the steel wall (kn 4e5 on its own mass) is the shortest, and the run says so.
        EXPECT_NE(said.find("time step"), std::string::npos) << said;
        EXPECT_NE(said.find("'light' with 'steel'"), std::string::npos) << said;
    }
    // The kernel call the drivers use gives the same.
    SceneSimulation s;
    linearScene(s);
    EXPECT_NEAR(s.scene().automaticTimeStep(50), tc / 50, 1e-12 * tc);
}

TEST(AutomaticTimeStep, HertzianLawsAtTheExpectedImpactSpeed) {
    // Two materials, mixed by the law's rule (Young's moduli averaged); a wall of the stiff one.
    const HertzMindlin stiff = HertzMindlin::fromMaterial(1e7, 0.3, 0.8), soft = HertzMindlin::fromMaterial(2e6, 0.3, 0.8);
    auto scene = [&](SceneSimulation& s) {
        const auto a = s.scene().addSpecies("stiff", 1, stiff);
        const auto b = s.scene().addSpecies("soft", 1, soft);
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), a);
        s.scene().addParticle(Vec3(0, 0, 2), 0.5, a);
        s.scene().addParticle(Vec3(3, 0, 2), 0.5, a);
        s.scene().addParticle(Vec3(6, 0, 2), 0.25, b);
    };
    const double mA = sphereMass(1, 0.5), mB = sphereMass(1, 0.25), mixedE = 0.5 * (stiff.effectiveYoungsModulus + soft.effectiveYoungsModulus);
    for (const double v : {1.0, 10.0}) {
        const double tc = std::min({hertzCollisionTime(stiff.effectiveYoungsModulus, mA / 2, 0.25, v),
                                    hertzCollisionTime(stiff.effectiveYoungsModulus, mA, 0.5, v),
                                    hertzCollisionTime(mixedE, mA * mB / (mA + mB), 0.5 * 0.25 / 0.75, v),
                                    hertzCollisionTime(mixedE, mB, 0.25, v)});
        SceneSimulation s;
        s.setup = scene;
        testing::internal::CaptureStdout();
        s.solveOrThrow(autoStep(v == 1 ? std::vector<std::string>{} : std::vector<std::string>{"--impact-speed", "10"}));
        const std::string said = testing::internal::GetCapturedStdout();
        EXPECT_NEAR(s.settings().timeStep, tc / 50, 1e-9 * tc) << "impact speed " << v;
        if (v == 10) {
            EXPECT_NE(said.find("impact speed 10"), std::string::npos) << said;
        }
    }
}

// The check of a step given by hand times Hertzian pairs at --impact-speed too: a step of a
// twentieth of the collision time at the law's own speed (1) passes, and at speed 100, where the
// impact is 100^(1/5) = 2.5 times shorter, it is a eighth of it and refused.
TEST(AutomaticTimeStep, HandGivenStepCheckedAtTheImpactSpeed) {
    const HertzMindlin law = HertzMindlin::fromMaterial(1e7, 0.3, 0.8);
    const double m = sphereMass(1, 0.5), tc = hertzCollisionTime(law.effectiveYoungsModulus, m / 2, 0.25, 1);
    auto run = [&](std::vector<std::string> flags) {
        SceneSimulation s;
        s.setup = [&](SceneSimulation& sim) {
            const auto a = sim.scene().addSpecies("grains", 1, law);
            sim.scene().addParticle(Vec3(0, 0, 2), 0.5, a);
            sim.scene().addParticle(Vec3(3, 0, 2), 0.5, a);
        };
        std::vector<std::string> all = {"--dt", str(tc / 20), "--end-time", str(tc), "--files", "off"};
        all.insert(all.end(), flags.begin(), flags.end());
        testing::internal::CaptureStdout();
        try {
            s.solveOrThrow(all);
        } catch (...) {
            testing::internal::GetCapturedStdout();
            throw;
        }
        testing::internal::GetCapturedStdout();
    };
    EXPECT_NO_THROW(run({}));
    expectError([&] { run({"--impact-speed", "100"}); }, {"larger than 0.1 x the shortest collision time"});
}

TEST(AutomaticTimeStep, RestartedRunKeepsTheStepItChose) {
    const std::string name = "AutomaticTimeStep";
    SceneSimulation first;
    first.setup = linearScene;
    testing::internal::CaptureStdout();
    first.solveOrThrow({"--dt", "auto", "--end-time", "0.01", "--name", name, "--vtu", "off"});
    testing::internal::GetCapturedStdout();
    SceneSimulation again;
    testing::internal::CaptureStdout();
    again.solveOrThrow({"--restart", name + ".restart", "--dt", "auto", "--end-time", "0.02", "--files", "off"});
    testing::internal::GetCapturedStdout();
    EXPECT_EQ(again.settings().timeStep, first.settings().timeStep);
}

TEST(AutomaticTimeStep, BadSettingsNamed) {
    for (const auto& [flags, named] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--steps-per-collision", "5"}, "--steps-per-collision"},
             {{"--steps-per-collision", "nan"}, "--steps-per-collision"},
             {{"--impact-speed", "-1"}, "--impact-speed"},
             {{"--largest-step-fraction", "2"}, "--largest-step-fraction"},
             {{"--largest-step-fraction", "0.5", "--steps-per-collision", "1.5"}, "at least 2"}}) {
        SceneSimulation s;
        s.setup = linearScene;
        expectError([&] { s.solveOrThrow(autoStep(flags)); }, {named});
    }
    // Nothing can move, so nothing collides: the step must be given.
    SceneSimulation still;
    still.setup = [](SceneSimulation& s) {
        const auto sand = s.scene().addSpecies("sand", 1, LinearSpringDashpot{1e5, 1, 0, 0, 0.5});
        s.scene().addFixedParticle(Vec3::Zero(), 0.5, sand);
    };
    expectError([&] { still.solveOrThrow(autoStep()); }, {"--dt auto", "give --dt"});
}

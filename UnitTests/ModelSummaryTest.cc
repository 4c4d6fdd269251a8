// The line a run prints when it starts (Run/ModelSummary.h): what it models, read from the scene
// the test builds, and printed by every run (Simulation::solve).
#include <gtest/gtest.h>

#include "Run/ModelSummary.h"
#include "TestHelpers.h"

using namespace talus;
using test::SceneSimulation;

namespace {

void expectSays(const std::string& line, const std::vector<std::string>& parts) {
    for (const std::string& part : parts) EXPECT_NE(line.find(part), std::string::npos) << "'" << part << "' in: " << line;
}

}  // namespace

TEST(ModelSummary, FrictionlessSpheresOnAFloor) {
    SceneSimulation s;
    const auto glass = s.scene().addSpecies("glass", 1, LinearSpringDashpot{1e5, 1, 0, 0, 0});
    s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), glass);
    s.scene().addParticle(Vec3(0, 0, 1), 0.5, glass);
    s.scene().addParticle(Vec3(2, 0, 1), 0.5, glass);
    s.scene().setGravity(Vec3::Zero());
    s.settings().skin = 0.05;
    expectSays(describeModel(s.state(), false), {"models 2 spheres, 1 species", "LinearSpringDashpot",
                                                 "frictionless (no tangential force)", "contact ends treated",
                                                 "no gravity", "walls: 1 plane", "list skin 0.05"});
}

TEST(ModelSummary, FrictionRangeOverThePairsPresentOnly) {
    SceneSimulation s;
    Scene& scene = s.scene();
    const auto a = scene.addSpecies("a", 1, LinearSpringDashpot{1e5, 1, 1e4, 1, 0.3});
    const auto b = scene.addSpecies("b", 1, LinearSpringDashpot{1e5, 1, 1e4, 1, 0.5});
    scene.addSpecies("unused", 1, LinearSpringDashpot{1e5, 1, 1e4, 1, 0.9});  // no particle: not said
    scene.species().pair<LinearSpringDashpot>(a, b).friction = 0.1;
    scene.addParticle(Vec3(0, 0, 1), 0.5, a);
    scene.addParticle(Vec3(2, 0, 1), 0.5, b);
    scene.addFixedParticle(Vec3(4, 0, 1), 0.5, b);
    scene.setDomain(Vec3(-5, -5, -5), Vec3(5, 5, 5));
    scene.setPeriodic(true, false, true);
    const std::string line = describeModel(s.state(), true);
    expectSays(line, {"models 3 spheres (1 fixed), 2 species", "friction 0.1 to 0.5", "tangential springs kept",
                      "walls: none", "periodic along x z", "(0.2 x the smallest radius)"});
    EXPECT_EQ(line.find("0.9"), std::string::npos) << line;
}

TEST(ModelSummary, RollingResistanceSuperquadricsAndCylinders) {
    SceneSimulation s;
    Scene& scene = s.scene();
    const auto sand = scene.addSpecies(
        "sand", 1, LinearSpringDashpotRolling::of(LinearSpringDashpot{1e5, 1, 1e4, 1, 0.5}, 1e3, 1, 0.2));
    scene.addCylinderWall(Vec3::Zero(), Vec3::UnitY(), 5, sand);
    scene.addWall(Vec3::UnitY(), Vec3(0, -1, 0), sand);
    scene.addParticle(Vec3(0, 0, 0), 0.5, sand);
    const std::size_t ellipsoid = scene.addShape(Superquadric(0.5, 0.5, 1, 1, 1));
    scene.addSuperquadric(Vec3(2, 0, 0), ellipsoid, sand);
    expectSays(describeModel(s.state(), true),
               {"models 1 sphere and 1 superquadric", "LinearSpringDashpotRolling", "rolling resistance up to 0.2",
                "contact ends treated between spheres (superquadric contacts: plain velocity Verlet)", "rigid bodies",
                "walls: 1 plane, 1 cylinder"});
}

TEST(ModelSummary, SuperquadricContactsSaidPlain) {
    SceneSimulation s;
    const auto sand = s.scene().addSpecies("sand", 1, LinearSpringDashpot{1e5, 1, 1e4, 1, 0.5});
    const std::size_t ellipsoid = s.scene().addShape(Superquadric(0.5, 0.5, 1, 1, 1));
    s.scene().addSuperquadric(Vec3(2, 0, 0), ellipsoid, sand);
    expectSays(describeModel(s.state(), true),
               {"models 1 superquadric", "contact ends plain velocity Verlet (superquadric contacts)"});
}

TEST(ModelSummary, EveryRunSaysItFirst) {
    SceneSimulation s;
    s.setup = [](SceneSimulation& sim) {
        const auto glass = sim.scene().addSpecies("glass", 1, LinearSpringDashpot{1e5, 1, 0, 0, 0});
        sim.scene().addParticle(Vec3(0, 0, 1), 0.5, glass);
    };
    testing::internal::CaptureStdout();
    s.solveOrThrow({"--dt", "1e-4", "--end-time", "1e-3", "--files", "off", "--name", "summary"});
    const std::string said = testing::internal::GetCapturedStdout();
    EXPECT_EQ(said.find("summary: models 1 sphere"), 0u) << said;
}

// Triangle meshes that follow a prescribed motion (Scene::addMeshWall with a motion, Walls/
// MeshWalls.h): the vertices move each step, the contacts feel the wall's velocity at the contact
// point, and the neighbour list is built anew before the mesh can reach a particle it did not list.
// A flat mesh moving within its own plane, or turning about its normal, is the plane wall of the
// same motion (PrescribedMotionTest.cc checks those against analytic motions), so the two runs
// must agree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "Integration/Integrator.h"
#include "TestHelpers.h"

using namespace talus;
using namespace talus::test;

namespace {

// The flat square [-n/2, n/2]^2 at z = 0 of n x n unit cells, each split along a diagonal.
TriangleMesh flatSquare(int n) {
    std::vector<TriangleCorners> triangles;
    auto at = [&](int i, int j) { return Vec3(i - 0.5 * n, j - 0.5 * n, 0); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return TriangleMesh(triangles);
}

struct Sphere {
    double radius = 0.3, mass = 1;
    LinearSpringDashpot law = LinearSpringDashpot::fromCollision(0.01, 0.6, 1).withFriction(0.4);
    double density() const { return mass / (4.0 / 3.0 * pi * std::pow(radius, 3)); }
};

// One sphere and a floor at z = 0 following `motion`: a mesh of triangles or a plane wall.
struct FloorRun {
    Vec3 position, velocity, angularVelocity;
    std::uint64_t builds, wallRelistings;
};
FloorRun runOnFloor(bool mesh, const PrescribedMotion& motion, const Vec3& start, const Vec3& gravity,
                    double endTime) {
    const Sphere sphere;
    SceneSimulation s;
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(gravity);
        sim.scene().setDomain(Vec3(-6, -6, -3), Vec3(6, 6, 6));
        const auto species = sim.scene().addSpecies("grains", sphere.density(), sphere.law);
        const int moving = static_cast<int>(sim.scene().addMotion(motion));
        if (mesh)
            sim.scene().addMeshWall(flatSquare(10), species, moving);
        else
            sim.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species, moving);
        sim.scene().addParticle(start, sphere.radius, species);
    };
    s.settings().skin = 0.01;
    s.runFor(1e-4, endTime);
    const ParticleStore& p = s.scene().particles();
    return {p.position[0], p.velocity[0], p.angularVelocity[0], s.state().pairList.builds,
            s.state().pairList.wallRelistings};
}

void expectSameRun(const FloorRun& onMesh, const FloorRun& onPlane, double tolerance) {
    EXPECT_LT((onMesh.position - onPlane.position).norm(), tolerance);
    EXPECT_LT((onMesh.velocity - onPlane.velocity).norm(), tolerance);
    EXPECT_LT((onMesh.angularVelocity - onPlane.angularVelocity).norm(), tolerance);
}

}  // namespace

// A sphere dropped on a floor of triangles sliding sideways is dragged along by friction until it
// rolls with the floor: as on a plane wall with the same motion. (Each triangle keeps its own
// tangential spring, Theory/ContactLaws.md, which starts anew when the sphere passes to the next
// triangle: the two runs differ by that, not by rounding alone; a wrong wall velocity at the
// contact would part them by the floor's speed.)
TEST(MovingMesh, ASlidingFloorDragsASphereAsAMovingPlaneDoes) {
    const PrescribedMotion sliding{.velocity = Vec3(0.5, -0.2, 0)};
    const Vec3 start(-0.2, 0.3, 0.35), gravity(0, 0, -1);
    const FloorRun onMesh = runOnFloor(true, sliding, start, gravity, 3);
    const FloorRun onPlane = runOnFloor(false, sliding, start, gravity, 3);
    std::printf("[ measured ] after 3 time units: sphere at (%.6f, %.6f), velocity (%.6f, %.6f)\n", onMesh.position.x(),
                onMesh.position.y(), onMesh.velocity.x(), onMesh.velocity.y());
    // (Dragged: rolling, it moves at 2/7 of the floor's speed once it rolls with it.)
    EXPECT_GT(onMesh.position.x() - start.x(), 0.3);
    expectSameRun(onMesh, onPlane, 1e-8);
}

// A floor of triangles turning about the vertical axis spins up a sphere resting off the axis, as
// a plane turning with it does: the wall's velocity at the contact point is the motion's there (to
// the springs that start anew at the triangles' edges, above: the floor turns 3.2 rad under it).
TEST(MovingMesh, ATurningFloorCarriesASphereAsATurningPlaneDoes) {
    const PrescribedMotion turning{.angularVelocity = Vec3(0, 0, 0.8), .centre = Vec3(0.1, -0.1, 0)};
    const Vec3 start(1.3, 0.4, 0.3), gravity(0, 0, -1);
    const FloorRun onMesh = runOnFloor(true, turning, start, gravity, 4);
    const FloorRun onPlane = runOnFloor(false, turning, start, gravity, 4);
    EXPECT_GT(onMesh.velocity.norm(), 0.25);  // (carried round: the floor's speed there is about 1)
    expectSameRun(onMesh, onPlane, 2e-5);
}

// A floor of triangles rising at speed 2 towards a sphere that floats at rest 1.2 above it (no
// gravity) hits it and throws it up: the sphere does not move, so only the mesh's travel can call
// for the relisting of the triangles that lists their contact (PairList::meshTravel,
// relistWalls), with no build of the whole list before the hit. The sphere leaves at the speed the
// rising plane gives it.
TEST(MovingMesh, ARisingFloorHitsASphereItWasNotListedWith) {
    const PrescribedMotion rising{.velocity = Vec3(0, 0, 2)};
    const Vec3 start(0.4, -0.2, 1.5);
    const FloorRun onMesh = runOnFloor(true, rising, start, Vec3::Zero(), 1.2);
    const FloorRun onPlane = runOnFloor(false, rising, start, Vec3::Zero(), 1.2);
    std::printf("[ measured ] the sphere leaves at %.6f; %llu list builds, the triangles listed anew %llu times\n",
                onMesh.velocity.z(), static_cast<unsigned long long>(onMesh.builds),
                static_cast<unsigned long long>(onMesh.wallRelistings));
    EXPECT_GT(onMesh.velocity.z(), 2.5);  // (2 (1 + e) for a wall of infinite mass: 3.2)
    EXPECT_GT(onMesh.wallRelistings, 10u);
    const FloorRun beforeTheHit = runOnFloor(true, rising, start, Vec3::Zero(), 0.55);
    EXPECT_EQ(beforeTheHit.velocity.z(), 0);
    EXPECT_EQ(beforeTheHit.builds, 1u);  // (the first)
    EXPECT_GT(beforeTheHit.wallRelistings, 10u);
    expectSameRun(onMesh, onPlane, 1e-10);
}

// A run writing ParaView files writes the moving mesh in each frame, indexed by NAME_mesh.pvd,
// where it is then.
TEST(MovingMesh, ParaViewFramesShowTheMeshWhereItIs) {
    const Sphere sphere;
    SceneSimulation s;
    s.setup = [&](SceneSimulation& sim) {
        const auto species = sim.scene().addSpecies("grains", sphere.density(), sphere.law);
        sim.scene().setDomain(Vec3(-6, -6, -3), Vec3(6, 6, 6));
        const int rising = static_cast<int>(sim.scene().addMotion({.velocity = Vec3(0, 0, 0.25)}));
        sim.scene().addMeshWall(flatSquare(2), species, rising);
        sim.scene().addParticle(Vec3(0, 0, 3), sphere.radius, species);
    };
    s.settings().name = "movingmesh_frames";
    s.settings().timeStep = 1e-3;
    s.settings().progressInterval = 1e9;
    s.solveOrThrow({"--end-time", "2", "--output-interval", "1", "--vtu", "on"});
    EXPECT_FALSE(std::filesystem::exists("movingmesh_frames_mesh.vtu"));
    const std::string index = readWholeFile("movingmesh_frames_mesh.pvd");
    for (int k = 0; k < 3; ++k) {
        const std::string frame = "movingmesh_frames_mesh_" + std::to_string(k) + ".vtu";
        EXPECT_NE(index.find(frame), std::string::npos) << index;
        // (The first vertex, (-1, -1, z), at z = 0.25 t: 0, 0.25, 0.5.)
        const std::string text = readWholeFile(frame);
        const std::size_t positions = text.find("Name=\"Position\"");
        ASSERT_NE(positions, std::string::npos) << frame;
        std::istringstream firstVertex(text.substr(text.find('>', positions) + 1));
        Vec3 x;
        firstVertex >> x.x() >> x.y() >> x.z();
        EXPECT_LT((x - Vec3(-1, -1, 0.25 * k)).norm(), 1e-12) << frame;
    }
}

// The one-pass first half of the step (Particles/DriftPass.h) takes scenes whose walls and meshes
// follow motions (they move after the pass, as in the plain step) and gives the plain step's run
// to the bit: spheres dropped into a turning drum of a cylinder and a turning floor of triangles.
// A particle on a motion still sends the step to the plain path.
TEST(MovingMesh, TheDriftPassMovesTheWallsAsThePlainStepDoes) {
    const Sphere sphere;
    auto run = [&](bool driftPass, bool particleOnMotion) {
        auto s = std::make_unique<SceneSimulation>();
        s->setup = [&, particleOnMotion](SceneSimulation& sim) {
            sim.scene().setGravity(Vec3(0, 0, -1));
            sim.scene().setDomain(Vec3(-6, -6, -3), Vec3(6, 6, 6));
            const auto species = sim.scene().addSpecies("grains", sphere.density(), sphere.law);
            const int turning = static_cast<int>(sim.scene().addMotion({.angularVelocity = Vec3(0, 0, 0.5)}));
            sim.scene().addCylinderWall(Vec3::Zero(), Vec3::UnitZ(), 4, species, turning);
            sim.scene().addMeshWall(flatSquare(10), species, turning);
            for (int k = 0; k < 40; ++k)
                sim.scene().addParticle(Vec3(-2.5 + 0.7 * (k % 8), -1.5 + 0.7 * (k / 8), 0.5 + 0.1 * (k % 3)), sphere.radius,
                                        species, Vec3(0.1 * (k % 3), -0.1, 0));
            if (particleOnMotion) sim.scene().addFixedParticle(Vec3(3, 0, 0.3), 0.2, species, turning);
        };
        s->settings().stepper.driftPass = driftPass;
        s->runFor(1e-4, 2);
        return s;
    };
    const auto onePass = run(true, false), plain = run(false, false);
    EXPECT_EQ(onePass->integrator().statistics().driftPassSteps, 20000u);
    EXPECT_EQ(plain->integrator().statistics().driftPassSteps, 0u);
    EXPECT_GT(onePass->state().pairList.wallPairs.size(), 40u);  // (the floor's triangles and the mantle)
    expectSameParticles(onePass->scene().particles(), plain->scene().particles());
    for (std::size_t v = 0; v < plain->state().meshes[0]->mesh.vertexCount(); ++v)
        ASSERT_TRUE(sameBits(onePass->state().meshes[0]->mesh.vertex(v), plain->state().meshes[0]->mesh.vertex(v)));
    EXPECT_EQ(run(true, true)->integrator().statistics().driftPassSteps, 0u);
}

// Triangle meshes as walls (Scene::addMeshWall, Walls/MeshWalls.h; Theory/ContactLaws.md
// "Triangle meshes"): one wall per triangle, each counting the faces, edges and vertices that are
// its to count, so that a sphere meets every local minimum of its distance to the mesh once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "IO/RestartFile.h"
#include "TestHelpers.h"
#include "Walls/MeshContact.h"

using namespace talus;
using namespace talus::test;

namespace {

// The square [-n/2, n/2]^2 of n x n unit cells at heights height(x, y), each cell split along its
// diagonal from (x, y) to (x + 1, y + 1): interior vertices are met by six triangles.
std::vector<TriangleCorners> heightField(int n, double (*height)(double, double)) {
    std::vector<TriangleCorners> triangles;
    auto at = [&](int i, int j) {
        const double x = i - 0.5 * n, y = j - 0.5 * n;
        return Vec3(x, y, height(x, y));
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return triangles;
}
double flat(double, double) { return 0; }
double bumpy(double x, double y) { return 0.3 * std::sin(1.3 * x + 0.4) * std::cos(0.9 * y) + 0.05 * x; }

struct Floor {
    double radius = 0.3, mass = 1, g = 1;
    LinearSpringDashpot law = LinearSpringDashpot::fromCollision(0.01, 0.5, 1).withFriction(0.5);
    double density() const { return mass / (4.0 / 3.0 * pi * std::pow(radius, 3)); }
};

}  // namespace

// Each triangle's own answer (Wall::gapTo through triangleGap): the triangles that count a
// contact closer than the radius give the contacts of sphereMeshContacts, which looks at the whole
// mesh at once, for random centres over a bumpy mesh (faces, edges and vertices, convex and
// concave).
TEST(MeshWall, TrianglesCountTheContactsOfTheWholeMesh) {
    const TriangleMesh mesh(heightField(6, bumpy));
    std::vector<std::uint32_t> all(mesh.triangleCount());
    for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> across(-2.8, 2.8), up(-0.6, 0.8);
    const double radius = 0.45;
    int contacts = 0, edgeOrVertex = 0, several = 0;
    for (int n = 0; n < 2000; ++n) {
        const Vec3 x(across(random), across(random), up(random));
        const std::vector<MeshContact> whole = sphereMeshContacts(mesh, x, radius, all);
        std::vector<double> expected, counted;
        for (const MeshContact& c : whole) {
            expected.push_back(c.overlap);
            edgeOrVertex += c.feature != MeshFeature::face;
        }
        for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
            const TriangleGap g = triangleGap(mesh, t, x);
            if (g.counts && g.distance < radius) counted.push_back(radius - g.distance);
        }
        std::sort(expected.begin(), expected.end());
        std::sort(counted.begin(), counted.end());
        ASSERT_EQ(counted.size(), expected.size()) << "centre " << x.transpose();
        for (std::size_t k = 0; k < counted.size(); ++k) EXPECT_EQ(counted[k], expected[k]) << "centre " << x.transpose();
        contacts += static_cast<int>(whole.size());
        several += whole.size() > 1;
    }
    std::printf("[ measured ] %d contacts, %d at an edge or a vertex; %d centres touch twice or more\n", contacts,
                edgeOrVertex, several);
    EXPECT_GT(edgeOrVertex, 50);
    EXPECT_GT(several, 50);
}

// A sphere resting on a flat floor of 32 triangles feels its weight once, over a face, on an edge
// of two triangles (a cell's side, a cell's diagonal) and on a vertex of six, and a hair off it:
// its overlap is m g / kn, as on a plane.
TEST(MeshWall, ASphereOnAFloorOfTrianglesFeelsItsWeightOnce) {
    const Floor floor;
    for (const Vec3& at : {Vec3(0.3, 0.7, 0), Vec3(0, 0.4, 0), Vec3(0.5, 0.5, 0), Vec3(0, 0, 0), Vec3(1e-12, -1e-12, 0),
                           Vec3(-1, 1, 0)}) {
        SceneSimulation s;
        s.setup = [&](SceneSimulation& sim) {
            sim.scene().setGravity(Vec3(0, 0, -floor.g));
            sim.scene().setDomain(Vec3(-3, -3, -2), Vec3(3, 3, 4));
            const auto species = sim.scene().addSpecies("grains", floor.density(), floor.law);
            sim.scene().addMeshWall(TriangleMesh(heightField(4, flat)), species);
            sim.scene().addParticle(at + Vec3(0, 0, floor.radius), floor.radius, species);
        };
        s.runFor(2e-4, 2);
        const double overlap = floor.radius - s.scene().particles().position[0].z();
        EXPECT_NEAR(overlap, floor.mass * floor.g / floor.law.normalStiffness, 1e-12) << "at " << at.transpose();
        // (Rounding tilts the normal at an edge or a vertex by about 1e-16: a sideways drift.)
        EXPECT_LT((s.scene().particles().position[0] - at).head<2>().norm(), 1e-10) << "at " << at.transpose();
    }
}

// A sphere rolling over the floor of triangles, across cell sides and diagonals, moves as on a
// plane wall: the same path and velocity to 1e-10 after 3 time units.
TEST(MeshWall, ASphereRollsAcrossEdgesAsOnAPlane) {
    const Floor floor;
    const double overlap = floor.mass * floor.g / floor.law.normalStiffness;
    auto roll = [&](bool mesh) {
        SceneSimulation s;
        s.setup = [&](SceneSimulation& sim) {
            sim.scene().setGravity(Vec3(0, 0, -floor.g));
            sim.scene().setDomain(Vec3(-3, -3, -2), Vec3(3, 3, 4));
            const auto species = sim.scene().addSpecies("grains", floor.density(), floor.law);
            if (mesh)
                sim.scene().addMeshWall(TriangleMesh(heightField(4, flat)), species);
            else
                sim.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
            const Vec3 velocity(0.8, 0.3, 0);
            const std::size_t i = sim.scene().addParticle(Vec3(-1.7, -0.9, floor.radius - overlap), floor.radius, species,
                                                          velocity);
            // rolling: w x (-r z) = v
            sim.scene().particles().angularVelocity[i] = Vec3::UnitZ().cross(velocity) / floor.radius;
        };
        s.runFor(1e-4, 3);
        return std::pair{s.scene().particles().position[0], s.scene().particles().velocity[0]};
    };
    const auto [onMesh, meshVelocity] = roll(true);
    const auto [onPlane, planeVelocity] = roll(false);
    EXPECT_GT(onMesh.x(), 0.6);  // (crossed 2 cell sides and 4 diagonals)
    EXPECT_LT((onMesh - onPlane).norm(), 1e-10);
    EXPECT_LT((meshVelocity - planeVelocity).norm(), 1e-10);
}

// A run of spheres falling onto the bumpy mesh, resting or turning about a tilted axis through
// (0.3, 0, 0), saved and continued from its restart file, goes on as the run that never stopped:
// the meshes are in the file with their motion and merging tolerance (format 10).
void expectRestartContinuesExactly(bool turning) {
    const Floor floor;
    auto setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(Vec3(0, 0, -floor.g));
        sim.scene().setDomain(Vec3(-3, -3, -2), Vec3(3, 3, 4));
        const auto species = sim.scene().addSpecies("grains", floor.density(), floor.law);
        const int motion = turning ? static_cast<int>(sim.scene().addMotion(
                                         {.angularVelocity = Vec3(0.05, 0.02, 0.3), .centre = Vec3(0.3, 0, 0)}))
                                   : -1;
        sim.scene().addMeshWall(TriangleMesh(heightField(6, bumpy)), species, motion);
        for (int k = 0; k < 8; ++k)
            sim.scene().addParticle(Vec3(-2.3 + 0.65 * k, 0.3 * std::sin(k), 0.9 + 0.1 * (k % 3)), floor.radius, species,
                                    Vec3(0.2, -0.1 * (k % 2), 0));
    };
    const double timeStep = 1e-4;
    const int saved = turning ? 12000 : 15000, total = saved + 10000;  // (saved with spheres on the mesh)
    const std::string name = turning ? "meshwall_turning_restart" : "meshwall_restart";
    SceneSimulation first;
    first.setup = setup;
    first.settings().name = name;
    first.settings().timeStep = timeStep;
    first.settings().progressInterval = 1e9;
    first.solveOrThrow({"--end-time", std::to_string(saved * timeStep), "--output-interval",
                        std::to_string(saved * timeStep), "--vtu", "off"});
    ASSERT_GT(first.state().pairList.wallPairs.size(), 0u);
    SimulationState read;
    readRestartFile(name + ".restart", read);
    ASSERT_EQ(read.meshes.size(), 1u);
    EXPECT_EQ(read.meshes[0]->mesh.triangleCount(), 72u);
    EXPECT_EQ(read.meshes[0]->motion, turning ? 0 : -1);
    EXPECT_EQ(read.meshes[0]->mesh.tolerance(), first.state().meshes[0]->mesh.tolerance());
    EXPECT_EQ(read.walls[5].mesh, read.meshes[0].get());
    EXPECT_EQ(read.walls[5].triangle, 5u);
    // A travel that is not a distance is refused, naming it (the mesh line's seventh number).
    std::string text = readWholeFile(name + ".restart");
    const std::size_t meshLine = text.find('\n', text.find("\nmeshes 1\n") + 1) + 1;
    std::istringstream fields(text.substr(meshLine, text.find('\n', meshLine) - meshLine));
    std::vector<std::string> numbers{std::istream_iterator<std::string>(fields), std::istream_iterator<std::string>()};
    ASSERT_EQ(numbers.size(), 8u);
    numbers[6] = "-1";
    std::string line;
    for (const std::string& number : numbers) line += "   " + number;
    text.replace(meshLine, text.find('\n', meshLine) - meshLine, line);
    writeWholeFile(name + "-bad.restart", text);
    SimulationState bad;
    expectError([&] { readRestartFile(name + "-bad.restart", bad); }, {"travel since the list build"});

    SceneSimulation restarted;
    restarted.settings().progressInterval = 1e9;
    restarted.solveOrThrow({"--restart", name + ".restart", "--end-time", std::to_string(total * timeStep),
                            "--files", "off"});
    SceneSimulation uninterrupted;
    uninterrupted.setup = setup;
    uninterrupted.settings().timeStep = timeStep;
    uninterrupted.settings().progressInterval = 1e9;
    uninterrupted.solveOrThrow(stepsWithoutFiles(timeStep, total));
    ASSERT_EQ(restarted.step(), static_cast<std::uint64_t>(total));
    expectSameContinuation(restarted, uninterrupted);
    for (std::size_t v = 0; v < restarted.state().meshes[0]->mesh.vertexCount(); ++v)
        ASSERT_TRUE(sameBits(restarted.state().meshes[0]->mesh.vertex(v), uninterrupted.state().meshes[0]->mesh.vertex(v)));
}

TEST(MeshWall, ARestartContinuesExactly) { expectRestartContinuesExactly(false); }
TEST(MeshWall, ARestartContinuesExactlyWhileTheMeshTurns) { expectRestartContinuesExactly(true); }

TEST(MeshWall, BadUseIsNamed) {
    auto scene = [](SceneSimulation& sim) {
        sim.scene().setDomain(Vec3(-3, -3, -2), Vec3(3, 3, 4));
        const auto species = sim.scene().addSpecies("grains", 1, LinearSpringDashpot::fromCollision(0.01, 0.5, 1));
        MeshSource source;
        source.name = "ASCII STL file floor.stl";
        sim.scene().addMeshWall(TriangleMesh(heightField(2, flat), source), species);
        return species;
    };
    SceneSimulation removing;
    removing.setup = [&](SceneSimulation& sim) {
        scene(sim);
        sim.scene().removeWall(3);
    };
    expectError([&] { removing.runFor(1e-4, 1e-3); }, {"removeWall", "wall 3 is a triangle of a mesh"});
    SceneSimulation shaped;
    shaped.setup = [&](SceneSimulation& sim) {
        const auto species = scene(sim);
        sim.scene().addSuperquadric(Vec3(0, 0, 1), sim.scene().addShape(Superquadric::ellipsoid(0.4, 0.2, 0.2)), species);
    };
    expectError([&] { shaped.runFor(1e-4, 1e-3); }, {"mesh wall (ASCII STL file floor.stl) meets spheres only",
                                                    "is a superquadric"});
    SceneSimulation noSpecies;
    noSpecies.setup = [](SceneSimulation& sim) {
        sim.scene().addSpecies("grains", 1, LinearSpringDashpot::fromCollision(0.01, 0.5, 1));
        sim.scene().addMeshWall(TriangleMesh(heightField(2, flat)), 4);
    };
    expectError([&] { noSpecies.runFor(1e-4, 1e-3); }, {"mesh wall: species 4 does not exist"});
    SceneSimulation noMotion;
    noMotion.setup = [](SceneSimulation& sim) {
        const auto species = sim.scene().addSpecies("grains", 1, LinearSpringDashpot::fromCollision(0.01, 0.5, 1));
        sim.scene().addMeshWall(TriangleMesh(heightField(2, flat)), species, 2);
    };
    expectError([&] { noMotion.runFor(1e-4, 1e-3); }, {"mesh wall: motion 2 does not exist"});
}

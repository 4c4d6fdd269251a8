// The description of the restart file in Formats/RestartFormat.h agrees with what the kernel
// writes: talus-cg reads the domain, wall and particle lines by the positions named there, so a
// field the writer moves without the description would be read as another. Each field of a small
// state gets a value no other field has, and is looked for at its named position.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "Formats/RestartFormat.h"
#include "IO/RestartFile.h"
#include "Shapes/Superquadric.h"
#include "SimulationState.h"

using namespace talus;
namespace restart = talus::formats::restart;

namespace {

// The words of the first line that starts with `key` (the key dropped), and of the `item`-th line
// after it (the key kept: an item line has none).
std::vector<std::string> wordsOf(const std::string& path, const std::string& key, int item = -1) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string first;
        words >> first;
        if (first != key) continue;
        for (int k = 0; k <= item; ++k) std::getline(in, line);
        std::istringstream itemWords(line);
        std::vector<std::string> result;
        for (std::string w; (item < 0 ? words : itemWords) >> w;) result.push_back(w);
        return result;
    }
    ADD_FAILURE() << "no line '" << key << "' in " << path;
    return {};
}

// Two particles (the second fixed, of species 1, moving with motion 0) with distinct values.
SimulationState distinctState(bool shapes) {
    SimulationState s;
    s.time = 0.125;
    s.step = 17;
    s.domain.lo = Vec3(-1, -2, -3);
    s.domain.hi = Vec3(4, 5, 6);
    s.domain.periodic = {true, false, true};
    s.species.add("sand", 11, LinearSpringDashpot::fromCollision(0.01, 0.8, 0.5));
    s.species.add("glass", 12, LinearSpringDashpot::fromCollision(0.01, 0.9, 0.5));
    s.motions.push_back(PrescribedMotion{});
    s.walls.push_back(Wall{});
    Wall& w = s.walls.back();
    w.normal = Vec3(0.25, 0.5, 0.75);
    w.point = Vec3(1.5, 2.5, 3.5);
    w.species = 1;
    w.motion = 0;
    w.radius = 9.5;
    ParticleStore& p = s.particles;
    if (shapes) {
        p.enableShapes();
        s.shapes.push_back(Superquadric(4, 2, 1, 0.5, 0.75));  // (every field distinct)
    }
    for (int i = 0; i < 2; ++i) {
        const double b = 100 * (i + 1);  // particle i's values: b + 1, b + 2, ...
        p.id.push_back(7 + static_cast<std::uint64_t>(i));
        p.position.push_back(Vec3(b + 1, b + 2, b + 3));
        p.velocity.push_back(Vec3(b + 4, b + 5, b + 6));
        p.angularVelocity.push_back(Vec3(b + 7, b + 8, b + 9));
        p.force.push_back(Vec3(b + 10, b + 11, b + 12));
        p.torque.push_back(Vec3(b + 13, b + 14, b + 15));
        p.radius.push_back(b + 16);
        p.mass.push_back(b + 17);
        p.invMass.push_back(i == 1 ? 0.0 : 1 / (b + 17));
        p.invInertia.push_back(b + 19);
        p.species.push_back(static_cast<std::uint32_t>(i));
        p.fixed.push_back(static_cast<std::uint8_t>(i));
        p.motion.push_back(i == 1 ? 0 : -1);
        if (shapes) {
            p.orientation.push_back(Quat(0.5, 0.5, 0.5, 0.5));
            p.angularMomentum.push_back(Vec3(b + 20, b + 21, b + 22));
            p.principalInertia.push_back(Vec3(b + 23, b + 24, b + 25));
            p.shape.push_back(i == 1 ? 0 : -1);
        }
    }
    s.nextId = 9;
    return s;
}

}  // namespace

TEST(RestartFormat, FieldsAreWhereTheDescriptionSays) {
    for (const bool shapes : {false, true}) {
        const std::string path = shapes ? "restartformat_shapes.restart" : "restartformat_spheres.restart";
        writeRestartFile(path, distinctState(shapes));

        const auto first = wordsOf(path, restart::magicWords[0]);
        ASSERT_EQ(first.size(), 2u);
        EXPECT_EQ(first[0], restart::magicWords[1]);
        EXPECT_EQ(first[1], std::to_string(restart::version));

        const auto time = wordsOf(path, restart::key::time);
        ASSERT_EQ(time.size(), std::size_t(restart::timeFields));
        EXPECT_EQ(time[restart::time], "0.125");
        EXPECT_EQ(time[restart::step], "17");

        const auto domain = wordsOf(path, restart::key::domain);
        ASSERT_EQ(domain.size(), std::size_t(restart::domainFields));
        EXPECT_EQ(domain[restart::domainLower + 1], "-2");
        EXPECT_EQ(domain[restart::domainUpper + 2], "6");
        EXPECT_EQ(domain[restart::periodic + 0], "1");
        EXPECT_EQ(domain[restart::periodic + 1], "0");

        const auto species = wordsOf(path, restart::key::species, 1);
        ASSERT_GE(species.size(), std::size_t(restart::speciesFieldsAtLeast));
        EXPECT_EQ(species[restart::speciesName], "glass");
        EXPECT_EQ(species[restart::density], "12");
        EXPECT_EQ(species[restart::law], "LinearSpringDashpot");

        const auto wall = wordsOf(path, restart::key::walls, 0);
        ASSERT_EQ(wall.size(), std::size_t(restart::wallFields));
        EXPECT_EQ(wall[restart::wallNormal + 2], "0.75");
        EXPECT_EQ(wall[restart::wallPoint + 1], "2.5");
        EXPECT_EQ(wall[restart::wallSpecies], "1");
        EXPECT_EQ(wall[restart::wallMotion], "0");
        EXPECT_EQ(wall[restart::wallRadius], "9.5");

        const auto shapesLine = wordsOf(path, restart::key::shapes);
        ASSERT_EQ(shapesLine.size(), std::size_t(restart::shapesFields));
        EXPECT_EQ(shapesLine[restart::shapesFlag], shapes ? "1" : "0");
        EXPECT_EQ(shapesLine[restart::shapeCount], shapes ? "1" : "0");
        if (shapes) {
            const auto shape = wordsOf(path, restart::key::shapes, 0);
            ASSERT_EQ(shape.size(), std::size_t(restart::shapeFields));
            EXPECT_EQ(shape[restart::semiAxes], "4");
            EXPECT_EQ(shape[restart::semiAxes + 2], "1");
            EXPECT_EQ(shape[restart::blockiness], "0.5");
            EXPECT_EQ(shape[restart::blockiness + 1], "0.75");
        }

        const auto particles = wordsOf(path, restart::key::particles);
        ASSERT_EQ(particles.size(), std::size_t(restart::particlesFields));
        EXPECT_EQ(particles[restart::particleCount], "2");
        EXPECT_EQ(particles[restart::nextId], "9");

        const auto p = wordsOf(path, restart::key::particles,
                               1);  // the second particle: b = 200
        ASSERT_EQ(p.size(), std::size_t(shapes ? restart::shapedFields : restart::sphereFields));
        EXPECT_EQ(p[restart::id], "8");
        EXPECT_EQ(p[restart::position + 2], "203");
        EXPECT_EQ(p[restart::velocity], "204");
        EXPECT_EQ(p[restart::angularVelocity + 1], "208");
        EXPECT_EQ(p[restart::force + 2], "212");
        EXPECT_EQ(p[restart::torque], "213");
        EXPECT_EQ(p[restart::radius], "216");
        EXPECT_EQ(p[restart::mass], "217");
        EXPECT_EQ(p[restart::inverseMass], "0");
        EXPECT_EQ(p[restart::inverseInertia], "219");
        EXPECT_EQ(p[restart::particleSpecies], "1");
        EXPECT_EQ(p[restart::fixed], "1");
        EXPECT_EQ(p[restart::motion], "0");
        if (shapes) {
            EXPECT_EQ(p[restart::orientation + 3], "0.5");
            EXPECT_EQ(p[restart::angularMomentum + 2], "222");
            EXPECT_EQ(p[restart::principalInertia], "223");
            EXPECT_EQ(p[restart::shape], "0");
        }
    }
}

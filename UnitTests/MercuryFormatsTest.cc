// The .data, .fstat and .ene files (Documentation/FileFormats/): MercuryDPM's column layouts,
// checked against MercuryDPM's own files in shared/reference, and their numbers checked against
// each other (contact geometry and energies recomputed from the .data frame).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ContactTestScenes.h"

using namespace talus;
using namespace talus::test;

namespace {

using Row = std::vector<double>;

std::vector<std::string> lines(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in) << "cannot read " << path;
    std::vector<std::string> result;
    for (std::string line; std::getline(in, line);) result.push_back(line);
    return result;
}

// The numbers of a line ('#' and words that are not numbers are skipped).
Row numbers(const std::string& line) {
    std::istringstream in(line);
    Row row;
    for (std::string word; in >> word;) {
        char* end = nullptr;
        const double x = std::strtod(word.c_str(), &end);
        if (end == word.c_str() + word.size()) row.push_back(x);
    }
    return row;
}

std::size_t fields(const std::string& line) {
    std::istringstream in(line);
    std::size_t n = 0;
    for (std::string word; in >> word;) ++n;
    return n;
}

// A scene with every kind of contact: two mobile spheres pressed together, one pressed on the
// floor, and one pressed on a fixed sphere; gravity off so the frame at t = 0 is the set-up.
void writeScene(const std::string& name) {
    TestScene scene;
    scene.setup = [](TestScene& s) {
        s.scene().setGravity(Vec3::Zero());
        s.scene().setDomain(Vec3(-5, -5, -1), Vec3(5, 5, 5));
        const auto a = s.scene().addSpecies("a", unitMassDensity, LinearSpringDashpot::fromCollision(0.005, 0.5, 0.5).withFriction(0.5));
        const auto b = s.scene().addSpecies("b", 2 * unitMassDensity, LinearSpringDashpot::fromCollision(0.005, 0.5, 0.5));
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), a);
        s.scene().addParticle(Vec3(0, 0, 2), 0.5, a, Vec3(0.1, 0, 0));
        s.scene().addParticle(Vec3(0.99, 0, 2), 0.5, b, Vec3(0, 0.2, 0), Vec3(0, 0, 1));
        s.scene().addParticle(Vec3(3, 0, 0.49), 0.5, a, Vec3(0, 0, -0.1));
        s.scene().addFixedParticle(Vec3(-3, 0, 2), 0.5, a);
        s.scene().addParticle(Vec3(-3, 0.98, 2), 0.5, b);
    };
    scene.settings().name = name;
    scene.settings().timeStep = 1e-4;
    scene.settings().endTime = 1e-3;
    scene.settings().progressInterval = 1e9;
    scene.settings().writeVtu = false;
    scene.solveOrThrow({});
}

const std::string reference = std::string(TALUS_SHARED_DIR) + "/reference/mercury/chute/Bidi_on";

}  // namespace

// Field counts of every kind of line equal those of MercuryDPM's files.
TEST(MercuryFormats, ColumnLayoutsMatchMercuryDPM) {
    if (!std::ifstream(reference + ".data")) GTEST_SKIP() << "no MercuryDPM reference files at " << reference;
    writeScene("formats_layout");
    const auto ours = lines("formats_layout.data"), theirs = lines(reference + ".data");
    EXPECT_EQ(fields(ours[0]), fields(theirs[0]));  // N t xmin ymin zmin xmax ymax zmax
    EXPECT_EQ(numbers(ours[0])[0], 5);
    for (std::size_t k = 1; k <= 5; ++k) EXPECT_EQ(fields(ours[k]), fields(theirs[1])) << ours[k];

    const auto fstat = lines("formats_layout.fstat"), refFstat = lines(reference + ".fstat");
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(fstat[k][0], '#');
        EXPECT_EQ(fields(fstat[k]), fields(refFstat[k])) << fstat[k];
    }
    EXPECT_EQ(fields(fstat[3]), fields(refFstat[3]));

    const auto ene = lines("formats_layout.ene"), refEne = lines(reference + ".ene");
    EXPECT_EQ(fields(ene[1]), fields(refEne[0]));  // ours has a header line first
}

// The first frame recomputed from the .data file: .fstat normals, overlaps and line counts, and
// the .ene energies and centre of mass.
TEST(MercuryFormats, FstatAndEneAgreeWithTheDataFrame) {
    writeScene("formats_values");
    const auto data = lines("formats_values.data");
    const std::size_t n = static_cast<std::size_t>(numbers(data[0])[0]);
    std::vector<Row> particle;  // x y z vx vy vz r 0 0 0 wx wy wz species, by id (= line)
    for (std::size_t k = 1; k <= n; ++k) particle.push_back(numbers(data[k]));

    // .fstat frame 0: three header lines, then contact lines until the next '#'.
    const auto fstat = lines("formats_values.fstat");
    std::map<std::pair<int, int>, int> sides;
    // The elastic energy of the linear springs, 1/2 kn dn^2 + 1/2 kt xi^2 summed over the contacts
    // (each once): dn from the .data positions, |xi| the .fstat's tangential overlap. Every pair
    // law of the scene has the same kn and kt (species a and b are made with the same collision
    // time, restitution and reduced mass; a mixed pair takes their mean).
    const LinearSpringDashpot law = LinearSpringDashpot::fromCollision(0.005, 0.5, 0.5);
    double springEnergy = 0, tangentialEnergy = 0;
    std::size_t k = 3;
    for (; k < fstat.size() && fstat[k][0] != '#'; ++k) {
        const Row c = numbers(fstat[k]);
        ASSERT_EQ(c.size(), 16u);
        const int i = static_cast<int>(c[1]), j = static_cast<int>(c[2]);
        const bool firstSide = sides.count({j, i}) == 0;
        ++sides[{i, j}];
        const Vec3 xi(particle[i][0], particle[i][1], particle[i][2]);
        const Vec3 n(c[10], c[11], c[12]);
        EXPECT_NEAR(n.norm(), 1, 1e-9);
        const double overlap = j < 0 ? particle[i][6] - xi.z()
                                     : particle[i][6] + particle[j][6] -
                                           (xi - Vec3(particle[j][0], particle[j][1], particle[j][2])).norm();
        if (firstSide) {
            const double tangential = 0.5 * law.tangentialStiffness * c[7] * c[7];
            springEnergy += 0.5 * law.normalStiffness * overlap * overlap + tangential;
            tangentialEnergy += tangential;
        }
        if (j < 0) {  // the floor z = 0; MercuryDPM writes the normal into the wall
            EXPECT_EQ(j, -1);
            EXPECT_NEAR((n - Vec3(0, 0, -1)).norm(), 0, 1e-9);
            EXPECT_NEAR(c[6], overlap, 1e-9);  // overlap r - distance
            continue;
        }
        const Vec3 xj(particle[j][0], particle[j][1], particle[j][2]);
        EXPECT_NEAR((n - (xi - xj).normalized()).norm(), 0, 1e-9) << fstat[k];
        EXPECT_NEAR(c[6], overlap, 1e-9);
        EXPECT_GE(c[8], 0);                        // pressed together at rest: repulsive
        EXPECT_LE(c[9], 0.5 * std::abs(c[8]) + 1e-12);  // Coulomb, mu <= 0.5
    }
    // Two mobile spheres: both sides; a mobile on a fixed sphere: the mobile side only; the floor
    // once.
    EXPECT_EQ(sides[std::make_pair(0, 1)], 1);
    EXPECT_EQ(sides[std::make_pair(1, 0)], 1);
    EXPECT_EQ(sides[std::make_pair(4, 3)], 1);
    EXPECT_EQ(sides.count(std::make_pair(3, 4)), 0u);
    EXPECT_EQ(sides[std::make_pair(2, -1)], 1);
    EXPECT_EQ(sides.size(), 4u);

    // .ene frame 0 against sums over the mobile particles of the .data frame (density 6/pi for
    // species 0, 12/pi for species 1; gravity is off, so the gravitational energy is 0).
    const Row e = numbers(lines("formats_values.ene")[1]);
    ASSERT_EQ(e.size(), 9u);
    double kinetic = 0, rotational = 0, mass = 0;
    Vec3 moment = Vec3::Zero();
    for (std::size_t id = 0; id < n; ++id) {
        if (id == 3) continue;  // the fixed sphere
        const Row& q = particle[id];
        const double m = sphereMass(q[6], q[13] == 0 ? unitMassDensity : 2 * unitMassDensity);
        kinetic += 0.5 * m * (q[3] * q[3] + q[4] * q[4] + q[5] * q[5]);
        rotational += 0.5 * 0.4 * m * q[6] * q[6] * (q[10] * q[10] + q[11] * q[11] + q[12] * q[12]);
        moment += m * Vec3(q[0], q[1], q[2]);
        mass += m;
    }
    EXPECT_EQ(e[0], 0);
    EXPECT_EQ(e[1], 0);
    EXPECT_NEAR(e[2], kinetic, 1e-9 * kinetic);
    EXPECT_NEAR(e[3], rotational, 1e-9 * rotational);
    // The springs: overlaps 0.02, 0.01 and 0.01, 1/2 kn (4 + 1 + 1) 1e-4 = 62.1003 with
    // kn = 2.07e5, and the tangential spring of the pair (0, 1), whose contact points move sideways
    // at |vt| = 0.295: |xi| = |vt| dt = 2.95e-5 after the first step, 2.6e-5 of energy, which the
    // check sees. The .ene file writes 10 digits: 62.10037022, 5e-9 at most off.
    EXPECT_NEAR(e[4], springEnergy, 1e-8);
    EXPECT_GT(tangentialEnergy, 100 * 1e-8);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(e[5 + a], moment[a] / mass, 1e-9);
    EXPECT_EQ(e[8], 3);  // contacts, each once: the mobile pair, the mobile-fixed pair, the floor
}

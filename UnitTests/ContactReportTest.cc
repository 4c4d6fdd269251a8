// The contacts of an output step (Contacts/ContactReport.h, ContactRecords): without .fstat the
// kernel keeps only their number and elastic energy, which must be what it sums from the records
// when .fstat is written.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "ContactTestScenes.h"
#include "TestHelpers.h"

using namespace talus;
using namespace talus::test;

namespace {

// Spheres settling in a box of walls (pairs in the batched and the scalar paths, wall contacts),
// 4000 steps with a frame every 200.
void settleInBox(SceneSimulation& s, const std::string& name, bool fstat) {
    s.setup = [](SceneSimulation& scene) {
        const double side = 3.6;
        scene.scene().setGravity(Vec3(0, 0, -1));
        scene.scene().setDomain(Vec3::Zero(), Vec3(side, side, 8.4));
        const auto species = scene.scene().addSpecies("glass", unitMassDensity, LinearSpringDashpot::fromCollision(0.05, 0.5, 0.5).withFriction(0.4));
        addOpenBox(scene, side, species);
        std::mt19937_64 random(11);
        std::uniform_real_distribution<double> radiusOf(0.4, 0.5), velocityOf(-0.5, 0.5);
        for (int k = 0; k < 5; ++k)
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i)
                    scene.scene().addParticle(1.2 * Vec3(i + 0.5, j + 0.5, k + 0.5), radiusOf(random), species,
                                      Vec3(velocityOf(random), velocityOf(random), velocityOf(random)));
    };
    s.settings().name = name;
    s.settings().timeStep = 1e-3;
    s.settings().progressInterval = 1e9;
    s.solveOrThrow({"--end-time", "4", "--output-interval", "0.2", "--vtu", "off", "--fstat", fstat ? "on" : "off"});
}

// The contact counts of the .ene file (its last column), one per frame.
std::vector<long> eneContactCounts(const std::string& path) {
    std::istringstream in(readWholeFile(path));
    std::vector<long> counts;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == 't' || line[0] == '#') continue;
        counts.push_back(std::stol(line.substr(line.find_last_of(' ') + 1)));
    }
    return counts;
}

}  // namespace

TEST(ContactRecords, WithoutFstatTheEneFileAndEnergiesAreTheSame) {
    SceneSimulation withFstat, without;
    settleInBox(withFstat, "contactrecords_fstat", true);
    settleInBox(without, "contactrecords_plain", false);
    EXPECT_FALSE(readWholeFile("contactrecords_fstat.fstat").empty());
    EXPECT_FALSE(std::ifstream("contactrecords_plain.fstat").good()) << "--fstat off still wrote a .fstat file";
    // The same trajectory, and the same number and elastic energy of the contacts in every frame.
    EXPECT_EQ(readWholeFile("contactrecords_fstat.data"), readWholeFile("contactrecords_plain.data"));
    EXPECT_EQ(readWholeFile("contactrecords_fstat.ene"), readWholeFile("contactrecords_plain.ene"));
    EXPECT_TRUE(sameBits(withFstat.energies().elastic, without.energies().elastic));
    // Not a vacuous comparison: the spheres have fallen into a pile whose contacts store energy
    // (more contacts than spheres; 57 in the run that set this bound).
    const std::vector<long> counts = eneContactCounts("contactrecords_plain.ene");
    ASSERT_EQ(counts.size(), 21u);  // t = 0, 0.2, ..., 4
    EXPECT_GT(counts.back(), 45);   // 45 spheres
    EXPECT_GT(without.energies().elastic, 0);
    std::printf("[ measured ] contacts at the last frame %ld, elastic energy %.6g\n", counts.back(),
                without.energies().elastic);
}

// The LAMMPS data-file reader (IO/LammpsDataFile.h): the peers' start files, and malformed files.
#include <gtest/gtest.h>

#include <fstream>

#include "IO/LammpsDataFile.h"
#include "TestHelpers.h"

using namespace talus;
using namespace talus::test;

namespace {

const std::string valid =
    "title line\n\n2 atoms\n2 atom types\n\n0 20 xlo xhi\n0 10 ylo yhi\n-1 30 zlo zhi\n\n"
    "Atoms # sphere\n\n"
    "7 1 1 1.90985931710274 1.5 2.5 0.25\n"
    "9 2 0.79 1.90985931710274 3 4 5\n\n"
    "Velocities\n\n9 0.1 0.2 0.3 1 2 3\n";

}  // namespace

TEST(LammpsDataFile, ReadsAtomsVelocitiesAndBox) {
    writeWholeFile("lammps_valid.data", valid);
    const LammpsData d = readLammpsData("lammps_valid.data");
    EXPECT_EQ(d.types, 2);
    EXPECT_EQ(d.lo, Vec3(0, 0, -1));
    EXPECT_EQ(d.hi, Vec3(20, 10, 30));
    ASSERT_EQ(d.atoms.size(), 2u);
    EXPECT_EQ(d.atoms[0].id, 7u);
    EXPECT_EQ(d.atoms[0].type, 1);
    EXPECT_EQ(d.atoms[0].position, Vec3(1.5, 2.5, 0.25));
    EXPECT_EQ(d.atoms[0].velocity, Vec3::Zero());  // no velocity line: at rest
    EXPECT_EQ(d.atoms[1].diameter, 0.79);
    EXPECT_EQ(d.atoms[1].velocity, Vec3(0.1, 0.2, 0.3));
    EXPECT_EQ(d.atoms[1].angularVelocity, Vec3(1, 2, 3));
}

// The settled bed of the peer benchmark (shared/peers/README.md): 200 base spheres (type 1) and
// 1000 + 2000 flowing ones (types 2 and 3) in a 20 x 10 box.
TEST(LammpsDataFile, ReadsThePeersSettledBed) {
    const std::string path = std::string(TALUS_SHARED_DIR) + "/peers/data/chute_B_settled.data";
    if (!std::ifstream(path)) GTEST_SKIP() << "no peer start file at " << path;
    const LammpsData d = readLammpsData(path);
    int count[4] = {0, 0, 0, 0};
    for (const LammpsAtom& a : d.atoms) ++count[a.type];
    EXPECT_EQ(count[1], 200);
    EXPECT_EQ(count[2], 1000);
    EXPECT_EQ(count[3], 2000);
    EXPECT_EQ(d.hi - d.lo, Vec3(20, 10, 31));
}

TEST(LammpsDataFile, MalformedFilesNameFileAndLine) {
    struct Case {
        std::string text, expected;
    };
    auto replaced = [](const std::string& from, const std::string& to) {
        std::string t = valid;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    const std::vector<Case> cases = {
        {replaced("9 2 0.79", "9 3 0.79"), "line 13: atom type 3 is not in 1..2"},
        {replaced("1.5 2.5 0.25", "1.5 x 0.25"), "line 12: bad number 'x'"},
        {replaced("9 2 0.79", "7 2 0.79"), "line 13: atom id 7 appears twice"},
        {replaced("1 1.90985931710274 1.5", "-1 1.90985931710274 1.5"), "line 12: the diameter must be positive"},
        {replaced("2 atoms", "3 atoms"), "declares 3 atoms, the Atoms section has 2"},
        {replaced("9 0.1 0.2 0.3 1 2 3", "8 0.1 0.2 0.3 1 2 3"), "line 17: velocity of unknown atom id 8"},
        {replaced("9 0.1 0.2 0.3 1 2 3", "9 0.1 0.2"), "line 17: a velocity line has 7 words"},
        {replaced("0 20 xlo xhi", "20 0 xlo xhi"), "line 6: empty box along x"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.expected);
        writeWholeFile("lammps_bad.data", c.text);
        expectError([] { readLammpsData("lammps_bad.data"); }, {"lammps_bad.data", c.expected});
    }
    expectError([] { readLammpsData("lammps_missing.data"); }, {"cannot open", "lammps_missing.data"});
}

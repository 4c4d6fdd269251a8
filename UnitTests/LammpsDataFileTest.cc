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

// Image flags (ix iy iz) count the box lengths an atom has crossed: the box here is 20 x 10 x 31,
// so flags 1 -1 2 move (1.5, 2.5, 0.25) to (1.5 + 20, 2.5 - 10, 0.25 + 62).
TEST(LammpsDataFile, ImageFlagsShiftByWholeBoxLengths) {
    std::string text = valid;
    text.replace(text.find("1.5 2.5 0.25"), 12, "1.5 2.5 0.25 1 -1 +2");
    writeWholeFile("lammps_images.data", text);
    const LammpsData d = readLammpsData("lammps_images.data");
    EXPECT_EQ(d.atoms[0].position, Vec3(21.5, -7.5, 62.25));
    EXPECT_EQ(d.atoms[1].position, Vec3(3, 4, 5));
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
        // Integers where integers are due: image flags, ids, types and counts (no stoi that
        // throws past the caller, no "1.7" read as 1, no 1e30 cast to an id).
        {replaced("1.5 2.5 0.25", "1.5 2.5 0.25 0 a 0"), "line 12: bad integer 'a' for the image flag"},
        {replaced("1.5 2.5 0.25", "1.5 2.5 0.25 0 1.7 0"), "line 12: '1.7' for the image flag is not an integer"},
        {replaced("1.5 2.5 0.25", "1.5 2.5 0.25 0 0 99999999999999999999"), "line 12: the image flag 99999999999999999999 is out of range"},
        {replaced("1.5 2.5 0.25", "1.5 2.5 0.25 0 0 2000000000"), "line 12: the image flag 2000000000 is out of range"},
        {replaced("7 1 1 1.909", "1e30 1 1 1.909"), "line 12: '1e30' for the atom id is not a whole number"},
        {replaced("7 1 1 1.909", "1.7 1 1 1.909"), "line 12: '1.7' for the atom id is not a whole number"},
        {replaced("7 1 1 1.909", "-7 1 1 1.909"), "line 12: the atom id must not be negative, found -7"},
        {replaced("7 1 1 1.909", "0 1 1 1.909"), "line 12: atom id 0: LAMMPS atom ids start at 1"},
        {replaced("9 2 0.79", "9 1.7 0.79"), "line 13: '1.7' for the atom type is not an integer"},
        {replaced("2 atoms", "2.5 atoms"), "line 3: '2.5' for the atom count is not a whole number"},
        {replaced("9 0.1 0.2 0.3 1 2 3", "9.5 0.1 0.2 0.3 1 2 3"), "line 17: '9.5' for the atom id is not a whole number"},
        // Sections and velocity lines given twice, or in the wrong order.
        {valid + "\nVelocities\n\n7 0 0 0 0 0 0\n", "line 19: a second Velocities section"},
        {valid + "\nAtoms # sphere\n", "line 19: a second Atoms section"},
        {valid + "9 0.1 0.2 0.3 1 2 3\n", "line 18: a second velocity of atom id 9"},
        {replaced("Atoms # sphere\n", "Velocities\n\n9 0 0 0 0 0 0\nAtoms # sphere\n"),
         "line 10: the Velocities section comes before the Atoms section"},
        // Sections, styles and header lines this reader does not take, or lacks.
        {replaced("Atoms # sphere", "Masses\n\n1 1\n2 1\n\nAtoms # sphere"), "line 10: unsupported section 'Masses'"},
        {replaced("Atoms # sphere", "Atoms # atomic"), "line 10: atom style 'atomic'"},
        {replaced("2 atom types\n", ""), "line 9: the Atoms section comes before an 'atom types' header line"},
        {replaced("-1 30 zlo zhi\n", ""), "line 9: no zlo zhi line in the header"},
        {replaced("2 atom types\n", "2 atom types\n3 atom types\n"), "line 5: a second 'atom types' header line"},
        {replaced("0 20 xlo xhi", "0 20 0 xlo xhi xy"), "line 6: unknown or unsupported header line"},
        {replaced("2 atom types", "2 2 atom types"), "line 4: unknown or unsupported header line '2 2 atom types'"},
        // Numbers that are not finite, and sizes that are not positive.
        {replaced("9 2 0.79", "9 2 nan"), "line 13: 'nan' for the diameter is not a finite number"},
        {replaced("1.5 2.5 0.25", "1.5 inf 0.25"), "line 12: 'inf' for the position is not a finite number"},
        {replaced("9 0.1 0.2 0.3 1 2 3", "9 0.1 0.2 0.3 1 -inf 3"), "line 17: '-inf' for the angular velocity is not a finite number"},
        {replaced("0 20 xlo xhi", "0 1e999 xlo xhi"), "line 6: bad number '1e999' for the box"},
        {replaced("9 2 0.79 1.909", "9 2 0 1.909"), "line 13: the diameter must be positive"},
        {replaced("9 2 0.79 1.90985931710274", "9 2 0.79 -1"), "line 13: the density must be positive"},
        // A line cut short (a truncated file), and a file that ends in the header.
        {replaced("9 2 0.79 1.90985931710274 3 4 5", "9 2 0.79 1.90985931710274 3 4"), "line 13: an atom line (style sphere) has 7 or 10 words"},
        {"title\n2 atoms\n2 atom", "line 3: unknown or unsupported header line '2 atom'"},
        {"", "no Atoms section"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.expected);
        writeWholeFile("lammps_bad.data", c.text);
        expectError([] { readLammpsData("lammps_bad.data"); }, {"lammps_bad.data", c.expected});
    }
    expectError([] { readLammpsData("lammps_missing.data"); }, {"cannot open", "lammps_missing.data"});
}

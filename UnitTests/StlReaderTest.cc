// STL and triangle-table files (IO/StlReader.h): hand-made ASCII and binary files (the binary ones
// encoded here, byte by byte, independently of the writer), round trips through the writer, the
// table format of the 2024 benchmark, and every kind of bad file, whose message names the file and
// the line or the triangle.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <bit>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>

#include "IO/StlReader.h"
#include "TestHelpers.h"

using namespace talus;
using namespace talus::test;

namespace {

// A binary STL file: the header padded to 80 bytes, the count, then per triangle a zero normal,
// the nine coordinates and a zero attribute, all little-endian.
std::string binaryStl(const std::string& header, std::uint32_t count, const std::vector<std::array<float, 9>>& corners) {
    std::string bytes = header;
    bytes.resize(80, ' ');
    auto put = [&](std::uint32_t u) {
        for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<char>(u >> 8 * k & 0xff));
    };
    put(count);
    for (const auto& c : corners) {
        for (int k = 0; k < 3; ++k) put(0);
        for (const float x : c) put(std::bit_cast<std::uint32_t>(x));
        bytes.append(2, '\0');
    }
    return bytes;
}

// The unit square of the plane z = 0 as two triangles, counter-clockwise seen from +z.
const std::vector<std::array<float, 9>> square = {{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0}};

const std::vector<std::string> squareAscii = {
    "solid square",              // 1
    "  facet normal 0 0 1",      // 2
    "    outer loop",            // 3
    "      vertex 0 0 0",        // 4
    "      vertex 1 0 0",        // 5
    "      vertex 1 1 0",        // 6
    "    endloop",               // 7
    "  endfacet",                // 8
    "  facet normal 0 0 1",      // 9
    "    outer loop",            // 10
    "      vertex 0 0 0",        // 11
    "      vertex 1 1 0",        // 12
    "      vertex 0 1 0",        // 13
    "    endloop",               // 14
    "  endfacet",                // 15
    "endsolid square"};          // 16

std::string joined(const std::vector<std::string>& lines, const std::string& end = "\n") {
    std::string text;
    for (const std::string& line : lines) text += line + end;
    return text;
}

// The square's lines with line `number` (from 1) replaced, or removed (nullopt).
std::string squareWithLine(std::size_t number, const std::optional<std::string>& line) {
    std::vector<std::string> lines = squareAscii;
    if (line)
        lines[number - 1] = *line;
    else
        lines.erase(lines.begin() + static_cast<long>(number - 1));
    return joined(lines);
}

void expectUnitSquare(const TriangleMesh& mesh, double scale) {
    ASSERT_EQ(mesh.triangleCount(), 2u);
    EXPECT_EQ(mesh.vertexCount(), 4u);
    EXPECT_EQ(mesh.edgeCount(), 5u);
    for (std::size_t t = 0; t < 2; ++t) {
        EXPECT_EQ(mesh.normal(t), Vec3(0, 0, 1));
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) EXPECT_EQ(mesh.corner(t, k)[a], scale * square[t][3 * k + a]);
    }
}

}  // namespace

// A folder of its own under the system's temporary folder for each test, removed after it.
class StlReader : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = std::filesystem::temp_directory_path() /
                  ("talus-stl-" + std::to_string(::getpid()) + "-" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }

    std::string path(const std::string& name) const { return (folder_ / name).string(); }
    // Writes `bytes` to the file `name` of the folder; returns its path.
    std::string file(const std::string& name, const std::string& bytes) const {
        writeWholeFile(path(name), bytes);
        return path(name);
    }

    std::filesystem::path folder_;
};

// The square as ASCII (with tabs, Windows line ends, blank lines and capitals, as exporters write
// it) and as binary, also with a header that starts with "solid" (told apart by its size, 84 + 50
// x 2 bytes); in millimetres read with scale 0.001.
TEST_F(StlReader, ReadsHandMadeAsciiAndBinaryFiles) {
    std::string text = joined(squareAscii, "\r\n");
    text.replace(text.find("  facet normal"), 14, "\tFACET Normal");
    text = "\n" + text;
    expectUnitSquare(readStl(file("ascii.stl", text)), 1);
    expectUnitSquare(readStl(file("ascii.stl", joined(squareAscii)), 0.001), 0.001);
    expectUnitSquare(readStl(file("binary.stl", binaryStl("made by hand", 2, square))), 1);
    expectUnitSquare(readStl(file("solid.stl", binaryStl("solid square, but binary", 2, square))), 1);
    expectUnitSquare(readStl(file("binary.stl", binaryStl("made by hand", 2, square)), 0.001), 0.001);
}

// Written and read back: ASCII keeps every double to the bit (17 digits), binary keeps them as
// 32-bit floats; the triangles keep their order and corner order, so their normals come back.
TEST_F(StlReader, AsciiAndBinaryRoundTrips) {
    std::vector<TriangleCorners> triangles;
    std::mt19937_64 random(41);
    std::uniform_real_distribution<double> position(-1, 1);
    for (int k = 0; k < 50; ++k) {
        const Vec3 a(position(random), position(random), position(random));
        triangles.push_back({a, a + Vec3(0.1, position(random) / 7, 0), a + Vec3(0, 0.1, position(random) / 3)});
    }
    const TriangleMesh mesh(triangles);
    for (const StlEncoding encoding : {StlEncoding::ascii, StlEncoding::binary}) {
        writeStl(path("round.stl"), mesh, encoding, "round");
        const TriangleMesh back = readStl(path("round.stl"));
        ASSERT_EQ(back.triangleCount(), mesh.triangleCount());
        EXPECT_EQ(back.vertexCount(), mesh.vertexCount());
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            for (int k = 0; k < 3; ++k) {
                const Vec3 x = mesh.corner(t, k);
                const Vec3 expected = encoding == StlEncoding::ascii ? x : Vec3(x.cast<float>().cast<double>());
                EXPECT_TRUE(sameBits(back.corner(t, k), expected)) << "triangle " << t;
            }
            EXPECT_NEAR((back.normal(t) - mesh.normal(t)).norm(), 0, encoding == StlEncoding::ascii ? 0 : 1e-5);
        }
    }
    // The binary file's size: 84 + 50 x 50 bytes.
    EXPECT_EQ(std::filesystem::file_size(path("round.stl")), 84u + 50u * 50u);
}

// The benchmark's format: a header line, then nine numbers per line separated by tabs (or spaces),
// Windows line ends. Two quads of a wall, four triangles; the corner (0.102, 4.6955e-12, 0.0145778)
// written a second time as (0.102, 4.69547e-12, 0.0145778), 3e-17 away (below the tolerance 1e-9 x
// the diagonal ~0.3): 6 vertices, 6 outer edges and 3 inner ones (the two diagonals and the side
// between the quads), shared by two triangles each.
TEST_F(StlReader, ReadsTheBenchmarksTriangleTables) {
    const std::string p0 = "0.102\t4.6955e-12\t0.0145778", p0again = "0.102\t4.69547e-12\t0.0145778";
    const std::string p1 = "0.101803\t0.0063413\t0.0145778", p2 = "0.101803\t0.0063413\t0.314578";
    const std::string p3 = "0.102\t4.69547e-12\t0.314578";
    const std::string p4 = "0.101213\t0.0126581\t0.0145778", p5 = "0.101213\t0.0126581\t0.314578";
    const std::string text = "vertex1_X[m] vertex1_Y[m] vertex1_Z[m] vertex2_X[m] vertex2_Y[m] vertex2_Z[m] "
                             "vertex3_X[m] vertex3_Y[m] vertex3_Z[m]\r\n" +
                             p0 + "\t" + p1 + "\t" + p2 + "\r\n" + p0again + "\t" + p2 + "\t" + p3 + "\r\n" + p1 +
                             "\t" + p4 + "\t" + p5 + "\r\n" + p1 + "  " + p5 + " " + p2 + "\r\n";
    const TriangleMesh mesh = readTriangleTable(file("walls.txt", text));
    ASSERT_EQ(mesh.triangleCount(), 4u);
    EXPECT_EQ(mesh.vertexCount(), 6u);
    ASSERT_EQ(mesh.edgeCount(), 9u);
    int inner = 0;
    for (std::size_t e = 0; e < mesh.edgeCount(); ++e) inner += mesh.edgeTriangles(e).size() == 2;
    EXPECT_EQ(inner, 3);
    EXPECT_EQ(mesh.corner(2, 1), Vec3(0.101213, 0.0126581, 0.0145778));
    // In millimetres; and a file without the header line (its first line nine numbers).
    EXPECT_EQ(readTriangleTable(path("walls.txt"), 1000).corner(2, 1), 1000 * Vec3(0.101213, 0.0126581, 0.0145778));
    const std::string headless = text.substr(text.find('\n') + 1);
    EXPECT_EQ(readTriangleTable(file("headless.txt", headless)).triangleCount(), 4u);
}

TEST_F(StlReader, BadAsciiFilesNameTheFileAndLine) {
    struct Case {
        std::string text, expected;
    };
    std::vector<std::string> fourVertices = squareAscii;
    fourVertices.insert(fourVertices.begin() + 6, "      vertex 2 2 0");
    const std::vector<Case> cases = {
        {squareWithLine(12, "vertex 1 nan 0"), "line 12: 'nan' for the y of a vertex is not a finite number"},
        {squareWithLine(5, "vertex 1 0 -inf"), "line 5: '-inf' for the z of a vertex is not a finite number"},
        {squareWithLine(13, "vertex 0 one 0"), "line 13: bad number 'one' for the y of a vertex"},
        {joined(fourVertices), "line 7: a fourth vertex: STL facets are triangles"},
        {squareWithLine(6, std::nullopt), "line 6: the facet has 2 vertices; STL facets are triangles"},
        {squareWithLine(13, "vertex 2 2 0"), "line 9: the triangle (0, 0, 0) (1, 1, 0) (2, 2, 0) has (nearly) zero area"},
        {joined({squareAscii.begin(), squareAscii.begin() + 11}), "line 9: the file ends inside the facet"},
        {joined({squareAscii.begin(), squareAscii.begin() + 15}), "line 15: the file ends without 'endsolid'"},
        {squareWithLine(3, "outer lop"), "line 3: expected 'outer loop', found 'outer lop'"},
        {squareWithLine(2, "facet normal 0 0"), "line 2: expected 'facet normal nx ny nz' or 'endsolid'"},
        {squareWithLine(2, "facet normal 0 x 1"), "line 2: bad number 'x' for the facet normal"},
        {squareWithLine(8, "endfact"), "line 8: expected 'endfacet', found 'endfact'"},
        {squareWithLine(6, "vertex 1 1"), "line 6: expected 'vertex x y z', found 'vertex 1 1'"},
        {squareWithLine(4, "normal 0 0 0"), "line 4: expected 'vertex x y z' or 'endloop'"},
        {joined(squareAscii) + "more\n", "line 17: expected 'solid', found 'more'"},
        {"solid empty\nendsolid empty\n", ": no triangles"},
    };
    for (const Case& c : cases) {
        const std::string path = file("bad.stl", c.text);
        expectError([&] { readStl(path); }, {"ASCII STL file " + path, c.expected});
    }
}

TEST_F(StlReader, BadBinaryFilesNameTheFileAndTriangle) {
    struct Case {
        std::string bytes, expected;
    };
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const std::string whole = binaryStl("h", 2, square);
    const std::vector<Case> cases = {
        {whole.substr(0, whole.size() - 10), "triangle 2: the file ends inside this triangle (174 bytes"},
        {binaryStl("h", 3, square), "triangle 3: the file ends inside this triangle (184 bytes, but its count of 3"},
        {binaryStl("h", 1, square), ": 184 bytes, but its count of 1 triangles takes 134"},
        // (a header that starts with "solid" and a wrong size: the zero bytes tell it is binary)
        {binaryStl("solid x", 1, square), ": 184 bytes, but its count of 1 triangles takes 134"},
        {binaryStl("h", 2, {square[0], {0, 0, 0, 1, nan, 0, 0, 1, 0}}), "triangle 2: corner 2 (1, nan, 0) is not finite"},
        {binaryStl("h", 2, {{0, 0, 0, 1, 0, 0, 1, 1, inf}, square[1]}), "triangle 1: corner 3 (1, 1, inf) is not finite"},
        {binaryStl("h", 2, {square[0], {0, 0, 0, 1, 1, 0, 2, 2, 0}}), "triangle 2: the triangle (0, 0, 0) (1, 1, 0) (2, 2, 0)"},
        {"not an STL file", ": 15 bytes, shorter than the 84 bytes of header and triangle count"},
        {binaryStl("h", 0, {}), ": no triangles"},
    };
    for (const Case& c : cases) {
        const std::string path = file("bad.stl", c.bytes);
        expectError([&] { readStl(path); }, {"binary STL file " + path, c.expected});
    }
}

TEST_F(StlReader, BadTriangleTablesNameTheFileAndLine) {
    struct Case {
        std::string text, expected;
    };
    const std::string header = "x1 y1 z1 x2 y2 z2 x3 y3 z3\n", first = "0\t0\t0\t1\t0\t0\t1\t1\t0\n";
    const std::vector<Case> cases = {
        {header + first + "0 0 0 1 1 0 0 1\n", "line 3: a triangle is 9 numbers (x y z of each of its three corners), found 8"},
        {header + "0 0 0 1 abc 0 1 1 0\n", "line 2: bad number 'abc' for the y of corner 2"},
        {header + first + "\n0 0 0 1 1 0 0 1 nan\n", "line 4: 'nan' for the z of corner 3 is not a finite number"},
        {header + first + "0 0 0 1 1 0 2 2 0\n", "line 3: the triangle (0, 0, 0) (1, 1, 0) (2, 2, 0) has (nearly) zero area"},
        {header + first + first, "line 3: the triangle has the same corners as the one at line 2"},
        {header, ": no triangles"},
        {"", " is empty"},
    };
    for (const Case& c : cases) {
        const std::string path = file("bad.txt", c.text);
        expectError([&] { readTriangleTable(path); }, {"triangle table " + path, c.expected});
    }
}

TEST_F(StlReader, MissingEmptyAndUnwritableFiles) {
    expectError([&] { readStl(path("none.stl")); }, {"cannot open STL file " + path("none.stl")});
    expectError([&] { readTriangleTable(path("none.txt")); }, {"cannot open triangle table " + path("none.txt")});
    const std::string empty = file("empty.stl", "");
    expectError([&] { readStl(empty); }, {"STL file " + empty + " is empty"});
    expectError([&] { readStl(file("square.stl", joined(squareAscii)), 0); }, {"scale of", "must be positive"});
    const TriangleMesh mesh = readStl(path("square.stl"));
    expectError([&] { writeStl(path("no/folder.stl"), mesh, StlEncoding::ascii); }, {"cannot write", "no/folder.stl"});
    expectError([&] { writeStl(path("named.stl"), mesh, StlEncoding::ascii, "two words"); },
                {"the solid name of an STL file must be one word"});
}

// The readers on MercuryDPM's own files (shared/reference/mercury/chute, README there) and on
// broken files: counts, times and values checked against the file text read independently
// here; a depth profile that integrates to mass per unit area; errors that name file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "CGTestHelpers.h"
#include "Formats/RestartFormat.h"
#include "Fields/CoarseGrainer.h"
#include "IO/DataFileReader.h"
#include "IO/FstatFileReader.h"
#include "IO/InputError.h"
#include "IO/RestartFileReader.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

const std::string chute = std::string(TALUS_SHARED_DIR) + "/reference/mercury/chute/Bidi_on";

std::vector<std::string> fileLines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<double> numbersOf(const std::string& line) {
    std::istringstream in(line);
    std::vector<double> values;
    for (std::string word; in >> word;) values.push_back(std::strtod(word.c_str(), nullptr));
    return values;
}

}  // namespace

TEST(MercuryFiles, DataFramesMatchTheFileText) {
    const auto frames = readAllDataFrames(chute + ".data");
    const auto text = fileLines(chute + ".data");
    ASSERT_EQ(frames.size(), 3u);
    const double times[] = {9.9, 9.95, 10.0};
    std::size_t header = 0;
    for (int f = 0; f < 3; ++f) {
        const auto h = numbersOf(text[header]);
        EXPECT_EQ(frames[f].size(), std::size_t(h[0]));
        EXPECT_EQ(frames[f].size(), 3114u);  // README: 1000 + 2000 + 114 base particles
        EXPECT_DOUBLE_EQ(frames[f].time, times[f]);
        EXPECT_DOUBLE_EQ(frames[f].box.hi[0], 20);
        EXPECT_DOUBLE_EQ(frames[f].box.hi[1], 10);
        // A few particle lines, column by column.
        for (std::size_t p : {std::size_t(0), std::size_t(1), std::size_t(1500), std::size_t(3113)}) {
            const auto row = numbersOf(text[header + 1 + p]);
            ASSERT_EQ(row.size(), 14u);
            for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(frames[f].position[p][k], row[k]);
                EXPECT_EQ(frames[f].velocity[p][k], row[3 + k]);
            }
            EXPECT_EQ(frames[f].radius[p], row[6]);
            EXPECT_EQ(frames[f].species[p], int(row[13]));
        }
        header += 1 + frames[f].size();
    }
}

TEST(MercuryFiles, FstatFramesMatchTheFileText) {
    const auto frames = readAllFstatFrames(chute + ".fstat");
    const auto text = fileLines(chute + ".fstat");
    ASSERT_EQ(frames.size(), 3u);
    // Contact lines of the first frame: those between the first and the second block of '#'.
    std::size_t first = 3, count = 0;
    while (first + count < text.size() && text[first + count][0] != '#') ++count;
    EXPECT_EQ(frames[0].contacts.size(), count);
    EXPECT_DOUBLE_EQ(frames[0].time, 9.9);
    EXPECT_DOUBLE_EQ(frames[2].time, 10.0);
    // Force on i: fn n + ft t (pairs), -(fn n + ft t) (walls, fstat.md).
    bool sawWall = false;
    for (std::size_t c = 0; c < count; ++c) {
        const auto row = numbersOf(text[first + c]);
        const ContactLine& line = frames[0].contacts[c];
        ASSERT_EQ(line.i, long(row[1]));
        ASSERT_EQ(line.j, long(row[2]));
        const double sign = row[2] < 0 ? -1 : 1;
        sawWall |= row[2] < 0;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(line.force[k], sign * (row[8] * row[10 + k] + row[9] * row[13 + k]), 1e-12);
    }
    EXPECT_TRUE(sawWall);
}

TEST(MercuryFiles, RestartGivesDensitiesPeriodicityAndFixedParticles) {
    const RestartInfo info = readRestartFile(chute + ".restart");
    EXPECT_EQ(info.writer, "MercuryDPM");
    ASSERT_EQ(info.speciesDensity.size(), 2u);
    EXPECT_NEAR(info.speciesDensity[0], 6 / std::numbers::pi, 1e-13);
    EXPECT_TRUE(info.periodic[0]);
    EXPECT_TRUE(info.periodic[1]);
    EXPECT_FALSE(info.periodic[2]);
    ASSERT_EQ(info.fixed.size(), 3114u);
    EXPECT_EQ(std::count(info.fixed.begin(), info.fixed.end(), true), 114);
}

// The depth profile of density of the flowing particles (fixed base excluded), integrated over
// z by quadrature split at the supports' edges, is their mass per unit area,
// (1000 + 2000 x 0.79^3) / (20 x 10) (README: 1000 of d = 1 and 2000 of d = 0.79, density 6/pi).
TEST(MercuryFiles, DepthProfileIntegratesToMassPerArea) {
    const auto frames = readAllDataFrames(chute + ".data");
    const RestartInfo info = readRestartFile(chute + ".restart");
    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName("Z");
    setup.width = WidthMatrix::isotropic(0.5);
    setup.speciesDensity = info.speciesDensity;
    setup.periodic = info.periodic;
    setup.excluded = info.fixed;
    CoarseGrainer grainer(setup);
    const ParticleFrame& frame = frames[2];
    grainer.setFrame(frame, nullptr);
    double mass = 0, zMin = 1e9, zMax = -1e9;
    std::vector<double> breaks;
    for (std::size_t p = 0; p < frame.size(); ++p) {
        if (info.fixed[p]) continue;
        mass += 6 / std::numbers::pi * sphereVolume(frame.radius[p]);
        const double z = frame.position[p][2];
        breaks.insert(breaks.end(), {z - 0.5, z, z + 0.5});
        zMin = std::min(zMin, z);
        zMax = std::max(zMax, z);
    }
    EXPECT_NEAR(mass, 1000 + 2000 * std::pow(0.79, 3), 1e-9);
    const GaussLegendre gl(8);
    std::vector<double> z, w;
    gl.panels(zMin - 1, zMax + 1, breaks, z, w);
    std::vector<Vec3> points;
    for (double h : z) points.push_back({0, 0, h});
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    double integral = 0;
    for (std::size_t k = 0; k < z.size(); ++k) integral += w[k] * sums[k * grainer.layout().count()];
    EXPECT_NEAR(integral / (mass / 200), 1.0, 1e-10);
    std::printf("[ mercury ] depth profile integral %.12g, mass per area %.12g\n", integral, mass / 200);
}

// Frames before a time window are skipped unparsed (their lines counted): a frame whose particle
// line is not a number is read in full when asked for, and passed over when it lies before the
// window; a truncated frame is still found while skipping.
TEST(MercuryFiles, FramesBeforeTheWindowAreSkippedUnparsed) {
    write("skip.data", "1 0 0 0 0 1 1 1\n0.5 0.5 x 0 0 0 0.5 0 0 0 0 0 0 0\n"
                       "1 1 0 0 0 1 1 1\n0.25 0.5 0.5 0 0 0 0.5 0 0 0 0 0 0 0\n");
    EXPECT_EQ(errorOf([] { readAllDataFrames("skip.data"); }), "skip.data line 2: bad number 'x' for the position");
    DataFileReader reader("skip.data");
    ParticleFrame frame;
    ASSERT_TRUE(reader.readFrame(frame, 0.5));
    EXPECT_EQ(frame.time, 1.0);
    ASSERT_EQ(frame.size(), 1u);
    EXPECT_EQ(frame.position[0][0], 0.25);
    EXPECT_FALSE(reader.readFrame(frame, 0.5));
    write("skipShort.data", "2 0 0 0 0 1 1 1\n0.5 0.5 0.5 0 0 0 0.5 0 0 0 0 0 0 0\n");
    EXPECT_EQ(errorOf([] {
                  DataFileReader short_("skipShort.data");
                  ParticleFrame f;
                  short_.readFrame(f, 0.5);
              }),
              "skipShort.data line 3: file ends after 1 of the 2 particle lines of the frame at t = 0 (header line 1): "
              "truncated file?");
}

TEST(BadFiles, ErrorsNameFileAndLine) {
    write("short.data", "2 0.5 0 0 0 1 1 1\n0.5 0.5 0.5 0 0 0 0.5 0 0 0 0 0 0 0\n");
    EXPECT_EQ(errorOf([] { readAllDataFrames("short.data"); }),
              "short.data line 3: file ends after 1 of the 2 particle lines of the frame at t = 0.5 (header line 1): truncated file?");
    write("columns.data", "1 0 0 0 0 1 1 1\n0.5 0.5 0.5 0 0 0 0.5 0 0\n");
    EXPECT_EQ(errorOf([] { readAllDataFrames("columns.data"); }), "columns.data line 2: expected 14 columns, found 9");
    write("number.data", "1 0 0 0 0 1 1 1\n0.5 0.5 x 0 0 0 0.5 0 0 0 0 0 0 0\n");
    EXPECT_EQ(errorOf([] { readAllDataFrames("number.data"); }), "number.data line 2: bad number 'x' for the position");
    write("species.data", "1 0 0 0 0 1 1 1\n0.5 0.5 0.5 0 0 0 0.5 0 0 0 0 0 0 1.5\n");
    EXPECT_EQ(errorOf([] { readAllDataFrames("species.data"); }),
              "species.data line 2: info column is 1.5, not a species index (0, 1, ...)");
    write("header.data", "1 0 0 0 1 1\n");
    EXPECT_NE(errorOf([] { readAllDataFrames("header.data"); }).find("header.data line 1: a 2-D .data header"), std::string::npos);
    EXPECT_EQ(errorOf([] { readAllDataFrames("missing.data"); }), "cannot open missing.data");
    write("columns.fstat", "# 0 1\n# 0 0 0 1 1 1\n# 0.5 0.5 0 0 0 0\n0 1 0 0.5 0.5 0.5 0.01 0 1 0\n");
    EXPECT_EQ(errorOf([] { readAllFstatFrames("columns.fstat"); }), "columns.fstat line 4: expected 16 columns, found 10");
    write("truncated.fstat", "# 0 1\n# 0 0 0 1 1 1\n");
    EXPECT_EQ(errorOf([] { readAllFstatFrames("truncated.fstat"); }),
              "truncated.fstat line 3: file ends inside the header of the frame at t = 0: truncated file?");
    write("bad.restart", "Talus restart 4\nname x\ndomain 0 0 0 1 1 1 1 0\n");
    EXPECT_EQ(errorOf([] { readRestartFile("bad.restart"); }), "bad.restart line 3: expected 'domain' with 9 values, found 8");
    // Species without a density.
    CoarseGrainingSetup setup;
    setup.speciesDensity = {1.0};
    CoarseGrainer grainer(setup);
    write("two.data", "1 0 0 0 0 1 1 1\n0.5 0.5 0.5 0 0 0 0.5 0 0 0 0 0 0 1\n");
    const auto frames = readAllDataFrames("two.data");
    EXPECT_EQ(errorOf([&] { grainer.setFrame(frames[0], nullptr, "two.data"); }),
              "two.data line 2: a particle of species 1, but densities are known for 1 species only (--density d0,d1,... or --restart)");
}

// Numbers that are no finite numbers, counts that are negative or absurd, and an inverted box:
// each an InputError naming file and line (before, NaN and Inf positions, times and forces were
// read as such, and a negative particle count in a restart file gave std::length_error).
TEST(BadFiles, NonFiniteNumbersCountsAndBoxes) {
    const std::string particle = "0.5 0.5 0.5 0 0 0 0.5 0 0 0 0 0 0 0\n";
    struct Case {
        std::string path, text, expected;
    };
    const std::vector<Case> dataCases = {
        {"nan.data", "1 0 0 0 0 1 1 1\n0.5 nan 0.5 0 0 0 0.5 0 0 0 0 0 0 0\n",
         "nan.data line 2: 'nan' for the position is not a finite number"},
        {"inf.data", "1 inf 0 0 0 1 1 1\n" + particle, "inf.data line 1: 'inf' for the time t is not a finite number"},
        {"overflow.data", "1 0 0 0 0 1 1 1\n0.5 0.5 0.5 1e999 0 0 0.5 0 0 0 0 0 0 0\n",
         "overflow.data line 2: bad number '1e999' for the velocity (too large)"},
        {"inverted.data", "1 0 0 0 0 1 -1 1\n" + particle,
         "inverted.data line 1: the domain maximum -1 lies below the minimum 0 along y (an inverted box)"},
        {"negative.data", "-1 0 0 0 0 1 1 1\n", "negative.data line 1: the particle count N must not be negative, found -1"},
        {"fraction.data", "1.5 0 0 0 0 1 1 1\n" + particle, "fraction.data line 1: '1.5' for the particle count N is not a whole number"},
        {"huge.data", "9223372036854775807 0 0 0 0 1 1 1\n" + particle,
         "huge.data line 3: file ends after 1 of the 9223372036854775807 particle lines of the frame at t = 0 (header line 1): truncated file?"},
    };
    for (const Case& c : dataCases) {
        write(c.path, c.text);
        EXPECT_EQ(errorOf([&] { readAllDataFrames(c.path); }), c.expected);
    }
    const std::string header = "# 0 1\n# 0 0 0 1 1 1\n# 0.5 0.5 0 0 0 0\n";
    const std::vector<Case> fstatCases = {
        {"nan.fstat", header + "0 1 0 0.5 0.5 0.5 0.01 0 nan 0 1 0 0 0 1 0\n",
         "nan.fstat line 4: 'nan' for the normal force fn is not a finite number"},
        {"inf.fstat", header + "0 1 0 0.5 0.5 0.5 0.01 0 1 0 -inf 0 0 0 1 0\n",
         "inf.fstat line 4: '-inf' for the normal is not a finite number"},
        {"time.fstat", "# nan 1\n# 0 0 0 1 1 1\n# 0.5 0.5 0 0 0 0\n", "time.fstat line 1: 'nan' for the frame time is not a finite number"},
        {"index.fstat", header + "0 1.5 0 0.5 0.5 0.5 0.01 0 1 0 1 0 0 0 1 0\n",
         "index.fstat line 4: '1.5' for particle i is not an integer"},
    };
    for (const Case& c : fstatCases) {
        write(c.path, c.text);
        EXPECT_EQ(errorOf([&] { readAllFstatFrames(c.path); }), c.expected);
    }
    const std::string newer = std::to_string(talus::formats::restart::version + 1);
    const std::string talus = "Talus restart 6\nname x\ntime 0.5 10\ndomain 0 0 0 1 1 1 1 0 0\nspecies 1\n  a 1 law\n";
    // One ellipsoid of semi-axes 0.5 0.25 0.25 (density 1: mass 4/3 pi / 32) and a particle line of it
    // (34 fields: restart.md) with the given shape index.
    const std::string ellipsoid = talus + "shapes 1 1\n   0.5 0.25 0.25 1 1\n";
    const auto shapedParticle = [](const std::string& shape, const std::string& mass = "0.1308996938995747") {
        return "   0 0.5 0.5 0.5 0 0 0 0 0 0 0 0 0 0 0 0 0.5 " + mass + " 7.64 0 0 0 -1 1 0 0 0 0 0 0 1 1 1 " + shape + "\n";
    };
    const std::vector<Case> restartCases = {
        {"negative.restart", talus + "particles -1 0\n", "negative.restart line 7: the particle count must not be negative, found -1"},
        {"species.restart", "Talus restart 6\nspecies -2\n", "species.restart line 2: the species count must not be negative, found -2"},
        {"walls.restart", talus + "walls 1\n  0 0 1 0 0 0 0 -1 -0.5\n",
         "walls.restart line 8: the wall radius must be 0 (a plane) or positive (a cylinder)"},
        {"axis.restart", talus + "walls 1\n  0 0 0 0 0 0 0 -1 0.5\n",
         "axis.restart line 8: a cylinder wall needs an axis direction (its normal), found 0 0 0"},
        {"time.restart", "Talus restart 6\ntime inf 10\n", "time.restart line 2: 'inf' for the time is not a finite number"},
        {"flag.restart", "Talus restart 6\ndomain 0 0 0 1 1 1 2 0 0\n", "flag.restart line 2: a periodic flag must be 0 or 1, found 2"},
        {"mercury.restart", "MercuryDPM 1\nParticles -3\n", "mercury.restart line 2: the particle count must not be negative, found -3"},
        // Shapes (restart format 5 on; IO/ParticleShapes.h): superquadrics are the one kind the
        // format knows; a later format is refused rather than misread.
        {"kind.restart", talus + "shapes 2 0\n", "kind.restart line 7: shapes flag 2: an unknown kind of shapes (0: spheres only, 1: superquadrics)"},
        {"shapeline.restart", talus + "shapes 1 1\n   0.5 0.25 0.25 1 1 3 0.1\n",
         "shapeline.restart line 8: expected a superquadric 'a b c e1 e2' (5 numbers) for shape 0, found 7 fields: an unknown kind of shape"},
        {"concave.restart", talus + "shapes 1 1\n   0.5 0.25 0.25 1.5 1\n",
         "concave.restart line 8: the blockiness e1 = 1.5, e2 = 1 of shape 0 is outside (0, 1]: not a convex superquadric"},
        {"nanshape.restart", talus + "shapes 1 1\n   0.5 nan 0.25 1 1\n", "nanshape.restart line 8: 'nan' for a semi-axis of shape 0 is not a finite number"},
        {"infshape.restart", talus + "shapes 1 1\n   0.5 0.25 0.25 1 -inf\n", "infshape.restart line 8: '-inf' for the blockiness e2 of shape 0 is not a finite number"},
        {"shapecount.restart", talus + "shapes 1 -1\n", "shapecount.restart line 7: the shape count must not be negative, found -1"},
        {"shapeindex.restart", ellipsoid + "particles 1 1\n" + shapedParticle("2"),
         "shapeindex.restart line 10: particle id 0 has shape 2, which is no shape of the file (it has 1; -1: a sphere)"},
        {"shapetext.restart", ellipsoid + "particles 1 1\n" + shapedParticle("box"), "shapetext.restart line 10: bad integer 'box' for the shape index of particle id 0"},
        {"unshaped.restart", ellipsoid + "particles 1 1\n   0 0.5 0.5 0.5 0 0 0 0 0 0 0 0 0 0 0 0 0.5 1 1 10 0 0 -1\n",
         "unshaped.restart line 10: expected 34 fields for a particle of a scene with shapes, found 23"},
        {"mass.restart", ellipsoid + "particles 1 1\n" + shapedParticle("0", "0.5236"),
         "mass.restart line 10: the mass 0.5236 of particle id 0 is not its species' density times the volume of its shape 0 (0.1308996939)"},
        {"mercuryshape.restart", "MercuryDPM 1\nParticles 1\nSuperQuadricParticle id 0 indSpecies 0 axes 1 0.5 0.5 exp1 1 exp2 1\n",
         "mercuryshape.restart line 3: a MercuryDPM SuperQuadricParticle: talus-cg takes superquadric shapes from Talus restart files "
         "only (as a sphere of its .data radius, its bounding radius, its mass and volume would be wrong)"},
        {"mercurykind.restart", "MercuryDPM 1\nParticles 1\nClumpParticle id 0 invMass 1\n",
         "mercurykind.restart line 3: particle of an unknown kind 'ClumpParticle' (BaseParticle, SphericalParticle, LiquidFilmParticle "
         "or ThermalParticle)"},
        {"version.restart", "Talus restart " + newer + "\n",
         "version.restart line 1: format version " + newer + " is newer than this talus-cg reads (up to " +
             std::to_string(talus::formats::restart::version) + ")"},
        {"nanradius.restart", talus + "shapes 0 0\nparticles 1 1\n   0 0.5 0.5 0.5 0 0 0 0 0 0 0 0 0 0 0 0 nan 1 1 10 0 0 -1\n",
         "nanradius.restart line 9: 'nan' for the radius is not a finite number"},
    };
    for (const Case& c : restartCases) {
        write(c.path, c.text);
        EXPECT_EQ(errorOf([&] { readRestartFile(c.path); }), c.expected);
    }
}

// A kernel that reaches over very many periodic lengths (here a .data box 1e-9 long in periodic
// x, a width of 1): every image of a particle whose support overlaps the box is a source, 2e9 of
// them for each particle, and building the frame never ended (or ran out of memory). It is an
// InputError naming the frame's header line, the periodic length and the kernel's reach; a
// kernel reaching over 20 lengths, the most allowed, still gets its images.
TEST(BadFiles, KernelReachingOverTooManyPeriodicLengths) {
    write("thin.data", "1 0 0 0 0 1e-9 1 1\n5e-10 0.5 0.5 0 0 0 0.5 0 0 0 0 0 0 0\n");
    const auto thin = readAllDataFrames("thin.data");
    CoarseGrainingSetup setup;
    setup.width = WidthMatrix::isotropic(1);
    setup.periodic = {true, false, false};
    CoarseGrainer cartesian(setup);
    const std::string expected =
        "thin.data line 1: along the periodic x axis the kernel reaches 1 from a particle (cut off at 1 times the "
        "width), 1000000000 times the periodic length 1e-09 of the domain; at most 20 periodic lengths are supported "
        "(every one adds two images of each particle): average over x (--coordinates), narrow the kernel (--width) or "
        "check the domain in the file";
    EXPECT_EQ(errorOf([&] { cartesian.setFrame(thin[0], nullptr, "thin.data"); }), expected);
    // The same along the axis of cylindrical coordinates about x.
    CoarseGrainingSetup drum = setup;
    drum.coordinates = Coordinates::fromName("RZ");
    drum.coordinates.setAxis(0, {0, 0.5, 0.5});
    CoarseGrainer cylindrical(drum);
    EXPECT_EQ(errorOf([&] { cylindrical.setFrame(thin[0], nullptr, "thin.data"); }), expected);
    // At the limit: a box of 1/16 and a width of 1.25, reached over 20 times. The images are those
    // whose support [x - 1.25, x + 1.25], x = 1/32, overlaps [0, 1/16]: n / 16 from n = -20 to 20.
    write("narrow.data", "1 0 0 0 0 0.0625 1 1\n0.03125 0.5 0.5 0 0 0 0.5 0 0 0 0 0 0 0\n");
    const auto narrow = readAllDataFrames("narrow.data");
    setup.width = WidthMatrix::isotropic(1.25);
    CoarseGrainer wide(setup);
    wide.setFrame(narrow[0], nullptr, "narrow.data");
    EXPECT_EQ(wide.particleSourceCount(), 41u);
}

// The file formats of talus-cg (App/FieldWriter.h): the HDF5 file read back with HDF5's C API
// holds exactly (bitwise) the derived fields computed here from the sums, in the documented
// (nz, ny, nx) order; the .stat file read back holds the sums in MercuryDPM's columns to its 16
// digits; the XDMF file names the datasets. The end-to-end comparison with the CSV output, with
// h5py and an XML parser, is checkOutputFormats.py (ctest CG.Program.OutputFormats*).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "App/CsvWriter.h"
#include "App/FieldWriter.h"
#include "App/StatFieldWriter.h"
#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/DerivedFields.h"
#include "Fields/EvaluationPoints.h"
#include "IO/InputError.h"
#ifdef TALUS_CG_WITH_HDF5
#include <hdf5.h>

#include "App/Hdf5FieldWriter.h"
#endif

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

// 200 random particles of two species in a 6 x 4 x 5 box, evaluated on a 5 x 3 grid in XZ.
struct Sample {
    FieldOutputSetup output;
    std::vector<double> sums;
};

Sample sample(const std::string& path, bool grid) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> x(0, 6), y(0, 4), z(0, 5), v(-1, 1);
    std::vector<Vec3> position, velocity;
    std::vector<double> radius;
    std::vector<int> species;
    for (int i = 0; i < 200; ++i) {
        position.push_back({x(random), y(random), z(random)});
        velocity.push_back({v(random), v(random), v(random)});
        species.push_back(i % 2);
        radius.push_back(i % 2 ? 0.4 : 0.5);
    }
    const ParticleFrame frame = makeFrame(position, radius, DomainBox{{0, 0, 0}, {6, 4, 5}}, velocity, species);
    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName("XZ");
    setup.width = WidthMatrix::diagonal(1.5, 1, 0.8);
    setup.speciesDensity = {2, 2};
    CoarseGrainer grainer(setup);
    grainer.setFrame(frame, nullptr);
    Sample s;
    s.output.path = path;
    s.output.coordinates = setup.coordinates;
    s.output.layout = grainer.layout();
    s.output.grid = grid;
    s.output.count = {5, 1, 3};
    s.output.lo = {0, 0, 0};
    s.output.hi = {6, 4, 5};
    s.output.points = grid ? gridPoints(setup.coordinates, s.output.count, s.output.lo, s.output.hi)
                           : std::vector<Vec3>{{1, 0, 1}, {2.5, 0, 3}, {5, 0, 4.5}};
    s.output.width = setup.width;
    grainer.evaluate(s.output.points, s.sums);
    return s;
}

}  // namespace

TEST(OutputFormats, StatFileHoldsTheSumsInMercuryColumns) {
    Sample s = sample("sample.stat", true);
    s.output.timeAverage = true;
    {
        auto writer = makeFieldWriter(OutputFormat::Stat, s.output);
        writer->writeFrame(1.5, 2.5, s.sums);
        writer->close();
    }
    std::ifstream in("sample.stat");
    std::string line;
    std::getline(in, line);
    std::istringstream names(line);
    std::vector<std::string> columns;
    for (std::string name; names >> name;) columns.push_back(name);
    ASSERT_EQ(columns.size(), 88u);  // MercuryDPM's 85, then InteractionForceX Y Z
    EXPECT_EQ(columns[1], "Density");
    EXPECT_EQ(columns[14], "MomentumFluxXX");  // after 1 + 1 + 3 + 3 + 6 columns
    EXPECT_EQ(columns[29], "NormalStressXX");  // after MomentumFlux 6, DisplacementMomentumFlux 6, EnergyFlux 3
    EXPECT_EQ(columns[84], "ContactCoupleStressZZ");
    EXPECT_EQ(columns[85], "InteractionForceX");
    EXPECT_EQ(columns[87], "InteractionForceZ");
    std::getline(in, line);
    EXPECT_EQ(line.rfind("w 1.095445115 dim 3 domainStat 0 6 0 4 0 5 n 5 1 3 statType XZ CG_type Lucy", 0), 0u) << line;  // w = sqrt(1.5 x 0.8)
    std::getline(in, line);
    EXPECT_EQ(line, "1.5 2.5");  // tmin tmax of the time average
    const FieldSums& layout = s.output.layout;
    for (std::size_t p = 0; p < s.output.points.size(); ++p) {
        std::getline(in, line);
        std::istringstream row(line);
        std::vector<double> v;
        for (double value; row >> value;) v.push_back(value);
        ASSERT_EQ(v.size(), 91u);
        const double* sums = s.sums.data() + p * layout.count();
        for (int k = 0; k < 3; ++k) EXPECT_EQ(v[k], s.output.points[p][k]);
        auto near = [](double a, double b) { return std::abs(a - b) <= 1e-15 * std::max(1.0, std::abs(b)); };
        EXPECT_TRUE(near(v[3], sums[FieldSums::volumeFraction]));
        EXPECT_TRUE(near(v[4], sums[FieldSums::density]));
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(near(v[5 + c], sums[FieldSums::momentum + c]));
        for (int c = 0; c < 6; ++c) EXPECT_TRUE(near(v[3 + 14 + c], sums[FieldSums::momentumFlux + c]));
        for (int c = 0; c < 9; ++c) EXPECT_EQ(v[3 + 29 + c], 0.0);  // no contact stress evaluated
        for (int c = 0; c < 3; ++c) EXPECT_EQ(v[3 + 85 + c], 0.0);  // nor boundary forces
    }
    EXPECT_FALSE(std::getline(in, line) && !line.empty());
}

// The CSV writer writes each number as printf's %.12g would (it formats them with std::to_chars):
// random doubles of every exponent, both signs, zeros, subnormals, infinities and NaNs, each row
// compared character by character with the row that fprintf makes.
TEST(OutputFormats, CsvNumbersAreThoseOfPrintf) {
    const std::string path = ::testing::TempDir() + "csvNumbers.csv";
    std::mt19937_64 random(7);
    std::vector<std::vector<double>> rows;
    for (int r = 0; r < 400; ++r) {
        std::vector<double> row;
        for (int k = 0; k < 8; ++k) {
            std::uint64_t bits = random();
            if (r % 4 == 0) bits &= ~(std::uint64_t{0x7f0} << 52);  // (exponents near 1 and subnormals)
            double v;
            std::memcpy(&v, &bits, sizeof v);
            row.push_back(v);
        }
        rows.push_back(row);
    }
    const double infinity = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    rows.push_back({0.0, -0.0, infinity, -infinity, nan, -nan, std::numeric_limits<double>::denorm_min(), 1e300});
    rows.push_back({0.1, 1.0 / 3, 123456789012.5, 1234567890123.0, 5e-324, 2.5e-5, 100000, 1e15});
    {
        CsvWriter csv(path, std::vector<int>{2}, true, {}, {});
        for (const std::vector<double>& row : rows) csv.writeRow(0.5, Vec3{0, 0, -0.25}, row);
        csv.close();
    }
    std::ifstream in(path);
    std::string line;
    for (int k = 0; k < 2; ++k) std::getline(in, line);  // (units and names)
    for (const std::vector<double>& row : rows) {
        char expected[1024];
        int used = std::snprintf(expected, sizeof expected, "%.12g,%.12g", 0.5, -0.25);
        for (double v : row) used += std::snprintf(expected + used, sizeof expected - used, ",%.12g", v);
        ASSERT_TRUE(std::getline(in, line));
        EXPECT_EQ(line, std::string(expected));
    }
}

TEST(OutputFormats, UnknownFormatIsNamed) {
    try {
        outputFormatFromName("vtu");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "--output-format: unknown format 'vtu' (csv, hdf5, stat or vtk)");
    }
    EXPECT_EQ(defaultOutputPath(OutputFormat::Hdf5, "run"), "run.cg.h5");
    EXPECT_EQ(defaultOutputPath(OutputFormat::Stat, "run"), "run.stat");
    EXPECT_EQ(defaultOutputPath(OutputFormat::Vtk, "run"), "run.cg.pvd");
}

#ifdef TALUS_CG_WITH_HDF5
namespace {

std::vector<double> readDataset(hid_t file, const std::string& name, std::vector<hsize_t>& dims) {
    const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    EXPECT_GE(dataset, 0) << name;
    const hid_t space = H5Dget_space(dataset);
    dims.assign(H5Sget_simple_extent_ndims(space), 0);
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    std::vector<double> values(H5Sget_simple_extent_npoints(space));
    H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Sclose(space);
    H5Dclose(dataset);
    return values;
}

}  // namespace

TEST(OutputFormats, Hdf5GridReadsBackBitwiseInXFastestOrder) {
    const Sample s = sample("sample.h5", true);
    {
        auto writer = makeFieldWriter(OutputFormat::Hdf5, s.output);
        writer->writeFrame(0.5, 0.5, s.sums);
        writer->writeFrame(0.75, 0.75, s.sums);
        writer->close();
    }
    const hid_t file = H5Fopen("sample.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    std::vector<hsize_t> dims;
    EXPECT_EQ(readDataset(file, "/time", dims), (std::vector<double>{0.5, 0.75}));
    const std::vector<double> x = readDataset(file, "/grid/x", dims);
    ASSERT_EQ(x.size(), 5u);
    EXPECT_EQ(x[1], 1.8);  // cell centres: 0 + 1.5 x 6/5
    const std::vector<double> z = readDataset(file, "/grid/z", dims);
    ASSERT_EQ(z.size(), 3u);
    const std::vector<OutputColumn> columns = derivedColumns(s.output.layout);
    for (std::size_t f = 0; f < columns.size(); ++f) {
        const std::vector<double> field = readDataset(file, "/frames/000001/" + columns[f].name, dims);
        ASSERT_EQ(dims, (std::vector<hsize_t>{3, 1, 5})) << columns[f].name;  // (nz, ny, nx)
        for (long i = 0; i < 5; ++i) {
            for (long k = 0; k < 3; ++k) {
                const long p = i * 3 + k;  // the grid's order: x slowest
                EXPECT_EQ(s.output.points[p][0], x[i]);
                EXPECT_EQ(s.output.points[p][2], z[k]);
                std::vector<double> values;
                appendDerivedFields(s.output.layout, s.sums.data() + p * s.output.layout.count(), values);
                EXPECT_EQ(field[k * 5 + i], values[f]) << columns[f].name << " at " << i << " " << k;
            }
        }
    }
    // The frame's time as a number attribute.
    const hid_t group = H5Gopen2(file, "/frames/000001", H5P_DEFAULT);
    const hid_t attribute = H5Aopen(group, "time", H5P_DEFAULT);
    double time = 0;
    H5Aread(attribute, H5T_NATIVE_DOUBLE, &time);
    EXPECT_EQ(time, 0.75);
    H5Aclose(attribute);
    H5Gclose(group);
    H5Fclose(file);
    // The XDMF file points at the datasets with these dimensions.
    std::ifstream xmf(Hdf5FieldWriter::xdmfPath("sample.h5"));
    std::stringstream text;
    text << xmf.rdbuf();
    EXPECT_NE(text.str().find("<Topology TopologyType=\"3DRectMesh\" Dimensions=\"3 1 5\"/>"), std::string::npos);
    EXPECT_NE(text.str().find("<Time Value=\"0.75\"/>"), std::string::npos);
    EXPECT_NE(text.str().find("Format=\"HDF\">sample.h5:/frames/000001/Concentration_s1</DataItem>"), std::string::npos);
}

TEST(OutputFormats, Hdf5PointListIsAPolyvertexSet) {
    const Sample s = sample("points.h5", false);
    {
        auto writer = makeFieldWriter(OutputFormat::Hdf5, s.output);
        writer->writeFrame(1, 1, s.sums);
        writer->close();
    }
    const hid_t file = H5Fopen("points.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    std::vector<hsize_t> dims;
    const std::vector<double> points = readDataset(file, "/points", dims);
    EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
    EXPECT_EQ(points[3], 2.5);
    const std::vector<double> density = readDataset(file, "/frames/000000/Density", dims);
    EXPECT_EQ(dims, (std::vector<hsize_t>{3}));
    for (int p = 0; p < 3; ++p) EXPECT_EQ(density[p], s.sums[p * s.output.layout.count() + FieldSums::density]);
    H5Fclose(file);
    std::ifstream xmf("points.xmf");
    std::stringstream text;
    text << xmf.rdbuf();
    EXPECT_NE(text.str().find("<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"3\" NodesPerElement=\"1\"/>"), std::string::npos);
}
#endif

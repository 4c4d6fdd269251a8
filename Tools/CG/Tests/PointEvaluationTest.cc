// Theory/CoarseGraining.md "Fields": a grid is a list of points, so the same point gives
// bitwise the same values from a grid, from a point file, alone or in another order; and
// concentrations are fractions in [0, 1] that add up to 1 wherever there is mass.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/DerivedFields.h"
#include "Fields/EvaluationPoints.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

// A dense random bidisperse packing in a periodic box, with random velocities.
ParticleFrame randomMixture(int count, unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> x(0, 6), y(0, 4), z(0, 5), v(-1, 1);
    std::vector<Vec3> position, velocity;
    std::vector<double> radius;
    std::vector<int> species;
    for (int i = 0; i < count; ++i) {
        position.push_back({x(random), y(random), z(random)});
        velocity.push_back({v(random), v(random), v(random)});
        species.push_back(i % 3 == 0 ? 0 : 1);
        radius.push_back(species.back() == 0 ? 0.5 : 0.397);
    }
    return makeFrame(position, radius, DomainBox{{0, 0, 0}, {6, 4, 5}}, velocity, species);
}

CoarseGrainer mixtureGrainer(KernelShape shape, const std::string& coordinates, const WidthMatrix& width) {
    CoarseGrainingSetup setup;
    setup.shape = shape;
    setup.coordinates = Coordinates::fromName(coordinates);
    setup.width = width;
    setup.speciesDensity = {1.9, 1.9};
    setup.periodic = {true, true, false};
    return CoarseGrainer(setup);
}

}  // namespace

TEST(PointEvaluation, GridAndPointFileGiveBitwiseIdenticalValues) {
    const ParticleFrame frame = randomMixture(300, 3);
    for (const std::string coordinates : {"XYZ", "XZ", "Z"}) {
        const std::array<double, 9> rotated{0.6, 0.1, 0.05, 0.1, 0.5, -0.08, 0.05, -0.08, 0.4};
        for (const WidthMatrix& width : {WidthMatrix::isotropic(0.7), WidthMatrix::full(rotated)}) {
            CoarseGrainer grainer = mixtureGrainer(KernelShape::Lucy, coordinates, width);
            grainer.setFrame(frame, nullptr);
            const std::vector<Vec3> grid = gridPoints(grainer.setup().coordinates, {7, 5, 9}, {0, 0, -1}, {6, 4, 6});
            std::vector<double> onGrid;
            grainer.evaluate(grid, onGrid);

            // The same points through a file (17 significant digits read back exactly), reversed.
            const std::string path = "points_" + coordinates + ".txt";
            {
                std::FILE* file = std::fopen(path.c_str(), "w");
                ASSERT_NE(file, nullptr);
                std::fprintf(file, "# reversed grid\n");
                for (auto p = grid.rbegin(); p != grid.rend(); ++p) std::fprintf(file, "%.17g %.17g %.17g\n", (*p)[0], (*p)[1], (*p)[2]);
                std::fclose(file);
            }
            const std::vector<Vec3> listed = readPointList(path, grainer.setup().coordinates);
            ASSERT_EQ(listed.size(), grid.size());
            std::vector<double> onList;
            grainer.evaluate(listed, onList);
            const int fields = grainer.layout().count();
            double largest = 0;
            for (std::size_t p = 0; p < grid.size(); ++p) {
                const std::size_t q = grid.size() - 1 - p;
                for (int f = 0; f < fields; ++f) {
                    ASSERT_EQ(onGrid[p * fields + f], onList[q * fields + f]) << coordinates << " point " << p << " field " << f;
                }
                largest = std::max(largest, onGrid[p * fields]);
            }
            EXPECT_GT(largest, 0.5) << "the grid sees the packing";
            // One point alone.
            std::vector<double> alone;
            const std::size_t middle = grid.size() / 2;
            const std::vector<Vec3> one(1, grid[middle]);
            grainer.evaluate(one, alone);
            for (int f = 0; f < fields; ++f) EXPECT_EQ(alone[f], onGrid[middle * fields + f]);
        }
    }
}

TEST(PointEvaluation, ConcentrationsAreFractionsThatAddUpToOne) {
    const ParticleFrame frame = randomMixture(200, 5);
    for (KernelShape shape : {KernelShape::Lucy, KernelShape::Gauss, KernelShape::Heaviside}) {
        CoarseGrainer grainer = mixtureGrainer(shape, "XYZ", WidthMatrix::diagonal(0.4, 0.9, 0.3));
        grainer.setFrame(frame, nullptr);
        // Points everywhere, the edges of supports and empty space included.
        const std::vector<Vec3> points = gridPoints(grainer.setup().coordinates, {24, 16, 30}, {0, 0, -2}, {6, 4, 7});
        std::vector<double> sums, values;
        grainer.evaluate(points, sums);
        const FieldSums& layout = grainer.layout();
        const auto columns = derivedColumns(layout);
        const std::size_t phi0 = columns.size() - 2, phi1 = columns.size() - 1;
        ASSERT_EQ(columns[phi0].name, "Concentration_s0");
        int empty = 0;
        for (std::size_t p = 0; p < points.size(); ++p) {
            values.clear();
            appendDerivedFields(layout, sums.data() + p * layout.count(), values);
            EXPECT_GE(values[phi0], 0.0);
            EXPECT_LE(values[phi0], 1.0);
            EXPECT_GE(values[phi1], 0.0);
            EXPECT_LE(values[phi1], 1.0);
            if (values[0] > 0) EXPECT_NEAR(values[phi0] + values[phi1], 1.0, 1e-12);
            else ++empty;
        }
        EXPECT_GT(empty, 0) << "some points see no particle";
    }
}

// Velocity and kinetic stress of particles that all move with one velocity: V = v, sigma_k = 0
// (no fluctuation); two streams +-u of equal mass: V = 0, sigma_k,xx = rho u^2.
TEST(PointEvaluation, VelocityAndKineticStressOfUniformAndCounterStreamingMotion) {
    std::vector<Vec3> x, v;
    for (int i = 0; i < 40; ++i) {
        x.push_back({0.3 + 0.1 * i, 1.0 + 0.01 * i, 2.0});
        v.push_back({0.7, -0.2, 0.1});
    }
    const DomainBox box{{0, 0, 0}, {5, 3, 4}};
    CoarseGrainer grainer = mixtureGrainer(KernelShape::Lucy, "XYZ", WidthMatrix::isotropic(1.0));
    grainer.setFrame(makeFrame(x, std::vector<double>(x.size(), 0.5), box, v), nullptr);
    std::vector<double> sums, values;
    grainer.evaluate({{2.0, 1.2, 2.1}}, sums);
    appendDerivedFields(grainer.layout(), sums.data(), values);
    EXPECT_NEAR(values[5], 0.7, 1e-14);
    EXPECT_NEAR(values[6], -0.2, 1e-14);
    EXPECT_NEAR(values[7], 0.1, 1e-14);
    for (int c = 8; c < 14; ++c) EXPECT_NEAR(values[c], 0.0, 1e-13);

    // Each position holds a pair moving at +-u along x.
    std::vector<Vec3> x2, v2;
    for (const Vec3& p : x) {
        x2.push_back(p);
        x2.push_back(p);
        v2.push_back({1.5, 0, 0});
        v2.push_back({-1.5, 0, 0});
    }
    grainer.setFrame(makeFrame(x2, std::vector<double>(x2.size(), 0.5), box, v2), nullptr);
    grainer.evaluate({{2.0, 1.2, 2.1}}, sums);
    values.clear();
    appendDerivedFields(grainer.layout(), sums.data(), values);
    EXPECT_NEAR(values[5], 0.0, 1e-14);
    EXPECT_NEAR(values[8], values[0] * 1.5 * 1.5, 1e-12 * values[0]);  // KineticStressXX = rho u^2
    EXPECT_NEAR(values[13], 0.0, 1e-14);                                 // KineticStressZZ
}

// A driver coarse-graining its own particles gives their masses (ParticleFrame::mass; the drum's
// ellipsoids are no spheres of their .data radius). Density and species density are then sums of
// those masses times the kernel, the volume fraction still that of spheres of the radius: with
// the masses doubled (m = 2 rho V, exact in floating point) the density doubles to the bit and
// the volume fraction stays. In cylindrical coordinates too. A mass list of the wrong length is
// refused.
TEST(PointEvaluation, GivenMassesReplaceThoseOfTheRadius) {
    const ParticleFrame spheres = makeFrame({{1, 1, 1}, {1.4, 0.8, 1.2}, {2, 2, 2}}, {0.5, 0.3, 0.4},
                                            DomainBox{{0, 0, 0}, {3, 3, 3}}, {}, {0, 1, 0});
    for (const std::string coordinates : {"XYZ", "XZ", "RZ"}) {
        CoarseGrainingSetup setup;
        setup.coordinates = Coordinates::fromName(coordinates);
        if (setup.coordinates.isCylindrical()) setup.coordinates.setAxis(1, {0, 0, 0});
        setup.width = WidthMatrix::isotropic(0.8);
        setup.speciesDensity = {1.5, 2.5};
        ParticleFrame given = spheres;
        for (std::size_t p = 0; p < given.size(); ++p)
            given.mass.push_back(2 * setup.speciesDensity[given.species[p]] * sphereVolume(given.radius[p]));
        const auto points = gridPoints(setup.coordinates, {6, 6, 6}, {0.5, 0.5, 0.5}, {2.5, 2.5, 2.5});
        std::vector<double> fromRadius, fromMass;
        CoarseGrainer grainer(setup);
        grainer.setFrame(spheres, nullptr);
        grainer.evaluate(points, fromRadius);
        grainer.setFrame(given, nullptr);
        grainer.evaluate(points, fromMass);
        const FieldSums& f = grainer.layout();
        double total = 0;
        for (std::size_t p = 0; p < points.size(); ++p) {
            const double* a = fromRadius.data() + p * f.count();
            const double* b = fromMass.data() + p * f.count();
            EXPECT_EQ(b[FieldSums::density], 2 * a[FieldSums::density]) << coordinates << " point " << p;
            EXPECT_EQ(b[f.speciesDensityIndex(1)], 2 * a[f.speciesDensityIndex(1)]) << coordinates << " point " << p;
            EXPECT_EQ(b[FieldSums::volumeFraction], a[FieldSums::volumeFraction]) << coordinates << " point " << p;
            total += a[FieldSums::density];
        }
        EXPECT_GT(total, 0) << coordinates;  // (the points see the particles)
    }
    ParticleFrame wrong = spheres;
    wrong.mass = {1, 2};
    CoarseGrainingSetup setup;
    setup.speciesDensity = {1.5, 2.5};
    CoarseGrainer grainer(setup);
    EXPECT_THROW(grainer.setFrame(wrong, nullptr), InputError);
}

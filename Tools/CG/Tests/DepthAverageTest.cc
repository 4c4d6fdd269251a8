// Depth-averaged chute fields (issue 5 item 4, Fields/DepthAverage.h) on synthetic packings
// whose answers are known: layers of equal spheres on a lattice, with a shear velocity u_x = c z
// and small particles in chosen layers.
//
// - The mass per area, the mass-weighted velocity and the concentration are integrals of the
//   density, momentum and species-density fields over z; CG conserves mass and momentum, so over
//   a z range that holds every kernel they are the column's totals, sum m, sum m u / sum m and
//   sum m_s / sum m. The midpoint rule of the grid converges like the Fourier transform of the
//   kernel at 2 pi/dz, i.e. like (dz/w)^4 for Lucy (its third derivative jumps at 0 and at the
//   edge); the constant is below 1 (0.22 measured at dz = w/20), so dz = w/400 gives < 1e-10.
// - Per x (XZ, periodic x) the kernel's x-marginal summed over an x-lattice of spacing a is
//   1/a up to the Fourier transform of that marginal at k = 2 pi w_x/a (Poisson summation):
//   the |r|^3 term of the 2-D Lucy polynomial gives ~720 k^-5, its edge ~200 k^-4.5; at
//   w_x = 20 a (k = 126) together < 2e-7.
// - With the default bulk density (mass-weighted mean density), a slab of uniform density rho_0
//   and thickness H smoothed by a 1-D kernel has int rho = rho_0 H and int rho^2 = rho_0^2
//   (H - 2B), B = int F (1 - F) dz over one edge (F the kernel's cumulative distribution); so
//   h = H^2/(H - 2B). B is computed here by quadrature of the Lucy polynomial. A lattice of layers
//   a apart is that slab up to the Euler-Maclaurin term (a^2/24) K' at the edges, a relative change
//   of int rho^2 of order 0.02 (a/w)^2 (4e-5 measured at a = w/20): a = w/200 gives 4e-7.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/DepthAverage.h"
#include "Fields/EvaluationPoints.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

constexpr double shearRate = 0.3;  // u_x = c z
constexpr double radius = 0.1;     // small spheres on a fine lattice: the kernels are smooth over it
constexpr double density = 2;      // both species
const double sphereMass = density * sphereVolume(radius);

struct Column {
    double mass = 0, momentumX = 0, smallMass = 0;
};

// Columns of `layers(x)` layers at z = (j + 1/2) dz_lattice on an x-lattice of spacing ax over
// [0, lx) (y at the box centre); species 1 (small) in the layers j >= smallFrom.
ParticleFrame lattice(double lx, double ly, double ax, double dzLattice, const std::function<int(double)>& layers,
                      int smallFrom, double zTop) {
    std::vector<Vec3> x, v;
    std::vector<double> r;
    std::vector<int> s;
    for (double xi = 0.5 * ax; xi < lx; xi += ax) {
        for (int j = 0; j < layers(xi); ++j) {
            const double z = (j + 0.5) * dzLattice;
            x.push_back({xi, 0.5 * ly, z});
            v.push_back({shearRate * z, 0, 0});
            r.push_back(radius);
            s.push_back(j >= smallFrom ? 1 : 0);
        }
    }
    return makeFrame(x, r, DomainBox{{0, 0, 0}, {lx, ly, zTop}}, v, s);
}

Column columnOf(int layers, double dzLattice, int smallFrom) {
    Column c;
    for (int j = 0; j < layers; ++j) {
        const double z = (j + 0.5) * dzLattice;
        c.mass += sphereMass;
        c.momentumX += sphereMass * shearRate * z;
        if (j >= smallFrom) c.smallMass += sphereMass;
    }
    return c;
}

std::vector<std::vector<double>> depthAverageOf(const ParticleFrame& frame, const std::string& coordinates,
                                                 const WidthMatrix& width, std::array<long, 3> count, double zLo,
                                                 double zHi, std::optional<double> bulk, std::vector<Vec3>& points) {
    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName(coordinates);
    setup.width = width;
    setup.speciesDensity = {density, density};
    setup.periodic = {true, true, false};
    CoarseGrainer grainer(setup);
    grainer.setFrame(frame, nullptr);
    points = gridPoints(setup.coordinates, count, {frame.box.lo[0], frame.box.lo[1], zLo},
                        {frame.box.hi[0], frame.box.hi[1], zHi});
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    std::vector<std::vector<double>> rows;
    depthAverage(grainer.layout(), sums, count[2], (zHi - zLo) / double(count[2]), bulk, rows);
    return rows;
}

// Column indices of depthAveragedColumns.
enum { massPerArea, bulkDensity, height, solidHeight, velocityX, velocityY, velocityZ, concentration0, concentration1 };

}  // namespace

TEST(DepthAverage, OneColumnGivesTheTotalsPerArea) {
    // Z: 24 layers 0.2 apart (H = 4.8), the top 10 small, on a 2 x 1.5 box (area 3).
    const double lx = 2, ly = 1.5, dzLattice = 0.2;
    const ParticleFrame frame = lattice(lx, ly, lx, dzLattice, [](double) { return 24; }, 14, 5);
    const Column expected = columnOf(24, dzLattice, 14);
    for (double w : {0.5, 1.0}) {
        std::vector<Vec3> points;
        const double zLo = -w - 1, zHi = 4.8 + w + 1;  // every kernel inside
        const auto rows = depthAverageOf(frame, "Z", WidthMatrix::isotropic(w), {1, 1, long(400 * (zHi - zLo) / w)}, zLo,
                                         zHi, std::optional<double>(1.25), points);
        ASSERT_EQ(rows.size(), 1u);
        const auto& row = rows[0];
        const double area = lx * ly;
        EXPECT_NEAR(row[massPerArea] / (expected.mass / area), 1, 1e-10) << "w = " << w;
        EXPECT_NEAR(row[velocityX] / (expected.momentumX / expected.mass), 1, 1e-10);
        EXPECT_NEAR(row[velocityY], 0, 1e-15);
        EXPECT_NEAR(row[concentration1], expected.smallMass / expected.mass, 1e-10);
        EXPECT_NEAR(row[concentration0] + row[concentration1], 1, 1e-12);
        EXPECT_EQ(row[bulkDensity], 1.25);
        EXPECT_NEAR(row[height] / (expected.mass / area / 1.25), 1, 1e-10);
        // Solid height: the particles' volume per area.
        EXPECT_NEAR(row[solidHeight] / (24 * sphereVolume(radius) / area), 1, 1e-10);
    }
}

TEST(DepthAverage, PerXColumnsOfTwoHeights) {
    // XZ, periodic x over [0, 80): columns of 8 layers for x < 40 and 16 layers beyond, lattice
    // spacing 0.5 along x, 0.2 along z, small particles from layer 4 on; wx = 10 = 20 spacings,
    // wz = 0.5. Far from the steps (x = 0 and 40) the columns are the local totals; everywhere,
    // the x integral of the mass per area is the total mass per y length.
    const double lx = 80, ly = 2, ax = 0.5, dzLattice = 0.2, wx = 10;
    auto layers = [](double x) { return x < 40 ? 8 : 16; };
    const ParticleFrame frame = lattice(lx, ly, ax, dzLattice, layers, 4, 5);
    std::vector<Vec3> points;
    const long nx = 80;
    const auto rows = depthAverageOf(frame, "XZ", WidthMatrix::diagonal(wx, 1, 0.5), {nx, 1, 2000}, -1, 4.2,
                                     std::nullopt, points);
    ASSERT_EQ(rows.size(), std::size_t(nx));
    double integral = 0, totalMass = 0;
    for (std::size_t p = 0; p < frame.size(); ++p) totalMass += sphereMass;
    for (long c = 0; c < nx; ++c) {
        const auto& row = rows[c];
        const double x = points[c * 2000][0];
        integral += row[massPerArea] * lx / double(nx);
        const double distance = std::min({x, std::abs(x - 40), lx - x});
        if (distance < wx + 0.5) continue;  // the kernel reaches the step
        const int n = layers(x);
        const Column expected = columnOf(n, dzLattice, 4);
        EXPECT_NEAR(row[massPerArea] / (expected.mass / (ax * ly)), 1, 1e-6) << "x = " << x;
        EXPECT_NEAR(row[velocityX] / (expected.momentumX / expected.mass), 1, 1e-6) << "x = " << x;
        EXPECT_NEAR(row[concentration1], expected.smallMass / expected.mass, 1e-6) << "x = " << x;
    }
    // Midpoint rule in x of a periodic smooth field: the same spectral accuracy.
    EXPECT_NEAR(integral / (totalMass / ly), 1, 1e-6);
}

TEST(DepthAverage, DefaultBulkDensityGivesTheSlabThicknessPlusTheEdgeSmoothing) {
    // A slab of 2000 layers 0.0025 apart (H = 5), one particle per layer in a 1 x 1 box: uniform
    // density rho_0 = m/0.0025 smoothed by a 1-D Lucy kernel of width w = 0.5 (200 layers).
    const double dzLattice = 0.0025, H = 2000 * dzLattice, w = 0.5;
    const ParticleFrame frame = lattice(1, 1, 1, dzLattice, [](double) { return 2000; }, 100000, 6);
    // B = w int_{-1}^{1} F(1 - F) du, F(u) = int_{-1}^{u} (5/4)(1 - 6q^2 + 8|q|^3 - 3q^4) dq.
    auto lucy = [](double q) {
        q = std::abs(q);
        return 1.25 * (1 - 6 * q * q + 8 * q * q * q - 3 * q * q * q * q);
    };
    const GaussLegendre rule(40);
    auto cumulative = [&](double u) {  // split at 0, where |q|^3 is not smooth
        double f = 0;
        std::vector<double> x, wq;
        rule.panels(-1, u, {0.0}, x, wq);
        for (std::size_t k = 0; k < x.size(); ++k) f += wq[k] * lucy(x[k]);
        return f;
    };
    double B = 0;
    std::vector<double> x, wq;
    rule.panels(-1, 1, {0.0}, x, wq);
    for (std::size_t k = 0; k < x.size(); ++k) {
        const double F = cumulative(x[k]);
        B += wq[k] * F * (1 - F);
    }
    B *= w;
    std::vector<Vec3> points;
    const auto rows = depthAverageOf(frame, "Z", WidthMatrix::isotropic(w), {1, 1, 1600}, -1, 7, std::nullopt, points);
    const double rho0 = sphereMass / dzLattice;
    EXPECT_NEAR(rows[0][height] / (H * H / (H - 2 * B)), 1, 2e-6) << "B = " << B;
    EXPECT_NEAR(rows[0][bulkDensity] / (rho0 * (H - 2 * B) / H), 1, 2e-6);
}

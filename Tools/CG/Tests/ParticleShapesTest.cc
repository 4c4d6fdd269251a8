// Particles of any shape (IO/ParticleShapes.h): the superquadric volume against a quadrature of
// the body's height done here, the shapes and particles of a Talus restart file with superquadric
// particles, and the mass and volume they give the fields of a .data frame (not those of the
// bounding sphere the .data radius describes).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "IO/DataFileReader.h"
#include "IO/FstatFileReader.h"
#include "IO/InputError.h"
#include "IO/RestartFileReader.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

// The volume of a superquadric by direct quadrature of its height, independent of the beta
// functions: in the octant x, y >= 0 the body (Theory/Superquadrics.md eq. (1)) reaches
// z = c (1 - nu^(e2/e1))^(e1/2), nu = (x/a)^(2/e2) + (y/b)^(2/e2), over the quarter superellipse
// y <= b (1 - (x/a)^(2/e2))^(e2/2); V = 8 times the double integral. The panels' end mapping
// (CGTestHelpers.h) makes the root-like edges of both integrands smooth.
double volumeByQuadrature(double a, double b, double c, double e1, double e2) {
    const GaussLegendre rule(60);
    std::vector<double> xs, wx, ys, wy;
    rule.panels(0, a, {}, xs, wx);
    double sum = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const double yMax = b * std::pow(std::max(0.0, 1 - std::pow(xs[i] / a, 2 / e2)), e2 / 2);
        rule.panels(0, yMax, {}, ys, wy);
        for (std::size_t j = 0; j < ys.size(); ++j) {
            const double nu = std::pow(xs[i] / a, 2 / e2) + std::pow(ys[j] / b, 2 / e2);
            sum += wx[i] * wy[j] * c * std::pow(std::max(0.0, 1 - std::pow(nu, e2 / e1)), e1 / 2);
        }
    }
    return 8 * sum;
}

// A Talus restart file (restart.md, format 7) with one species of density `rho`, the shapes
// `shapeLines`, and particle lines of a scene with shapes (34 fields) from `particles`: id, x,
// radius, mass, shape index.
struct ShapedParticle {
    long id;
    double x, radius, mass;
    int shape;
};
std::string shapedRestart(double rho, const std::string& shapeLines, int shapeCount, const std::vector<ShapedParticle>& particles) {
    std::ostringstream out;
    out.precision(17);
    out << "Talus restart 7\nname shapes\ntime 1 100\ndomain -10 -10 -10 10 10 10 0 0 0\nspecies 1\n   grain " << rho
        << " LinearSpringDashpot 1 0 0 0 0 1\nwalls 0\nshapes 1 " << shapeCount << "\n" << shapeLines << "particles "
        << particles.size() << " 10\n";
    for (const ShapedParticle& p : particles) {
        // id, position, velocity, angular velocity, force, torque, radius, mass, inverse mass,
        // inverse inertia, species, fixed, motion, orientation, angular momentum, principal inertia, shape
        out << "   " << p.id << " " << p.x << " 0 0  0 0 0  0 0 0  0 0 0  0 0 0  " << p.radius << " " << p.mass << " "
            << 1 / p.mass << " 0 0 0 -1  0.6 0 0.8 0  0 0 0  1 1 1  " << p.shape << "\n";
    }
    return out.str();
}

// A .data frame at t = 1 whose lines are the particles at x = 0, 5, ... (ascending id).
std::string dataFrame(const std::vector<double>& radius) {
    std::ostringstream out;
    out.precision(10);
    out << radius.size() << " 1 -10 -10 -10 10 10 10\n";
    for (std::size_t p = 0; p < radius.size(); ++p) out << 5.0 * p << " 0 0 0 0 0 " << radius[p] << " 0 0 0 0 0 0 0\n";
    return out.str();
}

}  // namespace

// Eq. (3) of Theory/Superquadrics.md against the sphere, the ellipsoid (4/3 pi a b c) and the
// quadrature above for blocky and flat shapes.
TEST(ParticleShapes, SuperquadricVolume) {
    const SuperquadricShape sphere{{0.5, 0.5, 0.5}, 1, 1}, ellipsoid{{0.8, 0.4, 0.3}, 1, 1}, box{{0.8, 0.4, 0.3}, 0.01, 0.01};
    EXPECT_NEAR(sphere.volume(), std::numbers::pi / 6, 1e-15);
    EXPECT_NEAR(ellipsoid.volume(), 4.0 / 3 * std::numbers::pi * 0.8 * 0.4 * 0.3, 1e-15);
    for (const auto& [e1, e2] : {std::pair{1.0, 1.0}, {0.5, 0.5}, {0.3, 0.8}, {0.9, 0.2}}) {
        const SuperquadricShape shape{{0.8, 0.4, 0.3}, e1, e2};
        const double quadrature = volumeByQuadrature(0.8, 0.4, 0.3, e1, e2);
        EXPECT_NEAR(shape.volume() / quadrature, 1, 1e-7) << "e1 = " << e1 << ", e2 = " << e2;
    }
    // A block with nearly sharp edges approaches the box 2a x 2b x 2c.
    EXPECT_NEAR(box.volume() / (8 * 0.8 * 0.4 * 0.3), 1, 0.01);
}

// A restart file in slot order (ids 3, 0, 7) gives the particles in ascending id, the order of the
// .data lines, with their shapes; the .data frame then gets the superquadric's volume, and its
// density and volume fraction at the centre of the ellipsoid are rho_s V W(0) and V W(0), W(0) =
// 105/(16 pi w^3) for the 3-D Lucy kernel of width w (KernelProfile.h). With the bounding
// sphere's volume (the .data radius 0.8) they would be 0.8^2/(0.4 x 0.3) = 5.3 times larger.
TEST(ParticleShapes, RestartShapesGiveMassAndVolume) {
    const double rho = 2;
    const SuperquadricShape ellipsoid{{0.8, 0.4, 0.3}, 1, 1}, block{{0.5, 0.5, 0.25}, 0.5, 0.4};
    const double v0 = ellipsoid.volume(), v1 = block.volume();
    const std::string shapes = "   0.8 0.4 0.3 1 1\n   0.5 0.5 0.25 0.5 0.40000000000000002\n";
    const double blockRadius = 0.6;  // any: the reader takes the radius as the file gives it
    write("shaped.restart", shapedRestart(rho, shapes, 2,
                                          {{3, 10, blockRadius, rho * v1, 1}, {0, 0, 0.8, rho * v0, 0}, {7, 15, 0.5, rho * 4.0 / 3 * std::numbers::pi / 8, -1}}));
    const RestartInfo info = readRestartFile("shaped.restart");
    ASSERT_EQ(info.shapes.size(), 2u);
    EXPECT_EQ(info.shapes[1].semiAxes, (std::array<double, 3>{0.5, 0.5, 0.25}));
    EXPECT_EQ(info.shapes[1].e2, 0.4);
    ASSERT_EQ(info.particles.size(), 3u);
    EXPECT_EQ(info.particles[0].id, 0);
    EXPECT_EQ(info.particles[1].id, 3);
    EXPECT_EQ(info.particles[2].id, 7);
    EXPECT_EQ(info.particles[0].shape, 0);
    EXPECT_EQ(info.particles[1].shape, 1);
    EXPECT_EQ(info.particles[2].shape, -1);
    EXPECT_EQ(info.particles[0].orientation, (std::array<double, 4>{0.6, 0, 0.8, 0}));
    EXPECT_EQ(info.fixed.size(), 3u);

    // The .data lines: ids 0, 3, 7 at x = 0, 5, 10 (the .data positions are the frame's own).
    write("shaped.data", dataFrame({0.8, blockRadius, 0.5}));
    std::vector<ParticleFrame> frames = readAllDataFrames("shaped.data");
    applyRestartShapes(info, frames[0], "shaped.data");
    ASSERT_EQ(frames[0].volume.size(), 3u);
    EXPECT_EQ(frames[0].volumeOf(0), v0);
    EXPECT_EQ(frames[0].volumeOf(1), v1);
    EXPECT_NEAR(frames[0].volumeOf(2), 4.0 / 3 * std::numbers::pi / 8, 1e-15);
    EXPECT_EQ(frames[0].massOf(0, rho), rho * v0);

    CoarseGrainingSetup setup;
    setup.speciesDensity = {rho};
    const double w = 1;
    setup.width = WidthMatrix::isotropic(w);
    CoarseGrainer grainer(setup);
    grainer.setFrame(frames[0], nullptr, "shaped.data");
    std::vector<double> sums;
    grainer.evaluate({{0, 0, 0}, {5, 0, 0}}, sums);
    const int fields = grainer.layout().count();
    const double w0 = 105 / (16 * std::numbers::pi * w * w * w);
    EXPECT_NEAR(sums[FieldSums::density], rho * v0 * w0, 1e-13);
    EXPECT_NEAR(sums[FieldSums::volumeFraction], v0 * w0, 1e-13);
    EXPECT_NEAR(sums[fields + FieldSums::density], rho * v1 * w0, 1e-13);
}

// The .data frame and the restart file must describe the same particles: as many, and each line
// with the restart particle's radius (the bounding radius) and species.
TEST(ParticleShapes, FramesThatDoNotMatchTheRestartFile) {
    const SuperquadricShape ellipsoid{{0.8, 0.4, 0.3}, 1, 1};
    const double rho = 1, v0 = ellipsoid.volume();
    write("match.restart", shapedRestart(rho, "   0.8 0.4 0.3 1 1\n", 1, {{0, 0, 0.8, rho * v0, 0}, {1, 5, 0.5, rho * 0.5, -1}}));
    const RestartInfo info = readRestartFile("match.restart");
    write("fewer.data", dataFrame({0.8}));
    auto fewer = readAllDataFrames("fewer.data");
    EXPECT_EQ(errorOf([&] { applyRestartShapes(info, fewer[0], "fewer.data"); }),
              "fewer.data line 1: the frame at t = 1 has 1 particles, but the restart file describes 2: their shapes cannot be "
              "matched (a frame before the last insertion? --time-min)");
    write("radius.data", dataFrame({0.8, 0.6}));
    auto radius = readAllDataFrames("radius.data");
    EXPECT_EQ(errorOf([&] { applyRestartShapes(info, radius[0], "radius.data"); }),
              "radius.data line 3: radius 0.6 and species 0, but the restart file's particle 1 (id 1) has radius 0.5 and "
              "species 0: the files describe different particles");
}

// The contact stress of two superquadrics spreads the force along their line of centres: its
// integral over a depth profile (Z) is the virial f (x) b / area with b = x_i - x_j (the box's
// area A = 20 x 20 from the .data header). Ellipsoids of semi-axes (0.8, 0.4, 0.3) at (0, 0, 0)
// and (1.2, 0, 0.5), a contact at c = (0.7, 0, 0.2) with normal (-1, 0, 0) and fn = 2, written
// from both sides: f on i = (-2, 0, 0), b = (-1.2, 0, -0.5), so int sigma_xx dz = 2.4/A and
// int sigma_xz dz = 1/A. Taking them as spheres of their bounding radii would put the branch
// (r_i + r_j - dn) n = (-1.59, 0, 0) along the normal (int sigma_xz dz = 0) and refuse the
// contact point, 0.728 from x_i instead of r - dn/2 = 0.795.
TEST(ParticleShapes, ContactStressBranchIsTheLineOfCentres) {
    const SuperquadricShape ellipsoid{{0.8, 0.4, 0.3}, 1, 1};
    const double rho = 1, m = rho * ellipsoid.volume();
    write("pair.restart", shapedRestart(rho, "   0.8 0.4 0.3 1 1\n", 1, {{0, 0, 0.8, m, 0}, {1, 0, 0.8, m, 0}}));
    write("pair.data", "2 1 -10 -10 -10 10 10 10\n0 0 0 0 0 0 0.8 0 0 0 0 0 0 0\n1.2 0 0.5 0 0 0 0.8 0 0 0 0 0 0 0\n");
    write("pair.fstat", "# 1 1\n# -10 -10 -10 10 10 10\n# 0.8 0.8 0 0 0 0\n"
                        "1 0 1 0.7 0 0.2 0.01 0 2 0 -1 0 0 0 0 0\n1 1 0 0.7 0 0.2 0.01 0 2 0 1 0 0 0 0 0\n");
    const RestartInfo info = readRestartFile("pair.restart");
    std::vector<ParticleFrame> frames = readAllDataFrames("pair.data");
    applyRestartShapes(info, frames[0], "pair.data");
    const auto contacts = readAllFstatFrames("pair.fstat");
    CoarseGrainingSetup setup;
    setup.speciesDensity = {rho};
    setup.coordinates = Coordinates::fromName("Z");
    setup.contactStress = true;
    CoarseGrainer grainer(setup);
    grainer.setFrame(frames[0], &contacts[0], "pair.data", "pair.fstat");
    // The integrand is smooth between the breakpoints: the segment's ends z = 0, 0.5 and them +- w.
    const GaussLegendre rule(20);
    std::vector<double> z, weight;
    rule.panels(-1.5, 2, {-1, -0.5, 0, 0.5, 1, 1.5}, z, weight);
    std::vector<Vec3> points;
    for (double zk : z) points.push_back({0, 0, zk});
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    const int fields = grainer.layout().count(), stress = grainer.layout().contactStressIndex();
    double xx = 0, xz = 0;
    for (std::size_t k = 0; k < z.size(); ++k) {
        xx += weight[k] * sums[k * fields + stress + 0];
        xz += weight[k] * sums[k * fields + stress + 2];
    }
    const double area = 400;
    EXPECT_NEAR(xx * area, 2.4, 1e-12);
    EXPECT_NEAR(xz * area, 1.0, 1e-12);
}

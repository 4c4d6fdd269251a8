// Cylindrical coordinates (Fields/CylindricalCoarseGrainer.h), tests (b)-(d) of issue 5, each
// against an expectation derived without the angular quadrature of Kernels/AngularMoments.h:
//  (b) a ring of particles: with Heaviside the mean over the circle is the fraction of the circle
//      inside the support ball, phi_c/pi with cos phi_c from the law of cosines; on the axis
//      r = 0 every kernel gives W(|x_i - point|); and for Lucy and Gauss the sums (density,
//      radial/azimuthal/axial momentum, momentum flux) equal those of the Cartesian fields of
//      20000 particles spread evenly over the ring, projected on (e_r, e_theta, e_s): a sum over
//      evenly spaced particles is the trapezoid rule of the angular average.
//  (c) solid-body rotation v = omega e_s x (x - c) (plus a uniform axial drift): radial velocity
//      zero and angular velocity omega to round-off, azimuthal velocity the angular mean of the
//      Cartesian field
//      <p . e_theta> / <rho> (trapezoid rule over 4096 points of the circle), and omega r where
//      the density is uniform (a fine lattice).
//  (d) bad input names the flag.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include "App/Options.h"
#include "App/RunInputs.h"
#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/DerivedFields.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

constexpr double pi = std::numbers::pi;

// A drum axis along z through `centre` (so that e_r, e_theta are the familiar ones of x, y).
CoarseGrainer cylindricalGrainer(const char* name, KernelShape shape, double width, const Vec3& centre, int axis = 2) {
    CoarseGrainingSetup setup;
    setup.shape = shape;
    setup.coordinates = Coordinates::fromName(name);
    setup.coordinates.setAxis(axis, centre);
    setup.width = WidthMatrix::isotropic(width);
    setup.speciesDensity = {1.5};
    return CoarseGrainer(setup);
}

CoarseGrainer cartesianGrainer(const char* name, KernelShape shape, double width) {
    CoarseGrainingSetup setup;
    setup.shape = shape;
    setup.coordinates = Coordinates::fromName(name);
    setup.width = WidthMatrix::isotropic(width);
    setup.speciesDensity = {1.5};
    return CoarseGrainer(setup);
}

// N particles evenly on the circle of radius R0 about the z axis through `centre` at height z0,
// each with radial, azimuthal and axial velocity u in its own (e_r, e_theta, e_z).
ParticleFrame ring(int n, double r0, double z0, const Vec3& centre, const Vec3& u, const DomainBox& box) {
    std::vector<Vec3> x, v;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * pi * (i + 0.3) / n;
        x.push_back({centre[0] + r0 * std::cos(a), centre[1] + r0 * std::sin(a), z0});
        v.push_back({u[0] * std::cos(a) - u[1] * std::sin(a), u[0] * std::sin(a) + u[1] * std::cos(a), u[2]});
    }
    return makeFrame(x, std::vector<double>(n, 0.1), box, v);
}

const DomainBox ringBox{{-10, -10, -10}, {10, 10, 10}};

}  // namespace

TEST(CylindricalFields, HeavisideRingIsTheArcInsideTheBall) {
    // Mass m = 1.5 * 4/3 pi 0.1^3 per particle; 7 particles at R0 = 3, z0 = 0.4 (angles do not
    // matter: the average over the circle depends on ri and si only).
    const double w = 1.2, r0 = 3, z0 = 0.4;
    const int n = 7;
    const double m = 1.5 * sphereVolume(0.1);
    CoarseGrainer grainer = cylindricalGrainer("RZ", KernelShape::Heaviside, w, {0, 0, 0});
    grainer.setFrame(ring(n, r0, z0, {0, 0, 0}, {0, 0, 0}, ringBox), nullptr);
    std::vector<Vec3> points;
    for (double r : {1.9, 2.2, 2.5, 3.0, 3.4, 3.9, 4.15}) {
        for (double z : {0.4, 0.9, -0.3}) points.push_back({r, 0, z});
    }
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    const int fields = grainer.layout().count();
    int inside = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double r = points[p][0], dz = points[p][2] - z0;
        // |x - xi|^2 = r^2 + R0^2 - 2 r R0 cos(phi) + dz^2 < w^2  <=>  cos(phi) > cosEdge.
        const double cosEdge = (r * r + r0 * r0 + dz * dz - w * w) / (2 * r * r0);
        const double arc = cosEdge >= 1 ? 0.0 : cosEdge <= -1 ? pi : std::acos(cosEdge);
        const double expected = n * m * 3 / (4 * pi * w * w * w) * arc / pi;
        if (arc > 0) ++inside;
        EXPECT_NEAR(sums[p * fields + FieldSums::density], expected, 1e-13 * n * m) << "r " << r << " z " << points[p][2];
    }
    EXPECT_GT(inside, 12);  // most points see part of the ring
}

TEST(CylindricalFields, OnTheAxisEveryKernelGivesItsValueAtTheRingDistance) {
    const double w = 1.0, r0 = 0.6;
    const double m = 1.5 * sphereVolume(0.1);
    for (KernelShape shape : {KernelShape::Lucy, KernelShape::Gauss, KernelShape::Heaviside}) {
        const double width = shape == KernelShape::Gauss ? w / 3 : w;
        CoarseGrainer grainer = cylindricalGrainer("RZ", shape, width, {1, 2, 0});
        grainer.setFrame(ring(5, r0, 0.0, {1, 2, 0}, {0.3, -0.2, 0.1}, ringBox), nullptr);
        std::vector<Vec3> points{{0, 0, 0}, {0, 0, 0.5}};
        std::vector<double> sums;
        grainer.evaluate(points, sums);
        const int fields = grainer.layout().count();
        for (std::size_t p = 0; p < points.size(); ++p) {
            const double q = std::hypot(r0, points[p][2]) / width;
            // Theory/CoarseGraining.md eq. (5)-(10) / KernelProfile.h in 3-D, written out here.
            double w3 = 0;
            if (shape == KernelShape::Lucy && q < 1) w3 = 105 / (16 * pi) * (1 - 6 * q * q + 8 * q * q * q - 3 * q * q * q * q);
            if (shape == KernelShape::Heaviside && q < 1) w3 = 3 / (4 * pi);
            if (shape == KernelShape::Gauss && q < 3) {
                w3 = std::exp(-0.5 * q * q) / (4 * pi * (std::sqrt(pi / 2) * std::erf(3 / std::sqrt(2.0)) - 3 * std::exp(-4.5)));
            }
            const double expected = 5 * m * w3 / (width * width * width);
            EXPECT_GT(expected, 0);
            EXPECT_NEAR(sums[p * fields + FieldSums::density], expected, 1e-14 * expected) << kernelShapeName(shape);
            // On the axis e_r is undefined: the radial and azimuthal momentum vanish exactly.
            EXPECT_EQ(sums[p * fields + FieldSums::momentum + 0], 0.0);
            EXPECT_EQ(sums[p * fields + FieldSums::momentum + 1], 0.0);
            EXPECT_NEAR(sums[p * fields + FieldSums::momentum + 2], 0.1 * expected, 1e-14 * expected);
        }
    }
}

TEST(CylindricalFields, RingSumsEqualTheCartesianFieldsOfManyParticlesOnIt) {
    // 20000 particles of mass m on the ring: the Cartesian sum at a point of the circle of radius
    // r is the trapezoid rule (2 pi / N steps) of N times the angular mean. For the C^2 Lucy
    // kernel its error is far below the tolerance 1e-9 of the largest value. The cut Gauss kernel
    // jumps by W_edge = c_d e^{-9/2} / w^d at the two ends of the arc, where the trapezoid rule
    // can be off by at most one particle's contribution each: the tolerance adds 2 m W_edge
    // (times |u| for momenta, |u|^2 for the momentum flux).
    const int n = 20000;
    const double r0 = 2.0, z0 = 0.3;
    const Vec3 centre{0.5, -1, 0};
    const Vec3 u{0.4, 1.3, -0.7};  // radial, azimuthal, axial of every particle
    const ParticleFrame frame = ring(n, r0, z0, centre, u, ringBox);
    for (KernelShape shape : {KernelShape::Lucy, KernelShape::Gauss}) {
        for (const char* name : {"RZ", "R"}) {
            const bool rz = std::string(name) == "RZ";
            const double width = shape == KernelShape::Gauss ? 0.35 : 1.1;
            CoarseGrainer cylindrical = cylindricalGrainer(name, shape, width, centre);
            CoarseGrainer cartesian = cartesianGrainer(rz ? "XYZ" : "XY", shape, width);
            cylindrical.setFrame(frame, nullptr);
            cartesian.setFrame(frame, nullptr);
            std::vector<Vec3> points, lab;
            const double angle = 0.377;
            for (double r : {0.05, 0.4, 1.0, 1.5, 1.9, 2.0, 2.05, 2.6, 3.0}) {
                for (double z : {0.3, 0.8}) {
                    points.push_back({r, 0, z});
                    lab.push_back({centre[0] + r * std::cos(angle), centre[1] + r * std::sin(angle), z});
                }
            }
            std::vector<double> sums, reference;
            cylindrical.evaluate(points, sums);
            cartesian.evaluate(lab, reference);
            const int fields = cylindrical.layout().count();
            const int labFields = cartesian.layout().count();
            ASSERT_EQ(fields, labFields + 2);  // and the angular momentum and moment of inertia
            double largest = 0;
            for (double value : reference) largest = std::max(largest, std::abs(value));
            const double m = 1.5 * sphereVolume(0.1), speed = std::hypot(u[0], u[1], u[2]);
            const int d = rz ? 3 : 2;
            const double edge = shape == KernelShape::Gauss
                                    ? 2 * m * KernelProfile(shape, d).normalisation() * std::exp(-4.5) / std::pow(width, d) / (rz ? 1.0 : 20.0)
                                    : 0.0;
            const double tolerance = 1e-9 * largest + edge, momentumTolerance = 1e-9 * largest + edge * speed,
                         fluxTolerance = 1e-9 * largest + edge * speed * speed;
            const double er[3] = {std::cos(angle), std::sin(angle), 0}, et[3] = {-std::sin(angle), std::cos(angle), 0},
                         es[3] = {0, 0, 1};
            const double* basis[3] = {er, et, es};
            for (std::size_t p = 0; p < points.size(); ++p) {
                const double* c = &sums[p * fields];
                const double* x = &reference[p * labFields];
                const std::string where = kernelShapeName(shape) + " " + name + " r " + std::to_string(points[p][0]) + " z " +
                                          std::to_string(points[p][2]);
                EXPECT_NEAR(c[FieldSums::density], x[FieldSums::density], tolerance) << where;
                EXPECT_NEAR(c[FieldSums::volumeFraction], x[FieldSums::volumeFraction], tolerance / 1.5) << where;
                // Every particle has radius r0 and azimuthal velocity u_t: L = r0 u_t rho, I = r0^2
                // rho (up to the rounding of r_i and u_t from the positions, summed over 20000
                // terms).
                const int angular = cylindrical.layout().angularMomentumIndex();
                const double l = r0 * u[1] * c[FieldSums::density], inertia = r0 * r0 * c[FieldSums::density];
                EXPECT_NEAR(c[angular], l, 1e-11 * std::abs(l) + 1e-300) << where;
                EXPECT_NEAR(c[angular + 1], inertia, 1e-11 * inertia + 1e-300) << where;
                // Cartesian momentum and momentum flux projected on the local basis.
                const double* pm = x + FieldSums::momentum;
                const double* k = x + FieldSums::momentumFlux;
                const double K[3][3] = {{k[0], k[1], k[2]}, {k[1], k[3], k[4]}, {k[2], k[4], k[5]}};
                for (int a = 0; a < 3; ++a) {
                    const double projected = pm[0] * basis[a][0] + pm[1] * basis[a][1] + pm[2] * basis[a][2];
                    EXPECT_NEAR(c[FieldSums::momentum + a], projected, momentumTolerance) << where << " momentum " << a;
                }
                const int row[6] = {0, 0, 0, 1, 1, 2}, col[6] = {0, 1, 2, 1, 2, 2};
                for (int q = 0; q < 6; ++q) {
                    double projected = 0;
                    for (int i = 0; i < 3; ++i) {
                        for (int j = 0; j < 3; ++j) projected += basis[row[q]][i] * K[i][j] * basis[col[q]][j];
                    }
                    EXPECT_NEAR(c[FieldSums::momentumFlux + q], projected, fluxTolerance) << where << " flux " << q;
                }
            }
        }
    }
}

namespace {

// Solid-body rotation about the y axis through c plus an axial drift, particles random in a
// cylinder of radius 5, periodic along y.
struct Rotation {
    Vec3 centre{1, 0, -2};
    double omega = 0.7, drift = 0.25;
    ParticleFrame frame;
};

Rotation rotatingParticles(int n, unsigned seed) {
    Rotation rot;
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vec3> x, v;
    std::vector<double> radius;
    for (int i = 0; i < n; ++i) {
        const double r = 5 * std::sqrt(unit(random)), a = 2 * pi * unit(random);
        const Vec3 d{r * std::cos(a), 4 * unit(random), r * std::sin(a)};
        x.push_back({rot.centre[0] + d[0], d[1], rot.centre[2] + d[2]});
        // omega e_y x d = omega (d_z, 0, -d_x)
        v.push_back({rot.omega * d[2], rot.drift, -rot.omega * d[0]});
        radius.push_back(0.15 + 0.1 * unit(random));
    }
    rot.frame = makeFrame(x, radius, {{-5, 0, -8}, {7, 4, 4}}, v);
    return rot;
}

}  // namespace

TEST(CylindricalFields, SolidBodyRotationIsAzimuthalWithNoRadialVelocity) {
    const Rotation rot = rotatingParticles(600, 3);
    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName("RZ");
    setup.coordinates.setAxis(1, rot.centre);
    setup.width = WidthMatrix::isotropic(1.5);
    setup.periodic = {false, true, false};
    setup.speciesDensity = {1.5};
    CoarseGrainer grainer(setup);
    grainer.setFrame(rot.frame, nullptr);
    CoarseGrainingSetup labSetup = setup;
    labSetup.coordinates = Coordinates::fromName("XYZ");
    CoarseGrainer cartesian(labSetup);
    cartesian.setFrame(rot.frame, nullptr);

    std::vector<Vec3> points;
    for (double r : {0.3, 1.2, 2.5, 3.7, 4.6}) {
        for (double y : {0.5, 2.0, 3.9}) points.push_back({r, 0, y});
    }
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    const FieldSums& layout = grainer.layout();
    const int fields = layout.count();
    const int circle = 4096;
    for (std::size_t p = 0; p < points.size(); ++p) {
        std::vector<double> derived;
        appendDerivedFields(layout, &sums[p * fields], derived);
        const double rho = derived[0], vr = derived[5], vt = derived[6], vs = derived[7];
        ASSERT_GT(rho, 0);
        const double r = points[p][0];
        EXPECT_LT(std::abs(vr), 1e-14 * rot.omega * 5) << "r " << r;
        EXPECT_NEAR(vs, rot.drift, 1e-14) << "r " << r;
        // Angular momentum over moment of inertia: sum m r_i (omega r_i) C0 / sum m r_i^2
        // C0 = omega.
        EXPECT_NEAR(derived.back(), rot.omega, 1e-14) << "r " << r;
        // The angular mean of the Cartesian fields on the circle (trapezoid rule; for a periodic
        // C^2 integrand its error falls faster than 1/circle^2).
        std::vector<Vec3> lab;
        for (int k = 0; k < circle; ++k) {
            const double a = 2 * pi * k / circle;
            lab.push_back({rot.centre[0] + r * std::cos(a), points[p][2], rot.centre[2] + r * std::sin(a)});
        }
        std::vector<double> labSums;
        cartesian.evaluate(lab, labSums);
        double meanRho = 0, meanTheta = 0, meanRadial = 0;
        const int labFields = cartesian.layout().count();
        for (int k = 0; k < circle; ++k) {
            const double a = 2 * pi * k / circle;
            // Right-handed about +y: e_r = (cos, 0, sin) in (x, z), e_theta = e_y x e_r = (sin, 0,
            // -cos).
            const double* s = &labSums[k * labFields];
            meanRho += s[FieldSums::density] / circle;
            meanTheta += (s[FieldSums::momentum] * std::sin(a) - s[FieldSums::momentum + 2] * std::cos(a)) / circle;
            meanRadial += (s[FieldSums::momentum] * std::cos(a) + s[FieldSums::momentum + 2] * std::sin(a)) / circle;
        }
        EXPECT_NEAR(rho, meanRho, 1e-9 * meanRho) << "r " << r;
        EXPECT_NEAR(vt, meanTheta / meanRho, 1e-9 * rot.omega * 5) << "r " << r;
        EXPECT_NEAR(meanRadial / meanRho, 0.0, 1e-9 * rot.omega * 5) << "r " << r;
        EXPECT_GT(vt, 0);
    }
}

TEST(CylindricalFields, SolidBodyRotationOfAUniformLatticeGivesOmegaR) {
    // Equal particles on a square lattice of spacing h = 0.05 filling the disc r < 5 of the
    // cross-section (axis y), coarse-grained with R (2-D kernel of width 1, averaged along y):
    // in a uniform continuum the kernel-weighted mean position is the point itself, so
    // V_theta = omega r exactly; the lattice sum differs from the continuum integral by the
    // kernel's Fourier transform at the reciprocal lattice vectors 2 pi / h (Poisson summation),
    // which for a C^2 kernel falls at least like (h / w)^4 ~ 1e-5 of the density (much faster in
    // practice: the largest deviation of V_theta / (omega r) - 1 measured for r = 1 to 3.5 is
    // 6.1e-9). Tolerance 1e-7 of omega r.
    const double h = 0.05, omega = 0.7;
    std::vector<Vec3> x, v;
    for (double a = -5 + h / 2; a < 5; a += h) {
        for (double b = -5 + h / 2; b < 5; b += h) {
            if (a * a + b * b >= 25) continue;
            x.push_back({a, 0.5, b});
            v.push_back({omega * b, 0, -omega * a});
        }
    }
    const ParticleFrame frame = makeFrame(x, std::vector<double>(x.size(), 0.02), {{-6, 0, -6}, {6, 1, 6}}, v);
    CoarseGrainer grainer = cylindricalGrainer("R", KernelShape::Lucy, 1.0, {0, 0, 0}, 1);
    grainer.setFrame(frame, nullptr);
    std::vector<Vec3> points;
    for (double r = 1.0; r <= 3.51; r += 0.25) points.push_back({r, 0, 0});
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    const int fields = grainer.layout().count();
    for (std::size_t p = 0; p < points.size(); ++p) {
        std::vector<double> derived;
        appendDerivedFields(grainer.layout(), &sums[p * fields], derived);
        const double r = points[p][0];
        EXPECT_NEAR(derived[6], omega * r, 1e-7 * omega * r) << "r " << r;
        EXPECT_LT(std::abs(derived[5]), 1e-14 * omega * 5) << "r " << r;
    }
}

namespace {

std::string errorOf(const std::vector<const char*>& args, const std::string& restartText = "") {
    std::vector<const char*> argv{"talus-cg"};
    argv.insert(argv.end(), args.begin(), args.end());
    try {
        const ProgramOptions options = parseOptions(static_cast<int>(argv.size()), argv.data());
        if (!restartText.empty()) {
            std::ofstream("cylinder.restart") << restartText;
        }
        std::ostringstream log;
        RunInputs inputs = resolveRunInputs(options, log);
        CoarseGrainer grainer(inputs.setup);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// A Talus restart file (restart.md) with one drum wall along y through (1, 0, -2), radius 15.
const char* const drumRestart =
    "Talus restart 5\n"
    "domain -20 0 -20 20 4 20 0 1 0\n"
    "species 1\n"
    "   sphere 1.909859317102744 LinearSpringDashpot 1 1 1 1 0 1\n"
    "walls 2\n"
    "   0 0 1 0 0 -15 0 -1 0\n"
    "   0 1 0 1 0 -2 0 0 15\n"
    "shapes 0 0\n"
    "particles 0 0\n";

}  // namespace

TEST(CylindricalFields, BadInputNamesTheFlag) {
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--restart", "none"}),
              "--coordinates RZ: no drum axis: give --axis x|y|z and --axis-point X Y Z (no restart file)");
    EXPECT_EQ(errorOf({"run", "--coordinates", "R", "--axis", "y", "--restart", "none"}),
              "--axis-point: give a point of the drum axis, X Y Z (no restart file)");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "-r", "-1", "5"}), "-r: the radius range must have 0 <= min < max, found -1 5");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "-r", "3", "2"}), "-r: the radius range must have 0 <= min < max, found 3 2");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--axis", "w"}), "--axis: expected the drum axis direction x, y or z, found 'w'");
    EXPECT_EQ(errorOf({"run", "--axis", "y"}), "--axis: only used with cylindrical coordinates (--coordinates RZ or R)");
    EXPECT_EQ(errorOf({"run", "-r", "0", "2"}), "-r: only used with cylindrical coordinates (--coordinates RZ or R)");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--axis", "y", "-x", "0", "1"}),
              "-x: cylindrical coordinates resolve the distance from the axis (-r MIN MAX) and the coordinate along the axis (the range flag of --axis)");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--output-format", "stat"}),
              "--output-format stat: cylindrical coordinates are written as csv or vtk only");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--mixing", "1"}), "--mixing: not available in cylindrical coordinates (--coordinates RZ)");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--axis", "y", "--axis-point", "0", "0", "0", "--restart", "none", "--widths", "1", "2", "3"}),
              "--widths: in cylindrical coordinates the widths across the axis (z and x for --axis y) must be equal, found 3 and 1");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--axis", "z", "--axis-point", "0", "0", "0", "--restart", "none", "--periodic", "x"}),
              "--coordinates RZ: the domain is periodic along x, across the drum axis z: cylindrical coordinates need a bounded cross-section (--periodic)");
    // The axis and drum radius from the restart file's cylinder wall (the plane is skipped); an
    // --axis along another direction finds no wall there.
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--restart", "cylinder.restart"}, drumRestart), "no error");
    EXPECT_EQ(errorOf({"run", "--coordinates", "RZ", "--axis", "x", "--restart", "cylinder.restart"}, drumRestart),
              "--axis-point: give a point of the drum axis, X Y Z (cylinder.restart has no cylinder wall along x)");
}

TEST(CylindricalFields, DrumAxisAndRadiusComeFromTheRestartFile) {
    std::ofstream("drum.restart") << drumRestart;
    const char* argv[] = {"talus-cg", "run", "--coordinates", "RZ", "--restart", "drum.restart"};
    const ProgramOptions options = parseOptions(6, argv);
    std::ostringstream log;
    const RunInputs inputs = resolveRunInputs(options, log);
    EXPECT_EQ(inputs.setup.coordinates.axis(), 1);
    EXPECT_EQ(inputs.setup.coordinates.axisPoint(), (Vec3{1, 0, -2}));
    ASSERT_TRUE(inputs.drumRadius.has_value());
    EXPECT_EQ(*inputs.drumRadius, 15.0);
    EXPECT_TRUE(inputs.setup.periodic[1]);
    EXPECT_NE(log.str().find("drum axis along y through (1, 0, -2) (from drum.restart), drum radius 15"), std::string::npos) << log.str();
}

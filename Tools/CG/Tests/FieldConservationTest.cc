// Theory/CoarseGraining.md eq. (5)-(6): the integral of the density field over a
// domain that contains every kernel is the total mass, and that of the momentum field the total
// momentum, in 3-D, in 2-D and 1-D averaged coordinates, with periodic images, for every kernel.
//
// The integral is computed by nested Gauss-Legendre quadrature whose panels end where the field
// is not smooth: at each level the breakpoints are the particle centres and the ends of their
// (ellipsoidal) supports along that line, x_i +- e_k sqrt(1 - sum over outer axes of
// ((x_l - x_il)/e_l)^2) with e_k = R w_k. Between breakpoints the field is smooth, so the
// quadrature converges to round-off instead of stalling at the kinks (Lucy) or jumps (Gauss
// cut off, Heaviside) of the kernels.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

struct Scene {
    ParticleFrame frame;
    std::vector<double> density{1.0, 2.5};
    double totalMass = 0;
    Vec3 totalMomentum{0, 0, 0};
};

// Six particles of two species, random sizes, positions and velocities inside [2, 4]^3
// (or near the periodic faces in x when `nearFaces`).
Scene randomScene(unsigned seed, bool nearFaces) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> position(2, 4), radius(0.3, 0.5), velocity(-1, 1), face(0.05, 0.4);
    Scene s;
    DomainBox box{{0, 0, 0}, {8, 7.5, 9}};  // holds every support (x_i +- 3 x 0.7 at most)
    std::vector<Vec3> x, v;
    std::vector<double> r;
    std::vector<int> species;
    for (int i = 0; i < 6; ++i) {
        Vec3 p{position(random), position(random), position(random)};
        if (nearFaces) p[0] = i % 2 == 0 ? face(random) : 8 - face(random);
        x.push_back(p);
        v.push_back({velocity(random), velocity(random), velocity(random)});
        r.push_back(radius(random));
        species.push_back(i % 2);
        const double m = s.density[i % 2] * sphereVolume(r.back());
        s.totalMass += m;
        for (int k = 0; k < 3; ++k) s.totalMomentum[k] += m * v.back()[k];
    }
    s.frame = makeFrame(x, r, box, v, species);
    return s;
}

// Integral over the resolved axes (within the box) of density and momentum.
struct Integrals {
    double mass = 0;
    Vec3 momentum{0, 0, 0};
};

Integrals integrate(const CoarseGrainer& grainer, const Scene& scene, const Vec3& extent) {
    const auto axes = grainer.setup().coordinates.kernelAxes();
    const DomainBox& box = scene.frame.box;
    // Centres whose supports may reach into the box: the particles and their periodic images.
    std::vector<Vec3> centres;
    for (const Vec3& x : scene.frame.position) {
        for (int n = -1; n <= 1; ++n) {
            if (n != 0 && !grainer.setup().periodic[0]) continue;
            centres.push_back({x[0] + n * box.length(0), x[1], x[2]});
        }
    }
    const GaussLegendre gl(12);
    const int fields = grainer.layout().count();
    Integrals result;
    std::vector<Vec3> points;
    std::vector<double> weights, sums;
    // Recursion over the resolved axes; the innermost level evaluates a batch of points.
    std::function<void(std::size_t, Vec3, double)> level = [&](std::size_t depth, Vec3 fixed, double weight) {
        const int axis = axes[depth];
        std::vector<double> breaks;
        for (const Vec3& c : centres) {
            double left = 1;
            for (std::size_t outer = 0; outer < depth; ++outer) {
                const int o = axes[outer];
                const double t = (fixed[o] - c[o]) / extent[o];
                left -= t * t;
            }
            if (left <= 0) continue;
            breaks.push_back(c[axis]);
            breaks.push_back(c[axis] - extent[axis] * std::sqrt(left));
            breaks.push_back(c[axis] + extent[axis] * std::sqrt(left));
        }
        std::vector<double> x, w;
        gl.panels(box.lo[axis], box.hi[axis], breaks, x, w);
        if (depth + 1 < axes.size()) {
            for (std::size_t i = 0; i < x.size(); ++i) {
                Vec3 next = fixed;
                next[axis] = x[i];
                level(depth + 1, next, weight * w[i]);
            }
            return;
        }
        points.clear();
        weights.clear();
        for (std::size_t i = 0; i < x.size(); ++i) {
            Vec3 p = fixed;
            p[axis] = x[i];
            points.push_back(p);
            weights.push_back(weight * w[i]);
        }
        grainer.evaluate(points, sums);
        for (std::size_t i = 0; i < points.size(); ++i) {
            result.mass += weights[i] * sums[i * fields + FieldSums::density];
            for (int k = 0; k < 3; ++k) result.momentum[k] += weights[i] * sums[i * fields + FieldSums::momentum + k];
        }
    };
    level(0, Vec3{0, 0, 0}, 1.0);
    return result;
}

struct Case {
    KernelShape shape;
    std::string coordinates;
    bool diagonal;
    bool periodic;
};

class FieldConservation : public testing::TestWithParam<Case> {};

}  // namespace

TEST_P(FieldConservation, DensityAndMomentumIntegrateToTotals) {
    const Case c = GetParam();
    const Scene scene = randomScene(11, c.periodic);
    CoarseGrainingSetup setup;
    setup.shape = c.shape;
    setup.coordinates = Coordinates::fromName(c.coordinates);
    const Vec3 widths = c.diagonal ? Vec3{0.45, 0.7, 0.55} : Vec3{0.6, 0.6, 0.6};
    setup.width = WidthMatrix::diagonal(widths[0], widths[1], widths[2]);
    setup.speciesDensity = scene.density;
    setup.periodic = {c.periodic, false, false};
    CoarseGrainer grainer(setup);
    grainer.setFrame(scene.frame, nullptr);
    const double cutoff = c.shape == KernelShape::Gauss ? 3.0 : 1.0;
    const Vec3 extent{cutoff * widths[0], cutoff * widths[1], cutoff * widths[2]};
    const Integrals integral = integrate(grainer, scene, extent);
    // Averaged directions divide the fields by their box lengths (Coordinates.h).
    const double averaged = setup.coordinates.averagedLength(scene.frame.box);
    const double relativeMass = integral.mass * averaged / scene.totalMass - 1;
    EXPECT_NEAR(relativeMass, 0.0, 1e-8);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(integral.momentum[k] * averaged, scene.totalMomentum[k], 1e-8 * scene.totalMass);
    }
    std::printf("[ mass ] %s %s%s%s: relative mass error %.2e\n", kernelShapeName(c.shape).c_str(), c.coordinates.c_str(),
                c.diagonal ? " diagonal" : "", c.periodic ? " periodic x" : "", relativeMass);
}

INSTANTIATE_TEST_SUITE_P(
    AllKernels, FieldConservation,
    testing::ValuesIn([] {
        std::vector<Case> cases;
        for (KernelShape shape : {KernelShape::Lucy, KernelShape::Gauss, KernelShape::Heaviside}) {
            cases.push_back({shape, "XYZ", false, false});
            cases.push_back({shape, "XYZ", true, false});
            cases.push_back({shape, "XZ", true, false});
            cases.push_back({shape, "Z", false, false});
            cases.push_back({shape, "X", true, true});
            cases.push_back({shape, "XZ", false, true});
        }
        return cases;
    }()),
    [](const testing::TestParamInfo<Case>& info) {
        return kernelShapeName(info.param.shape) + info.param.coordinates + (info.param.diagonal ? "Diagonal" : "Isotropic") +
               (info.param.periodic ? "PeriodicX" : "");
    });

// The contact stress (Theory/CoarseGraining.md eq. (10); Weinhart et al. 2012): each contact force
// spread along the branch between the two centres (centre and contact point for walls) by the line
// integral of the kernel, compressive positive.
//
// 1. The exact line integrals of KernelProfile (polynomial + asinh for Lucy, erf for Gauss)
//    against Gauss-Legendre quadrature along the segment split where the integrand is not smooth.
// 2. A pair pressed together along z with force f, depth profile: where the kernel lies wholly
//    within the branch the stress is f per unit area (the force transmitted through every
//    horizontal plane between the centres), the same whether the file lists the pair once or
//    from both sides; its integral over z is the virial f b / area.
// 3. A particle resting on a wall: the same between its centre and the contact point.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

TEST(ContactStress, ExactLineIntegralsAgreeWithQuadrature) {
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    const GaussLegendre gl(40);
    for (KernelShape shape : {KernelShape::Lucy, KernelShape::Gauss, KernelShape::Heaviside}) {
        for (int d = 1; d <= 3; ++d) {
            const KernelProfile profile(shape, d);
            const double scale = shape == KernelShape::Gauss ? 3.0 : 1.0;
            for (int trial = 0; trial < 400; ++trial) {
                double u0[3] = {0, 0, 0}, e[3] = {0, 0, 0};
                for (int k = 0; k < d; ++k) {
                    u0[k] = scale * coordinate(random);
                    e[k] = scale * coordinate(random);
                }
                if (trial % 4 == 1) {  // a line through the evaluation point (m = 0)
                    for (int k = 0; k < 3; ++k) u0[k] = -0.37 * e[k];
                }
                if (trial % 4 == 2) {  // a very short segment (the quadrature branch of the code)
                    for (double& c : e) c *= 1e-5;
                }
                // Reference: panels split at the closest point and at the support's edges.
                const double a = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
                const double b = u0[0] * e[0] + u0[1] * e[1] + u0[2] * e[2];
                const double c = u0[0] * u0[0] + u0[1] * u0[1] + u0[2] * u0[2];
                const double sStar = -b / a;
                std::vector<double> breaks{sStar};
                const double R2 = profile.cutoffSquared();
                const double m2 = c - b * b / a;
                if (m2 < R2) {
                    breaks.push_back(sStar - std::sqrt((R2 - m2) / a));
                    breaks.push_back(sStar + std::sqrt((R2 - m2) / a));
                }
                std::vector<double> s, w;
                gl.panels(0, 1, breaks, s, w);
                double reference = 0;
                for (std::size_t k = 0; k < s.size(); ++k) reference += w[k] * profile.value(a * s[k] * s[k] + 2 * b * s[k] + c);
                const double exact = profile.lineIntegral(u0, e);
                ASSERT_NEAR(exact, reference, 1e-11 * std::max(1.0, std::abs(reference)))
                    << kernelShapeName(shape) << " " << d << "-D trial " << trial << " u0 " << u0[0] << " e " << e[0];
                // One dimension (depth profiles): the antiderivative along the axis.
                if (d == 1) {
                    ASSERT_NEAR(profile.lineIntegralAlongAxis(u0[0], e[0]), reference, 1e-11 * std::max(1.0, std::abs(reference)))
                        << kernelShapeName(shape) << " along the axis, trial " << trial << " u0 " << u0[0] << " e " << e[0];
                }
            }
        }
    }
}

// A branch across the axis of a one-dimensional kernel (e = 0: a contact with a vertical wall in a
// depth profile, or two particles at the same height): the line integral of a constant, the
// kernel's value at u0, not zero.
TEST(ContactStress, BranchAcrossTheAxisTakesTheKernelsValue) {
    for (KernelShape shape : {KernelShape::Lucy, KernelShape::Gauss, KernelShape::Heaviside}) {
        const KernelProfile profile(shape, 1);
        for (double u0 : {0.0, 0.3, -0.7, 0.99, 1.5, -4.0}) {
            const double expected = profile.value(u0 * u0);
            EXPECT_DOUBLE_EQ(profile.lineIntegralAlongAxis(u0, 0.0), expected) << kernelShapeName(shape) << " u0 " << u0;
            // (and continuous with a branch that leans a little)
            EXPECT_NEAR(profile.lineIntegralAlongAxis(u0, 1e-9), expected, 1e-8) << kernelShapeName(shape) << " u0 " << u0;
        }
    }
}

namespace {

struct Profile {
    std::vector<double> z, stressZZ, stressXZ;
};

Profile depthProfile(KernelShape shape, const ParticleFrame& frame, const ContactFrame& contacts, double width,
                     const std::vector<double>& z) {
    CoarseGrainingSetup setup;
    setup.shape = shape;
    setup.coordinates = Coordinates::fromName("Z");
    setup.width = WidthMatrix::isotropic(width);
    setup.contactStress = true;
    CoarseGrainer grainer(setup);
    grainer.setFrame(frame, &contacts);
    std::vector<Vec3> points;
    for (double h : z) points.push_back({0, 0, h});
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    Profile p;
    p.z = z;
    const int fields = grainer.layout().count(), first = grainer.layout().contactStressIndex();
    for (std::size_t i = 0; i < z.size(); ++i) {
        p.stressZZ.push_back(sums[i * fields + first + 8]);
        p.stressXZ.push_back(sums[i * fields + first + 2]);
    }
    return p;
}

}  // namespace

TEST(ContactStress, PairTransmitsItsForceBetweenTheCentres) {
    // Particle 0 at z = 2, particle 1 at z = 2.9 (radii 0.5, overlap 0.1), box 4 x 2.5 in x, y.
    const DomainBox box{{0, 0, 0}, {4, 2.5, 6}};
    const ParticleFrame frame = makeFrame({{1, 1, 2}, {1, 1, 2.9}}, {0.5, 0.5}, box);
    const double f = 3.0, area = 4 * 2.5;
    // Force on particle 1 from 0 is +f z (repulsive); normal from partner to particle.
    ContactFrame once, twice;
    once.contacts.push_back(contactLine(1, 0, {1, 1, 2.45}, {0, 0, 1}, 0.1, {0.4, 0, f}));
    twice = once;
    twice.contacts.push_back(contactLine(0, 1, {1, 1, 2.45}, {0, 0, -1}, 0.1, {-0.4, 0, -f}));
    const GaussLegendre gl(20);
    for (KernelShape shape : {KernelShape::Lucy, KernelShape::Gauss, KernelShape::Heaviside}) {
        const double width = shape == KernelShape::Gauss ? 0.05 : 0.15;
        const double reach = shape == KernelShape::Gauss ? 3 * width : width;
        const Profile middle = depthProfile(shape, frame, once, width, {2.45});
        EXPECT_NEAR(middle.stressZZ[0], f / area, 1e-13) << kernelShapeName(shape);
        EXPECT_NEAR(middle.stressXZ[0], 0.4 / area, 1e-13) << kernelShapeName(shape);
        EXPECT_NEAR(depthProfile(shape, frame, twice, width, {2.45}).stressZZ[0], middle.stressZZ[0], 1e-14);
        // Virial: int sigma_zz dz = f b_z / area, b_z = 0.9 (quadrature split at the kinks).
        std::vector<double> z, w;
        gl.panels(1.5, 3.5, {2 - reach, 2, 2 + reach, 2.9 - reach, 2.9, 2.9 + reach}, z, w);
        const Profile profile = depthProfile(shape, frame, twice, width, z);
        double integral = 0;
        for (std::size_t k = 0; k < z.size(); ++k) integral += w[k] * profile.stressZZ[k];
        EXPECT_NEAR(integral, f * 0.9 / area, 1e-11) << kernelShapeName(shape);
        // Outside the branch and its kernels: no stress.
        EXPECT_EQ(depthProfile(shape, frame, once, width, {2 - 1.01 * reach}).stressZZ[0], 0.0);
    }
}

TEST(ContactStress, WallContactTransmitsItsForceBetweenCentreAndContactPoint) {
    // A particle at z = 0.45 on the wall z = 0 (overlap 0.05); the .fstat wall line has the
    // normal into the wall and the force on the particle is -(fn n) = +fn z.
    const DomainBox box{{0, 0, -1}, {2, 2, 3}};
    const ParticleFrame frame = makeFrame({{1, 1, 0.45}}, {0.5}, box);
    ContactFrame contacts;
    const double fn = 2.0, area = 4;
    contacts.contacts.push_back(contactLine(0, -1, {1, 1, -0.025}, {0, 0, -1}, 0.05, {0, 0, fn}));
    const Profile p = depthProfile(KernelShape::Lucy, frame, contacts, 0.1, {0.2, 0.7});
    EXPECT_NEAR(p.stressZZ[0], fn / area, 1e-13);
    EXPECT_EQ(p.stressZZ[1], 0.0);
}

TEST(ContactStress, MismatchedFilesAreRejected) {
    const DomainBox box{{0, 0, 0}, {4, 2.5, 6}};
    const ParticleFrame frame = makeFrame({{1, 1, 2}, {1, 1, 2.9}}, {0.5, 0.5}, box);
    ContactFrame contacts;
    contacts.contacts.push_back(contactLine(1, 0, {1, 1, 2.2}, {0, 0, 1}, 0.1, {0, 0, 1}));
    contacts.contacts.back().line = 12;
    CoarseGrainingSetup setup;
    setup.contactStress = true;
    CoarseGrainer grainer(setup);
    try {
        grainer.setFrame(frame, &contacts, "a.data", "a.fstat");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("a.fstat line 12: the contact point is"), std::string::npos) << error.what();
    }
    contacts.contacts.back() = contactLine(1, 7, {1, 1, 2.45}, {0, 0, 1}, 0.1, {0, 0, 1});
    contacts.contacts.back().line = 13;
    EXPECT_THROW(grainer.setFrame(frame, &contacts, "a.data", "a.fstat"), InputError);
}

// Along one axis a grid's points whose clipped piece of the branch is shorter than 1e-3 widths
// (where the antiderivative's difference loses digits) take the line integral's own answer; they
// are found at both ends of a contact's run of points, not by a pass over all of them. Points a
// hair inside both ends of the stressed range must get the same bits on a grid as alone, and the
// value the line integral gives.
TEST(ContactStress, ShortPiecesAtBothEndsOfAGridTakeTheLineIntegral) {
    const DomainBox box{{0, 0, 0}, {4, 2.5, 6}};
    const ParticleFrame frame = makeFrame({{1, 1, 2}, {1, 1, 2.9}}, {0.5, 0.5}, box);
    const double f = 3.0, area = 4 * 2.5, width = 0.15;
    ContactFrame contacts;
    contacts.contacts.push_back(contactLine(1, 0, {1, 1, 2.45}, {0, 0, 1}, 0.1, {0, 0, f}));
    const KernelProfile lucy(KernelShape::Lucy, 1);
    for (double inside : {1e-4, 5e-5}) {  // (1e-4 of a length is 6.7e-4 widths)
        const double first = 2 - width + inside, last = 2.9 + width - inside;
        std::vector<double> z;
        for (int k = 0; k <= 12; ++k) z.push_back(first + (last - first) * k / 12.0);
        z.back() = last;
        const Profile grid = depthProfile(KernelShape::Lucy, frame, contacts, width, z);
        for (std::size_t k = 0; k < z.size(); ++k) {
            const Profile alone = depthProfile(KernelShape::Lucy, frame, contacts, width, {z[k]});
            EXPECT_EQ(grid.stressZZ[k], alone.stressZZ[0]) << "z = " << z[k];
            // sigma_zz = (f b_z / area) times the kernel's mean along the branch, in widths
            // (1/w per unit length; the mean over s in [0, 1] of u0 + s e, from the centre at 2.9).
            const double expected =
                f * 0.9 / area / width * lucy.lineIntegralAlongAxis((z[k] - 2.9) / width, 0.9 / width);
            EXPECT_NEAR(grid.stressZZ[k], expected, 1e-12 * f / area) << "z = " << z[k];
        }
        EXPECT_GT(grid.stressZZ.front(), 0.0);
        EXPECT_GT(grid.stressZZ.back(), 0.0);
    }
}

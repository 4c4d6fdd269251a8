// The domain average, coordinates O (MercuryCG's `O`; Fields/CoarseGrainer.h "The domain
// average"): one value per frame, each field the sum over the frame divided by the box volume.
//
// 1. Hand sums: five particles, two pair contacts (one written once, one from both sides) and a
//    wall contact in a 4 x 3 x 5 box: density, volume fraction, momentum, momentum flux, species
//    densities, contact stress sum f (x) b / V and the wall's force / V, written out by hand.
// 2. Consistency with a kernel field: the mean over z of a fine Z profile (Lucy, width w) is
//    (1/V) sum_i m_i F_i, F_i = G((hi - z_i)/w) - G((lo - z_i)/w) the part of particle i's kernel
//    inside the box (G the distribution function of the 1-D Lucy kernel, written out here), so it
//    equals O's value less the mass of the kernels that reach out of the box; for contacts whose
//    branches lie a width inside the box the two are equal.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "App/Options.h"
#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

std::vector<double> domainAverage(const ParticleFrame& frame, const ContactFrame& contacts, std::vector<double> densities,
                                  FieldSums& layout) {
    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName("O");
    setup.speciesDensity = std::move(densities);
    setup.contactStress = true;
    CoarseGrainer grainer(setup);
    grainer.setFrame(frame, &contacts);
    std::vector<double> sums;
    grainer.evaluate({Vec3{0, 0, 0}}, sums);
    layout = grainer.layout();
    return sums;
}

// The distribution function of the 1-D Lucy kernel of unit width, (5/4)(1 - 6u^2 + 8|u|^3 - 3u^4)
// on |u| < 1: G(t) = 1/2 + (5/4)(t - 2t^3 + 2t^4 - (3/5)t^5) for 0 <= t <= 1, G(-t) = 1 - G(t).
double lucyDistribution(double t) {
    if (t <= -1) return 0;
    if (t >= 1) return 1;
    const double a = std::abs(t);
    const double g = 0.5 + 1.25 * (a - 2 * a * a * a + 2 * a * a * a * a - 0.6 * a * a * a * a * a);
    return t >= 0 ? g : 1 - g;
}

}  // namespace

TEST(DomainAverage, FieldsAreTheHandSumsOverTheBoxVolume) {
    const DomainBox box{{0, 0, 0}, {4, 3, 5}};
    const double volume = 60;
    // Particles 0 and 1 touch along z (overlap 0.1), 2 and 3 along x (overlap 0.05), 4 rests on
    // the wall z = 0 (overlap 0.05).
    const ParticleFrame frame = makeFrame({{1, 1, 1}, {1, 1, 1.9}, {3, 2, 4}, {3.65, 2, 4}, {2, 1.5, 0.45}},
                                          {0.5, 0.5, 0.4, 0.3, 0.5}, box,
                                          {{1, 0, 0.5}, {0, 2, 0}, {-1, 1, 3}, {0.5, 0, 0}, {0, 0, -0.2}}, {0, 0, 1, 1, 0});
    ContactFrame contacts;
    // Pair 1-0, once: force on 1 (0.4, 0, 3), branch x_1 - x_0 = (0, 0, 0.9).
    contacts.contacts.push_back(contactLine(1, 0, {1, 1, 1.45}, {0, 0, 1}, 0.1, {0.4, 0, 3}));
    // Pair 2-3 from both sides: force on 2 (-5, 0.5, 0) along the branch x_2 - x_3 = (-0.65, 0, 0).
    contacts.contacts.push_back(contactLine(2, 3, {3.375, 2, 4}, {-1, 0, 0}, 0.05, {-5, 0.5, 0}));
    contacts.contacts.push_back(contactLine(3, 2, {3.375, 2, 4}, {1, 0, 0}, 0.05, {5, -0.5, 0}));
    // Wall contact of 4 at c = (2, 1.5, -0.025): force (0.2, 0, 2) on 4, branch x_4 - c = (0, 0, 0.475).
    contacts.contacts.push_back(contactLine(4, -1, {2, 1.5, -0.025}, {0, 0, -1}, 0.05, {0.2, 0, 2}));
    FieldSums layout;
    const std::vector<double> sums = domainAverage(frame, contacts, {2, 3}, layout);

    // Masses rho_s (4/3) pi r^3 with densities 2 (species 0) and 3 (species 1).
    const double v5 = sphereVolume(0.5), v4 = sphereVolume(0.4), v3 = sphereVolume(0.3);
    const double m5 = 2 * v5, m4 = 3 * v4, m3 = 3 * v3;
    const double tolerance = 1e-15;
    EXPECT_NEAR(sums[FieldSums::density], (3 * m5 + m4 + m3) / volume, tolerance);
    EXPECT_NEAR(sums[FieldSums::volumeFraction], (3 * v5 + v4 + v3) / volume, tolerance);
    EXPECT_NEAR(sums[FieldSums::momentum + 0], (m5 * 1 - m4 + m3 * 0.5) / volume, tolerance);
    EXPECT_NEAR(sums[FieldSums::momentum + 1], (m5 * 2 + m4) / volume, tolerance);
    EXPECT_NEAR(sums[FieldSums::momentum + 2], (m5 * 0.5 + m4 * 3 - m5 * 0.2) / volume, tolerance);
    EXPECT_NEAR(sums[FieldSums::momentumFlux + 0], (m5 + m4 + m3 * 0.25) / volume, tolerance);       // xx
    EXPECT_NEAR(sums[FieldSums::momentumFlux + 1], (-m4) / volume, tolerance);                       // xy
    EXPECT_NEAR(sums[FieldSums::momentumFlux + 2], (m5 * 0.5 - 3 * m4) / volume, tolerance);         // xz
    EXPECT_NEAR(sums[FieldSums::momentumFlux + 3], (4 * m5 + m4) / volume, tolerance);               // yy
    EXPECT_NEAR(sums[FieldSums::momentumFlux + 4], (3 * m4) / volume, tolerance);                    // yz
    EXPECT_NEAR(sums[FieldSums::momentumFlux + 5], (0.25 * m5 + 9 * m4 + 0.04 * m5) / volume, tolerance);  // zz
    EXPECT_NEAR(sums[layout.speciesDensityIndex(0)], 3 * m5 / volume, tolerance);
    EXPECT_NEAR(sums[layout.speciesDensityIndex(1)], (m4 + m3) / volume, tolerance);
    // Contact stress sum f (x) b / V, row-major: xx 5 x 0.65, yx -0.5 x 0.65, xz 0.4 x 0.9 +
    // 0.2 x 0.475, zz 3 x 0.9 + 2 x 0.475; the pair written twice counts once.
    const double stress[9] = {3.25, 0, 0.36 + 0.095, -0.325, 0, 0, 0, 0, 2.7 + 0.95};
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(sums[layout.contactStressIndex() + k], stress[k] / volume, 1e-15) << k;
    // The wall's force on the flow per volume.
    const double force[3] = {0.2, 0, 2};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sums[layout.interactionForceIndex() + k], force[k] / volume, 1e-16) << k;
}

TEST(DomainAverage, MeanOfADepthProfileIsTheAverageLessTheKernelsOutsideTheBox) {
    const DomainBox box{{0, 0, 0}, {4, 3, 5}};
    const double volume = 60, lz = 5, w = 0.8;
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> ux(0, 4), uy(0, 3), uz(0, 5), middle(2, 3), uv(-1, 1);
    std::vector<Vec3> x, v;
    std::vector<double> r;
    ContactFrame contacts;
    // 40 touching pairs with their centres in 1 <= z <= 4, a width inside the box: b_z <= 1.
    for (int k = 0; k < 40; ++k) {
        Vec3 n{uv(random), uv(random), uv(random)};
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& c : n) c /= length;
        const double ra = 0.5, rb = 0.4, overlap = 0.02, d = ra + rb - overlap;
        const Vec3 a{ux(random), uy(random), middle(random)};
        const Vec3 b{a[0] - d * n[0], a[1] - d * n[1], a[2] - d * n[2]};
        const long i = static_cast<long>(x.size());
        x.insert(x.end(), {a, b});
        r.insert(r.end(), {ra, rb});
        const double fn = 1 + uv(random) * 0.5, ft = 0.3 * uv(random);
        // A tangential part along (n x e_z) normalised (any direction perpendicular to n).
        Vec3 t{n[1], -n[0], 0};
        const double tl = std::hypot(t[0], t[1]);
        for (double& c : t) c /= tl;
        const Vec3 point{a[0] - (ra - overlap / 2) * n[0], a[1] - (ra - overlap / 2) * n[1], a[2] - (ra - overlap / 2) * n[2]};
        contacts.contacts.push_back(contactLine(i, i + 1, point, n, overlap, {fn * n[0] + ft * t[0], fn * n[1] + ft * t[1], fn * n[2] + ft * t[2]}));
    }
    // 200 particles anywhere in the box, many within w of its faces z = 0 and z = 5.
    for (int k = 0; k < 200; ++k) {
        x.push_back({ux(random), uy(random), uz(random)});
        r.push_back(0.3);
    }
    for (std::size_t k = 0; k < x.size(); ++k) v.push_back({uv(random), uv(random), uv(random)});
    const ParticleFrame frame = makeFrame(x, r, box, v);
    FieldSums layout;
    const std::vector<double> average = domainAverage(frame, contacts, {1.5}, layout);

    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName("Z");
    setup.width = WidthMatrix::isotropic(w);
    setup.speciesDensity = {1.5};
    setup.contactStress = true;
    CoarseGrainer grainer(setup);
    grainer.setFrame(frame, &contacts);
    const int n = 2000;
    const double h = lz / n;
    std::vector<Vec3> points;
    for (int k = 0; k < n; ++k) points.push_back({0, 0, (k + 0.5) * h});
    std::vector<double> profile;
    grainer.evaluate(points, profile);
    const int fields = layout.count();
    auto mean = [&](int field) {
        double sum = 0;
        for (int k = 0; k < n; ++k) sum += profile[k * fields + field];
        return sum / n;
    };
    // The midpoint rule's error on [0, lz] for a C2 function f is at most lz h^2/24 max|f''|; one
    // particle's kernel, (5/4w) g((z - z_i)/w) with |g''| <= 12, is nonzero on 2w, so its error
    // relative to its mass is at most 2w h^2/24 (15/w^3) = 1.25 (h/w)^2. A contact's profile is
    // the kernel averaged along its branch: the same bound on |f''|, on a support 2w + |b_z|
    // <= 2w + 1.
    const double particleBound = 1.25 * (h / w) * (h / w), contactBound = (2 * w + 1) * h * h / 24 * 15 / (w * w * w);
    double expectedDensity = 0, expectedMomentum[3] = {0, 0, 0}, massScale = 0, momentumScale[3] = {0, 0, 0};
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double m = 1.5 * sphereVolume(r[i]);
        const double inside = lucyDistribution((lz - x[i][2]) / w) - lucyDistribution((0 - x[i][2]) / w);
        expectedDensity += m * inside / volume;
        massScale += m / volume;
        for (int c = 0; c < 3; ++c) {
            expectedMomentum[c] += m * v[i][c] * inside / volume;
            momentumScale[c] += std::abs(m * v[i][c]) / volume;
        }
    }
    EXPECT_NEAR(mean(FieldSums::density), expectedDensity, particleBound * massScale);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean(FieldSums::momentum + c), expectedMomentum[c], particleBound * momentumScale[c]) << c;
    // The loss is real: far above the tolerance (particles within w of the faces).
    EXPECT_GT(average[FieldSums::density] - mean(FieldSums::density), 1000 * particleBound * massScale);
    // Branches a width inside the box: the mean of the contact stress is O's.
    for (int k = 0; k < 9; ++k) {
        double scale = 0;
        for (const ContactLine& c : contacts.contacts) scale += std::abs(c.force[k / 3]) * 0.9 / volume;
        EXPECT_NEAR(mean(layout.contactStressIndex() + k), average[layout.contactStressIndex() + k], contactBound * scale) << k;
    }
}

TEST(DomainAverage, PointOptionsAreRefused) {
    auto errorOfOptions = [](std::vector<const char*> args) {
        args.insert(args.begin(), "talus-cg");
        return errorOf([&] { parseOptions(static_cast<int>(args.size()), args.data()); });
    };
    EXPECT_EQ(errorOfOptions({"run", "--coordinates", "O", "-n", "4"}),
              "-n: --coordinates O gives one value per frame for the whole domain box: there are no points to choose");
    EXPECT_EQ(errorOfOptions({"run", "--coordinates", "O", "--points", "p.txt"}),
              "--points: --coordinates O gives one value per frame for the whole domain box: there are no points to choose");
    EXPECT_EQ(errorOfOptions({"run", "--coordinates", "Q"}), "--coordinates: 'Q' is not one of XYZ, XY, XZ, YZ, X, Y, Z, RZ, R, O");
}

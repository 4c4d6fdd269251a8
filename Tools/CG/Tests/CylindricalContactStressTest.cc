// The contact stress in cylindrical coordinates (Fields/CylindricalCoarseGrainer.h): the Cartesian
// contact stress of Theory/CoarseGraining.md eq. (10) averaged over the angle about the axis in the
// local basis (e_r, e_theta, e_s), and the boundary's force density likewise.
//
// The reference is independent of the cylindrical code: the Cartesian fields (exact line
// integrals, CoarseGrainer in XYZ or XY) at 4096 points evenly on the circle of radius r at s,
// each tensor projected on the local basis of its point, e_a . sigma e_b, and averaged (the
// trapezoid rule in the angle, whose error for the C^2 Lucy kernel is far below the tolerance).
// The configuration: 30 touching pairs with random normals and frictional forces at distances 0
// to 3 from the axis (some straddling it), 3 of them written from both sides, and 4 particles
// touching walls (boundary contacts: InteractionForce).
// A second test checks statics: a ring of spheres pressed together and held by the drum wall
// satisfies the radial balance of the cylindrical components, hoop term included.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

struct Contacts {
    ParticleFrame frame;
    ContactFrame contacts;
};

Vec3 randomUnit(std::mt19937_64& random) {
    std::normal_distribution<double> g;
    Vec3 n{g(random), g(random), g(random)};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& c : n) c /= length;
    return n;
}

// A force on i with normal part fn along n and a tangential part of size ft perpendicular to it.
Vec3 frictionalForce(const Vec3& n, double fn, double ft, std::mt19937_64& random) {
    const Vec3 a = randomUnit(random);
    const double along = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    Vec3 t{a[0] - along * n[0], a[1] - along * n[1], a[2] - along * n[2]};
    const double length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    return {fn * n[0] + ft * t[0] / length, fn * n[1] + ft * t[1] / length, fn * n[2] + ft * t[2] / length};
}

Contacts randomContacts(const Vec3& centre) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> radius(0, 3), angle(0, 2 * std::numbers::pi), height(-1, 1), unit(0, 1);
    Contacts c;
    std::vector<Vec3> x;
    std::vector<double> r;
    for (int k = 0; k < 34; ++k) {
        const double ra = 0.5, rb = 0.35, overlap = 0.03;
        const double rho = radius(random), theta = angle(random);
        const Vec3 a{centre[0] + rho * std::cos(theta), centre[1] + rho * std::sin(theta), height(random)};
        const Vec3 n = randomUnit(random);  // from the partner (or into... the wall) to i
        const long i = static_cast<long>(x.size());
        const Vec3 point{a[0] - (ra - overlap / 2) * n[0], a[1] - (ra - overlap / 2) * n[1], a[2] - (ra - overlap / 2) * n[2]};
        const Vec3 f = frictionalForce(n, 1 + unit(random), 0.4 * unit(random), random);
        x.push_back(a);
        r.push_back(ra);
        if (k >= 30) {
            // A wall: the .fstat normal points into the wall (-n) and the force on i is f.
            c.contacts.contacts.push_back(contactLine(i, -1, point, {-n[0], -n[1], -n[2]}, overlap, f));
            continue;
        }
        const double d = ra + rb - overlap;
        x.push_back({a[0] - d * n[0], a[1] - d * n[1], a[2] - d * n[2]});
        r.push_back(rb);
        c.contacts.contacts.push_back(contactLine(i, i + 1, point, n, overlap, f));
        if (k % 10 == 0) c.contacts.contacts.push_back(contactLine(i + 1, i, point, {-n[0], -n[1], -n[2]}, overlap, {-f[0], -f[1], -f[2]}));
    }
    c.frame = makeFrame(x, r, DomainBox{{-6, -6, -4}, {6, 6, 4}});
    return c;
}

CoarseGrainer grainer(const char* coordinates, double width, const Vec3& centre) {
    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName(coordinates);
    if (setup.coordinates.isCylindrical()) setup.coordinates.setAxis(2, centre);
    setup.width = WidthMatrix::isotropic(width);
    setup.contactStress = true;
    return CoarseGrainer(setup);
}

}  // namespace

TEST(CylindricalContactStress, EqualsTheAngularMeanOfTheCartesianStressInTheLocalBasis) {
    const Vec3 centre{0.3, -0.2, 0};
    const Contacts c = randomContacts(centre);
    const double width = 1.1;
    const int angles = 4096;
    for (const char* name : {"RZ", "R"}) {
        const bool rz = std::string(name) == "RZ";
        CoarseGrainer cylindrical = grainer(name, width, centre);
        CoarseGrainer cartesian = grainer(rz ? "XYZ" : "XY", width, centre);
        cylindrical.setFrame(c.frame, &c.contacts);
        cartesian.setFrame(c.frame, &c.contacts);
        std::vector<Vec3> points;
        for (double r : {0.0, 0.2, 0.7, 1.3, 2.0, 2.9, 3.6}) {
            for (double s : {-0.8, 0.1, 0.9}) points.push_back({r, 0, rz ? s : 0.0});
        }
        std::vector<double> sums, reference;
        cylindrical.evaluate(points, sums);
        const FieldSums layout = cylindrical.layout(), labLayout = cartesian.layout();
        double largest = 0, largestForce = 0, worst = 0, worstForce = 0;
        std::vector<std::array<double, 12>> expected(points.size());
        for (std::size_t p = 0; p < points.size(); ++p) {
            std::vector<Vec3> circle;
            for (int j = 0; j < angles; ++j) {
                const double theta = 2 * std::numbers::pi * j / angles;
                circle.push_back({centre[0] + points[p][0] * std::cos(theta), centre[1] + points[p][0] * std::sin(theta), points[p][2]});
            }
            cartesian.evaluate(circle, reference);
            expected[p].fill(0);
            for (int j = 0; j < angles; ++j) {
                const double theta = 2 * std::numbers::pi * j / angles;
                const double e[3][3] = {{std::cos(theta), std::sin(theta), 0}, {-std::sin(theta), std::cos(theta), 0}, {0, 0, 1}};
                const double* sigma = &reference[j * labLayout.count() + labLayout.contactStressIndex()];
                const double* force = &reference[j * labLayout.count() + labLayout.interactionForceIndex()];
                for (int a = 0; a < 3; ++a) {
                    for (int b = 0; b < 3; ++b) {
                        double value = 0;
                        for (int k = 0; k < 3; ++k) {
                            for (int l = 0; l < 3; ++l) value += e[a][k] * sigma[3 * k + l] * e[b][l];
                        }
                        expected[p][3 * a + b] += value / angles;
                    }
                    expected[p][9 + a] += (e[a][0] * force[0] + e[a][1] * force[1] + e[a][2] * force[2]) / angles;
                }
            }
            for (int k = 0; k < 9; ++k) largest = std::max(largest, std::abs(expected[p][k]));
            for (int k = 9; k < 12; ++k) largestForce = std::max(largestForce, std::abs(expected[p][k]));
        }
        for (std::size_t p = 0; p < points.size(); ++p) {
            const double* stress = &sums[p * layout.count() + layout.contactStressIndex()];
            const double* force = &sums[p * layout.count() + layout.interactionForceIndex()];
            for (int k = 0; k < 9; ++k) {
                worst = std::max(worst, std::abs(stress[k] - expected[p][k]) / largest);
                EXPECT_NEAR(stress[k], expected[p][k], 2e-6 * largest) << name << " r " << points[p][0] << " s " << points[p][2] << " component " << k;
            }
            for (int k = 0; k < 3; ++k) {
                worstForce = std::max(worstForce, std::abs(force[k] - expected[p][9 + k]) / largestForce);
                EXPECT_NEAR(force[k], expected[p][9 + k], 1e-9 * largestForce) << name << " r " << points[p][0] << " component " << k;
            }
        }
        EXPECT_GT(largest, 0);
        EXPECT_GT(largestForce, 0);
        std::printf("%s: contact stress within %.2g, boundary force within %.2g of the largest value\n", name, worst, worstForce);
    }
}

TEST(CylindricalContactStress, StaticRingSatisfiesTheRadialBalanceInCylindricalComponents) {
    // Statics: 12 equal spheres on a ring of radius R0 about the z axis, each pressed by its two
    // neighbours with force F along the chord (outwards in sum, 2 F sin(pi/12) along e_r) and
    // held by the drum wall outside with 2 F sin(pi/12) inwards. Every particle is at rest with no
    // net force, so the coarse-grained momentum balance reads div(sigma_c) = InteractionForce at
    // every point (CoarseGrainer.h "Boundaries"), and for the angular means, in cylindrical
    // components (divergence over the second index, the theta derivatives of means vanishing):
    //   r:  d(sigma_rr)/dr + d(sigma_rs)/ds + (sigma_rr - sigma_tt)/r = f_r
    //   s:  d(sigma_sr)/dr + d(sigma_ss)/ds + sigma_sr/r              = f_s
    // The hoop term (sigma_rr - sigma_tt)/r is what carries the ring's load: without it the
    // balance fails by the whole wall force.
    const int n = 12;
    const double r0 = 3, f = 2.0, pi = std::numbers::pi, chord = 2 * r0 * std::sin(pi / n);
    const double radius = 0.5 * chord + 0.02, overlap = 2 * radius - chord;
    const Vec3 centre{0, 0, 0};
    std::vector<Vec3> x;
    for (int k = 0; k < n; ++k) x.push_back({r0 * std::cos(2 * pi * k / n), r0 * std::sin(2 * pi * k / n), 0});
    Contacts c;
    c.frame = makeFrame(x, std::vector<double>(n, radius), DomainBox{{-6, -6, -3}, {6, 6, 3}});
    for (int k = 0; k < n; ++k) {
        for (int side : {-1, 1}) {
            const int j = (k + side + n) % n;
            const Vec3 d{x[k][0] - x[j][0], x[k][1] - x[j][1], x[k][2] - x[j][2]};
            const Vec3 normal{d[0] / chord, d[1] / chord, d[2] / chord};
            const Vec3 point{x[k][0] - (radius - overlap / 2) * normal[0], x[k][1] - (radius - overlap / 2) * normal[1], 0};
            c.contacts.contacts.push_back(contactLine(k, j, point, normal, overlap, {f * normal[0], f * normal[1], 0}));
        }
        // The wall outside: normal into the wall (+e_r), force on the particle -2 F sin(pi/n) e_r.
        const Vec3 er{x[k][0] / r0, x[k][1] / r0, 0};
        const double wallOverlap = 0.01, hold = 2 * f * std::sin(pi / n);
        const Vec3 point{x[k][0] + (radius - wallOverlap / 2) * er[0], x[k][1] + (radius - wallOverlap / 2) * er[1], 0};
        c.contacts.contacts.push_back(contactLine(k, -1, point, er, wallOverlap, {-hold * er[0], -hold * er[1], 0}));
    }
    CoarseGrainer cylindrical = grainer("RZ", 1.0, centre);
    cylindrical.setFrame(c.frame, &c.contacts);
    const FieldSums layout = cylindrical.layout();
    const double h = 1e-3;
    double worst = 0, hoopScale = 0, forceScale = 0;
    for (double r : {2.2, 2.6, 3.0, 3.3, 3.7}) {
        for (double s : {-0.4, 0.0, 0.3}) {
            std::vector<Vec3> points{{r, 0, s}, {r - h, 0, s}, {r + h, 0, s}, {r, 0, s - h}, {r, 0, s + h}};
            std::vector<double> sums;
            cylindrical.evaluate(points, sums);
            auto stress = [&](int p, int k) { return sums[p * layout.count() + layout.contactStressIndex() + k]; };
            auto force = [&](int k) { return sums[layout.interactionForceIndex() + k]; };
            const double radial = (stress(2, 0) - stress(1, 0)) / (2 * h) + (stress(4, 2) - stress(3, 2)) / (2 * h) +
                                  (stress(0, 0) - stress(0, 4)) / r - force(0);
            const double axial = (stress(2, 6) - stress(1, 6)) / (2 * h) + (stress(4, 8) - stress(3, 8)) / (2 * h) + stress(0, 6) / r - force(2);
            hoopScale = std::max(hoopScale, std::abs(stress(0, 0) - stress(0, 4)) / r);
            forceScale = std::max(forceScale, std::abs(force(0)));
            worst = std::max({worst, std::abs(radial), std::abs(axial)});
        }
    }
    // Central differences with h = 1e-3 of fields that vary on the width 1: h^2 errors ~1e-6 of
    // the scale; the branch quadrature's error (5e-7 of the largest value, smooth in r, s) enters
    // its derivatives at the same order. 1e-4 of the wall force density is far above both and far
    // below the hoop term that the balance needs.
    EXPECT_GT(hoopScale, 0.1 * forceScale);
    EXPECT_LT(worst, 1e-4 * forceScale) << "hoop scale " << hoopScale << ", wall force density " << forceScale;
    std::printf("static ring: largest residual %.2g of the wall force density %.3g (hoop term up to %.3g)\n", worst / forceScale,
                forceScale, hoopScale);
}

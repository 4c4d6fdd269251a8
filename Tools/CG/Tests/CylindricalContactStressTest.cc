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

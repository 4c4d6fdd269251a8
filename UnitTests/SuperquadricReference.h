// An independent reference for superquadric contact detection (Contacts/SuperquadricContact.h):
// the same contact point reached by a different algorithm, for tests and the accuracy sweep.
//
// The contact point minimises max(Fi, Fj) (both convex; at the minimum Fi = Fj and
// grad Fi = -mu^2 grad Fj, the conditions Talus solves by Newton's method on four unknowns).
// Here the dual route: for a weight w in [0, 1], X(w) minimises w Fi + (1 - w) Fj (a smooth
// convex function: Newton's method with a backtracking line search, globally convergent), and
// Fi(X(w)) - Fj(X(w)) decreases with w, so w is found by bisection. The overlap is found by
// bisection along the normal. Slow (hundreds of evaluations per contact) and robust.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <Eigen/Cholesky>

#include "Contacts/SuperquadricContact.h"

namespace talus::reference {

struct Contact {
    Vec3 point;
    double value;    // Fi = Fj at the point: negative when the bodies overlap
    Vec3 normal;     // from j to i
    double overlap;  // di + dj (0 when apart)
};

inline Vec3 minimiseWeightedSum(const PlacedSuperquadric& i, const PlacedSuperquadric& j, double w, Vec3 x,
                                double scale) {
    auto h = [&](const Vec3& y) { return w * i.valueAt(y) + (1 - w) * j.valueAt(y); };
    for (int k = 0; k < 200; ++k) {
        const ShapeValue a = i.at(x), b = j.at(x);
        const Vec3 g = w * a.gradient + (1 - w) * b.gradient;
        Mat3 H = w * a.hessian + (1 - w) * b.hessian;
        // Flat interiors of blocky shapes have nearly singular Hessians: a little Levenberg.
        H += 1e-12 * (1 + H.norm()) * Mat3::Identity();
        Vec3 step = -H.ldlt().solve(g);
        if (!step.allFinite() || step.dot(g) >= 0) step = -g * scale * scale;
        const double h0 = h(x);
        double t = 1;
        while (h(x + t * step) > h0 + 1e-4 * t * step.dot(g) && t > 1e-14) t *= 0.5;
        x += t * step;
        if (t * step.norm() < 1e-15 * scale) break;
    }
    return x;
}

// Distance from x (inside the body) along u to the surface, by bisection.
inline double surfaceDistance(const PlacedSuperquadric& body, const Vec3& x, const Vec3& u) {
    double inside = 0, outside = 2 * body.shape->boundingRadius() + (x - body.centre).norm();
    for (int k = 0; k < 200 && outside - inside > 1e-16 * outside; ++k) {
        const double middle = 0.5 * (inside + outside);
        (body.valueAt(x + middle * u) < 0 ? inside : outside) = middle;
    }
    return 0.5 * (inside + outside);
}

inline Contact contact(const PlacedSuperquadric& i, const PlacedSuperquadric& j, int bisections = 60) {
    const double scale = std::min(i.shape->semiAxes().minCoeff(), j.shape->semiAxes().minCoeff());
    double low = 0, high = 1;  // at w = 0, X = centre of j: Fi > Fj; at w = 1 the reverse
    Vec3 x = 0.5 * (i.centre + j.centre);
    for (int k = 0; k < bisections; ++k) {
        const double w = 0.5 * (low + high);
        x = minimiseWeightedSum(i, j, w, x, scale);
        (i.valueAt(x) > j.valueAt(x) ? low : high) = w;
    }
    Contact c;
    c.point = x;
    c.value = 0.5 * (i.valueAt(x) + j.valueAt(x));
    const Vec3 outOfI = i.at(x).gradient.normalized();
    c.normal = -outOfI;
    c.overlap = c.value < 0 ? surfaceDistance(i, x, outOfI) + surfaceDistance(j, x, -outOfI) : 0;
    return c;
}

// Random test configurations of two superquadrics by class, overlapping by up to a tenth of the
// smaller semi-axis (or, for a share of them, apart by up to 5% of it while their bounding
// spheres overlap). The touching distance along the chosen direction is found with the
// reference solver, by bisection.
enum class Case { spheres, ellipsoids, blocky, parallelFaces, edgeOnFace, needles, sphereOnEllipsoid };
inline const char* name(Case c) {
    const char* names[] = {"spheres", "ellipsoids (aspect 1-10)", "blocky (e 0.1-1)", "near-parallel flat faces",
                           "edge on face", "needle crossings (aspect 10)", "a sphere on an ellipsoid (aspect 1-10)"};
    return names[static_cast<int>(c)];
}

struct Configuration {
    Superquadric shapeI, shapeJ;
    PlacedSuperquadric i, j;
    double targetOverlap;  // negative: a gap
    // The placed shapes point into this object: copy with care (see rebind).
    Configuration(const Superquadric& a, const Superquadric& b) : shapeI(a), shapeJ(b), i{}, j{}, targetOverlap(0) {}
    Configuration(const Configuration& o) : shapeI(o.shapeI), shapeJ(o.shapeJ), i(o.i), j(o.j), targetOverlap(o.targetOverlap) {
        rebind();
    }
    void rebind() { i.shape = &shapeI, j.shape = &shapeJ; }
};

inline Mat3 randomRotation(std::mt19937_64& random) {
    std::normal_distribution<double> gauss;
    return Quat(gauss(random), gauss(random), gauss(random), gauss(random)).normalized().toRotationMatrix();
}

inline Configuration randomConfiguration(Case kind, std::mt19937_64& random) {
    std::uniform_real_distribution<double> uniform(0, 1);
    auto between = [&](double a, double b) { return a + (b - a) * uniform(random); };
    Superquadric a = Superquadric::sphere(1), b = a;
    Mat3 Ri = randomRotation(random), Rj = randomRotation(random);
    Vec3 u = Vec3(between(-1, 1), between(-1, 1), between(-1, 1)).normalized();
    const Mat3 tilt = Eigen::AngleAxisd(between(-1e-3, 1e-3), Vec3(between(-1, 1), between(-1, 1), 1).normalized()).toRotationMatrix();
    switch (kind) {
    case Case::spheres:
        a = Superquadric::sphere(between(0.3, 1)), b = Superquadric::sphere(between(0.3, 1));
        break;
    case Case::ellipsoids:
        a = Superquadric::ellipsoid(1, between(0.1, 1), between(0.1, 1));
        b = Superquadric::ellipsoid(between(0.1, 1), 1, between(0.1, 1));
        break;
    case Case::blocky:
        a = {between(0.3, 1), between(0.3, 1), between(0.3, 1), between(0.1, 1), between(0.1, 1)};
        b = {between(0.3, 1), between(0.3, 1), between(0.3, 1), between(0.1, 1), between(0.1, 1)};
        break;
    case Case::parallelFaces:  // blocks face to face, one tilted by up to a milliradian
        a = {1, 1, 0.5, between(0.1, 0.3), between(0.1, 0.3)};
        b = {0.8, 0.8, 0.5, between(0.1, 0.3), between(0.1, 0.3)};
        Rj = Ri * tilt;
        u = Ri * Vec3(between(-0.05, 0.05), between(-0.05, 0.05), 1).normalized();
        break;
    case Case::edgeOnFace:  // j turned 45 degrees about its x axis: an edge against i's face
        a = {1, 1, 0.5, between(0.1, 0.3), between(0.1, 0.3)};
        b = {0.8, 0.5, 0.5, between(0.1, 0.3), between(0.1, 0.3)};
        Rj = Ri * Eigen::AngleAxisd(pi / 4, Vec3::UnitX()).toRotationMatrix() * tilt;
        u = Ri * Vec3(between(-0.1, 0.1), between(-0.1, 0.1), 1).normalized();
        break;
    case Case::sphereOnEllipsoid:
        a = Superquadric::sphere(between(0.3, 1));  // (smaller spheres: a limit, Superquadrics.md "Not done yet")
        b = Superquadric::ellipsoid(between(0.1, 1), 1, between(0.1, 1));
        break;
    case Case::needles:  // long axes crossing at right angles (up to a milliradian)
        a = Superquadric::ellipsoid(1, 0.1, 0.1), b = Superquadric::ellipsoid(1, 0.1, 0.1);
        Rj = Ri * Eigen::AngleAxisd(pi / 2, Vec3::UnitZ()).toRotationMatrix() * tilt;
        u = Ri * Vec3(between(-0.05, 0.05), between(-0.05, 0.05), 1).normalized();
        break;
    }
    Configuration c(a, b);
    const double size = std::min(a.semiAxes().minCoeff(), b.semiAxes().minCoeff());
    c.targetOverlap = uniform(random) < 0.1 ? -0.05 * size * uniform(random) : 0.1 * size * uniform(random);
    c.i = {&c.shapeI, Vec3(between(-1, 1), between(-1, 1), between(-1, 1)), Ri};
    c.j = {&c.shapeJ, c.i.centre, Rj};
    // Touching distance along u by bisection on the sign of the reference's Fi = Fj.
    double near = 0, far = a.boundingRadius() + b.boundingRadius();
    for (int k = 0; k < 30; ++k) {
        const double middle = 0.5 * (near + far);
        c.j.centre = c.i.centre + middle * u;
        (contact(c.i, c.j, 30).value < 0 ? near : far) = middle;
    }
    // Then moved in along the normal there by the target overlap.
    c.j.centre = c.i.centre + far * u;
    const Vec3 normal = contact(c.i, c.j).normal;
    c.j.centre += c.targetOverlap * normal;  // the normal points from j to i
    return c;
}

}  // namespace talus::reference

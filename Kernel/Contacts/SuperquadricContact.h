// Contact detection between two convex superquadrics, the exact stage of Theory/Superquadrics.md
// eq. (5)-(8) (after the neighbour grid and the bounding spheres).
//
// The contact point Xc minimises Fi + Fj subject to Fi = Fj (F the lab-frame shape functions),
// found by a damped Newton solve of
//   Phi(X, mu) = [grad Fi + mu^2 grad Fj ; Fi - Fj] = 0
// with the Jacobian [[Hi + mu^2 Hj, 2 mu grad Fj], [(grad Fi - grad Fj)^T, 0]], the step halved
// while |Phi| does not decrease. The bodies touch iff Fi(Xc) = Fj(Xc) < 0. A lasting contact
// warm-starts from its last Xc and mu; a new one from the bounding spheres' contact point with
// mu = 1. If Newton fails, the shapes are morphed from their bounding spheres to the true
// shapes in 4, then 8, then 16 stages, each stage's solution starting the next (the thesis's
// "plan B", Denissen 2019, app. 5.A.2).
#pragma once

#include <cmath>

#include "Math/Vector.h"
#include "Shapes/Superquadric.h"

namespace talus {

// A superquadric placed in the lab frame: x_lab = centre + rotation x_body.
struct PlacedSuperquadric {
    const Superquadric* shape = nullptr;
    Vec3 centre = Vec3::Zero();
    Mat3 rotation = Mat3::Identity();

    PlacedSuperquadric() = default;
    PlacedSuperquadric(const Superquadric* s, const Vec3& c, const Mat3& r) : shape(s), centre(c), rotation(r) {
        // An ellipsoid's lab shape function is the quadric F = d^T Q d - 1 with d = x - centre and
        // Q = A diag(1/a^2, 1/b^2, 1/c^2) A^T: one matrix per body and step, then every evaluation
        // is a matrix-vector product (the ellipsoid fast path).
        if (s->isEllipsoid()) quadric = r * s->semiAxes().cwiseInverse().cwiseAbs2().asDiagonal() * r.transpose();
    }

    // F, grad F and the Hessian in the lab frame (Theory/Superquadrics.md eq. (2): A grad f, A H
    // A^T).
    ShapeValue at(const Vec3& x) const;
    double valueAt(const Vec3& x) const {
        if (shape->isEllipsoid()) {
            const Vec3 d = x - centre;
            return d.dot(quadric * d) - 1;
        }
        return shape->shapeFunction(rotation.transpose() * (x - centre));
    }

    Mat3 quadric = Mat3::Zero();  // ellipsoids only
};

// The point and multiplier a contact remembers from step to step (the warm start).
struct SuperquadricContactPoint {
    Vec3 point = Vec3::Zero();
    double multiplier = 1;
};

// The Newton solve's convergence test after a step (SuperquadricContact.cc): the residual at the
// new point is within the tolerance and the step that led there was below sqrt(tolerance) x
// scale, or the residual alone is a hundred times below the tolerance. Newton's method converges
// quadratically (Theory/Superquadrics.md "Convergence"): after a step s the error is of order
// |s|^2 / scale, so a step of sqrt(tolerance) scale leaves an error of order tolerance x scale, the
// accuracy the residual test asks for; a warm start that moved by less than that ends after one
// iteration. `mismatch` is Fi - Fj, `gradientResidual2` the squared first three components of Phi,
// `step2` the squared length of the step taken. Branch-free, so that the ellipsoid lanes
// (EllipsoidContactBatch.h) share it with the scalar solve.
[[gnu::always_inline]] inline bool newtonConverged(double mismatch, double gradientResidual2, double gradientLengthI,
                                                   double step2, double scale, double tolerance) {
    const double tolerance2 = tolerance * tolerance, gradientScale = 1 + scale * gradientLengthI;
    const double limit2 = tolerance2 * gradientScale * gradientScale;
    const bool residualSmall = (std::abs(mismatch) <= tolerance) & (gradientResidual2 <= limit2);
    const bool residualTiny = (std::abs(mismatch) <= 0.01 * tolerance) & (gradientResidual2 <= 1e-4 * limit2);
    return (residualSmall & (step2 <= tolerance * scale * scale)) | residualTiny;
}

// The positive root t of c + 2 b t + a t^2 = 0 (a > 0, c < 0: from inside an ellipsoid to its
// surface, distanceToSurface), in the form that does not cancel. Both quotients are formed and
// one is chosen, so that the ellipsoid lanes can share it (a division inside a select does not
// vectorise).
[[gnu::always_inline]] inline double rootToSurface(double a, double b, double c) {
    const double root = std::sqrt(b * b - a * c);
    const double outer = -c / (b + root), inner = (root - b) / a;
    return b > 0 ? outer : inner;
}

struct SuperquadricContactSettings {
    double tolerance = 1e-10;   // relative: |Fi - Fj|, the gradient residual, and the error of X / (bounding radius)
    int maxIterations = 50;     // per Newton solve
};

struct SuperquadricContact {
    bool converged = false;     // the answer is certain: apart bounding spheres, or Newton (or plan B) found the point
    bool touching = false;      // Fi(Xc) = Fj(Xc) < 0
    SuperquadricContactPoint solution;
    Vec3 normal = Vec3::Zero();        // unit, from j to i (the kernel's convention, Theory/ContactLaws.md eq. (1)-(3)): -grad Fi/|grad Fi|
    double overlap = 0;                // di + dj with Fi(Xc - di normal) = 0, Fj(Xc + dj normal) = 0
    Vec3 contactPoint = Vec3::Zero();  // middle of the overlap along the normal (the sphere path's point)
    int iterations = 0;                // Newton iterations in all, plan B included
    int morphStages = 0;               // 0: plain Newton sufficed; else the stages plan B needed
    double gapBound = 0;               // apart: a lower bound of the distance between the bodies
};

// Exact contact of i and j, warm-started from `start` if given (a lasting contact), else from
// the bounding spheres. Pairs whose bounding spheres do not overlap are not touching (and not
// solved).
SuperquadricContact findSuperquadricContact(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                            const SuperquadricContactPoint* start = nullptr,
                                            const SuperquadricContactSettings& settings = {});

// Plan B alone: the contact found by morphing from the bounding spheres, without trying Newton's
// method on the true shapes first (what findSuperquadricContact falls back to when that fails;
// for testing the fallback on any configuration).
SuperquadricContact findSuperquadricContactByMorphing(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                                      const SuperquadricContactSettings& settings = {});

}  // namespace talus

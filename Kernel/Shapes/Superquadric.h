// A convex superquadric in its body frame (Theory/Superquadrics.md eq. (1)): semi-axes a, b, c
// along x, y, z and blockiness e1 (along z) and e2 (in the x-y plane), 0 < e1, e2 <= 1. e1 = e2 = 1
// is an ellipsoid; small e1 with e2 = 1 a cylinder, small e1 and e2 a block.
//
// Shape function (negative inside, zero on the surface):
//   f(x) = nu^(e2/e1) + |z/c|^(2/e1) - 1,   nu = |x/a|^(2/e2) + |y/b|^(2/e2).
// The body axes are the principal axes of inertia. Everything here is in the body frame; the
// lab frame is x_lab = X + R(q) x for a particle at X with orientation q.
#pragma once

#include "Math/Vector.h"

namespace talus {

// f with its gradient and Hessian at one point: the contact solver needs all three together.
struct ShapeValue {
    double value;
    Vec3 gradient;
    Mat3 hessian;
};

class Superquadric {
public:
    // Throws talus::Error naming the parameter for a semi-axis <= 0 (or not finite) or a
    // blockiness outside (0, 1].
    Superquadric(double a, double b, double c, double e1, double e2);
    static Superquadric sphere(double radius) { return {radius, radius, radius, 1, 1}; }
    static Superquadric ellipsoid(double a, double b, double c) { return {a, b, c, 1, 1}; }

    double a() const { return axes_.x(); }
    double b() const { return axes_.y(); }
    double c() const { return axes_.z(); }
    const Vec3& semiAxes() const { return axes_; }
    double e1() const { return e1_; }
    double e2() const { return e2_; }
    bool isEllipsoid() const { return e1_ == 1 && e2_ == 1; }
    bool isSphere() const { return isEllipsoid() && a() == b() && b() == c(); }

    double shapeFunction(const Vec3& x) const;
    Vec3 gradient(const Vec3& x) const;
    ShapeValue evaluate(const Vec3& x) const;  // f, gradient and Hessian

    // V = 2abc e1 e2 B(e1/2 + 1, e1) B(e2/2, e2/2) (Theory/Superquadrics.md eq. (3); Jaklic et al.
    // 2000).
    double volume() const;
    // Principal moments of inertia of a body of this density (Theory/Superquadrics.md eq. (4)): for
    // a sphere 2/5 m r^2.
    Vec3 principalInertia(double density) const;
    // The largest distance of a surface point from the centre, exact (see the .cc).
    double boundingRadius() const { return boundingRadius_; }

    // The surface point that lies furthest along the unit direction n: the deepest point into a
    // flat wall whose inward normal is -n (Theory/Superquadrics.md eq. (13), the thesis's eqs.
    // 5.44-5.54, derived anew in the .cc).
    Vec3 furthestPointAlong(const Vec3& n) const;

    bool operator==(const Superquadric&) const = default;

private:
    Vec3 axes_;
    double e1_, e2_;
    double boundingRadius_ = 0;
};

}  // namespace talus

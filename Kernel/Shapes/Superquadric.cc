#include "Shapes/Superquadric.h"

#include <cmath>

#include "Error.h"

namespace talus {

namespace {

double sign(double x) { return x < 0 ? -1.0 : 1.0; }

// max over u in [0, 1] of A u^e + B (1 - u)^e for 0 < e <= 1 (A, B >= 0). Concave in u for
// e <= 1, so the stationary point e A u^(e-1) = e B (1-u)^(e-1) is the maximum: u/(1-u) =
// (A/B)^(1/(1-e)). Written with s = (smaller/larger)^(1/(1-e)) <= 1 so nothing overflows;
// e = 1 is the limit s = 0.
double largestOfPowerSum(double A, double B, double e) {
    const double larger = std::max(A, B), smaller = std::min(A, B);
    if (e == 1 || larger == 0) return larger;
    const double s = std::pow(smaller / larger, 1 / (1 - e));
    return larger * std::pow(1 / (1 + s), e) + smaller * std::pow(s / (1 + s), e);
}

}  // namespace

Superquadric::Superquadric(double a, double b, double c, double e1, double e2) : axes_(a, b, c), e1_(e1), e2_(e2) {
    // (Messages built only on failure: the force loop makes sphere-shaped partners on the fly.)
    const char* names[] = {"semi-axis a", "semi-axis b", "semi-axis c"};
    for (int k = 0; k < 3; ++k)
        if (!(std::isfinite(axes_[k]) && axes_[k] > 0))
            throw Error(std::string("superquadric ") + names[k] + " must be positive and finite, got " + str(axes_[k]));
    if (!(e1 > 0 && e1 <= 1)) throw Error("superquadric blockiness e1 must lie in (0, 1] (convex shapes), got " + str(e1));
    if (!(e2 > 0 && e2 <= 1)) throw Error("superquadric blockiness e2 must lie in (0, 1] (convex shapes), got " + str(e2));
    // The surface in angles eta (latitude), omega (longitude): x = a cos^e1(eta) cos^e2(omega),
    // y = b cos^e1(eta) sin^e2(omega), z = c sin^e1(eta). Its squared distance from the centre is
    // cos^(2 e1)(eta) g + c^2 sin^(2 e1)(eta) with g = a^2 cos^(2 e2)(omega) + b^2 sin^(2
    // e2)(omega): the longitude maximises g alone, then the latitude the rest, both of the form
    // above.
    const double inPlane = largestOfPowerSum(a * a, b * b, e2);
    boundingRadius_ = std::sqrt(largestOfPowerSum(inPlane, c * c, e1));
}

double Superquadric::shapeFunction(const Vec3& x) const {
    if (isEllipsoid()) return x.cwiseQuotient(axes_).squaredNorm() - 1;
    const double p = 2 / e2_, q = 2 / e1_;
    const double nu = std::pow(std::abs(x.x() / a()), p) + std::pow(std::abs(x.y() / b()), p);
    return std::pow(nu, e2_ / e1_) + std::pow(std::abs(x.z() / c()), q) - 1;
}

Vec3 Superquadric::gradient(const Vec3& x) const { return evaluate(x).gradient; }

// Derivatives of f = nu^r + Z^q - 1 with X = |x|/a, Y = |y|/b, Z = |z|/c, p = 2/e2, q = 2/e1,
// r = e2/e1 (so p r = q):
//   dnu/dx = p X^(p-1) sgn(x)/a,  d2nu/dx2 = p (p-1) X^(p-2)/a^2,
//   df/dx = r nu^(r-1) dnu/dx,    d2f/dxdy = r (r-1) nu^(r-2) dnu/dx dnu/dy + r nu^(r-1) d2nu/dxdy,
//   df/dz = q Z^(q-1) sgn(z)/c,   d2f/dz2 = q (q-1) Z^(q-2)/c^2, no x-z or y-z terms.
// On the z axis (nu = 0) the first derivatives in x and y vanish (p >= 2); the second ones are
// their limit along the x and y axes, q (q-1) X^(q-2)/a^2 at X -> 0: 2/a^2 for e1 = 1, else 0.
ShapeValue Superquadric::evaluate(const Vec3& x) const {
    ShapeValue s;
    if (isEllipsoid()) {
        const Vec3 inverseSquare = axes_.cwiseProduct(axes_).cwiseInverse();
        s.value = x.cwiseProduct(x).dot(inverseSquare) - 1;
        s.gradient = 2 * x.cwiseProduct(inverseSquare);
        s.hessian = (2 * inverseSquare).asDiagonal();
        return s;
    }
    const double p = 2 / e2_, q = 2 / e1_, r = e2_ / e1_;
    const double X = std::abs(x.x()) / a(), Y = std::abs(x.y()) / b(), Z = std::abs(x.z()) / c();
    const double Xp1 = std::pow(X, p - 1), Yp1 = std::pow(Y, p - 1), Zq1 = std::pow(Z, q - 1);
    const double nu = Xp1 * X + Yp1 * Y;
    const double dnuX = p * Xp1 / a() * sign(x.x()), dnuY = p * Yp1 / b() * sign(x.y());
    const double d2nuX = p * (p - 1) * std::pow(X, p - 2) / (a() * a());
    const double d2nuY = p * (p - 1) * std::pow(Y, p - 2) / (b() * b());
    s.hessian.setZero();
    s.hessian(2, 2) = q * (q - 1) * std::pow(Z, q - 2) / (c() * c());
    s.gradient.z() = q * Zq1 / c() * sign(x.z());
    if (nu > 0) {
        const double nuR1 = std::pow(nu, r - 1), nuR2 = nuR1 / nu;
        s.value = nuR1 * nu + Zq1 * Z - 1;
        s.gradient.x() = r * nuR1 * dnuX;
        s.gradient.y() = r * nuR1 * dnuY;
        s.hessian(0, 0) = r * (r - 1) * nuR2 * dnuX * dnuX + r * nuR1 * d2nuX;
        s.hessian(1, 1) = r * (r - 1) * nuR2 * dnuY * dnuY + r * nuR1 * d2nuY;
        s.hessian(0, 1) = s.hessian(1, 0) = r * (r - 1) * nuR2 * dnuX * dnuY;
    } else {
        s.value = Zq1 * Z - 1;
        s.gradient.x() = s.gradient.y() = 0;
        const double axial = e1_ == 1 ? 2.0 : 0.0;
        s.hessian(0, 0) = axial / (a() * a());
        s.hessian(1, 1) = axial / (b() * b());
    }
    return s;
}

double Superquadric::volume() const {
    return 2 * a() * b() * c() * e1_ * e2_ * std::beta(e1_ / 2 + 1, e1_) * std::beta(e2_ / 2, e2_ / 2);
}

Vec3 Superquadric::principalInertia(double density) const {
    const double inPlane = std::beta(1.5 * e2_, e2_ / 2) * std::beta(e1_ / 2, 2 * e1_ + 1);
    const double axial = 4 * std::beta(e2_ / 2, e2_ / 2 + 1) * std::beta(1.5 * e1_, e1_ + 1);
    const double a2 = a() * a(), b2 = b() * b(), c2 = c() * c();
    const Vec3 moments(b2 * inPlane + c2 * axial, a2 * inPlane + c2 * axial, (a2 + b2) * inPlane);
    return density / 2 * a() * b() * c() * e1_ * e2_ * moments;
}

// Maximise n.x on f(x) = 0. In scaled coordinates X = x/a, Y = y/b, Z = z/c (all >= 0 by
// symmetry, signs restored at the end) with N = (a|nx|, b|ny|, c|nz|) the task is to maximise
// N.(X, Y, Z) on (X^p + Y^p)^r + Z^q = 1 (p = 2/e2, q = 2/e1, r = e2/e1). Lagrange's condition
// gives Y/X = alpha = (Ny/Nx)^(1/(p-1)) and Z/X = beta = ((1 + alpha^p)^(r-1) Nz/Nx)^(1/(q-1)),
// and the constraint X = ((1 + alpha^p)^r + beta^q)^(-1/q) (the thesis's eqs. 5.46-5.50, whose
// extracted exponents are garbled). The in-plane axis with the larger N is the reference, so
// alpha <= 1; for beta > 1 the same equation is solved for Z first, so that nothing overflows when
// n is nearly along z.
Vec3 Superquadric::furthestPointAlong(const Vec3& n) const {
    if (isEllipsoid()) {  // x^T D^-2 x = 1 with D = diag(a, b, c): x = D^2 n / |D n|, no powers
        const Vec3 scaledNormal = axes_.cwiseProduct(n);
        return axes_.cwiseProduct(scaledNormal) / scaledNormal.norm();
    }
    const Vec3 N = axes_.cwiseProduct(n.cwiseAbs());
    const int reference = N.x() >= N.y() ? 0 : 1, other = 1 - reference;
    Vec3 scaled;
    if (N[reference] == 0) {
        scaled = Vec3(0, 0, 1);
    } else {
        const double p = 2 / e2_, q = 2 / e1_, r = e2_ / e1_;
        const double alpha = std::pow(N[other] / N[reference], 1 / (p - 1));
        const double w = 1 + std::pow(alpha, p);
        const double beta = std::pow(std::pow(w, r - 1) * N.z() / N[reference], 1 / (q - 1));
        double referenceValue, z;
        if (beta <= 1) {
            referenceValue = std::pow(std::pow(w, r) + std::pow(beta, q), -1 / q);
            z = beta * referenceValue;
        } else {
            z = std::pow(std::pow(w, r) * std::pow(beta, -q) + 1, -1 / q);
            referenceValue = z / beta;
        }
        scaled[reference] = referenceValue;
        scaled[other] = alpha * referenceValue;
        scaled.z() = z;
    }
    return Vec3(sign(n.x()), sign(n.y()), sign(n.z())).cwiseProduct(axes_).cwiseProduct(scaled);
}

}  // namespace talus

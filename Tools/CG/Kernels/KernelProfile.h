// The radial shape of a coarse-graining function of unit width in 1, 2 or 3 dimensions
// (Theory/CoarseGraining.md eq. (2)): W1(u) = c_d f(|u|^2) for |u| < R, zero beyond. The physical
// kernel is W(r) = det(A) W1(A r) (WidthMatrix.h), so width enters only through A.
//
//   Lucy      f = 1 - 6q^2 + 8q^3 - 3q^4, R = 1 (the width is the cut-off radius),
//             c_1 = 5/4, c_2 = 5/pi, c_3 = 105/(16 pi)   (Theory/CoarseGraining.md eq. (2), Lucy 1977)
//   Gauss     f = exp(-q^2/2), R = 3 (the width is the standard deviation), c_d chosen so that
//             the truncated kernel integrates to exactly 1 over the ball of radius 3
//   Heaviside f = 1, R = 1, c_d = 1 / (volume of the unit ball): 1/2, 1/pi, 3/(4 pi)
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "Kernels/RadialShapes.h"

namespace talus::cg {

enum class KernelShape { Lucy, Gauss, Heaviside };

// Parses "Lucy", "Gauss", "Heaviside" (case-insensitive); throws InputError otherwise.
KernelShape kernelShapeFromName(const std::string& name);
std::string kernelShapeName(KernelShape shape);

class KernelProfile {
public:
    KernelProfile(KernelShape shape, int dimension);

    KernelShape shape() const { return shape_; }
    int dimension() const { return dimension_; }
    // c_d: the value of the unit-width kernel's normalisation in `dimension` dimensions.
    double normalisation() const { return normalisation_; }
    // R: the support radius of the unit-width kernel.
    double cutoff() const { return cutoff_; }
    double cutoffSquared() const { return cutoff_ * cutoff_; }

    // W1 at a point u with |u|^2 = q2 (zero outside the support).
    double value(double q2) const;

    // The line integral int_0^1 W1(u0 + s e) ds (Theory/CoarseGraining.md eq. (10), contact stress
    // along the branch vector; Weinhart et al. 2012), exact for every shape: the integrand depends
    // on s only through q^2(s) = a (s - s*)^2 + m^2, so the clipped interval has closed forms (erf
    // for Gauss, a polynomial plus asinh for Lucy). Very short clipped intervals use Gauss-Legendre
    // quadrature instead, where the closed forms would lose digits to cancellation.
    double lineIntegral(const double u0[3], const double e[3]) const;
    // The same for a kernel of one dimension (coordinates Z, say), where u0 and e are numbers:
    // int_0^1 W1(u0 + s e) ds = [G(max) - G(min)] / |e| over the ends clipped to the support, with
    // G(u) = c_1 int_0^u f(t^2) dt a polynomial (Lucy), erf (Gauss) or u (Heaviside): no square root
    // or logarithm, about 4 times faster than lineIntegral. Short clipped intervals go to
    // lineIntegral, as there.
    double lineIntegralAlongAxis(double u0, double e) const;
    // The same for a shape known when compiling (Kernels/RadialShapes.h), inlined into a loop
    // over points (Fields/AlongOneAxis.cc): lineIntegralAlongAxis is this for the profile's shape.
    template <class Shape>
    double lineIntegralAlongAxisOf(double u0, double e) const {
        if (e == 0) return value(u0 * u0);  // (a branch across the axis: the integrand is constant)
        const double u1 = u0 + e;
        const double lo = std::max(std::min(u0, u1), -Shape::cutoff), hi = std::min(std::max(u0, u1), Shape::cutoff);
        if (hi <= lo) return 0.0;
        if (hi - lo < 1e-3) [[unlikely]] {  // (as lineIntegral's short intervals: a difference of nearly equal values)
            const double point[3] = {u0, 0, 0}, segment[3] = {e, 0, 0};
            return lineIntegral(point, segment);
        }
        // (G(u) / c_1 is odd and constant beyond the cut-off; lo and hi are clipped already.)
        const double gHi = std::copysign(Shape::axialIntegral(std::abs(hi)), hi);
        const double gLo = std::copysign(Shape::axialIntegral(std::abs(lo)), lo);
        return normalisation_ * (gHi - gLo) / std::abs(e);
    }

private:
    double lucyAntiderivative(double tau, double m2) const;

    KernelShape shape_;
    int dimension_;
    double normalisation_;
    double cutoff_;
};

}  // namespace talus::cg

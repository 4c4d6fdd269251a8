// The radial shapes of KernelProfile.h as small functors, so that a loop over sources is compiled
// once per shape (no switch per source). Each returns f(q^2) without the normalisation, for
// q^2 below cutoffSquared (q: the distance in widths, Theory/CoarseGraining.md "Kernels"), and
// axialIntegral(x) = int_0^x f(t^2) dt for 0 <= x <= cutoff (the one-dimensional line integral,
// KernelProfile::lineIntegralAlongAxis): Lucy x - 2x^3 + 2x^4 - 3x^5/5 (0.4 at the cut-off 1, so
// c_1 = 5/4), Gauss sqrt(pi/2) erf(x / sqrt 2), Heaviside x. ofDistance(q) is f(q^2) from q >= 0
// itself, for kernels of one dimension where q = |u| is at hand (Lucy then takes no square root).
#pragma once

#include <cmath>
#include <numbers>

namespace talus::cg {

struct LucyShape {
    static constexpr double cutoff = 1.0, cutoffSquared = 1.0;
    static double axialIntegral(double x) { return x * (1 + x * x * (-2 + x * (2 - 0.6 * x))); }
    double operator()(double q2) const {
        return polynomial(std::sqrt(q2), q2);
    }
    static double ofDistance(double q) { return polynomial(q, q * q); }
    // f from q and q^2, each as the caller has it (the radial path its q^2, the axial one its q).
    static double polynomial(double q, double q2) { return 1 + q2 * (-6 + q * (8 - 3 * q)); }
};
struct GaussShape {
    static constexpr double cutoff = 3.0, cutoffSquared = 9.0;
    static double axialIntegral(double x) {
        return std::sqrt(std::numbers::pi / 2) * std::erf(x * (std::numbers::sqrt2 / 2));
    }
    double operator()(double q2) const { return std::exp(-0.5 * q2); }
    static double ofDistance(double q) { return std::exp(-0.5 * q * q); }
};
struct HeavisideShape {
    static constexpr double cutoff = 1.0, cutoffSquared = 1.0;
    static double axialIntegral(double x) { return x; }
    double operator()(double) const { return 1.0; }
    static double ofDistance(double) { return 1.0; }
};

}  // namespace talus::cg

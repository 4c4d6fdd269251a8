// The radial shapes of KernelProfile.h as small functors, so that a loop over sources is compiled
// once per shape (no switch per source). Each returns f(q^2) without the normalisation, for
// q^2 below cutoffSquared (q: the distance in widths, Theory/CoarseGraining.md "Kernels").
#pragma once

#include <cmath>

namespace talus::cg {

struct LucyShape {
    static constexpr double cutoffSquared = 1.0;
    double operator()(double q2) const {
        const double q = std::sqrt(q2);
        return 1 + q2 * (-6 + q * (8 - 3 * q));
    }
};
struct GaussShape {
    static constexpr double cutoffSquared = 9.0;
    double operator()(double q2) const { return std::exp(-0.5 * q2); }
};
struct HeavisideShape {
    static constexpr double cutoffSquared = 1.0;
    double operator()(double) const { return 1.0; }
};

}  // namespace talus::cg

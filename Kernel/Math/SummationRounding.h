#pragma once
// When two floating-point sums of the same positive terms may be called equal.
//
// A running total such as the maser's created mass is a sum of n positive terms added one at a
// time; the same mass counted again at the end (the particles in the chute plus the outlet's
// total) adds the same terms in another order. Recursive summation of n terms errs by at most
// (n - 1) u times the sum of their magnitudes, u = eps / 2, to first order and whatever the
// order of the additions (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed.,
// section 4.2), so two such sums differ by less than n eps S. A fixed
// relative tolerance is wrong both ways: too tight for long runs (177677 masses drifted by
// 3e-12 of the total in the thesis-scale maser chute) and needlessly loose for short ones.
// One particle more or less stays detectable while its mass exceeds n eps S, i.e. for n up to
// about 1e7 particles of comparable mass.
#include <algorithm>
#include <cmath>
#include <limits>

namespace talus {

// Whether sums a and b of `terms` positive terms each may be the same sum in two orders.
inline bool equalUpToSummationRounding(double a, double b, double terms) {
    const double bound = (terms + 1) * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b));
    return std::abs(a - b) <= bound;
}

}  // namespace talus

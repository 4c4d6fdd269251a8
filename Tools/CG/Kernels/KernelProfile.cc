#include "Kernels/KernelProfile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "IO/InputError.h"

namespace talus::cg {

namespace {

using std::numbers::pi;

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

double normalisationOf(KernelShape shape, int d) {
    switch (shape) {
        case KernelShape::Lucy:  // Theory/CoarseGraining.md
            return d == 1 ? 5.0 / 4.0 : d == 2 ? 5.0 / pi : 105.0 / (16.0 * pi);
        case KernelShape::Heaviside:  // 1 / volume of the unit ball
            return d == 1 ? 0.5 : d == 2 ? 1.0 / pi : 3.0 / (4.0 * pi);
        case KernelShape::Gauss: {
            // Integral of exp(-|u|^2/2) over |u| < 3:
            //   1-D  sqrt(2 pi) erf(3/sqrt 2)
            //   2-D  2 pi (1 - e^{-9/2})
            //   3-D  4 pi (sqrt(pi/2) erf(3/sqrt 2) - 3 e^{-9/2})   (integration by parts)
            const double e = std::erf(3.0 / std::sqrt(2.0));
            const double mass = d == 1 ? std::sqrt(2 * pi) * e
                                : d == 2 ? 2 * pi * (1 - std::exp(-4.5))
                                         : 4 * pi * (std::sqrt(pi / 2) * e - 3 * std::exp(-4.5));
            return 1.0 / mass;
        }
    }
    return 0;
}

// 8-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr double glNode[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                              0.9602898564975363};
constexpr double glWeight[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                0.1012285362903763};

}  // namespace

KernelShape kernelShapeFromName(const std::string& name) {
    const std::string n = lower(name);
    if (n == "lucy") return KernelShape::Lucy;
    if (n == "gauss" || n == "gaussian") return KernelShape::Gauss;
    if (n == "heaviside") return KernelShape::Heaviside;
    throw InputError("--function: unknown coarse-graining function '" + name +
                     "' (Lucy, Gauss or Heaviside)");
}

std::string kernelShapeName(KernelShape shape) {
    switch (shape) {
        case KernelShape::Lucy: return "Lucy";
        case KernelShape::Gauss: return "Gauss";
        case KernelShape::Heaviside: return "Heaviside";
    }
    return "?";
}

KernelProfile::KernelProfile(KernelShape shape, int dimension)
    : shape_(shape), dimension_(dimension), normalisation_(0),
      cutoff_(shape == KernelShape::Gauss ? 3.0 : 1.0) {
    if (dimension < 1 || dimension > 3) throw InputError("kernel dimension must be 1, 2 or 3");
    normalisation_ = normalisationOf(shape, dimension);
}

double KernelProfile::value(double q2) const {
    if (q2 >= cutoffSquared()) return 0.0;
    switch (shape_) {
        case KernelShape::Lucy: {
            const double q = std::sqrt(q2);
            return normalisation_ * (1 + q2 * (-6 + q * (8 - 3 * q)));
        }
        case KernelShape::Gauss: return normalisation_ * std::exp(-0.5 * q2);
        case KernelShape::Heaviside: return normalisation_;
    }
    return 0;
}

// Antiderivative in tau of the Lucy polynomial with q^2 = tau^2 + m^2 (without c_d):
//   int 1 - 6 q^2 + 8 q^3 - 3 q^4 dtau, using
//   int (tau^2 + m^2)^{3/2} dtau = tau (2 tau^2 + 5 m^2) sqrt(tau^2 + m^2) / 8
//                                 + 3 m^4 / 8 asinh(tau / m).
double KernelProfile::lucyAntiderivative(double tau, double m2) const {
    const double t2 = tau * tau;
    const double m = std::sqrt(m2);
    const double cube = tau * (2 * t2 + 5 * m2) * std::sqrt(t2 + m2) / 8 +
                        (m > 0 ? 3 * m2 * m2 / 8 * std::asinh(tau / m) : 0.0);
    return tau - 6 * (t2 * tau / 3 + m2 * tau) + 8 * cube -
           3 * (t2 * t2 * tau / 5 + 2 * m2 * t2 * tau / 3 + m2 * m2 * tau);
}

double KernelProfile::lineIntegral(const double u0[3], const double e[3]) const {
    // q^2(s) = a s^2 + 2 b s + c
    const double a = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    const double b = u0[0] * e[0] + u0[1] * e[1] + u0[2] * e[2];
    const double c = u0[0] * u0[0] + u0[1] * u0[1] + u0[2] * u0[2];
    const double R2 = cutoffSquared();
    if (a == 0) return value(c);  // a segment of zero length: a point
    const double sqrtA = std::sqrt(a);
    // tau = sqrt(a) (s - s*) with s* = -b/a the closest point: q^2 = tau^2 + m^2,
    // ds = dtau/sqrt(a). tau at s = 0 and s = 1 are computed as projections, (a s + b)/sqrt(a), not
    // from s*, which is huge for short segments far from the point and would cost digits.
    const double sStar = -b / a;
    // m^2 at the closest point itself (not c - b^2/a, which cancels).
    double m2 = 0;
    for (int k = 0; k < 3; ++k) {
        const double uk = u0[k] + sStar * e[k];
        m2 += uk * uk;
    }
    if (m2 >= R2) return 0.0;
    const double edge = std::sqrt(R2 - m2);
    const double tau0 = std::max(b / sqrtA, -edge);
    const double tau1 = std::min((a + b) / sqrtA, edge);
    if (tau1 <= tau0) return 0.0;
    if (tau1 - tau0 < 1e-3) {
        // Short interval: the closed forms would lose digits (a difference of two nearly equal
        // antiderivatives), and so would its length in tau. Integrate in s instead, with q^2
        // from u0 + s e directly, by 8-point Gauss-Legendre split at the closest point (where
        // Lucy's q^3 has its only non-smooth point).
        const double s0 = b / sqrtA >= -edge ? 0.0 : sStar - edge / sqrtA;
        const double s1 = (a + b) / sqrtA <= edge ? 1.0 : sStar + edge / sqrtA;
        auto gauss = [&](double lo, double hi) {
            const double mid = 0.5 * (lo + hi), rad = 0.5 * (hi - lo);
            double sum = 0;
            for (int k = 0; k < 4; ++k) {
                for (double sign : {-1.0, 1.0}) {
                    const double s = mid + sign * rad * glNode[k];
                    double q2 = 0;
                    for (int c = 0; c < 3; ++c) q2 += (u0[c] + s * e[c]) * (u0[c] + s * e[c]);
                    sum += glWeight[k] * value(q2);
                }
            }
            return sum * rad;
        };
        return (s0 < sStar && sStar < s1) ? gauss(s0, sStar) + gauss(sStar, s1) : gauss(s0, s1);
    }
    if (shape_ == KernelShape::Heaviside) return normalisation_ * (tau1 - tau0) / sqrtA;
    if (shape_ == KernelShape::Gauss) {
        // int exp(-(tau^2 + m^2)/2) dtau = e^{-m^2/2} sqrt(pi/2) [erf(tau/sqrt 2)]
        const double r = std::numbers::sqrt2 / 2;
        return normalisation_ * std::exp(-0.5 * m2) * std::sqrt(std::numbers::pi / 2) *
               (std::erf(tau1 * r) - std::erf(tau0 * r)) / sqrtA;
    }
    return normalisation_ * (lucyAntiderivative(tau1, m2) - lucyAntiderivative(tau0, m2)) / sqrtA;
}

double KernelProfile::lineIntegralAlongAxis(double u0, double e) const {
    switch (shape_) {
        case KernelShape::Lucy: return lineIntegralAlongAxisOf<LucyShape>(u0, e);
        case KernelShape::Gauss: return lineIntegralAlongAxisOf<GaussShape>(u0, e);
        case KernelShape::Heaviside: break;
    }
    return lineIntegralAlongAxisOf<HeavisideShape>(u0, e);
}

}  // namespace talus::cg

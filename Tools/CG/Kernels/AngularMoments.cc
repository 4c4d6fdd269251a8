#include "Kernels/AngularMoments.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace talus::cg {

namespace {

// Gauss-Kronrod 7/15 nodes on [-1, 1] (QUADPACK's qk15): Kronrod nodes and weights; the Gauss
// nodes are the odd entries and the last (centre) one.
constexpr double kronrodNode[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                   0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                   0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                   0.207784955007898467600689403773245, 0.0};
constexpr double kronrodWeight[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                     0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                     0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                     0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double gaussWeight[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                   0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Integrand {
    const KernelProfile& profile;
    double m2, fourA;
    void operator()(double phi, double out[3]) const {
        const double s = std::sin(0.5 * phi);
        const double w = profile.value(m2 + fourA * s * s);
        const double c = std::cos(phi);
        out[0] = w;
        out[1] = w * c;
        out[2] = w * (2 * c * c - 1);
    }
};

// One 15-point panel: the Kronrod sums and the difference to the embedded 7-point Gauss rule.
double kronrodPanel(const Integrand& f, double lo, double hi, double sum[3]) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    double kronrod[3] = {0, 0, 0}, gauss[3] = {0, 0, 0}, v[3];
    for (int k = 0; k < 8; ++k) {
        const int copies = k == 7 ? 1 : 2;
        for (int side = 0; side < copies; ++side) {
            f(mid + (side == 0 ? -1 : 1) * half * kronrodNode[k], v);
            for (int n = 0; n < 3; ++n) {
                kronrod[n] += kronrodWeight[k] * v[n];
                if (k % 2 == 1) gauss[n] += gaussWeight[k / 2] * v[n];  // k = 1, 3, 5 and the centre 7
            }
        }
    }
    double error = 0;
    for (int n = 0; n < 3; ++n) {
        sum[n] = kronrod[n] * half;
        error = std::max(error, std::abs(kronrod[n] - gauss[n]) * half);
    }
    return error;
}

// Globally adaptive (QUADPACK's qag strategy): bisect the panel with the largest error estimate
// until the estimates add up to at most `tolerance`, or `maxPanels` panels (never reached in the
// tests; the integrands are smooth on [0, phi_c] apart from the q^3 of Lucy near q = 0).
struct Panel {
    double lo, hi, error;
    double sum[3];
};

void adaptive(const Integrand& f, double lo, double hi, double tolerance, double sum[3]) {
    constexpr std::size_t maxPanels = 200;
    Panel first{lo, hi, 0, {0, 0, 0}};
    first.error = kronrodPanel(f, lo, hi, first.sum);
    std::vector<Panel> panels{first};
    double error = first.error;
    while (error > tolerance && panels.size() < maxPanels) {
        std::size_t worst = 0;
        for (std::size_t p = 1; p < panels.size(); ++p) {
            if (panels[p].error > panels[worst].error) worst = p;
        }
        const Panel split = panels[worst];
        const double mid = 0.5 * (split.lo + split.hi);
        Panel left{split.lo, mid, 0, {0, 0, 0}}, right{mid, split.hi, 0, {0, 0, 0}};
        left.error = kronrodPanel(f, left.lo, left.hi, left.sum);
        right.error = kronrodPanel(f, right.lo, right.hi, right.sum);
        panels[worst] = left;
        panels.push_back(right);
        error += left.error + right.error - split.error;
    }
    for (const Panel& p : panels) {
        for (int n = 0; n < 3; ++n) sum[n] += p.sum[n];
    }
}

}  // namespace

AngularMoments angularMoments(const KernelProfile& profile, double m2, double a) {
    AngularMoments result;
    const double R2 = profile.cutoffSquared();
    if (m2 >= R2) return result;
    if (a <= 0) {
        // On the axis (r = 0 or ri = 0) every point of the circle is as far: C0 = W1, and the
        // cos(n phi) averages vanish.
        result.c0 = profile.value(m2);
        return result;
    }
    // The arc inside the support: 4 a sin^2(phi/2) < R^2 - m2.
    const double reach = (R2 - m2) / (4 * a);
    const double phiEdge = reach >= 1 ? std::numbers::pi : 2 * std::asin(std::sqrt(reach));
    if (profile.shape() == KernelShape::Heaviside) {
        // A constant on the arc: (1/pi) int_0^phic cos(n phi) = sin(n phic)/(n pi), exactly.
        const double c = profile.normalisation() / std::numbers::pi;
        result.c0 = c * phiEdge;
        result.c1 = reach >= 1 ? 0.0 : c * std::sin(phiEdge);
        result.c2 = reach >= 1 ? 0.0 : c * 0.5 * std::sin(2 * phiEdge);
        return result;
    }
    const Integrand f{profile, m2, 4 * a};
    // Absolute tolerance 1e-13 c_d on (1/pi) int_0^phic, i.e. pi 1e-13 c_d on the integral.
    double sum[3] = {0, 0, 0};
    adaptive(f, 0.0, phiEdge, 1e-13 * profile.normalisation() * std::numbers::pi, sum);
    // The integrand is even in phi: (1/2 pi) int_{-phic}^{phic} = (1/pi) int_0^{phic}.
    result.c0 = sum[0] / std::numbers::pi;
    result.c1 = sum[1] / std::numbers::pi;
    result.c2 = sum[2] / std::numbers::pi;
    return result;
}

}  // namespace talus::cg

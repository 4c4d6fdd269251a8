// Helpers of the CG tests: Gauss-Legendre quadrature (nodes computed here by Newton's method
// on the Legendre polynomials, independently of the library), composite quadrature over
// panels between given breakpoints, small frames built by hand, and small files written for the
// readers with the message of the InputError they raise.
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "IO/FstatFileReader.h"
#include "IO/InputError.h"
#include "IO/ParticleFrame.h"

namespace talus::cg::test {

inline void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The message of the InputError `f` throws, or "(no error)".
inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no error)";
}

struct GaussLegendre {
    std::vector<double> node, weight;  // on [-1, 1]
    explicit GaussLegendre(int n) {
        for (int i = 0; i < n; ++i) {
            double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
            double dp = 0;
            for (int iteration = 0; iteration < 100; ++iteration) {
                double p0 = 1, p1 = x;
                for (int k = 2; k <= n; ++k) {
                    const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n * (x * p1 - p0) / (x * x - 1);
                const double dx = p1 / dp;
                x -= dx;
                if (std::abs(dx) < 1e-16) break;
            }
            node.push_back(x);
            weight.push_back(2 / ((1 - x * x) * dp * dp));
        }
    }
    // Nodes and weights of the panels of [lo, hi] split at the breakpoints inside it. Each panel
    // is mapped by x = a + (c - a)(3u^2 - 2u^3), u in [0, 1], whose Jacobian 6u(1 - u) vanishes at
    // both ends: an integrand that behaves like sqrt(x - a) at a breakpoint (a chord of a
    // support whose kernel does not vanish at its edge) becomes smooth in u.
    void panels(double lo, double hi, std::vector<double> breaks, std::vector<double>& x, std::vector<double>& w) const {
        breaks.push_back(lo);
        breaks.push_back(hi);
        std::sort(breaks.begin(), breaks.end());
        x.clear();
        w.clear();
        for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
            const double a = std::max(lo, breaks[b]), c = std::min(hi, breaks[b + 1]);
            if (!(c > a)) continue;
            for (std::size_t k = 0; k < node.size(); ++k) {
                const double u = 0.5 * (node[k] + 1);
                x.push_back(a + (c - a) * u * u * (3 - 2 * u));
                w.push_back(0.5 * weight[k] * (c - a) * 6 * u * (1 - u));
            }
        }
    }
};

// A frame of particles given by hand: species 0 unless set.
inline ParticleFrame makeFrame(const std::vector<Vec3>& x, const std::vector<double>& r, DomainBox box,
                               std::vector<Vec3> v = {}, std::vector<int> species = {}) {
    ParticleFrame f;
    f.box = box;
    f.position = x;
    f.radius = r;
    f.velocity = v.empty() ? std::vector<Vec3>(x.size(), Vec3{0, 0, 0}) : v;
    f.species = species.empty() ? std::vector<int>(x.size(), 0) : species;
    return f;
}

// A .fstat line given by hand: particle i, partner j (-(w+1) for wall w), contact point, normal
// (pairs: from j to i; walls: into the wall), overlap and the force on i.
inline ContactLine contactLine(long i, long j, Vec3 point, Vec3 normal, double overlap, Vec3 force) {
    ContactLine c;
    c.i = i;
    c.j = j;
    c.point = point;
    c.normal = normal;
    c.overlap = overlap;
    c.force = force;
    return c;
}

inline double sphereVolume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

}  // namespace talus::cg::test

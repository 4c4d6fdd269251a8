#include "DrumAnalysis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace talus::drum {

namespace {

// Theory/CoarseGraining.md eq. (2): the 2-D Lucy polynomial, normalised to 1 over the disc of
// radius w.
double lucy2d(double distance, double width) {
    const double s = distance / width;
    if (s >= 1) return 0;
    return 5 / (std::numbers::pi * width * width) * (1 - s * s * (6 - s * (8 - 3 * s)));
}

}  // namespace

MixingIndices mixingIndices(const ParticleStore& p, std::size_t sphereSpecies, double extent, int cells,
                            double width) {
    const double h = 2 * extent / cells;
    const auto centre = [&](int k) { return -extent + (k + 0.5) * h; };
    std::vector<double> rho(static_cast<std::size_t>(cells) * cells, 0.0), rhoS(rho.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.fixed[i]) continue;
        const double x = p.position[i].x(), z = p.position[i].z();
        // Only the cells within the kernel's support.
        const int x0 = std::max(0, static_cast<int>(std::floor((x - width + extent) / h)));
        const int x1 = std::min(cells - 1, static_cast<int>(std::floor((x + width + extent) / h)));
        const int z0 = std::max(0, static_cast<int>(std::floor((z - width + extent) / h)));
        const int z1 = std::min(cells - 1, static_cast<int>(std::floor((z + width + extent) / h)));
        for (int a = x0; a <= x1; ++a)
            for (int c = z0; c <= z1; ++c) {
                const double w = p.mass[i] * lucy2d(std::hypot(centre(a) - x, centre(c) - z), width);
                const std::size_t cell = static_cast<std::size_t>(a) * cells + c;
                rho[cell] += w;
                if (p.species[i] == sphereSpecies) rhoS[cell] += w;
            }
    }
    double mass = 0, sphereMass = 0, entropy = 0, momentX = 0, momentZ = 0;
    for (int a = 0; a < cells; ++a)
        for (int c = 0; c < cells; ++c) {
            const std::size_t cell = static_cast<std::size_t>(a) * cells + c;
            if (!(rho[cell] > 0)) continue;
            const double phi = std::clamp(rhoS[cell] / rho[cell], 0.0, 1.0);
            double m = 0;  // 0 ln 0 = 0
            if (phi > 0) m += phi * std::log(phi);
            if (phi < 1) m += (1 - phi) * std::log1p(-phi);
            entropy += rho[cell] * m;
            mass += rho[cell];
            sphereMass += rhoS[cell];
            momentX += rho[cell] * centre(a);
            momentZ += rho[cell] * centre(c);
        }
    MixingIndices result;
    if (!(mass > 0)) return result;
    result.mixing = -entropy / (std::numbers::ln2 * mass);
    const double cx = momentX / mass, cz = momentZ / mass;
    double sphereDistance = 0, materialDistance = 0;
    for (int a = 0; a < cells; ++a)
        for (int c = 0; c < cells; ++c) {
            const std::size_t cell = static_cast<std::size_t>(a) * cells + c;
            const double d = std::hypot(centre(a) - cx, centre(c) - cz);
            materialDistance += rho[cell] * d;
            sphereDistance += rhoS[cell] * d;
        }
    result.spheresAtCore = sphereMass > 0 && sphereDistance / sphereMass < materialDistance / mass;
    result.segregation = result.spheresAtCore ? result.mixing - 1 : 1 - result.mixing;
    return result;
}

double surfaceAngle(const ParticleStore& p, double binWidth, double centralFraction) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!p.fixed[i]) {
            lo = std::min(lo, p.position[i].x());
            hi = std::max(hi, p.position[i].x());
        }
    if (!(hi > lo)) return NAN;
    const double middle = 0.5 * (lo + hi), half = 0.5 * centralFraction * (hi - lo);
    const int bins = std::max(1, static_cast<int>(std::ceil(2 * half / binWidth)));
    const double width = 2 * half / bins;
    std::vector<double> top(static_cast<std::size_t>(bins), -std::numeric_limits<double>::infinity());
    std::vector<double> topX(top.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.fixed[i]) continue;
        const double u = (p.position[i].x() - (middle - half)) / width;
        if (u < 0 || u >= bins) continue;
        const std::size_t b = static_cast<std::size_t>(u);
        if (p.position[i].z() > top[b]) top[b] = p.position[i].z(), topX[b] = p.position[i].x();
    }
    // Least squares through the surface particles' centres (x, z).
    double n = 0, sx = 0, sz = 0, sxx = 0, sxz = 0;
    for (int b = 0; b < bins; ++b) {
        if (!std::isfinite(top[static_cast<std::size_t>(b)])) continue;
        const double x = topX[static_cast<std::size_t>(b)], z = top[static_cast<std::size_t>(b)];
        n += 1, sx += x, sz += z, sxx += x * x, sxz += x * z;
    }
    if (n < 3) return NAN;
    const double slope = (n * sxz - sx * sz) / (n * sxx - sx * sx);
    return std::atan(slope) * 180 / std::numbers::pi;
}

}  // namespace talus::drum

#include "DrumAnalysis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>


namespace talus::drum {

MixingIndices mixingIndices(const ParticleStore& p, std::size_t sphereSpecies, double extent, int cells,
                            double width) {
    cg::ParticleFrame bed;
    std::size_t speciesCount = sphereSpecies + 1;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.fixed[i]) continue;
        const Vec3& x = p.position[i];
        const Vec3& v = p.velocity[i];
        bed.position.push_back({x.x(), x.y(), x.z()});
        bed.velocity.push_back({v.x(), v.y(), v.z()});
        bed.radius.push_back(p.radius[i]);
        bed.species.push_back(static_cast<int>(p.species[i]));
        bed.mass.push_back(p.mass[i]);
        speciesCount = std::max<std::size_t>(speciesCount, p.species[i] + 1);
    }
    if (bed.size() == 0) return {};
    // Averaged along y over a box of length 1: the length of the drum would scale rho and rho_s
    // alike, which cancels in M and S.
    bed.box = {{-extent, 0, -extent}, {extent, 1, extent}};
    cg::CoarseGrainingSetup setup;
    setup.coordinates = cg::Coordinates::fromName("XZ");
    setup.width = cg::WidthMatrix::isotropic(width);
    setup.speciesDensity.assign(speciesCount, 1.0);  // (unused: the masses are given)
    return cg::frameMixingIndices(bed, setup, {cells, 1, cells}, {-extent, 0, -extent}, {extent, 0, extent},
                                  static_cast<int>(sphereSpecies));
}

const char* whereTheSpheresAre(const MixingIndices& indices) {
    if (std::isnan(indices.segregation)) return "one kind only";
    return indices.speciesAtCore ? "spheres at the core" : "spheres at the periphery";
}

double surfaceAngle(const ParticleStore& p, double binWidth, double centralFraction) {
    std::vector<std::array<double, 2>> mobile;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!p.fixed[i]) mobile.push_back({p.position[i].x(), p.position[i].z()});
    return surfaceAngle(mobile, binWidth, centralFraction);
}

double surfaceAngle(std::span<const std::array<double, 2>> centres, double binWidth, double centralFraction) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& [x, z] : centres) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
    if (!(hi > lo)) return NAN;
    const double middle = 0.5 * (lo + hi), half = 0.5 * centralFraction * (hi - lo);
    const int bins = std::max(1, static_cast<int>(std::ceil(2 * half / binWidth)));
    const double width = 2 * half / bins;
    std::vector<double> top(static_cast<std::size_t>(bins), -std::numeric_limits<double>::infinity());
    std::vector<double> topX(top.size(), 0.0);
    for (const auto& [x, z] : centres) {
        const double u = (x - (middle - half)) / width;
        if (u < 0 || u >= bins) continue;
        const std::size_t b = static_cast<std::size_t>(u);
        if (z > top[b]) top[b] = z, topX[b] = x;
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

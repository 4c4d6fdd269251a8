#include "Contacts/HGrid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "Error.h"

namespace talus {

HGrid::HGrid(double cellSizeRatio) : cellSizeRatio_(cellSizeRatio) {
    require(cellSizeRatio > 1, "HGrid cell size ratio must be greater than 1, got " + std::to_string(cellSizeRatio));
}

void HGrid::buildLevels(const ParticleStore& particles, const Domain& domain, double skin) {
    double minDiameter = INFINITY, maxDiameter = 0;
    for (double r : particles.radius) {
        minDiameter = std::min(minDiameter, 2 * r + skin);
        maxDiameter = std::max(maxDiameter, 2 * r + skin);
    }
    levels_.clear();
    for (double size = minDiameter;; size *= cellSizeRatio_) {
        Level level;
        level.size = std::min(size, maxDiameter);
        if (size * (1 + 1e-12) >= maxDiameter) level.size = maxDiameter;
        for (int a = 0; a < 3; ++a) {
            level.count[a] = 0;
            level.cell[a] = level.size;
            if (!domain.periodic[a]) continue;
            const double L = domain.length(a);
            // SPEC.md 1 pairs use the nearest image, which is unique only if no pair spans half the box.
            require(L >= 2 * maxDiameter, "periodic length along " + std::string(1, "xyz"[a]) + " (" +
                                              std::to_string(L) + ") must be at least twice the largest interaction "
                                              "diameter 2r + skin (" + std::to_string(maxDiameter) + ")");
            level.count[a] = std::max(1, static_cast<int>(std::floor(L / level.size)));
            level.cell[a] = L / level.count[a];
        }
        levels_.push_back(level);
        if (level.size >= maxDiameter) break;
    }
    levelOf_.resize(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const double diameter = 2 * particles.radius[i] + skin;
        std::uint32_t l = 0;
        while (levels_[l].size < diameter && l + 1 < levels_.size()) ++l;
        levelOf_[i] = l;
        ++levels_[l].particles;
    }
}

std::array<int, 3> HGrid::cellOf(const Vec3& x, const Level& level, const Domain& domain) const {
    std::array<int, 3> c;
    for (int a = 0; a < 3; ++a) {
        const double u = (x[a] - domain.lo[a]) / level.cell[a];
        c[a] = static_cast<int>(std::floor(u));
        if (level.count[a] > 0) c[a] = std::clamp(c[a], 0, level.count[a] - 1);
    }
    return c;
}

std::size_t HGrid::bucketOf(std::uint32_t level, int cx, int cy, int cz) const {
    // Multiplicative hash of the four integers (large odd constants, as in Teschner et al. 2003).
    std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(cx)) * 73856093ull;
    h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(cy)) * 19349663ull;
    h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(cz)) * 83492791ull;
    h ^= static_cast<std::uint64_t>(level) * 2654435761ull;
    h ^= h >> 29;
    return static_cast<std::size_t>(h) & bucketMask_;
}

void HGrid::findPairs(const ParticleStore& particles, const Domain& domain, double skin,
                      std::vector<ParticlePair>& pairs) {
    const std::size_t n = particles.size();
    if (n == 0) return;
    buildLevels(particles, domain, skin);

    // Counting sort of the particles into hash buckets (2 to 4 buckets per particle).
    std::size_t buckets = 1;
    while (buckets < 2 * n) buckets <<= 1;
    bucketMask_ = buckets - 1;
    bucketStart_.assign(buckets + 1, 0);
    std::vector<std::array<int, 3>> cells(n);
    std::vector<std::uint32_t> bucket(n);
    for (std::size_t i = 0; i < n; ++i) {
        cells[i] = cellOf(particles.position[i], levels_[levelOf_[i]], domain);
        bucket[i] = static_cast<std::uint32_t>(bucketOf(levelOf_[i], cells[i][0], cells[i][1], cells[i][2]));
        ++bucketStart_[bucket[i] + 1];
    }
    for (std::size_t b = 0; b < buckets; ++b) bucketStart_[b + 1] += bucketStart_[b];
    entries_.resize(n);
    {
        std::vector<std::uint32_t> fill(bucketStart_.begin(), bucketStart_.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
            entries_[fill[bucket[i]]++] = {static_cast<std::uint32_t>(i), cells[i][0], cells[i][1], cells[i][2], levelOf_[i]};
    }

    const PeriodicImage image(domain);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& xi = particles.position[i];
        const double di = 2 * particles.radius[i] + skin;
        const bool fixedI = particles.fixed[i];
        for (std::uint32_t l = levelOf_[i]; l < levels_.size(); ++l) {
            const Level& level = levels_[l];
            if (level.particles == 0) continue;
            // A partner at this level has diameter <= level.size, so its centre is within
            // (di + level.size)/2 of xi along each axis: at most three cells per axis.
            const double reach = 0.5 * (di + level.size);
            std::array<std::array<int, 3>, 3> range;  // per axis: up to 3 distinct (wrapped) cells
            std::array<int, 3> rangeSize;
            for (int a = 0; a < 3; ++a) {
                const int first = static_cast<int>(std::floor((xi[a] - reach - domain.lo[a]) / level.cell[a]));
                const int last = static_cast<int>(std::floor((xi[a] + reach - domain.lo[a]) / level.cell[a]));
                rangeSize[a] = 0;
                for (int c = first; c <= last && rangeSize[a] < 3; ++c) {
                    int wrapped = c;
                    if (level.count[a] > 0) {
                        wrapped = ((c % level.count[a]) + level.count[a]) % level.count[a];
                        if (std::find(range[a].begin(), range[a].begin() + rangeSize[a], wrapped) !=
                            range[a].begin() + rangeSize[a])
                            continue;
                    }
                    range[a][rangeSize[a]++] = wrapped;
                }
            }
            for (int ix = 0; ix < rangeSize[0]; ++ix)
                for (int iy = 0; iy < rangeSize[1]; ++iy)
                    for (int iz = 0; iz < rangeSize[2]; ++iz) {
                        const int cx = range[0][ix], cy = range[1][iy], cz = range[2][iz];
                        const std::size_t b = bucketOf(l, cx, cy, cz);
                        for (std::uint32_t e = bucketStart_[b]; e < bucketStart_[b + 1]; ++e) {
                            const Entry& entry = entries_[e];
                            if (entry.level != l || entry.cx != cx || entry.cy != cy || entry.cz != cz) continue;
                            const std::uint32_t j = entry.particle;
                            if (l == levelOf_[i] && j <= i) continue;
                            if (fixedI && particles.fixed[j]) continue;
                            if (withinListReach(image.nearest(xi - particles.position[j]), particles.radius[i],
                                                particles.radius[j], skin))
                                pairs.push_back({static_cast<std::uint32_t>(i), j});
                        }
                    }
        }
    }
}

}  // namespace talus

#include "Contacts/HGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "Error.h"

namespace talus {

HGrid::HGrid(double cellSizeRatio) : cellSizeRatio_(cellSizeRatio) {
    require(cellSizeRatio > 1, "HGrid cell size ratio must be greater than 1, got " + str(cellSizeRatio));
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
            // Theory/ContactLaws.md eq. (1)-(3) pairs use the nearest image, which is unique only
            // if no pair spans half the box.
            require(L >= 2 * maxDiameter, "periodic length along " + std::string(1, "xyz"[a]) + " (" +
                                              str(L) + ") must be at least twice the largest interaction "
                                              "diameter 2r + skin (" + str(maxDiameter) + ")");
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

std::size_t HGrid::denseLevelCount() const {
    return static_cast<std::size_t>(std::count_if(levels_.begin(), levels_.end(), [](const Level& l) { return l.dense; }));
}

void HGrid::placeDenseLevels(const std::vector<std::array<int, 3>>& cells) {
    // The box of each level's cells: every cell along a periodic axis, the particles' span along
    // an open one.
    std::vector<std::array<int, 3>> lo(levels_.size(), {INT32_MAX, INT32_MAX, INT32_MAX});
    std::vector<std::array<int, 3>> hi(levels_.size(), {INT32_MIN, INT32_MIN, INT32_MIN});
    for (std::size_t i = 0; i < cells.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            lo[levelOf_[i]][a] = std::min(lo[levelOf_[i]][a], cells[i][a]);
            hi[levelOf_[i]][a] = std::max(hi[levelOf_[i]][a], cells[i][a]);
        }
    std::size_t cellCount = 0;
    for (std::size_t l = 0; l < levels_.size(); ++l) {
        Level& level = levels_[l];
        level.dense = false;
        if (level.particles == 0) continue;
        double boxCells = 1;  // in double: a particle far off must not overflow the product
        for (int a = 0; a < 3; ++a) {
            if (level.count[a] > 0) {
                level.first[a] = 0;
                level.extent[a] = level.count[a];
            } else {
                level.first[a] = lo[l][a];
                level.extent[a] = static_cast<int>(std::min<std::int64_t>(
                    std::int64_t{hi[l][a]} - lo[l][a] + 1, INT32_MAX));
            }
            boxCells *= level.extent[a];
        }
        if (denseCellsPerParticle <= 0 || boxCells > denseCellsPerParticle * static_cast<double>(level.particles) + 512)
            continue;
        level.dense = true;
        level.cellBase = cellCount;
        cellCount += static_cast<std::size_t>(boxCells);
    }
    cellStart_.assign(cellCount + 1, 0);
}

namespace {

// Stable counting sort of the particles i with key[i] != skip into the ranges
// [start[k], start[k + 1]) of their keys (start: keys + 1 entries, zero on entry): place(slot, i)
// puts particle i at its slot, the slots of one key in ascending i.
template <class Place>
void countingSort(const std::vector<std::uint32_t>& key, std::uint32_t skip, std::vector<std::uint32_t>& start,
                  Place place) {
    for (std::uint32_t k : key)
        if (k != skip) ++start[k + 1];
    for (std::size_t k = 0; k + 1 < start.size(); ++k) start[k + 1] += start[k];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < key.size(); ++i)
        if (key[i] != skip) place(fill[key[i]]++, static_cast<std::uint32_t>(i));
}

constexpr std::uint32_t otherKind = UINT32_MAX;  // a particle of a level of the other kind

}  // namespace

void HGrid::fillDenseCells(const std::vector<std::array<int, 3>>& cells) {
    std::vector<std::uint32_t> cell(cells.size(), otherKind);
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (const Level& level = levels_[levelOf_[i]]; level.dense)
            cell[i] = static_cast<std::uint32_t>(denseCellOf(level, cells[i][0], cells[i][1], cells[i][2]));
    cellEntries_.resize(cells.size());
    countingSort(cell, otherKind, cellStart_, [&](std::uint32_t slot, std::uint32_t i) { cellEntries_[slot] = i; });
    cellEntries_.resize(cellStart_.back());
}

void HGrid::fillBuckets(const std::vector<std::array<int, 3>>& cells) {
    // Hash buckets for the hashed levels' particles (2 to 4 buckets per particle).
    std::size_t hashed = 0;
    for (const Level& level : levels_)
        if (!level.dense) hashed += level.particles;
    std::size_t buckets = 1;
    while (buckets < 2 * hashed) buckets <<= 1;
    bucketMask_ = buckets - 1;
    bucketStart_.assign(buckets + 1, 0);
    std::vector<std::uint32_t> bucket(cells.size(), otherKind);
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (!levels_[levelOf_[i]].dense)
            bucket[i] = static_cast<std::uint32_t>(bucketOf(levelOf_[i], cells[i][0], cells[i][1], cells[i][2]));
    entries_.resize(cells.size());
    countingSort(bucket, otherKind, bucketStart_, [&](std::uint32_t slot, std::uint32_t i) {
        entries_[slot] = {i, cells[i][0], cells[i][1], cells[i][2], levelOf_[i]};
    });
    entries_.resize(bucketStart_.back());
}

void HGrid::findPairs(const ParticleStore& particles, const Domain& domain, double skin,
                      std::vector<ParticlePair>& pairs) {
    const std::size_t n = particles.size();
    if (n == 0) return;
    buildLevels(particles, domain, skin);
    std::vector<std::array<int, 3>> cells(n);
    for (std::size_t i = 0; i < n; ++i) cells[i] = cellOf(particles.position[i], levels_[levelOf_[i]], domain);
    placeDenseLevels(cells);
    fillDenseCells(cells);
    fillBuckets(cells);

    const PeriodicImage image(domain);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& xi = particles.position[i];
        const double ri = particles.radius[i];
        const double di = 2 * ri + skin;
        const bool fixedI = particles.fixed[i];
        // Each pair of one level once, as (i, j) with the partner j before i in the particle
        // order: the force loop goes through the list in the order of i, so a partner's data was
        // read shortly before, for its own pairs, and is still in the caches (with j after i it
        // is not yet: at 10^6 particles the step took 4.5-6.5% longer;
        // Documentation/Performance.md).
        auto consider = [&](std::uint32_t j, bool ownLevel) {
            if (ownLevel && j >= i) return;
            if (fixedI && particles.fixed[j]) return;
            if (withinListReach(image.nearest(xi - particles.position[j]), ri, particles.radius[j], skin))
                pairs.push_back({static_cast<std::uint32_t>(i), j});
        };
        for (std::uint32_t l = levelOf_[i]; l < levels_.size(); ++l) {
            const Level& level = levels_[l];
            if (level.particles == 0) continue;
            const bool ownLevel = l == levelOf_[i];
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
                    } else if (level.dense && (c < level.first[a] || c >= level.first[a] + level.extent[a])) {
                        continue;  // outside the box of cells: empty
                    }
                    range[a][rangeSize[a]++] = wrapped;
                }
            }
            if (level.dense) {
                // The cells along z of one (cx, cy) lie next to each other in cellStart_: each run
                // of consecutive cz is one range of particles, in the order cell by cell.
                for (int ix = 0; ix < rangeSize[0]; ++ix)
                    for (int iy = 0; iy < rangeSize[1]; ++iy)
                        for (int iz = 0; iz < rangeSize[2];) {
                            int run = 1;
                            while (iz + run < rangeSize[2] && range[2][iz + run] == range[2][iz] + run) ++run;
                            const std::size_t c = denseCellOf(level, range[0][ix], range[1][iy], range[2][iz]);
                            for (std::uint32_t e = cellStart_[c]; e < cellStart_[c + run]; ++e)
                                consider(cellEntries_[e], ownLevel);
                            iz += run;
                        }
                continue;
            }
            for (int ix = 0; ix < rangeSize[0]; ++ix)
                for (int iy = 0; iy < rangeSize[1]; ++iy)
                    for (int iz = 0; iz < rangeSize[2]; ++iz) {
                        const int cx = range[0][ix], cy = range[1][iy], cz = range[2][iz];
                        const std::size_t b = bucketOf(l, cx, cy, cz);
                        for (std::uint32_t e = bucketStart_[b]; e < bucketStart_[b + 1]; ++e) {
                            const Entry& entry = entries_[e];
                            if (entry.level != l || entry.cx != cx || entry.cy != cy || entry.cz != cz) continue;
                            consider(entry.particle, ownLevel);
                        }
                    }
        }
    }
}

}  // namespace talus

// Hierarchical grid neighbour search (Ogarko & Luding 2012, as in MercuryDPM), for packings of
// any size ratio.
//
// Each particle lives in the level whose cell size is the smallest one not below its interaction
// diameter D = 2r + skin; cell sizes grow by cellSizeRatio from level to level. A particle looks
// for partners in its own level (only partners with a higher slot, so each pair is found once)
// and in every coarser, non-empty level, in the at most 3x3x3 cells that can hold a partner.
// The cells of periodic axes wrap around. A level whose particles' cells span a box of at most
// denseCellsPerParticle cells per particle (a packing, a chute) keeps its cells in an array over
// that box: a cell's particles are one range, the cells along z next to each other one range
// too. A sparser level (a few particles spread wide, a particle flying off) hashes its cells, so
// memory stays O(N) whatever the extent of the packing. Both give the same pairs in the same
// order. The cost per particle is bounded by the number of non-empty levels, not by the size
// ratio: a 1:20 packing does not degrade to O(N^2).
#pragma once

#include <cstdint>
#include <vector>

#include "Boundaries/Domain.h"
#include "Particles/ParticleStore.h"

namespace talus {

struct ParticlePair {
    std::uint32_t i, j;
    bool operator==(const ParticlePair&) const = default;
};

// The listing rule: two particles whose separation d (nearest image) is below ri + rj + reach.
inline bool withinListReach(const Vec3& d, double ri, double rj, double reach) {
    const double limit = ri + rj + reach;
    return d.squaredNorm() < limit * limit;
}

class HGrid {
public:
    explicit HGrid(double cellSizeRatio = 2.0);

    // Appends to pairs every pair (i, j) closer than ri + rj + skin (nearest periodic image),
    // except pairs of two fixed particles, in an order that depends only on the positions:
    // grouped by i in ascending order, a pair of two particles of one level with j < i (the
    // force loop finds the partner's data in the caches, HGrid.cc).
    void findPairs(const ParticleStore& particles, const Domain& domain, double skin,
                   std::vector<ParticlePair>& pairs);

    std::size_t levelCount() const { return levels_.size(); }
    double cellSizeRatio() const { return cellSizeRatio_; }
    // Levels that kept their cells in an array at the last findPairs (the rest hashed them).
    std::size_t denseLevelCount() const;

    // A level is kept dense while its box of cells has at most this many cells per particle of
    // the level (plus a few hundred); 4 bytes a cell. 0 hashes every level.
    double denseCellsPerParticle = 16;

private:
    struct Level {
        double size;        // nominal cell size (>= the interaction diameters it holds)
        Vec3 cell;          // actual cell size per axis (stretched to divide periodic lengths)
        std::array<int, 3> count;  // cells along periodic axes; 0 along open axes
        std::size_t particles = 0;
        // Dense levels: the box of cells [first, first + extent) that holds the level's
        // particles, cell (cx, cy, cz) at cellBase + ((cx - first.x) extent.y + cy - first.y)
        // extent.z + cz - first.z of cellStart_.
        bool dense = false;
        std::array<int, 3> first{}, extent{};
        std::size_t cellBase = 0;
    };
    struct Entry {
        std::uint32_t particle;
        std::int32_t cx, cy, cz;
        std::uint32_t level;
    };

    void buildLevels(const ParticleStore& particles, const Domain& domain, double skin);
    std::array<int, 3> cellOf(const Vec3& x, const Level& level, const Domain& domain) const;
    std::size_t bucketOf(std::uint32_t level, int cx, int cy, int cz) const;

    double cellSizeRatio_;
    std::vector<Level> levels_;
    std::vector<std::uint32_t> levelOf_;   // per particle
    void placeDenseLevels(const std::vector<std::array<int, 3>>& cells);
    void fillDenseCells(const std::vector<std::array<int, 3>>& cells);
    void fillBuckets(const std::vector<std::array<int, 3>>& cells);
    std::size_t denseCellOf(const Level& level, int cx, int cy, int cz) const {
        return level.cellBase +
               (static_cast<std::size_t>(cx - level.first[0]) * level.extent[1] + (cy - level.first[1])) * level.extent[2] +
               (cz - level.first[2]);
    }

    std::vector<std::uint32_t> cellStart_;    // dense levels: size (their cells) + 1
    std::vector<std::uint32_t> cellEntries_;  // dense levels' particles sorted by cell, then slot
    std::vector<std::uint32_t> bucketStart_;  // hashed levels: size buckets + 1
    std::vector<Entry> entries_;           // hashed levels' particles sorted by bucket, then slot
    std::size_t bucketMask_ = 0;
};

}  // namespace talus

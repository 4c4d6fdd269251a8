// A cell list over the supports of the sources (particles, or contact segments) of a frame:
// each source is entered in every cell its support box overlaps, so the sources that can
// contribute at a point are exactly those listed in the point's cell. The cost of a field
// evaluation is then O(points x sources in range), not O(points x sources).
//
// The cells depend only on the sources, never on the evaluation points, so a point gets the
// same sources in the same order (and bitwise the same value) whether it is part of a grid or
// of a point list.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "IO/ParticleFrame.h"

namespace talus::cg {

class SupportBins {
public:
    // `boxLo[i]`, `boxHi[i]`: support box of source i (only the axes flagged in `binAxes` are
    // used); `cellSize[k]` the wanted cell size per axis (typically the support diameter).
    void build(const std::vector<Vec3>& boxLo, const std::vector<Vec3>& boxHi,
               const std::array<bool, 3>& binAxes, Vec3 cellSize);

    // The sources whose support box contains the cell of `point` (empty outside all boxes).
    struct Range {
        const std::uint32_t* begin;
        const std::uint32_t* end;
    };
    Range sourcesNear(const Vec3& point) const;

private:
    long cellIndex(const std::array<long, 3>& cell) const;

    std::array<bool, 3> binAxes_{false, false, false};
    Vec3 lo_{0, 0, 0};
    Vec3 inverseCellSize_{0, 0, 0};
    std::array<long, 3> cells_{1, 1, 1};
    std::vector<std::uint32_t> offsets_;  // CSR: sources of cell c are entries [offsets_[c], offsets_[c+1])
    std::vector<std::uint32_t> entries_;
};

}  // namespace talus::cg

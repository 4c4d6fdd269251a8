#include "Fields/SupportBins.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace talus::cg {

void SupportBins::build(const std::vector<Vec3>& boxLo, const std::vector<Vec3>& boxHi,
                        const std::array<bool, 3>& binAxes, Vec3 cellSize) {
    binAxes_ = binAxes;
    cells_ = {1, 1, 1};
    lo_ = {0, 0, 0};
    inverseCellSize_ = {0, 0, 0};
    const std::size_t n = boxLo.size();
    offsets_.assign(2, 0);
    entries_.clear();
    if (n == 0) return;
    Vec3 hi{};
    for (int k = 0; k < 3; ++k) {
        if (!binAxes[k]) continue;
        lo_[k] = std::numeric_limits<double>::max();
        hi[k] = std::numeric_limits<double>::lowest();
        for (std::size_t i = 0; i < n; ++i) {
            lo_[k] = std::min(lo_[k], boxLo[i][k]);
            hi[k] = std::max(hi[k], boxHi[i][k]);
        }
    }
    // Cells of the wanted size, but never more than about 8 cells per source in total (a few
    // sources spread over a large domain would otherwise make a mostly empty, huge table).
    const double maxCells = 8.0 * double(n) + 64.0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        double total = 1;
        for (int k = 0; k < 3; ++k) {
            if (!binAxes[k]) continue;
            const double extent = std::max(hi[k] - lo_[k], 1e-300);
            cells_[k] = std::max<long>(1, static_cast<long>(std::ceil(extent / cellSize[k])));
            total *= double(cells_[k]);
        }
        if (total <= maxCells) break;
        for (double& s : cellSize) s *= 1.5;
    }
    for (int k = 0; k < 3; ++k) {
        if (binAxes[k]) inverseCellSize_[k] = double(cells_[k]) / std::max(hi[k] - lo_[k], 1e-300);
    }
    const long totalCells = cells_[0] * cells_[1] * cells_[2];
    // Cell ranges of each box, counted first, then filled (CSR).
    auto cellRange = [&](const Vec3& a, const Vec3& b, std::array<long, 3>& first, std::array<long, 3>& last) {
        for (int k = 0; k < 3; ++k) {
            if (!binAxes[k]) {
                first[k] = last[k] = 0;
                continue;
            }
            first[k] = std::clamp<long>(static_cast<long>(std::floor((a[k] - lo_[k]) * inverseCellSize_[k])), 0, cells_[k] - 1);
            last[k] = std::clamp<long>(static_cast<long>(std::floor((b[k] - lo_[k]) * inverseCellSize_[k])), 0, cells_[k] - 1);
        }
    };
    offsets_.assign(totalCells + 1, 0);
    std::array<long, 3> first{}, last{};
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<std::uint32_t> fill;
        if (pass == 1) {
            for (long c = 0; c < totalCells; ++c) offsets_[c + 1] += offsets_[c];
            entries_.resize(offsets_[totalCells]);
            fill.assign(offsets_.begin(), offsets_.end() - 1);
        }
        for (std::size_t i = 0; i < n; ++i) {
            cellRange(boxLo[i], boxHi[i], first, last);
            for (long cx = first[0]; cx <= last[0]; ++cx) {
                for (long cy = first[1]; cy <= last[1]; ++cy) {
                    for (long cz = first[2]; cz <= last[2]; ++cz) {
                        const long c = cellIndex({cx, cy, cz});
                        if (pass == 0) ++offsets_[c + 1];
                        else entries_[fill[c]++] = static_cast<std::uint32_t>(i);
                    }
                }
            }
        }
    }
}

long SupportBins::cellIndex(const std::array<long, 3>& cell) const {
    return (cell[0] * cells_[1] + cell[1]) * cells_[2] + cell[2];
}

SupportBins::Range SupportBins::sourcesNear(const Vec3& point) const {
    std::array<long, 3> cell{0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        if (!binAxes_[k]) continue;
        const double f = std::floor((point[k] - lo_[k]) * inverseCellSize_[k]);
        if (!(f >= 0) || f >= double(cells_[k])) {
            // Beyond the last cell: only the edge of the last cell itself (a point exactly on
            // the upper end of the boxes) belongs to it.
            if (f == double(cells_[k]) && point[k] <= lo_[k] + double(cells_[k]) / inverseCellSize_[k]) {
                cell[k] = cells_[k] - 1;
                continue;
            }
            return {nullptr, nullptr};
        }
        cell[k] = static_cast<long>(f);
    }
    const long c = cellIndex(cell);
    if (entries_.empty()) return {nullptr, nullptr};
    return {entries_.data() + offsets_[c], entries_.data() + offsets_[c + 1]};
}

}  // namespace talus::cg

#include "Walls/TriangleGrid.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "Error.h"

namespace talus {

TriangleGrid::TriangleGrid(const TriangleMesh& mesh, double cellSize) : cellSize_(cellSize), origin_(mesh.lo()) {
    require(std::isfinite(cellSize) && cellSize > 0,
            "TriangleGrid: the cell size must be positive, got " + str(cellSize));
    for (int a = 0; a < 3; ++a) {
        const double cells = std::floor((mesh.hi()[a] - origin_[a]) / cellSize) + 1;
        require(cells <= double(maxCellsPerAxis), "TriangleGrid: the cell size " + str(cellSize) + " is too small for " +
                                                      mesh.source().name + " (" + str(cells) + " cells along " +
                                                      "xyz"[a] + ", at most " + std::to_string(maxCellsPerAxis) + ")");
        cells_[a] = static_cast<std::int64_t>(cells);
    }
    const std::size_t triangles = mesh.triangleCount();
    lo_.resize(triangles);
    hi_.resize(triangles);
    std::size_t entries = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
        lo_[t] = mesh.corner(t, 0).cwiseMin(mesh.corner(t, 1)).cwiseMin(mesh.corner(t, 2));
        hi_[t] = mesh.corner(t, 0).cwiseMax(mesh.corner(t, 1)).cwiseMax(mesh.corner(t, 2));
        const auto from = cellOf(lo_[t]), to = cellOf(hi_[t]);
        // (Counted in double: three axes of up to 2^21 cells overflow 64-bit integers.)
        const double cells = double(to[0] - from[0] + 1) * double(to[1] - from[1] + 1) * double(to[2] - from[2] + 1);
        if (cells <= double(maxEntries)) entries += static_cast<std::size_t>(cells);
        require(cells <= double(maxEntries) && entries <= maxEntries, "TriangleGrid: the cell size " + str(cellSize) + " is too small for " +
                                           mesh.source().name + " (more than " + std::to_string(maxEntries) +
                                           " cell entries of its triangles)");
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyTriangle;
    keyTriangle.reserve(entries);
    for (std::size_t t = 0; t < triangles; ++t) {
        const auto from = cellOf(lo_[t]), to = cellOf(hi_[t]);
        for (std::int64_t k = from[2]; k <= to[2]; ++k)
            for (std::int64_t j = from[1]; j <= to[1]; ++j)
                for (std::int64_t i = from[0]; i <= to[0]; ++i)
                    keyTriangle.emplace_back(key(i, j, k), static_cast<std::uint32_t>(t));
    }
    std::sort(keyTriangle.begin(), keyTriangle.end());
    cellTriangles_.reserve(keyTriangle.size());
    for (const auto& [cell, t] : keyTriangle) {
        if (occupiedKeys_.empty() || occupiedKeys_.back() != cell) {
            occupiedKeys_.push_back(cell);
            cellStart_.push_back(cellTriangles_.size());
        }
        cellTriangles_.push_back(t);
    }
    cellStart_.push_back(cellTriangles_.size());
    // (Counted in double as above; a moving mesh's grid is made at every list build, so a table
    // far larger than the occupied cells would cost more to fill than its lookups save.)
    const double allCells = double(cells_[0]) * double(cells_[1]) * double(cells_[2]);
    if (allCells <= double(maxDenseCells) && allCells <= 64 * double(occupiedKeys_.size()) + 4096) {
        denseCells_.assign(static_cast<std::size_t>(allCells), 0);
        for (std::size_t q = 0; q < occupiedKeys_.size(); ++q) denseCells_[occupiedKeys_[q]] = static_cast<std::uint32_t>(q + 1);
    }
}

std::size_t TriangleGrid::occupiedPlace(std::int64_t i, std::int64_t j, std::int64_t k) const {
    const std::uint64_t cell = key(i, j, k);
    if (!denseCells_.empty()) return denseCells_[cell] > 0 ? denseCells_[cell] - 1 : occupiedKeys_.size();
    const auto it = std::lower_bound(occupiedKeys_.begin(), occupiedKeys_.end(), cell);
    return it != occupiedKeys_.end() && *it == cell ? static_cast<std::size_t>(it - occupiedKeys_.begin())
                                                    : occupiedKeys_.size();
}

std::array<std::int64_t, 3> TriangleGrid::cellOf(const Vec3& x) const {
    std::array<std::int64_t, 3> cell;
    for (int a = 0; a < 3; ++a) {
        // (floor is monotone: a box that holds a point lies in cells that hold the point's cell.)
        const double q = std::floor((x[a] - origin_[a]) / cellSize_);
        cell[a] = static_cast<std::int64_t>(std::clamp(q, -1.0, double(cells_[a])));
    }
    return cell;
}

std::uint64_t TriangleGrid::key(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return static_cast<std::uint64_t>(i + cells_[0] * (j + cells_[1] * k));
}

std::vector<std::uint32_t> TriangleGrid::trianglesNear(const Vec3& centre, double radius) const {
    std::vector<std::uint32_t> found;
    trianglesNear(centre, radius, found);
    return found;
}

void TriangleGrid::trianglesNear(const Vec3& centre, double radius, std::vector<std::uint32_t>& found) const {
    found.clear();
    // (The message only when it is thrown: the build asks once per particle near a mesh, and
    // formatting it every time was 2.7% of a drum's time.)
    if (!(isFinite(centre) && std::isfinite(radius) && radius >= 0)) [[unlikely]]
        throw Error("TriangleGrid: a query needs a finite centre and radius, got radius " + str(radius));
    const Vec3 lo = centre.array() - radius, hi = centre.array() + radius;
    auto from = cellOf(lo), to = cellOf(hi);
    for (int a = 0; a < 3; ++a) {
        from[a] = std::max<std::int64_t>(from[a], 0);
        to[a] = std::min(to[a], cells_[a] - 1);
        if (from[a] > to[a]) return;
    }
    auto takeCell = [&](std::size_t q) {
        for (std::size_t e = cellStart_[q]; e < cellStart_[q + 1]; ++e) {
            const std::uint32_t t = cellTriangles_[e];
            if ((lo_[t].array() <= hi.array()).all() && (lo.array() <= hi_[t].array()).all()) found.push_back(t);
        }
    };
    const double cellsInBox =
        double(to[0] - from[0] + 1) * double(to[1] - from[1] + 1) * double(to[2] - from[2] + 1);
    if (cellsInBox > double(occupiedKeys_.size())) {
        // A box larger than the mesh's occupied cells (a large sphere, fine cells): walk those.
        for (std::size_t q = 0; q < occupiedKeys_.size(); ++q) {
            const std::int64_t cell = static_cast<std::int64_t>(occupiedKeys_[q]);
            const std::array<std::int64_t, 3> c{cell % cells_[0], cell / cells_[0] % cells_[1],
                                                cell / cells_[0] / cells_[1]};
            bool inBox = true;
            for (int a = 0; a < 3; ++a) inBox = inBox && from[a] <= c[a] && c[a] <= to[a];
            if (inBox) takeCell(q);
        }
    } else {
        for (std::int64_t k = from[2]; k <= to[2]; ++k)
            for (std::int64_t j = from[1]; j <= to[1]; ++j)
                for (std::int64_t i = from[0]; i <= to[0]; ++i)
                    if (const std::size_t q = occupiedPlace(i, j, k); q < occupiedKeys_.size()) takeCell(q);
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
}

}  // namespace talus

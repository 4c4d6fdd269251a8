// A uniform grid over a triangle mesh, to find the triangles a sphere may touch: each triangle is
// listed in every cell its bounding box overlaps, and a query takes the triangles listed in the
// cells the sphere's bounding box overlaps, keeping those whose bounding box overlaps the sphere's
// (each once, in increasing order). Only occupied cells are stored (a mesh is a surface: most
// cells of its box are empty). The grid holds the mesh where it was when the grid was built: a
// mesh that moves needs a new grid (or one built over the region it sweeps).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "Walls/TriangleMesh.h"

namespace talus {

class TriangleGrid {
public:
    // At most this many cells along an axis and this many (cell, triangle) entries in all: a cell
    // size far below the triangles' size is an error rather than a grid that fills the memory.
    static constexpr std::int64_t maxCellsPerAxis = std::int64_t{1} << 21;
    static constexpr std::size_t maxEntries = std::size_t{1} << 27;

    TriangleGrid(const TriangleMesh& mesh, double cellSize);

    // The triangles whose bounding boxes overlap the box [centre - radius, centre + radius].
    std::vector<std::uint32_t> trianglesNear(const Vec3& centre, double radius) const;
    // The same into `found` (cleared first): a vector kept from query to query keeps its memory.
    void trianglesNear(const Vec3& centre, double radius, std::vector<std::uint32_t>& found) const;

    double cellSize() const { return cellSize_; }

private:
    // The cell indices of x along each axis, clamped to [-1, cells] (outside the grid: -1 or cells).
    std::array<std::int64_t, 3> cellOf(const Vec3& x) const;
    std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) const;

    double cellSize_;
    Vec3 origin_;
    std::array<std::int64_t, 3> cells_;
    std::vector<Vec3> lo_, hi_;  // the triangles' bounding boxes
    // The occupied cells in increasing key; the triangles of occupiedKeys_[q] are
    // cellTriangles_[cellStart_[q] .. cellStart_[q + 1]).
    std::vector<std::uint64_t> occupiedKeys_;
    std::vector<std::size_t> cellStart_;
    std::vector<std::uint32_t> cellTriangles_;
    // Where the grid has at most maxDenseCells cells (and not far more than it has occupied
    // ones), per cell its place among the occupied ones
    // plus 1 (0: empty), found at once where occupiedKeys_ needs a binary search (most particles a
    // build asks about are far from the mesh, in empty cells).
    static constexpr std::int64_t maxDenseCells = std::int64_t{1} << 22;
    std::vector<std::uint32_t> denseCells_;
    // The place of cell (i, j, k) among the occupied cells, or occupiedKeys_.size() if empty.
    std::size_t occupiedPlace(std::int64_t i, std::int64_t j, std::int64_t k) const;
};

}  // namespace talus

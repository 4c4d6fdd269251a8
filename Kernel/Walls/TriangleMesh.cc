#include "Walls/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "Error.h"

namespace talus {

namespace {

// (Appended piece by piece: GCC 12 warns, wrongly, of overlapping copies in "(" + str(...).)
std::string text(const Vec3& x) {
    std::string s = "(";
    s += str(x.x()), s += ", ", s += str(x.y()), s += ", ", s += str(x.z()), s += ")";
    return s;
}

// A cell of the grid that finds corners closer than the tolerance: cells as wide as the
// tolerance, so that such corners lie in the same or in neighbouring cells.
struct Cell {
    std::int64_t i, j, k;
    bool operator==(const Cell&) const = default;
};

struct CellHash {
    std::size_t operator()(const Cell& c) const {
        return std::hash<std::int64_t>()(c.i * 73856093 ^ c.j * 19349663 ^ c.k * 83492791);
    }
};

// Compressed lists: the items of key q are list[start[q] .. start[q + 1]), in the order given.
void compress(std::size_t keys, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& keyItem,
              std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& list) {
    start.assign(keys + 1, 0);
    for (const auto& [key, item] : keyItem) ++start[key + 1];
    for (std::size_t q = 0; q < keys; ++q) start[q + 1] += start[q];
    list.resize(keyItem.size());
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (const auto& [key, item] : keyItem) list[next[key]++] = item;
}

}  // namespace

std::string MeshSource::place(std::size_t triangle) const {
    return placeWord + " " + std::to_string(places.empty() ? static_cast<long>(triangle) + 1 : places[triangle]);
}

TriangleMesh::TriangleMesh(const std::vector<TriangleCorners>& triangles, MeshSource source, double tolerance)
    : source_(std::move(source)) {
    require(source_.places.empty() || source_.places.size() == triangles.size(),
            source_.name + ": " + std::to_string(source_.places.size()) + " places for " +
                std::to_string(triangles.size()) + " triangles");
    checkCorners(triangles);
    mergeVertices(triangles, tolerance);
    findEdges();
    listVertexTriangles();
    updateBoundsAndNormals();
}

std::span<const std::uint32_t> TriangleMesh::vertexTriangles(std::size_t v) const {
    return {vertexTriangleList_.data() + vertexStart_[v], vertexStart_[v + 1] - vertexStart_[v]};
}

std::span<const std::uint32_t> TriangleMesh::edgeTriangles(std::size_t e) const {
    return {edgeTriangleList_.data() + edgeStart_[e], edgeStart_[e + 1] - edgeStart_[e]};
}

void TriangleMesh::translate(const Vec3& shift) {
    require(isFinite(shift), source_.name + ": the shift " + text(shift) + " is not finite");
    moveVertices([&shift](const Vec3& x) { return Vec3(x + shift); });
}

void TriangleMesh::rotate(const Vec3& point, const Mat3& rotation) {
    require(isFinite(point) && rotation.allFinite(), source_.name + ": a rotation must be finite");
    moveVertices([&](const Vec3& x) { return Vec3(point + rotation * (x - point)); });
}

void TriangleMesh::rotate(const Vec3& point, const Vec3& axis, double angle) {
    require(isFinite(axis) && axis.norm() > 0 && std::isfinite(angle),
            source_.name + ": a rotation needs a finite angle and a nonzero axis, got " + text(axis));
    rotate(point, Mat3(Eigen::AngleAxisd(angle, axis.normalized())));
}

void TriangleMesh::fail(std::size_t t, const std::string& problem) const {
    throw Error(source_.name + " " + source_.place(t) + ": " + problem);
}

void TriangleMesh::checkCorners(const std::vector<TriangleCorners>& triangles) const {
    if (triangles.empty()) throw Error(source_.name + ": no triangles");
    // (Vertex indices are 32 bits; three per triangle.)
    if (triangles.size() > std::numeric_limits<std::uint32_t>::max() / 3)
        throw Error(source_.name + ": more than " + std::to_string(std::numeric_limits<std::uint32_t>::max() / 3) +
                    " triangles");
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const TriangleCorners& c = triangles[t];
        for (int k = 0; k < 3; ++k)
            if (!isFinite(c[k])) fail(t, "corner " + std::to_string(k + 1) + " " + text(c[k]) + " is not finite");
        // Twice the area over the longest edge squared is the height on the longest edge over
        // that edge: small for a needle and for a flat triangle alike, 0 for a point.
        const double twiceArea = (c[1] - c[0]).cross(c[2] - c[0]).norm();
        const double longest2 = std::max({(c[1] - c[0]).squaredNorm(), (c[2] - c[1]).squaredNorm(),
                                          (c[0] - c[2]).squaredNorm()});
        if (!(twiceArea > flatness * longest2))
            fail(t, "the triangle " + text(c[0]) + " " + text(c[1]) + " " + text(c[2]) +
                        " has (nearly) zero area: its corners are (nearly) on one line");
    }
}

void TriangleMesh::mergeVertices(const std::vector<TriangleCorners>& triangles, double tolerance) {
    Vec3 lo = triangles[0][0], hi = lo;
    for (const TriangleCorners& c : triangles)
        for (const Vec3& x : c) {
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
    tolerance_ = relativeTolerance * (hi - lo).norm();  // > 0: a triangle has a positive area
    if (tolerance != 0) {
        // (A rigid motion changes the bounding box's diagonal by less than a factor sqrt(3).)
        require(tolerance >= 0.5 * tolerance_ && tolerance <= 2 * tolerance_,
                source_.name + ": the merging tolerance " + str(tolerance) + " is not near " + str(tolerance_) +
                    ", the mesh's own (relativeTolerance times its bounding box's diagonal)");
        tolerance_ = tolerance;
    }
    auto cellOf = [&](const Vec3& x) {
        const Vec3 q = (x - lo) / tolerance_;  // below 1 / relativeTolerance: fits the integers
        return Cell{std::int64_t(std::floor(q.x())), std::int64_t(std::floor(q.y())), std::int64_t(std::floor(q.z()))};
    };
    std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> cells;
    auto vertexAt = [&](const Vec3& x) {
        const Cell c = cellOf(x);
        std::uint32_t found = std::numeric_limits<std::uint32_t>::max();
        for (std::int64_t di = -1; di <= 1; ++di)
            for (std::int64_t dj = -1; dj <= 1; ++dj)
                for (std::int64_t dk = -1; dk <= 1; ++dk) {
                    const auto it = cells.find(Cell{c.i + di, c.j + dj, c.k + dk});
                    if (it == cells.end()) continue;
                    for (const std::uint32_t v : it->second)
                        if ((vertices_[v] - x).norm() <= tolerance_) found = std::min(found, v);
                }
        if (found != std::numeric_limits<std::uint32_t>::max()) return found;
        vertices_.push_back(x);
        cells[c].push_back(static_cast<std::uint32_t>(vertices_.size() - 1));
        return static_cast<std::uint32_t>(vertices_.size() - 1);
    };
    // A triangle twice would be met twice by every sphere that touches it.
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> bySmallestVertex;
    triangles_.reserve(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        std::array<std::uint32_t, 3> v;
        for (int k = 0; k < 3; ++k) v[k] = vertexAt(triangles[t][k]);
        for (int k = 0; k < 3; ++k)
            if (v[k] == v[(k + 1) % 3])
                fail(t, "corners " + std::to_string(k + 1) + " and " + std::to_string((k + 1) % 3 + 1) +
                            " are closer than the mesh's tolerance " + str(tolerance_) + " (one vertex)");
        std::array<std::uint32_t, 3> sorted = v;
        std::sort(sorted.begin(), sorted.end());
        std::vector<std::uint32_t>& sameStart = bySmallestVertex[sorted[0]];
        for (const std::uint32_t other : sameStart) {
            std::array<std::uint32_t, 3> o = triangles_[other];
            std::sort(o.begin(), o.end());
            if (o == sorted) fail(t, "the triangle has the same corners as the one at " + source_.place(other));
        }
        sameStart.push_back(static_cast<std::uint32_t>(t));
        triangles_.push_back(v);
    }
}

void TriangleMesh::findEdges() {
    std::unordered_map<std::uint64_t, std::uint32_t> edgeOf;  // key: lower vertex << 32 | higher
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edgeTriangle;
    triangleEdges_.resize(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = triangles_[t][k], b = triangles_[t][(k + 1) % 3];
            const std::array<std::uint32_t, 2> ends{std::min(a, b), std::max(a, b)};
            const auto [it, added] =
                edgeOf.emplace(std::uint64_t(ends[0]) << 32 | ends[1], static_cast<std::uint32_t>(edges_.size()));
            if (added) edges_.push_back(ends);
            triangleEdges_[t][k] = it->second;
            edgeTriangle.emplace_back(it->second, static_cast<std::uint32_t>(t));
        }
    compress(edges_.size(), edgeTriangle, edgeStart_, edgeTriangleList_);
}

void TriangleMesh::listVertexTriangles() {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> vertexTriangle;
    for (std::size_t t = 0; t < triangles_.size(); ++t)
        for (const std::uint32_t v : triangles_[t]) vertexTriangle.emplace_back(v, static_cast<std::uint32_t>(t));
    compress(vertices_.size(), vertexTriangle, vertexStart_, vertexTriangleList_);
}

void TriangleMesh::updateBoundsAndNormals() {
    lo_ = hi_ = vertices_[0];
    for (const Vec3& x : vertices_) {
        lo_ = lo_.cwiseMin(x);
        hi_ = hi_.cwiseMax(x);
    }
    edgeDirections_.resize(edges_.size());
    edgeLengths_.resize(edges_.size());
    for (std::size_t e = 0; e < edges_.size(); ++e) {
        const Vec3 along = vertices_[edges_[e][1]] - vertices_[edges_[e][0]];
        edgeLengths_[e] = along.norm();
        edgeDirections_[e] = along / edgeLengths_[e];
    }
    normals_.resize(triangles_.size());
    inwardEdgeNormals_.resize(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
        normals_[t] = (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0)).normalized();
        for (int k = 0; k < 3; ++k) {  // (the normal across the edge from corner k to k + 1: to its left)
            const std::uint32_t e = triangleEdges_[t][k];
            const double sign = edges_[e][0] == triangles_[t][k] ? 1 : -1;
            inwardEdgeNormals_[t][k] = sign * normals_[t].cross(edgeDirections_[e]);
        }
    }
}

}  // namespace talus

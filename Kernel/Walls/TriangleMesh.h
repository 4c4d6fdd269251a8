// A wall made of triangles (the silo, drum and box of the 2024 open-source DEM benchmark), as the
// contact search needs it (Walls/MeshContact.h): corners that coincide merged into one vertex, so
// that triangles sharing an edge or a vertex know it; per triangle its three vertices and its unit
// normal (right-hand rule over the vertex order); the unique edges with the triangles that share
// them; each vertex's triangles. A sphere meets a mesh at a face, an edge or a vertex, and these
// lists tell which triangles must agree before an edge or a vertex contact counts.
//
// The constructor checks every triangle: finite corners, an area that is not (nearly) zero, three
// distinct vertices after merging, no triangle twice. A problem is a talus::Error naming the source
// and the triangle's place in it ("ASCII STL file floor.stl line 12: ...").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "Math/Vector.h"

namespace talus {

using TriangleCorners = std::array<Vec3, 3>;

// Where the triangles of a mesh come from, for messages: the source ("binary STL file a.stl") and
// per triangle its place in it ("line 12", "triangle 5").
struct MeshSource {
    std::string name = "triangle mesh";
    std::string placeWord = "triangle";
    std::vector<long> places;  // per triangle; empty: triangle k is at place k + 1

    std::string place(std::size_t triangle) const;
};

class TriangleMesh {
public:
    // Two corners closer than this times the bounding box's diagonal are one vertex.
    static constexpr double relativeTolerance = 1e-9;
    // A triangle whose height over its longest edge is below this is flat (zero area).
    static constexpr double flatness = 1e-8;

    // tolerance: the merging tolerance (0: relativeTolerance times the bounding box's diagonal; a
    // mesh read back from a restart file keeps the one it was made with, which a rigid motion keeps).
    explicit TriangleMesh(const std::vector<TriangleCorners>& triangles, MeshSource source = {}, double tolerance = 0);

    std::size_t triangleCount() const { return triangles_.size(); }
    std::size_t edgeCount() const { return edges_.size(); }
    std::size_t vertexCount() const { return vertices_.size(); }

    // The three vertex indices of triangle t, in the order of its corners.
    const std::array<std::uint32_t, 3>& triangle(std::size_t t) const { return triangles_[t]; }
    const Vec3& corner(std::size_t t, int k) const { return vertices_[triangles_[t][k]]; }
    const Vec3& normal(std::size_t t) const { return normals_[t]; }
    // The edges of triangle t: edge k joins its corners k and k + 1 (mod 3).
    const std::array<std::uint32_t, 3>& triangleEdges(std::size_t t) const { return triangleEdges_[t]; }

    const Vec3& vertex(std::size_t v) const { return vertices_[v]; }
    std::span<const std::uint32_t> vertexTriangles(std::size_t v) const;

    // The two vertex indices of edge e, the lower first.
    const std::array<std::uint32_t, 2>& edge(std::size_t e) const { return edges_[e]; }
    // Edge e as a unit direction from its first vertex to its second, and its length; and the unit
    // vector in the plane of triangle t normal to its edge k that points into the triangle. Kept
    // with the vertices (the nearest point of a triangle asks them of every contact each step).
    const Vec3& edgeDirection(std::size_t e) const { return edgeDirections_[e]; }
    double edgeLength(std::size_t e) const { return edgeLengths_[e]; }
    const Vec3& inwardEdgeNormal(std::size_t t, int k) const { return inwardEdgeNormals_[t][k]; }
    std::span<const std::uint32_t> edgeTriangles(std::size_t e) const;

    // The bounding box [lo, hi] of the vertices.
    const Vec3& lo() const { return lo_; }
    const Vec3& hi() const { return hi_; }
    // The length below which two points of the mesh count as one (relativeTolerance times the
    // diagonal of the bounding box the mesh was built with; a rigid motion keeps it).
    double tolerance() const { return tolerance_; }
    const MeshSource& source() const { return source_; }

    void translate(const Vec3& shift);
    // Turns the mesh about `point` by `rotation` (x -> point + rotation (x - point)).
    void rotate(const Vec3& point, const Mat3& rotation);
    // Turns the mesh by `angle` (radians, right-hand rule) about the axis through `point`.
    void rotate(const Vec3& point, const Vec3& axis, double angle);
    // Moves every vertex x to to(x), a rigid motion (the tolerance stays), and returns the largest
    // distance a vertex moved.
    template <class RigidMap>
    double moveVertices(const RigidMap& to) {
        double largest2 = 0;
        for (Vec3& x : vertices_) {
            const Vec3 y = to(x);
            largest2 = std::max(largest2, (y - x).squaredNorm());
            x = y;
        }
        updateBoundsAndNormals();
        return std::sqrt(largest2);
    }

private:
    void checkCorners(const std::vector<TriangleCorners>& triangles) const;
    void mergeVertices(const std::vector<TriangleCorners>& triangles, double tolerance);
    void findEdges();
    void listVertexTriangles();
    void updateBoundsAndNormals();  // (and the edges' directions, lengths and inward normals)
    [[noreturn]] void fail(std::size_t t, const std::string& problem) const;

    MeshSource source_;
    std::vector<Vec3> vertices_;
    std::vector<std::array<std::uint32_t, 3>> triangles_;
    std::vector<Vec3> normals_;
    std::vector<std::array<Vec3, 3>> inwardEdgeNormals_;
    std::vector<Vec3> edgeDirections_;
    std::vector<double> edgeLengths_;
    std::vector<std::array<std::uint32_t, 3>> triangleEdges_;
    std::vector<std::array<std::uint32_t, 2>> edges_;
    // The triangles of edge e are edgeTriangleList_[edgeStart_[e] .. edgeStart_[e + 1]), and
    // likewise for the vertices.
    std::vector<std::uint32_t> edgeStart_, edgeTriangleList_;
    std::vector<std::uint32_t> vertexStart_, vertexTriangleList_;
    Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero();
    double tolerance_ = 0;
};

}  // namespace talus

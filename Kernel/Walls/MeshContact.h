// The contacts of a sphere with a triangle mesh (Walls/TriangleMesh.h), each met once.
//
// The contacts are the local minima over the mesh of the distance from the sphere's centre x that
// are closer than its radius r. For each triangle within reach the point nearest to x is found and
// classified as lying on the face, on an edge or at a vertex; then
//   - a face point counts (no point of the mesh near it is nearer);
//   - an edge point counts only if every triangle sharing the edge has its nearest point on that
//     edge (then the point is a local minimum over the union of those triangles, which is the
//     mesh around it); in particular not if one of them has a face contact;
//   - a vertex point counts only if every triangle containing the vertex has its nearest point at
//     that vertex; in particular not if one of them has a face contact or an edge contact at an
//     edge through the vertex.
// An edge or vertex found from several triangles counts once. The rule "an edge counts unless a
// triangle sharing it has a face contact" would not do: a sphere resting on the face of one
// triangle of a flat floor reaches edges of triangles around it whose nearest points lie on those
// edges although no triangle sharing them has a face contact (a second contact where there is one).
//
// A mesh has two sides: a sphere on either side of a face touches it, with the normal from the
// contact point towards the centre. Points within the mesh's tolerance of an edge or a vertex are
// classified as on it, so that on a flat mesh a sphere above a shared edge or vertex, where
// rounding may put it a hair inside either triangle, still meets exactly one feature.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "Walls/TriangleMesh.h"

namespace talus {

enum class MeshFeature : std::uint8_t { face, edge, vertex };

// The point of a triangle nearest to a given point and where on the triangle it lies: on the
// face (which = 0), on edge `which` (the one from corner which to corner which + 1 mod 3), or at
// corner `which`.
struct TrianglePoint {
    Vec3 point;
    MeshFeature feature;
    int which;
};

// The point of the triangle `corners` nearest to x. With a tolerance > 0, a point that lies within
// the tolerance of an edge is put on the edge, and one within it of a corner at the corner.
TrianglePoint closestPointOnTriangle(const Vec3& x, const TriangleCorners& corners, double tolerance = 0);
// The same for triangle t of `mesh` with the mesh's tolerance, from the geometry the mesh keeps
// (its normal, inward edge normals, edge directions and lengths: no square root, no division).
// An edge is walked from its first vertex (TriangleMesh::edge) by every triangle that shares it,
// so that they all find the very same point on it and classify it alike.
TrianglePoint closestPointOnMeshTriangle(const Vec3& x, const TriangleMesh& mesh, std::uint32_t t);

struct MeshContact {
    Vec3 normal;          // unit, from the contact point towards the centre
    Vec3 point;           // the point of the mesh nearest to the centre
    double overlap;       // radius minus the distance from the centre, > 0
    MeshFeature feature;  // for a history per feature
    std::uint32_t index;  // of the triangle, edge or vertex in the mesh
};

// The contacts of the sphere (centre, radius) with `mesh`, looking at the triangles `candidates`
// (indices into the mesh, e.g. from a TriangleGrid; every triangle the sphere reaches must be
// among them). A centre on the mesh (distance 0) takes the normal of the triangle that found it.
std::vector<MeshContact> sphereMeshContacts(const TriangleMesh& mesh, const Vec3& centre, double radius,
                                            std::span<const std::uint32_t> candidates);

// Where a sphere centred at x meets triangle t of `mesh` (a triangle as a wall, Walls/MeshWalls.h):
// the distance to the triangle's nearest point, the unit normal from that point towards x (the
// triangle's normal for a centre on it), and whether a contact there is the triangle's to count:
// a face point always; an edge or a vertex point when every triangle sharing it has its nearest
// point there too (the rule above) and t is the first of those triangles, so that exactly one
// triangle counts it. So the triangles that count a contact within a radius of x give the
// contacts of sphereMeshContacts.
struct TriangleGap {
    double distance;
    Vec3 normal;
    bool counts;
};
// A centre `countWithin` or farther from the triangle is not asked whether its point counts
// (counts is then true): a contact so far off is of no interest, and the asking is the dear part.
TriangleGap triangleGap(const TriangleMesh& mesh, std::uint32_t t, const Vec3& x,
                        double countWithin = std::numeric_limits<double>::infinity());

}  // namespace talus

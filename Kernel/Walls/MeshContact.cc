#include "Walls/MeshContact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace talus {

namespace {

// The point of the edge from corner `which` (at a) to corner which + 1 (at b) nearest to x. The
// edge is walked from the lexicographically smaller end, so that the triangles on either side of
// an edge of a mesh (which list its ends in opposite orders) compute the very same point and the
// same classification.
TrianglePoint closestPointOnEdge(const Vec3& x, const Vec3& a, const Vec3& b, int which, double tolerance) {
    const bool swapped = std::lexicographical_compare(b.data(), b.data() + 3, a.data(), a.data() + 3);
    const Vec3& from = swapped ? b : a;
    const Vec3& to = swapped ? a : b;
    const Vec3 along = to - from;
    const double length = along.norm();
    const double t = (x - from).dot(along) / (length * length);  // of the foot of x on the line
    const int fromCorner = swapped ? (which + 1) % 3 : which;
    const int toCorner = swapped ? which : (which + 1) % 3;
    if (t * length <= tolerance) return {from, MeshFeature::vertex, fromCorner};
    if ((1 - t) * length <= tolerance) return {to, MeshFeature::vertex, toCorner};
    return {from + t * along, MeshFeature::edge, which};
}

}  // namespace

TrianglePoint closestPointOnTriangle(const Vec3& x, const TriangleCorners& c, double tolerance) {
    const Vec3 normal = (c[1] - c[0]).cross(c[2] - c[0]).normalized();
    // The barycentric coordinate of the foot of x in the plane that belongs to corner k + 2 is
    // proportional to the distance of the foot from edge k (inwards positive): the foot lies in the
    // face's region when all three are positive (here: beyond the tolerance).
    bool insideFace = true;
    for (int k = 0; k < 3 && insideFace; ++k) {
        const Vec3 edge = c[(k + 1) % 3] - c[k];
        insideFace = edge.cross(x - c[k]).dot(normal) > tolerance * edge.norm();
    }
    if (insideFace) return {x - (x - c[0]).dot(normal) * normal, MeshFeature::face, 0};
    // Otherwise the nearest point lies on the boundary: the nearest of the three edges' points.
    TrianglePoint nearest{};
    double nearestDistance2 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        const TrianglePoint p = closestPointOnEdge(x, c[k], c[(k + 1) % 3], k, tolerance);
        if (const double d2 = (x - p.point).squaredNorm(); d2 < nearestDistance2) {
            nearest = p;
            nearestDistance2 = d2;
        }
    }
    return nearest;
}

TrianglePoint closestPointOnMeshTriangle(const Vec3& x, const TriangleMesh& mesh, std::uint32_t t) {
    const double tolerance = mesh.tolerance();
    // The signed distances of the foot of x in the plane from the three edges' lines (inwards
    // positive), as closestPointOnTriangle's test.
    bool insideFace = true;
    for (int k = 0; k < 3 && insideFace; ++k) insideFace = (x - mesh.corner(t, k)).dot(mesh.inwardEdgeNormal(t, k)) > tolerance;
    const Vec3& normal = mesh.normal(t);
    if (insideFace) return {x - (x - mesh.corner(t, 0)).dot(normal) * normal, MeshFeature::face, 0};
    TrianglePoint nearest{};
    double nearestDistance2 = std::numeric_limits<double>::infinity();
    const std::array<std::uint32_t, 3>& corners = mesh.triangle(t);
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t e = mesh.triangleEdges(t)[k];
        const std::uint32_t fromVertex = mesh.edge(e)[0];
        const Vec3& from = mesh.vertex(fromVertex);
        const double length = mesh.edgeLength(e);
        const double along = (x - from).dot(mesh.edgeDirection(e));  // of the foot of x on the line
        const int fromCorner = corners[k] == fromVertex ? k : (k + 1) % 3;
        const int toCorner = fromCorner == k ? (k + 1) % 3 : k;
        TrianglePoint p;
        if (along <= tolerance)
            p = {from, MeshFeature::vertex, fromCorner};
        else if (length - along <= tolerance)
            p = {mesh.vertex(mesh.edge(e)[1]), MeshFeature::vertex, toCorner};
        else
            p = {from + along * mesh.edgeDirection(e), MeshFeature::edge, k};
        if (const double d2 = (x - p.point).squaredNorm(); d2 < nearestDistance2) {
            nearest = p;
            nearestDistance2 = d2;
        }
    }
    return nearest;
}

namespace {

// The nearest points of the triangles a sphere looks at, found once each: those of the candidates,
// and those of their neighbours that an edge or a vertex must ask.
class NearestPoints {
public:
    struct Found;
    // (found: where the points go, cleared first; a caller may keep it from call to call.)
    NearestPoints(const TriangleMesh& mesh, const Vec3& x, std::vector<Found>& found) : mesh_(mesh), x_(x), found_(found) {
        found_.clear();
    }

    struct Found {
        std::uint32_t triangle;
        TrianglePoint nearest;
        std::uint32_t index;  // of the face, edge or vertex it lies on, in the mesh
    };

    const Found& of(std::uint32_t t) {
        for (const Found& f : found_)
            if (f.triangle == t) return f;
        const TrianglePoint p = closestPointOnMeshTriangle(x_, mesh_, t);
        const std::uint32_t index = p.feature == MeshFeature::face   ? t
                                    : p.feature == MeshFeature::edge ? mesh_.triangleEdges(t)[p.which]
                                                                     : mesh_.triangle(t)[p.which];
        found_.push_back({t, p, index});
        return found_.back();
    }

    // Whether every triangle in `triangles` has its nearest point on the feature.
    bool allOn(std::span<const std::uint32_t> triangles, MeshFeature feature, std::uint32_t index) {
        return std::all_of(triangles.begin(), triangles.end(), [&](std::uint32_t t) {
            const Found& f = of(t);
            return f.nearest.feature == feature && f.index == index;
        });
    }

private:
    const TriangleMesh& mesh_;
    Vec3 x_;
    std::vector<Found>& found_;
};

}  // namespace

std::vector<MeshContact> sphereMeshContacts(const TriangleMesh& mesh, const Vec3& centre, double radius,
                                            std::span<const std::uint32_t> candidates) {
    std::vector<MeshContact> contacts;
    std::vector<NearestPoints::Found> found;
    NearestPoints nearestPoints(mesh, centre, found);
    for (const std::uint32_t t : candidates) {
        // A triangle whose plane is out of reach is out of reach (and a neighbour that an edge
        // asks about is then found on demand).
        if (std::abs((centre - mesh.corner(t, 0)).dot(mesh.normal(t))) >= radius) continue;
        const NearestPoints::Found found = nearestPoints.of(t);  // (a copy: `of` may grow the list)
        const Vec3 apart = centre - found.nearest.point;
        const double distance = apart.norm();
        if (!(distance < radius)) continue;
        const MeshFeature feature = found.nearest.feature;
        const bool seen = std::any_of(contacts.begin(), contacts.end(), [&](const MeshContact& c) {
            return c.feature == feature && c.index == found.index;
        });
        if (seen) continue;
        const bool counts =
            feature == MeshFeature::face ||
            nearestPoints.allOn(feature == MeshFeature::edge ? mesh.edgeTriangles(found.index)
                                                             : mesh.vertexTriangles(found.index),
                                feature, found.index);
        if (!counts) continue;
        const Vec3 normal = distance > 0 ? Vec3(apart / distance) : mesh.normal(t);
        contacts.push_back({normal, found.nearest.point, radius - distance, feature, found.index});
    }
    return contacts;
}

TriangleGap triangleGap(const TriangleMesh& mesh, std::uint32_t t, const Vec3& x, double countWithin) {
    const TrianglePoint nearest = closestPointOnMeshTriangle(x, mesh, t);
    const Vec3 apart = x - nearest.point;
    const double distance = apart.norm();
    const Vec3 normal = distance > 0 ? Vec3(apart / distance) : mesh.normal(t);
    if (nearest.feature == MeshFeature::face || !(distance < countWithin)) return {distance, normal, true};
    // (An edge or a vertex: its triangles asked, as sphereMeshContacts asks them.)
    const std::uint32_t index =
        nearest.feature == MeshFeature::edge ? mesh.triangleEdges(t)[nearest.which] : mesh.triangle(t)[nearest.which];
    const std::span<const std::uint32_t> sharing =
        nearest.feature == MeshFeature::edge ? mesh.edgeTriangles(index) : mesh.vertexTriangles(index);
    if (t != *std::min_element(sharing.begin(), sharing.end())) return {distance, normal, false};
    thread_local std::vector<NearestPoints::Found> found;  // (its memory kept from call to call)
    NearestPoints nearestPoints(mesh, x, found);
    return {distance, normal, nearestPoints.allOn(sharing, nearest.feature, index)};
}

}  // namespace talus

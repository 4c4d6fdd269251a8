#include "Walls/MeshWalls.h"

#include <algorithm>

#include "Walls/MeshContact.h"
#include "Walls/Wall.h"

namespace talus {

namespace {
// The grid's cell: the triangles' mean longest edge (a particle's query then meets a few cells,
// a cell a few triangles).
double gridCell(const TriangleMesh& mesh) {
    double sum = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        double longest = 0;
        for (int k = 0; k < 3; ++k) longest = std::max(longest, (mesh.corner(t, (k + 1) % 3) - mesh.corner(t, k)).norm());
        sum += longest;
    }
    return sum / static_cast<double>(mesh.triangleCount());
}

Vec3 centroid(const TriangleMesh& mesh, std::size_t t) { return (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3; }
}  // namespace

MeshWalls::MeshWalls(TriangleMesh triangles, std::uint32_t wallSpecies, std::uint32_t first, std::int32_t motionIndex)
    : mesh(std::move(triangles)), grid(mesh, gridCell(mesh)), species(wallSpecies), firstWall(first), motion(motionIndex) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 c = centroid(mesh, t);
        double r = 0;
        for (int k = 0; k < 3; ++k) r = std::max(r, (mesh.corner(t, k) - c).norm());
        centre.push_back(c);
        reach.push_back(r * (1 + 1e-12));  // (a hair wider than the corners' rounding)
    }
}

void MeshWalls::move(const PrescribedMotion& m, const Mat3& R, double dt, std::vector<Wall>& walls) {
    lastStep = mesh.moveVertices([&](const Vec3& x) { return m.moved(x, R, dt); });
    travelled += lastStep;
    for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
        centre[t] = centroid(mesh, t);
        Wall& wall = walls[firstWall + t];
        wall.normal = mesh.normal(t);
        wall.point = mesh.corner(t, 0);
    }
}

void MeshWalls::regrid() {
    grid = TriangleGrid(mesh, grid.cellSize());
    travelled = 0;
}

Wall::Gap Wall::triangleGap(const Vec3& x, double countWithin) const {
    const TriangleGap g = talus::triangleGap(mesh->mesh, triangle, x, countWithin);
    return {g.distance, g.normal, 0, g.counts};
}

}  // namespace talus

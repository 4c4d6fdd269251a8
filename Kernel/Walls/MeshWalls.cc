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
}  // namespace

MeshWalls::MeshWalls(TriangleMesh triangles, std::uint32_t wallSpecies, std::uint32_t first)
    : mesh(std::move(triangles)), grid(mesh, gridCell(mesh)), species(wallSpecies), firstWall(first) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 c = (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3;
        double r = 0;
        for (int k = 0; k < 3; ++k) r = std::max(r, (mesh.corner(t, k) - c).norm());
        centre.push_back(c);
        reach.push_back(r * (1 + 1e-12));  // (a hair wider than the corners' rounding)
    }
}

Wall::Gap Wall::triangleGap(const Vec3& x, double countWithin) const {
    const TriangleGap g = talus::triangleGap(mesh->mesh, triangle, x, countWithin);
    return {g.distance, g.normal, 0, g.counts};
}

}  // namespace talus

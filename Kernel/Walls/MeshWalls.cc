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
    : mesh(std::move(triangles)), grid(mesh, gridCell(mesh)), species(wallSpecies), firstWall(first) {}

Wall::Gap Wall::triangleGap(const Vec3& x) const {
    const TriangleGap g = talus::triangleGap(mesh->mesh, triangle, x);
    return {g.distance, g.normal, 0, g.counts};
}

}  // namespace talus

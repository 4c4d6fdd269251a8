#include "Walls/MeshWalls.h"

#include <algorithm>

#include "Walls/MeshContact.h"
#include "Walls/Wall.h"

namespace talus {

namespace {
// The grid's cell: the triangles' median longest edge (a particle's query then meets a few cells,
// a cell a few triangles). Not the mean: a few long triangles, such as the fan that closes the end
// of a drum, would make the cells of the many others coarse, each holding many triangles
// (Documentation/Benchmarks/OpenSourceComparison.md, the drum's speed).
double gridCell(const TriangleMesh& mesh) {
    std::vector<double> longest(mesh.triangleCount(), 0);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) longest[t] = std::max(longest[t], mesh.edgeLength(mesh.triangleEdges(t)[k]));
    const auto middle = longest.begin() + static_cast<std::ptrdiff_t>(longest.size() / 2);
    std::nth_element(longest.begin(), middle, longest.end());
    return *middle;
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

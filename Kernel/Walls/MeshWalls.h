// A triangle mesh as walls (Scene::addMeshWall; Theory/ContactLaws.md "Triangle meshes"): one wall
// per triangle, the walls [firstWall, firstWall + triangleCount) of the scene, each meeting a
// particle at the triangle's point nearest to it, counted by the face, edge and vertex rule of
// Walls/MeshContact.h (triangleGap), and the grid that finds the triangles near a particle when the
// neighbour list is built. The mesh rests: it has no motion.
#pragma once

#include <cstdint>
#include <vector>

#include "Walls/TriangleGrid.h"
#include "Walls/TriangleMesh.h"

namespace talus {

struct MeshWalls {
    MeshWalls(TriangleMesh triangles, std::uint32_t wallSpecies, std::uint32_t first);

    TriangleMesh mesh;
    TriangleGrid grid;
    std::uint32_t species;
    std::uint32_t firstWall;
    // Per triangle its centroid and the radius of the sphere about it that holds the triangle: a
    // particle clear of that sphere is clear of the triangle, found without its nearest point.
    std::vector<Vec3> centre;
    std::vector<double> reach;
};

}  // namespace talus

// A triangle mesh as walls (Scene::addMeshWall; Theory/ContactLaws.md "Triangle meshes"): one wall
// per triangle, the walls [firstWall, firstWall + triangleCount) of the scene, each meeting a
// particle at the triangle's point nearest to it, counted by the face, edge and vertex rule of
// Walls/MeshContact.h (triangleGap), and the grid that finds the triangles near a particle when the
// neighbour list is built. A mesh may follow a prescribed motion (translation and rotation,
// Walls/PrescribedMotion.h): its vertices move with it each step, and the grid is built anew at each
// list build over where the mesh is then; until the next build the mesh moves less than half the
// list's reach (PairList::meshTravel), so the grid's triangles found within the reach plus the
// distance travelled hold every triangle a particle may meet.
#pragma once

#include <cstdint>
#include <vector>

#include "Walls/PrescribedMotion.h"
#include "Walls/TriangleGrid.h"
#include "Walls/TriangleMesh.h"

namespace talus {

struct Wall;

struct MeshWalls {
    MeshWalls(TriangleMesh triangles, std::uint32_t wallSpecies, std::uint32_t first, std::int32_t motionIndex = -1);

    TriangleMesh mesh;
    TriangleGrid grid;
    std::uint32_t species;
    std::uint32_t firstWall;
    // Per triangle its centroid and the radius of the sphere about it that holds the triangle: a
    // particle clear of that sphere is clear of the triangle, found without its nearest point.
    std::vector<Vec3> centre;
    std::vector<double> reach;
    std::int32_t motion = -1;  // of the scene's motions; -1: the mesh rests
    // A moving mesh: the farthest any of its points has moved since the grid was built (the sum of
    // the steps' largest vertex moves, at least the true distance) and the last step's move.
    double travelled = 0, lastStep = 0;

    bool moves() const { return motion >= 0; }
    // Moves the mesh over one step of its motion m, whose rotation over the step is R, as the
    // motion moves any point (PrescribedMotion::moved), with its triangles' walls (normal and
    // first corner) and centres.
    void move(const PrescribedMotion& m, const Mat3& R, double dt, std::vector<Wall>& walls);
    // The grid anew over where the mesh is now (at a list build); travelled back to 0.
    void regrid();
};

}  // namespace talus

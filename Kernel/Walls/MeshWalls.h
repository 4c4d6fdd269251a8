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

#include "Walls/MeshContact.h"
#include "Walls/PrescribedMotion.h"
#include "Walls/TriangleGrid.h"
#include "Walls/TriangleMesh.h"
#include "Walls/Wall.h"

namespace talus {

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

    // visit(t) for each triangle t nearer to x than `within` (its nearest point, as a wall's
    // signed distance measures it), in increasing order: the grid's candidates (asked farther by
    // the distance the mesh has travelled since the grid was made), less those clear of the sphere
    // that holds the triangle.
    template <class Visit>
    void forTrianglesWithin(const Vec3& x, double within, Visit visit) const {
        thread_local std::vector<std::uint32_t> near;  // (kept from call to call)
        grid.trianglesNear(x, within + travelled, near);
        for (const std::uint32_t t : near) {
            const double clear = reach[t] + within;
            if ((x - centre[t]).squaredNorm() >= clear * clear) continue;
            if (triangleGap(mesh, t, x, 0).distance < within) visit(t);
        }
    }
};

// Each wall of `walls` once, a mesh's triangles together: onWall(w) for a wall of its own,
// onMesh(mesh) for a mesh, whose triangles are the walls [firstWall, firstWall + triangleCount).
// (The listing of wall candidates and the filling ask the triangles near a place through the
// mesh's grid, not one by one.)
template <class OnWall, class OnMesh>
void forEachWallOrMesh(const std::vector<Wall>& walls, OnWall onWall, OnMesh onMesh) {
    for (std::uint32_t w = 0; w < walls.size(); ++w) {
        if (walls[w].isTriangle()) {
            const MeshWalls& mesh = *walls[w].mesh;
            onMesh(mesh);
            w = mesh.firstWall + static_cast<std::uint32_t>(mesh.mesh.triangleCount()) - 1;
            continue;
        }
        onWall(w);
    }
}

}  // namespace talus

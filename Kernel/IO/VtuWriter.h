// ParaView output: one VTK XML unstructured-grid file (.vtu) per frame holding the particles as
// points with radius, velocity, angular velocity, species, id and fixed flag, and a .pvd
// collection listing the frames with their times; and the triangle meshes that are walls
// (IO/OutputFiles.h: once, or a frame of them for each particles' frame when a mesh moves).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "Particles/ParticleStore.h"
#include "Shapes/Superquadric.h"
#include "Walls/MeshWalls.h"

namespace talus {

void writeVtu(const std::string& path, const ParticleStore& particles, const std::vector<std::uint32_t>& order,
              const std::vector<Superquadric>& shapes = {});
// The triangle meshes that are walls (Walls/MeshWalls.h), all in one .vtu file of triangles with
// each one's wall index, mesh and species, where they are now.
void writeMeshVtu(const std::string& path, const std::vector<std::shared_ptr<MeshWalls>>& meshes);
// Writes the .pvd index of frames 0..frames-1 named <base>_<k>.vtu at the given times.
void writePvd(const std::string& path, const std::string& base, const std::vector<double>& times);

}  // namespace talus

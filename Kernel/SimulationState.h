// Everything a run is: the settings, the particles, species, walls, boundaries, the neighbour
// list with its contact history, the random generator and how far the output files got.
// A restart file is exactly this struct (IO/RestartFile.h), which is what makes restarts exact.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/PairList.h"
#include "Particles/ParticleStore.h"
#include "Run/RunSettings.h"
#include "Shapes/Superquadric.h"
#include "Species/SpeciesTable.h"
#include "Walls/MeshWalls.h"
#include "Walls/Wall.h"
#include "Walls/PrescribedMotion.h"

namespace talus {

// How far each output file got: its byte size after the last saved frame, so that a restart
// continues it exactly (IO/OutputFiles.h).
struct OutputProgress {
    std::uint64_t savedFrames = 0;
    std::uint64_t dataBytes = 0, fstatBytes = 0, eneBytes = 0;
    std::vector<double> frameTimes;  // for the .pvd index of the .vtu frames
};

struct SimulationState {
    RunSettings settings;
    double time = 0;
    std::uint64_t step = 0;
    Vec3 gravity = Vec3(0, 0, -1);
    Domain domain;
    SpeciesTable species;
    std::vector<Superquadric> shapes;  // of the non-spherical particles (ParticleStore::shape)
    ParticleStore particles;
    std::vector<Wall> walls;
    // The triangle meshes whose triangles are walls (Walls/MeshWalls.h; each wall of a triangle
    // points to its mesh here, which a shared pointer keeps where it is).
    std::vector<std::shared_ptr<MeshWalls>> meshes;
    std::vector<PrescribedMotion> motions;
    PairList pairList;
    std::mt19937_64 random{20260101};
    std::uint64_t nextId = 0;
    OutputProgress output;
    // Values of the driver's that the restart file keeps (Run::keepInRestart, and every
    // number flag of addFlag), by name, as they were at the save.
    std::vector<std::pair<std::string, double>> keptValues;
};

}  // namespace talus

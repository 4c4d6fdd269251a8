// Everything a run is: the settings, the particles, species, walls, boundaries, the neighbour
// list with its contact history, the random generator and how far the output files got.
// A restart file is exactly this struct (IO/RestartFile.h), which is what makes restarts exact.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/PairList.h"
#include "Integration/StepperTuning.h"
#include "Particles/ParticleStore.h"
#include "Shapes/Superquadric.h"
#include "Species/SpeciesTable.h"
#include "Walls/Wall.h"
#include "Walls/PrescribedMotion.h"

namespace talus {

struct RunSettings {
    std::string name = "talus";   // output files are name.data, name.fstat, ...
    double timeStep = 0;
    double endTime = 0;
    double outputInterval = 0;     // simulated time between saved frames; 0: first and last only
    double skin = -1;              // neighbour-list skin; < 0: 0.2 x the smallest radius
    double cellSizeRatio = 2;      // of successive HGrid levels
    bool reorderParticles = true;  // along a space-filling curve at list rebuilds (slots change)
    bool writeData = true, writeFstat = true, writeEne = true, writeVtu = true, writeRestart = true;
    double progressInterval = 10;  // wall seconds between progress lines
    double maxOverlapFraction = 0.25;      // of the smaller radius, during the run
    double maxInitialOverlapFraction = 0.05;  // of the smaller radius, at the start
    // How the forces are summed (each changes the result, if only by round-off; the restart file
    // keeps them: Documentation/FileFormats/restart.md):
    bool idOrderedSums = false;  // in the order of partners' ids (--id-ordered-sums, IdOrderedForceSums.h)
    bool relist = true;          // pairs of added or moved particles relisted (--relist; PairList::maxRelisted)
    // How the steppers advance the run (waves: --wave-steps, --wave-strip; --drift-pass); the
    // restart file keeps the waves' steps and strip width, not the drift pass.
    StepperTuning stepper;
};

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
    std::vector<PrescribedMotion> motions;
    PairList pairList;
    std::mt19937_64 random{20260101};
    std::uint64_t nextId = 0;
    OutputProgress output;
    // Values of the driver's that the restart file keeps (Simulation::keepInRestart, and every
    // number flag of addFlag), by name, as they were at the save.
    std::vector<std::pair<std::string, double>> keptValues;
};

}  // namespace talus

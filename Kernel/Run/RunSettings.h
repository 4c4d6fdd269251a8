// The settings of a run (Documentation/Architecture.md "The driver contract"): a driver writes
// them in main() or setupInitialConditions() through Simulation::settings(), the command line
// overrides them, and solve() validates them all at once (validate()), each error naming the
// setting and its flag: after the first reading of the command line, so that a bad flag stops
// the run before the scene is built, and again before the run starts. The restart file keeps them (IO/RestartFile.h).
#pragma once

#include <limits>
#include <string>

#include "Integration/StepperTuning.h"

namespace talus {

struct RunSettings {
    std::string name = "talus";  // --name: output files are name.data, name.fstat, ...
    // --dt: the time step; automaticTimeStep (--dt auto): the shortest collision time of the scene over
    // stepsPerCollision (--steps-per-collision), Hertzian contacts at impactSpeed (--impact-speed; 0: at each
    // law's characteristic velocity), chosen when the run starts (Scene::automaticTimeStep).
    // (A value no flag can give: --dt takes finite numbers only.)
    static constexpr double automaticTimeStep = -std::numeric_limits<double>::infinity();
    double timeStep = 0;
    double stepsPerCollision = 50, impactSpeed = 0;
    // --largest-step-fraction: the largest dt / tc a run accepts (Theory/Integration.md eq. (12));
    // above 0.1 only for studies of where the integration fails (Documentation/SpeedVsError.md).
    double largestStepFraction = 0.1;
    double endTime = 0;          // --end-time
    double outputInterval = 0;   // --output-interval: simulated time between saved frames; 0: first and last only
    // --skin: the neighbour-list skin; automaticSkin: 0.2 x the smallest radius, set at the start.
    static constexpr double automaticSkin = -1;
    double skin = automaticSkin;
    double cellSizeRatio = 2;      // --cell-size-ratio: of successive HGrid levels (Contacts/HGrid.h)
    // --reorder: the particle order renewed along a space-filling curve at neighbour-list rebuilds
    // (Particles/SpaceFillingCurve.h). Slots then change during a run: find a particle by its id.
    bool reorderParticles = true;
    // --vtu, --fstat: which output files are written; setFileOutput (--files) sets them all.
    bool writeData = true, writeFstat = true, writeEne = true, writeVtu = true, writeRestart = true;
    double progressInterval = 10;             // --progress-interval: wall seconds between progress lines
    double maxOverlapFraction = 0.25;         // --max-overlap: of the smaller radius, during the run
    double maxInitialOverlapFraction = 0.05;  // of the smaller radius, at the start
    // --shape-tolerance: the Newton tolerance of the superquadric contact point (relative to the
    // smaller bounding radius; Theory/Superquadrics.md "Convergence"; SuperquadricContactSettings).
    double shapeTolerance = 1e-10;
    // How the forces are summed (each changes the result, if only by round-off; the restart file
    // keeps them: Documentation/FileFormats/restart.md):
    bool idOrderedSums = false;  // in the order of partners' ids (--id-ordered-sums, IdOrderedForceSums.h)
    bool relist = true;          // pairs of added or moved particles, a travelled mesh's triangles relisted (--relist; PairList::maxRelisted)
    // How the steppers advance the run (--waves, --wave-steps, --wave-strip, --waves-from,
    // --drift-pass, --near-skin-fraction, --sweep-frame, --sweep: Integration/StepperTuning.h);
    // the restart file keeps the waves' steps (those the run took) and strip width. With waves,
    // actionsBeforeTimeStep and actionsAfterTimeStep run once per wave.
    StepperTuning stepper;

    // All of .data, .fstat, .ene, .vtu and .restart on or off.
    void setFileOutput(bool on) { writeData = writeFstat = writeEne = writeVtu = writeRestart = on; }

    // Throws talus::Error naming the first setting out of its range (and its flag). Before the
    // scene is set up (started false) the time step may still be unset (0).
    void validate(bool started = true) const;
};

}  // namespace talus

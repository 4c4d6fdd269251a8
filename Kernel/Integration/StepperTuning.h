// How the steppers (Integration/Integrator.h) may advance a run: switches that change speed, not
// physics (at most the round-off of the force sums). Set from the command line (--wave-steps,
// --wave-strip, --drift-pass, --overlap-ghosts) or in a driver through settings().stepper; part of RunSettings.
// The restart file keeps the waves' two numbers (Documentation/FileFormats/restart.md).
#pragma once

#include <string>

#include "Error.h"

namespace talus {

struct StepperTuning {
    // Steps per wave (1-255; 1: a step per pass over the particles) and columns of cells per strip
    // of the waves (0: 8 per wave step). Documentation/TimeSkewing.md.
    int waveSteps = 1;
    int waveStripColumns = 0;
    // The first half of each step in one pass over the particles where the scene allows it
    // (Particles/DriftPass.h); off: pass by pass, for measurements and for tests that compare the
    // two (the same trajectories to the bit).
    bool driftPass = true;
    // On ranks, the forces of the pairs of two owned particles computed while the ghosts' states
    // travel (Parallel/RankContext.h); off (the default): after they have arrived. The same
    // trajectories to the bit; off because the overlap made 2 ranks slower at 3000 particles
    // (Documentation/Parallel.md "Speed").
    bool overlapGhosts = false;

    // Waves of `steps` steps (the strip width set before stays), or in strips of stripColumns.
    void setWaves(int steps) {
        require(steps >= 1 && steps <= 255, "waves of 1 to 255 steps, got " + std::to_string(steps));
        waveSteps = steps;
    }
    void setWaves(int steps, int stripColumns) {
        require(stripColumns >= 1, "strips of waves need at least one column, got " + std::to_string(stripColumns));
        setWaves(steps);
        waveStripColumns = stripColumns;
    }
    // The strip width the waves take: the one set, else 8 columns per step of the wave (64 for
    // waves of 8: the width measured fastest, Documentation/TimeSkewing.md "Strip width").
    int stripColumns() const { return waveStripColumns > 0 ? waveStripColumns : 8 * waveSteps; }

    bool operator==(const StepperTuning&) const = default;
};

}  // namespace talus

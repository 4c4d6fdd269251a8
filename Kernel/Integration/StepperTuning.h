// How the steppers (Integration/Integrator.h) and the force loop's sweep may advance a run:
// switches that change speed, not physics (at most the round-off of the force sums). Set from the
// command line (--waves, --wave-steps, --wave-strip, --waves-from, --drift-pass,
// --near-skin-fraction, --sweep-frame, --sweep, --overlap-ghosts) or in a driver through settings().stepper; part
// of RunSettings, which validates them. The restart file keeps the waves' steps and strip width
// (Documentation/FileFormats/restart.md): the steps the saved run took (1: none), so that a
// restarted run goes on as it did.
#pragma once

#include <cstdint>
#include <string>

#include "Contacts/SweepForm.h"
#include "Error.h"

namespace talus {

struct StepperTuning {
    // Waves (Documentation/TimeSkewing.md): taken where they pay (automatic: a box periodic along
    // x and y on one rank with at least wavesFromParticles particles; Integrator::chooseWaves),
    // wherever the scene allows them (on), or never (off).
    enum class Waves { automatic, on, off };
    Waves waves = Waves::automatic;
    // Steps per wave (2-255; 1: a step per pass, as off) and columns of cells per strip of the
    // waves (0: 8 per wave step). 8: the fastest measured (TimeSkewing.md "Wave length"). At the
    // start of a run the steps become those the run takes (1 where it takes no waves), which the
    // restart file keeps.
    int waveSteps = 8;
    int waveStripColumns = 0;
    // The particles from which automatic waves are taken: where waves of 8 overtake the drift
    // pass's single steps in the benchmark chute (Documentation/TimeSkewing.md, "When waves pay").
    static constexpr std::uint64_t defaultWavesFromParticles = 20000;
    std::uint64_t wavesFromParticles = defaultWavesFromParticles;
    // The first half of each step in one pass over the particles where the scene allows it
    // (Particles/DriftPass.h); off: pass by pass, for measurements and for tests that compare the
    // two (the same trajectories to the bit).
    bool driftPass = true;
    // The force loop's near list (Contacts/PairList.h NearPairs): the pairs within this fraction
    // of the skin (0: the whole list is swept every step). 0.15 was the fastest of 0.06-0.4 on the
    // benchmark chute (Documentation/Performance.md).
    double nearSkinFraction = 0.15;
    // The sweep grows the radii by the speeds relative to the mobile particles' mean velocity
    // (true) or by the speeds themselves (Contacts/PairSweep.h sweepFrameVelocity).
    bool sweepInFlowFrame = true;
    // The sweep's form (Contacts/SweepForm.h); undecided: the fastest, chosen by timing.
    SweepForm sweepForm = SweepForm::undecided;
    // On ranks, the forces of the pairs of two owned particles computed while the ghosts' states
    // travel (Parallel/RankContext.h); off (the default): after they have arrived. The same
    // trajectories to the bit; off because the overlap made 2 ranks slower at 3000 particles
    // (Documentation/Parallel.md "Speed").
    bool overlapGhosts = false;

    // Waves of `steps` steps wherever the scene allows them (1: none; the strip width set before
    // stays), or in strips of stripColumns.
    void setWaves(int steps) {
        require(steps >= 1 && steps <= 255, "waves of 1 to 255 steps, got " + std::to_string(steps));
        waveSteps = steps;
        waves = steps > 1 ? Waves::on : Waves::off;
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

// "auto", "on", "off"; and the choice named so (the error names `flag`).
const char* wavesName(StepperTuning::Waves waves);
StepperTuning::Waves wavesNamed(const std::string& name, const std::string& flag);
// "auto" for undecided, else the form's name; and the form named so (the error names `flag`).
SweepForm sweepFormNamed(const std::string& name, const std::string& flag);

}  // namespace talus

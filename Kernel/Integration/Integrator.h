// The steppers of a run and the choice among them (Documentation/Architecture.md, "Steppers"):
// at every advance the first that accepts the scene as it is then, in the order waves, drift
// pass, plain velocity Verlet (which takes any scene). Waves take a wave where one fits
// (WaveStepper::stepsNext); single steps are chosen after the driver's actionsBeforeTimeStep,
// which may add particles. The choice changes no physics: the steppers' trajectories are those of
// plain velocity Verlet, the forces of the waves summed in another order (round-off).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

#include "Integration/DriftPassStepper.h"
#include "Integration/PlainVerlet.h"
#include "Integration/WaveStepper.h"

namespace talus {

class Integrator {
public:
    // The steps of the last (or running) solve by each stepper, and the waves' own counts.
    struct Statistics {
        std::uint64_t plainSteps = 0, driftPassSteps = 0;
        WaveStepper::Statistics waves;
    };

    // The steps the next advance takes (1, or a wave's), the stepper chosen for them.
    std::uint64_t stepsNext(StepHost& host, std::uint64_t stepsLeft, std::uint64_t saveEvery);
    void advance(StepHost& host, bool recordContacts);

    // At the start of a run, before its first list build: the tuning put where it acts (the
    // list's near list and sweep frame, the sweep's form) and whether the run takes waves
    // (WaveStepper::choose).
    void tune(StepHost& host, bool restarted);
    // At every list build (the wave schedule is made for it) and after a restart.
    void afterListBuild(StepHost& host);
    void afterRestart(StepHost& host);
    // The order of the particles a list build of the given reach takes, where the waves' cells
    // give it (else a space-filling curve: Particles/SpaceFillingCurve.h).
    std::optional<WaveCells> cellsForBuild(const StepHost& host, double reach) const {
        return waves_.cellsForBuild(host, reach, nullptr);
    }

    void startRun();
    Statistics statistics() const { return {plainSteps_, driftPassSteps_, waves_.statistics()}; }
    // The stepper the scene takes now and why the ones before it decline it (one line, for the
    // start of a run), and the run's summary of its waves.
    void describeChoice(const StepHost& host, std::ostream& out, const std::string& name) const;
    void report(const StepHost& host, std::ostream& out, const std::string& name, std::uint64_t steps) const {
        waves_.report(host, out, name, steps);
    }

private:
    PlainVerlet plain_;
    DriftPassStepper driftPass_;
    WaveStepper waves_{driftPass_};
    Stepper* chosen_ = nullptr;
    std::uint64_t plainSteps_ = 0, driftPassSteps_ = 0;
};

}  // namespace talus

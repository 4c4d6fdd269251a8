// Something attached to a run that samples it at chosen steps together with each contact of those
// steps: the in-run coarse graining of Tools/CG/InRun (Documentation/CoarseGraining.md "Fields
// during a run") is one. The kernel knows only this interface, so it does not depend on what
// samples; a driver that links the sampler's library attaches one with Simulation::addSampler.
//
// The time loop asks before every advance (one step, or a wave of several: Integration/
// Integrator.h) whether the sampler wants one of the steps it covers. If so, the force evaluation
// of its last step records each contact, as it does on output steps (Contacts/ContactReport.h),
// and the sampler gets the state that step left: positions, velocities and forces at the end of
// the step, before the driver's actionsAfterTimeStep, the same numbers the .data and .fstat
// writers write at an output step. Under waves a wanted step inside a wave is sampled at the
// wave's end. On ranks every rank calls the sampler at the same steps with the records of its own
// pairs (those whose first particle it owns), so that each contact is given to one rank only.
#pragma once

#include <cstdint>
#include <vector>

#include "Contacts/ContactReport.h"

namespace talus {

class Simulation;

class StepSampler {
public:
    virtual ~StepSampler() = default;
    // Once before the time loop (after the set-up or the restart, the run's settings final).
    virtual void startRun(Simulation&) {}
    // Whether the advance over the steps first..last (numbered as Simulation::step() counts them,
    // both included) should be sampled at its end.
    virtual bool wantsSteps(const Simulation& simulation, std::uint64_t first, std::uint64_t last) const = 0;
    // The sample: the state after the step, each contact of its force evaluation in `contacts`.
    virtual void sample(Simulation& simulation, const ContactRecordList& contacts) = 0;
    // After the files of an output step were written (every save, the run's last step included).
    virtual void afterOutput(Simulation&) {}
    // After the time loop, before the driver's actionsAfterSolve.
    virtual void finishRun(Simulation&) {}
};

// A run's samplers: those attached (Simulation::addSampler), in order, and those that sample the
// current advance.
struct StepSamplers {
    std::vector<StepSampler*> attached;
    std::vector<StepSampler*> sampling;
};

}  // namespace talus

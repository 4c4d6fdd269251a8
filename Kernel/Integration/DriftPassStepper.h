// Velocity Verlet with the first half of the step in one pass over the particles
// (Particles/DriftPass.h: kick, drift, wrap, the list's check, the sweep's points, the forces
// started with gravity): the same trajectories as PlainVerlet to the bit, the particles' data
// read once instead of six times. For scenes where nothing but the particles' own motion happens
// between the drift and the forces.
#pragma once

#include "Integration/Stepper.h"
#include "Math/Vector.h"

namespace talus {

struct SimulationState;
struct StepWorkspace;

class DriftPassStepper final : public Stepper {
public:
    std::string_view name() const override { return "drift pass"; }
    std::string_view whyNot(const StepHost& host) const override;
    void advance(StepHost& host, bool recordContacts) override;
};

// The frame velocity of the sweep's growths (PairSweep.h) for a drift pass: the mean velocity
// the last pass measured, or a sample's; zero when the list sweeps in the box's frame.
Vec3 sweepFrame(const SimulationState& state, const StepWorkspace& work);

}  // namespace talus

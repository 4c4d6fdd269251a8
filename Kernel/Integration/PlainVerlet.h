// Velocity Verlet pass by pass (Documentation/Theory/Integration.md): half kick, drift, the
// rigid-body turn of the non-spherical particles, prescribed motions, the periodic wrap, the
// boundaries, the forces at the new positions, half kick. It takes any scene: the stepper of
// last resort.
#pragma once

#include "Integration/Stepper.h"

namespace talus {

struct SimulationState;

class PlainVerlet final : public Stepper {
public:
    std::string_view name() const override { return "plain velocity Verlet"; }
    std::string_view whyNot(const StepHost&) const override { return {}; }
    void advance(StepHost& host, bool recordContacts) override;
};

// Particles, walls, meshes and the turning of fixed superquadrics that follow a prescribed motion,
// moved over the step; their velocities those of the motion at the new positions.
void moveWithPrescribedMotion(SimulationState& s);

// The end of a single step, whatever its first half was: the time moves on, the boundaries act,
// the forces are computed (drifted: what a drift pass measured, or null), the second half kick.
void finishStep(StepHost& host, bool recordContacts, const DriftPassResult* drifted);

}  // namespace talus

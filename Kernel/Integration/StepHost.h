// What a stepper (Integration/Stepper.h) asks of the simulation it advances: the state, the
// workspace, the force computation with its neighbour-list upkeep, the boundaries that act after
// the drift, and the overlap check. Simulation implements it (Simulation.cc); a test may too.
#pragma once

namespace talus {

struct SimulationState;
struct StepWorkspace;
struct DriftPassResult;

// How computeForces checks the overlaps against their limit: not at all (the caller checks),
// agreed by all ranks at once, or (on ranks) agreed with the next step's neighbourhood: one
// collective per step instead of two. Output steps and the last step agree at once, so that no
// file holds a state past a blow-up that a rank has found.
enum class OverlapCheck { none, now, withNextStep };

class StepHost {
public:
    virtual SimulationState& state() = 0;
    virtual const SimulationState& state() const = 0;
    virtual StepWorkspace& workspace() = 0;
    virtual bool onRanks() const = 0;
    // Whether a boundary (Boundaries/Boundary.h) acts between the drift and the forces; they act.
    virtual bool boundariesActAfterDrift() const = 0;
    virtual void afterDrift() = 0;
    // The forces at the positions now (the neighbour list updated first; recordContacts: into the
    // workspace's records). drifted: what the step's drift pass measured (it has also made the
    // sweep's points and started the forces); null: measured and started here.
    virtual void computeForces(bool recordContacts, OverlapCheck check, const DriftPassResult* drifted) = 0;
    virtual void checkOverlaps(double limit, bool initial, bool agreeNow) = 0;
    // The particles in the order a list build takes (between steps: the forces are in p).
    virtual void reorderParticles(bool withPreviousForces) = 0;

protected:
    ~StepHost() = default;
};

}  // namespace talus

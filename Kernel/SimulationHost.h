// The simulation as the steppers see it (Integration/StepHost.h): a part of talus::Simulation,
// for its own source files only.
#pragma once

#include "Boundaries/Boundary.h"
#include "Integration/StepHost.h"
#include "Parallel/RankContext.h"
#include "Simulation.h"

namespace talus {

class Simulation::Host final : public StepHost {
public:
    explicit Host(Simulation& simulation) : s_(simulation) {}
    SimulationState& state() override { return s_.state_; }
    const SimulationState& state() const override { return s_.state_; }
    StepWorkspace& workspace() override { return *s_.work_; }
    bool onRanks() const override { return s_.ranks_->isSplit(); }
    bool boundariesActAfterDrift() const override {
        for (const auto& b : s_.scene_->boundaries())
            if (b->actsAfterDrift()) return true;
        return false;
    }
    void afterDrift() override {
        for (const auto& b : s_.scene_->boundaries()) b->afterDrift(s_);
    }
    void computeForces(bool recordContacts, OverlapCheck check, const DriftPassResult* drifted) override {
        s_.computeForces(recordContacts, check, drifted);
    }
    void checkOverlaps(double limit, bool initial, bool agreeNow) override { s_.checkOverlaps(limit, initial, agreeNow); }
    void reorderParticles(bool withPreviousForces) override { s_.reorderParticles(withPreviousForces); }

private:
    Simulation& s_;
};

}  // namespace talus

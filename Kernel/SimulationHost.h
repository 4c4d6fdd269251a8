// The simulation as the steppers see it (Integration/StepHost.h) and as its scene asks about the
// ranks (Scene/SceneRanks in Scene/Scene.h): a part of talus::Simulation, for its own source files only.
#pragma once

#include "Boundaries/Boundary.h"
#include "Integration/StepHost.h"
#include "Parallel/DomainSplit.h"
#include "Simulation.h"

namespace talus {

class Simulation::Host final : public StepHost, public SceneRanks {
public:
    explicit Host(Simulation& simulation) : s_(simulation) {}
    SimulationState& state() override { return s_.state_; }
    const SimulationState& state() const override { return s_.state_; }
    StepWorkspace& workspace() override { return *s_.work_; }
    bool onRanks() const override { return s_.onRanks(); }
    bool hasBoundaries() const override { return !s_.scene_->boundaries().empty(); }
    void afterDrift() override {
        for (Boundary* b : s_.scene_->boundaries()) b->afterDrift(s_);
    }
    void computeForces(bool recordContacts, OverlapCheck check, const DriftPassResult* drifted) override {
        s_.computeForces(recordContacts, check, drifted);
    }
    void checkOverlaps(double limit, bool initial, bool agreeNow) override { s_.checkOverlaps(limit, initial, agreeNow); }
    void reorderParticles(bool withPreviousForces) override { s_.reorderParticles(withPreviousForces); }

    // SceneRanks
    int rank() const override { return s_.rank(); }
    double sumOverRanks(double x) const override { return s_.sumOverRanks(x); }
    void releaseGhosts() override { s_.releaseGhosts(); }
    std::uint64_t provisionalId() override {
        return provisionalIdBase + (std::uint64_t(s_.rank()) << 40) + s_.provisionalIds_++;
    }
    bool isSentAsGhost(std::size_t slot) const override {
        return s_.split_->isSentAsGhost(static_cast<std::uint32_t>(slot));
    }

private:
    Simulation& s_;
};

}  // namespace talus

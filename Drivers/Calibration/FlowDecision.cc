#include "FlowDecision.h"

#include "Error.h"
#include "Simulation.h"

namespace talus {

const char* flowStateName(FlowState state) {
    switch (state) {
        case FlowState::steady: return "flowing";
        case FlowState::arrested: return "arrested";
        default: return "undecided";
    }
}

// (The plateau detector starts with the default criteria: reset checks the given ones first,
// naming their flags.)
FlowDecision::FlowDecision(const FlowCriteria& criteria) : plateau_(FlowCriteria{}.window, FlowCriteria{}.tolerance) {
    reset(criteria);
}

FlowDecision::FlowDecision(Simulation& simulation, const std::string& name) : FlowDecision() {
    simulation.run().keepInRestart(name + ".plateau", [this] { return plateau_.state(); },
                                   [this](const std::vector<double>& v) { plateau_.restore(v); });
    simulation.run().keepInRestart(name, [this] { return numbers(); }, [this](const std::vector<double>& v) { restore(v); });
}

void FlowDecision::reset(const FlowCriteria& c) {
    require(c.arrestEnergy > 0, "--arrest-energy must be positive, got " + str(c.arrestEnergy));
    require(c.arrestTime > 0, "--arrest-time must be positive, got " + str(c.arrestTime));
    require(c.window >= 4, "--window must be at least 4 samples, got " + std::to_string(c.window));
    require(c.tolerance > 0, "--tolerance must be positive, got " + str(c.tolerance));
    criteria_ = c;
    plateau_.reset(c.window, c.tolerance);
    state_ = FlowState::undecided;
    restSince_ = decidedAt_ = -1;
}

FlowState FlowDecision::add(double time, double energyPerMass, double massFlux) {
    if (state_ == FlowState::arrested) return state_;
    if (energyPerMass < criteria_.arrestEnergy) {
        if (restSince_ < 0) restSince_ = time;
        if (time - restSince_ >= criteria_.arrestTime) {
            state_ = FlowState::arrested;
            decidedAt_ = time;
            return state_;
        }
    } else
        restSince_ = -1;
    if (state_ == FlowState::undecided && plateau_.add(time, {energyPerMass, massFlux})) {
        state_ = FlowState::steady;
        decidedAt_ = time;
    }
    return state_;
}

std::vector<double> FlowDecision::numbers() const {
    return {criteria_.arrestEnergy, criteria_.arrestTime, static_cast<double>(state_), restSince_, decidedAt_};
}

void FlowDecision::restore(const std::vector<double>& v) {
    require(v.size() == 5, "flow decision: the restart file keeps 5 numbers for it, not " + std::to_string(v.size()));
    criteria_.arrestEnergy = v[0];
    criteria_.arrestTime = v[1];
    state_ = static_cast<FlowState>(static_cast<int>(v[2]));
    restSince_ = v[3];
    decidedAt_ = v[4];
}

}  // namespace talus

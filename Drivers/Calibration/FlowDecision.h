// Whether a chute flow has come to rest or to a steady state, decided from samples of its bulk
// taken at equal time intervals (Documentation/Calibration.md "When a point is decided"):
//  - arrested: the kinetic energy per unit mass has stayed below `arrestEnergy` g d for at least
//    `arrestTime` (every sample in that time below it); once arrested, always arrested;
//  - steady: the kinetic energy and the downslope mass flux are on a plateau
//    (Sampling/SteadyDetector.h: over the last `window` samples the least-squares line through
//    each changes by at most `tolerance` times its mean). A steady flow that later comes to rest
//    becomes arrested.
// Made with a simulation and a name, it keeps what it knows in the restart file, so that a
// restarted run goes on deciding where it stopped.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "Sampling/SteadyDetector.h"

namespace talus {

class Simulation;

struct FlowCriteria {
    double arrestEnergy = 1e-5;  // kinetic energy per unit mass, in units of g d
    double arrestTime = 10;      // in units of sqrt(d / g)
    std::size_t window = 100;    // samples on a plateau that make the flow steady
    double tolerance = 0.02;     // largest change of a series' trend over the window, relative to its mean
};

enum class FlowState { undecided, steady, arrested };
const char* flowStateName(FlowState state);  // "undecided", "flowing", "arrested"

class FlowDecision {
public:
    explicit FlowDecision(const FlowCriteria& criteria = {});
    FlowDecision(Simulation& simulation, const std::string& name);
    // Forgets every sample and takes the criteria anew; a criterion out of range is an error that
    // names its flag of CalibrationChute (--arrest-energy, --arrest-time, --window, --tolerance).
    void reset(const FlowCriteria& criteria);
    // One sample: time, kinetic energy per unit mass (g d), mass flux. Returns the state.
    FlowState add(double time, double energyPerMass, double massFlux);
    FlowState state() const { return state_; }
    double decidedAt() const { return decidedAt_; }  // time of the sample that decided; -1 if none

private:
    std::vector<double> numbers() const;
    void restore(const std::vector<double>& v);

    FlowCriteria criteria_;
    SteadyDetector plateau_;
    FlowState state_ = FlowState::undecided;
    double restSince_ = -1;  // first sample of the current run of samples below the arrest energy
    double decidedAt_ = -1;
};

}  // namespace talus

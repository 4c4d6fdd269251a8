#include "Sampling/SamplingClock.h"

#include <cmath>

#include "Error.h"
#include "Simulation.h"

namespace talus {

SamplingClock::SamplingClock(Simulation& simulation, const std::string& name) : simulation_(simulation) {
    simulation_.run().keepInRestart("clock." + name, next_);
}

bool SamplingClock::every(double interval) {
    require(std::isfinite(interval) && interval > 0, "sampling interval must be positive, got " + str(interval));
    const double t = simulation_.time(), halfStep = 0.5 * simulation_.settings().timeStep;
    // The first multiple of the interval after the start (t = 0 itself is not a sample).
    if (next_ < 0) next_ = interval * std::max(1.0, std::ceil((t - halfStep) / interval));
    if (t < next_ - halfStep) return false;
    next_ = interval * (std::floor((t + halfStep) / interval) + 1);
    return true;
}

}  // namespace talus

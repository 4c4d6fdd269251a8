// A driver's sampling clock: every(interval) is true once per interval of simulated time, at
// the first step at or past each multiple of the interval (within half a time step: t = k T
// reached by adding the step). The next sample time is kept in the restart file
// (Simulation::keepInRestart, "clock.NAME"), so a restarted run samples at the same steps as
// the run it continues, and a run stepping in waves (several steps between the driver's hooks)
// still samples once per interval, at the end of the wave that crosses the sample time.
#pragma once

#include <string>

namespace talus {

class Simulation;

class SamplingClock {
public:
    // Call from the driver's constructor (it registers the kept time); names are unique.
    SamplingClock(Simulation& simulation, const std::string& name);
    SamplingClock(const SamplingClock&) = delete;
    SamplingClock& operator=(const SamplingClock&) = delete;

    // Whether the run is due for a sample of this clock now (call once per step, from a hook);
    // a true answer moves the next sample time to the next multiple of `interval`.
    bool every(double interval);
    double nextSampleTime() const { return next_; }

private:
    Simulation& simulation_;
    double next_ = -1;  // the next sample time; negative: not yet set (the first call sets it)
};

}  // namespace talus

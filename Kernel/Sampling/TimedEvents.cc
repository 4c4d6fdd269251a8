#include "Sampling/TimedEvents.h"

#include <cmath>

#include "Simulation.h"

namespace talus {

TimedEvents::TimedEvents(Made made, Simulation& simulation, const std::string& name) : Boundary(made) {
    simulation.run().keepInRestart(
        name,
        [this] {
            std::vector<double> done;
            for (const Event& e : events_) done.push_back(e.done ? 1 : 0);
            return done;
        },
        [this, name](const std::vector<double>& done) {
            require(done.size() == events_.size(), "restart file: '" + name + "' holds " + std::to_string(done.size()) +
                                                       " timed events, the driver has " + std::to_string(events_.size()));
            for (std::size_t k = 0; k < done.size(); ++k) events_[k].done = done[k] != 0;
        });
}

void TimedEvents::at(double time, std::function<void()> action) {
    at([time] { return time; }, std::move(action));
}

void TimedEvents::at(std::function<double()> time, std::function<void()> action) {
    events_.push_back({std::move(time), std::move(action), false});
}

void TimedEvents::afterDrift(Simulation& simulation) {
    const double t = simulation.time(), halfStep = 0.5 * simulation.settings().timeStep;
    for (Event& e : events_) {
        if (e.done || t < e.time() - halfStep) continue;
        e.done = true;  // (before the action: an action that throws is not retried)
        e.action();
    }
}

}  // namespace talus

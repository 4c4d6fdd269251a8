// Things a driver does once at a given simulated time (open an orifice at t = 20, start a
// rotation, change the gravity): at(20.0, [this] { ... }). Each runs once, at the first step
// whose time is at or past its own (within half a time step), after the drift and before the
// forces of that step (a Boundary, Boundaries/Boundary.h), on every rank. Which have run is kept
// in the restart file (keepInRestart, "NAME"), so a restarted run does not run them again.
// Register the events in the driver's constructor, in the same order every run (they are kept by
// their place in that order); a time that a flag sets may be given as a function, read when the
// event is due. A scene with timed events steps one step at a time (no waves: a boundary).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "Boundaries/Boundary.h"

namespace talus {

class Simulation;

class TimedEvents : public Boundary {
public:
    // Made by the scene: TimedEvents& events = scene().addBoundary<TimedEvents>(*this, "events").
    TimedEvents(Made made, Simulation& simulation, const std::string& name);

    void at(double time, std::function<void()> action);
    void at(std::function<double()> time, std::function<void()> action);
    // Whether the event registered k-th (from 0) has run.
    bool done(std::size_t k) const { return events_.at(k).done; }

    bool actsAfterDrift() const override { return true; }
    void afterDrift(Simulation& simulation) override;
    bool runsOnRanks() const override { return true; }  // every rank runs every action

private:
    struct Event {
        std::function<double()> time;
        std::function<void()> action;
        bool done = false;
    };
    std::vector<Event> events_;
};

}  // namespace talus

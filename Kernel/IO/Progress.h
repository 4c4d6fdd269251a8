// Progress lines for long runs: simulated time, percent, wall time, ETA and particle-steps per
// second, printed every few wall seconds, and a summary at the end.
#pragma once

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <string>

namespace talus {

class Progress {
public:
    Progress(std::ostream& out, double intervalSeconds) : out_(out), interval_(intervalSeconds) {}

    void start(const std::string& name, double time, double endTime, std::uint64_t steps, std::size_t particles);
    // Call after every step, or every few (a wave of steps: Documentation/TimeSkewing.md), with
    // the steps done so far and the particles of the steps since the last call; prints when the
    // interval has passed since the last line.
    void update(double time, std::uint64_t stepsDone, std::size_t particles);
    void finish(double time, std::uint64_t stepsDone);
    // The run now ends at endTime after totalSteps steps in all (a driver brought its end time
    // forward: Simulation::solve): the percentage and the ETA count to it.
    void moveEnd(double endTime, std::uint64_t totalSteps) { endTime_ = endTime, totalSteps_ = totalSteps; }

    double particleStepsPerSecond() const;
    double particleSteps() const { return particleSteps_; }
    double wallSeconds() const;

private:
    using Clock = std::chrono::steady_clock;
    std::ostream& out_;
    double interval_;
    std::string name_;
    double startTime_ = 0, endTime_ = 0;
    std::uint64_t totalSteps_ = 0;
    Clock::time_point wallStart_, lastPrint_;
    double particleSteps_ = 0;
    std::uint64_t stepsDone_ = 0;  // at the last update
};

}  // namespace talus

#include "IO/Progress.h"

#include <cstdio>
#include <ostream>

namespace talus {

void Progress::start(const std::string& name, double time, double endTime, std::uint64_t steps, std::size_t particles) {
    name_ = name;
    startTime_ = time;
    endTime_ = endTime;
    totalSteps_ = steps;
    particleSteps_ = 0;
    stepsDone_ = 0;
    wallStart_ = lastPrint_ = Clock::now();
    char line[256];
    std::snprintf(line, sizeof line, "%s: running from t = %g to %g (%llu steps, %zu particles)\n", name.c_str(), time,
                  endTime, static_cast<unsigned long long>(steps), particles);
    out_ << line << std::flush;
}

void Progress::update(double time, std::uint64_t stepsDone, std::size_t particles) {
    const std::uint64_t since = stepsDone - stepsDone_;
    particleSteps_ += static_cast<double>(particles) * static_cast<double>(since);
    const bool everyFewSteps = (stepsDone >> 6) != (stepsDone_ >> 6);  // read the clock every 64 steps only
    stepsDone_ = stepsDone;
    if (!everyFewSteps) return;
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - lastPrint_).count() < interval_) return;
    lastPrint_ = now;
    const double wall = wallSeconds();
    const double fraction = totalSteps_ ? static_cast<double>(stepsDone) / totalSteps_ : 1.0;
    const double eta = fraction > 0 ? wall * (1 - fraction) / fraction : 0;
    char line[256];
    std::snprintf(line, sizeof line, "%s: t = %.6g / %g (%5.1f%%)  wall %.1f s  ETA %.1f s  %.3g particle-steps/s\n",
                  name_.c_str(), time, endTime_, 100 * fraction, wall, eta, particleStepsPerSecond());
    out_ << line << std::flush;
}

void Progress::finish(double time, std::uint64_t stepsDone) {
    char line[256];
    std::snprintf(line, sizeof line, "%s: finished at t = %.6g: %llu steps in %.2f s wall, %.3g particle-steps/s\n",
                  name_.c_str(), time, static_cast<unsigned long long>(stepsDone), wallSeconds(),
                  particleStepsPerSecond());
    out_ << line << std::flush;
}

double Progress::wallSeconds() const { return std::chrono::duration<double>(Clock::now() - wallStart_).count(); }

double Progress::particleStepsPerSecond() const {
    const double wall = wallSeconds();
    return wall > 0 ? particleSteps_ / wall : 0;
}

}  // namespace talus

#include "Sampling/SteadyDetector.h"

#include <cmath>

#include "Error.h"
#include "Simulation.h"

namespace talus {

SteadyDetector::SteadyDetector(std::size_t window, double tolerance) { reset(window, tolerance); }

SteadyDetector::SteadyDetector(Simulation& simulation, const std::string& name, std::size_t window, double tolerance)
    : SteadyDetector(window, tolerance) {
    simulation.keepInRestart(name, [this] { return state(); }, [this](const std::vector<double>& v) { restore(v); });
}

void SteadyDetector::reset(std::size_t window, double tolerance) {
    require(window >= 4, "steady-state window must be at least 4 samples, got " + std::to_string(window));
    require(tolerance > 0, "steady-state tolerance must be positive");
    window_ = window;
    tolerance_ = tolerance;
    history_.clear();
    samples_ = 0;
    steadySince_ = -1;
}

bool SteadyDetector::add(double time, const std::vector<double>& values) {
    require(history_.empty() || values.size() == history_.front().size(),
            "steady-state detector: every sample must have the same number of series");
    history_.push_back(values);
    ++samples_;
    if (history_.size() > window_) history_.erase(history_.begin());
    if (steady() || history_.size() < window_) return steady();
    const double n = static_cast<double>(window_), meanIndex = 0.5 * (n - 1);
    for (std::size_t q = 0; q < values.size(); ++q) {
        double mean = 0;
        for (std::size_t k = 0; k < window_; ++k) mean += history_[k][q];
        mean /= n;
        double covariance = 0, variance = 0;  // of the series with the sample index
        for (std::size_t k = 0; k < window_; ++k) {
            covariance += (k - meanIndex) * (history_[k][q] - mean);
            variance += (k - meanIndex) * (k - meanIndex);
        }
        const double changeOverWindow = covariance / variance * (n - 1);
        if (!(std::abs(changeOverWindow) <= tolerance_ * std::abs(mean))) return false;
    }
    steadySince_ = time;
    return true;
}

std::vector<double> SteadyDetector::state() const {
    std::vector<double> v = {static_cast<double>(window_), tolerance_, static_cast<double>(samples_), steadySince_,
                             static_cast<double>(history_.empty() ? 0 : history_.front().size())};
    for (const std::vector<double>& sample : history_) v.insert(v.end(), sample.begin(), sample.end());
    return v;
}

void SteadyDetector::restore(const std::vector<double>& v) {
    require(v.size() >= 5, "steady-state detector: a saved state needs at least 5 numbers");
    const auto series = static_cast<std::size_t>(v[4]);
    require(series == 0 ? v.size() == 5 : (v.size() - 5) % series == 0 && (v.size() - 5) / series <= v[0],
            "steady-state detector: the saved samples do not fit its window");
    reset(static_cast<std::size_t>(v[0]), v[1]);
    samples_ = static_cast<std::size_t>(v[2]);
    steadySince_ = v[3];
    for (std::size_t at = 5; at < v.size(); at += series) history_.emplace_back(v.begin() + at, v.begin() + at + series);
}

}  // namespace talus

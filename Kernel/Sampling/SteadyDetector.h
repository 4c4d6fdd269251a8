// Whether time series sampled at equal intervals have reached a plateau (a steady flow, a bed at
// rest, a settled packing): steady once, over the last `window` samples, the least-squares line
// through each series changes by at most `tolerance` times the series' mean magnitude from the
// first sample of the window to the last; it stays steady from then on. A trend, not a
// comparison of half-window means: a flow that still accelerates by 0.1% per sample passes a 2%
// test on half-window means of 20 samples, but not this one on 100 samples.
// Made with a simulation and a name, it keeps what it knows in the restart file
// (Simulation::keepInRestart, "NAME"), so that a restarted run goes on watching where it stopped.
// The samples are whole-scene numbers (every rank the same, Sampling/ParticleSums.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace talus {

class Simulation;

class SteadyDetector {
public:
    SteadyDetector(std::size_t window, double tolerance);
    // Kept in the restart file; call from the driver's constructor (and reset() once the flags
    // that set the window are read, in setupInitialConditions).
    SteadyDetector(Simulation& simulation, const std::string& name, std::size_t window = 50, double tolerance = 0.02);
    SteadyDetector(const SteadyDetector&) = default;
    SteadyDetector& operator=(const SteadyDetector&) = default;

    // Forgets every sample and sets the window and tolerance anew.
    void reset(std::size_t window, double tolerance);
    // Adds one sample of every series (the same number of series each time); returns steady().
    bool add(double time, const std::vector<double>& values);
    bool steady() const { return steadySince_ >= 0; }
    double steadySince() const { return steadySince_; }  // time of the sample that made it steady
    std::size_t samples() const { return samples_; }
    std::size_t window() const { return window_; }
    // Everything it knows as numbers (window, tolerance, samples, steady time, the last window
    // of samples), for a restart file, and back.
    std::vector<double> state() const;
    void restore(const std::vector<double>& state);

private:
    std::size_t window_;
    double tolerance_;
    std::vector<std::vector<double>> history_;  // the last window_ samples
    std::size_t samples_ = 0;
    double steadySince_ = -1;
};

}  // namespace talus

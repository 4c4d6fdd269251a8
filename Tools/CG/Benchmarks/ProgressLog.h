// Wall-clock timing and progress lines on stderr for the benchmark: a line at most every
// `interval` seconds, so short runs (the smoke test) stay quiet and long ones (10^6 particles)
// show that they are alive.
#pragma once

#include <chrono>
#include <iostream>
#include <string>

namespace talus::cg::benchmark {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class ProgressLog {
public:
    explicit ProgressLog(double interval = 3) : interval_(interval) {}

    void report(const std::string& message) {
        if (secondsSince(last_) < interval_) return;
        std::cerr << "talus-cg-benchmark: " << message << " (" << static_cast<long>(secondsSince(start_)) << " s)\n";
        last_ = std::chrono::steady_clock::now();
    }

private:
    double interval_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last_ = start_;
};

}  // namespace talus::cg::benchmark

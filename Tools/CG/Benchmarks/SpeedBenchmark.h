// The speed benchmark of issue 5: N random particles (SyntheticFrames.h) coarse-grained with
// the 3-D Lucy kernel onto a regular grid of about 10^4 points, best of a few repetitions.
#pragma once

#include <ostream>
#include <vector>

#include "Benchmarks/ProgressLog.h"

namespace talus::cg::benchmark {

struct SpeedSettings {
    std::vector<long> particleCounts{10000, 100000};
    long pointsPerAxis = 22;  // 22^3 = 10648 points
    double width = 1;
    int speciesCount = 2;
    int repeats = 3;
    // The cube holds the particles at volume fraction 0.5 for 10^5 particles whatever N is, so
    // the work per point grows with N and "points x particles per second" is a throughput.
    long referenceCount = 100000;
    double referenceVolumeFraction = 0.5;
};

// Prints one table row per particle count: setFrame and evaluate seconds of the fastest
// repetition, points x particles per second, microseconds per particle.
void runSpeedBenchmark(const SpeedSettings& settings, std::ostream& out, ProgressLog& progress);

}  // namespace talus::cg::benchmark

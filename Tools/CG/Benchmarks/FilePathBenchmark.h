// The whole path of talus-cg from files to fields (issue 42 item 5), one core: a simple cubic
// lattice of N touching spheres (random velocities, two species) with a contact to each lattice
// neighbour, written as a .data frame and a .fstat frame (every pair from both sides, as Talus and
// MercuryDPM write them, in the formats of Formats/), then timed stage by stage: reading the .data
// frame, reading the .fstat frame, the sums (CoarseGrainer::setFrame with the contact stress, and
// evaluate on a grid), writing the fields (CSV, and VTK for comparison), and the program as a
// user runs it (runCoarseGraining, CSV output), each the best of a few repetitions.
#pragma once

#include <ostream>
#include <string>

#include "Benchmarks/ProgressLog.h"

namespace talus::cg::benchmark {

struct FilePathSettings {
    long particles = 0;          // about (the lattice is the nearest cube); 0: not run
    long pointsPerAxis = 22;     // 22^3 = 10648 points, as the speed benchmark
    double width = 1;            // Lucy, 3-D
    int repeats = 3;
    std::string directory;       // where the files go (default: a new folder in the temporary directory)
};

// Prints one line per stage (seconds, share of the total, particles per second) and the program's
// own time; removes the files it wrote unless settings.directory named their folder.
void runFilePathBenchmark(const FilePathSettings& settings, std::ostream& out, ProgressLog& progress);

}  // namespace talus::cg::benchmark

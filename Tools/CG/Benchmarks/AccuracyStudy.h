// The speed-against-error study of issue 5: a slab of spheres on a cubic lattice (periodic in x
// and y) coarse-grained in 3-D with the Lucy kernel, for several grid spacings h and widths w.
// Per (w, h): the time of the evaluation, the error of the total mass (midpoint rule over the
// grid against the number of spheres) and of the density profile against the uniform slab's
// (SlabProfile.h), in the bulk and everywhere.
#pragma once

#include <ostream>
#include <vector>

#include "Benchmarks/ProgressLog.h"

namespace talus::cg::benchmark {

struct AccuracySettings {
    std::vector<double> widths{0.5, 1, 1.5, 2};
    std::vector<double> spacings{1, 0.5, 0.25, 0.125};
    int side = 6;    // lattice sites along x and y (the periodic box)
    int height = 8;  // layers along z
    double margin = 2;  // the grid reaches this far below and above the slab: w <= margin + 1/2
};

void runAccuracyStudy(const AccuracySettings& settings, std::ostream& out, ProgressLog& progress);

}  // namespace talus::cg::benchmark

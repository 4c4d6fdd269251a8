// talus-cg --width-scan: reads the frames of the time window, scans the widths of two
// directions at the scan points (Fields/WidthScan.h, Theory/CoarseGraining.md "Choosing the
// widths") and writes the scan as CSV: '#' lines (inputs, rule, points, result), then one row per
// point and width pair: point, w<a>, w<b>, value, sensitivity, particles, insensitive, plateau.
// Tools/Plot/plotWidthScan.py draws it. Progress and the chosen widths go to `log`.
#pragma once

#include <ostream>

#include "App/Options.h"

namespace talus::cg {

// Returns the number of frames scanned; throws InputError for bad input.
int runWidthScan(const ProgramOptions& options, std::ostream& log);

}  // namespace talus::cg

// One run of talus-cg: resolves the options against the files found (restart, fstat), reads the
// frames in the selected time window, coarse-grains them at the evaluation points, averages if
// asked and writes the CSV file; progress lines go to `log`.
#pragma once

#include <ostream>

#include "App/Options.h"

namespace talus::cg {

// Returns the number of frames coarse-grained; throws InputError for bad input.
int runCoarseGraining(const ProgramOptions& options, std::ostream& log);

}  // namespace talus::cg

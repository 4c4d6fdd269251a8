// The .restart file: the whole SimulationState in text, numbers with 17 significant digits so
// that every double reads back bitwise (Documentation/FileFormats/restart.md). A restarted run
// continues exactly as the uninterrupted run would have.
//
// Reading checks everything: a missing file, a wrong keyword, a bad number, an index out of
// range or a truncated file each give a talus::Error naming the file and line.
#pragma once

#include <string>

#include "SimulationState.h"

namespace talus {

void writeRestartFile(const std::string& path, const SimulationState& state);
void readRestartFile(const std::string& path, SimulationState& state);

}  // namespace talus

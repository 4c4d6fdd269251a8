// A talus-shallow run: builds the solver from the options, steps to the end time, writes the
// profiles and the front diagnostics at the output times and reports its progress and speed.
#pragma once

#include <ostream>

#include "App/Options.h"

namespace talus::shallow {

void runShallowFlow(const ProgramOptions& options, std::ostream& log);

}  // namespace talus::shallow

#include "Sampling/Messages.h"

#include <cstdarg>
#include <cstdio>

#include "IO/DurableFile.h"
#include "Simulation.h"

namespace talus {

void say(const Simulation& simulation, const char* format, ...) {
    if (simulation.ranks().rank() != 0) return;
    va_list arguments;
    va_start(arguments, format);
    std::vprintf(format, arguments);
    va_end(arguments);
}

void writeFileOnce(const Simulation& simulation, const std::string& path, const std::function<void(std::ostream&)>& write) {
    if (simulation.ranks().rank() == 0) replaceFile(path, write);
}

void requireOnAllRanks(const Simulation& simulation, bool condition, const std::string& message) {
    if (!condition) throw CollectiveError(message, simulation.ranks().rank() != 0);
}

}  // namespace talus

// A driver's messages, small files and whole-scene checks, written once whatever the rank count:
// say() prints on rank 0 only (printf format); writeFileOnce() writes a whole file on rank 0
// (replacing it safely, IO/DurableFile.h); requireOnAllRanks() stops the run on every rank with
// one message when a condition that every rank has computed alike (a whole-scene sum) fails.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace talus {

class Simulation;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void say(const Simulation& simulation, const char* format, ...);

void writeFileOnce(const Simulation& simulation, const std::string& path, const std::function<void(std::ostream&)>& write);

// Throws on every rank (rank 0's copy of the error is the one printed); call on all ranks.
void requireOnAllRanks(const Simulation& simulation, bool condition, const std::string& message);

}  // namespace talus

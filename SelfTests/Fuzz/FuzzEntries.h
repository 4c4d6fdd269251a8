// The entry functions of the fuzz targets: each feeds one input to one reader (or to a driver's
// command line) and returns when the reader succeeded or refused the input with its clean error
// (talus::Error, cg::InputError). Anything else is a finding: another exception escapes, a
// sanitizer stops the program, or the reader accepted input that breaks what it promises (a
// std::logic_error "accepted garbage: ..."). FuzzTarget.cc makes each a libFuzzer target;
// Replay.cc feeds the stored inputs to the same functions under ctest. They return true when the
// input was accepted, false when it was refused cleanly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace talus::fuzz {

bool lammpsData(const std::uint8_t* data, std::size_t size);    // Kernel/IO/LammpsDataFile.h
bool talusRestart(const std::uint8_t* data, std::size_t size);  // Kernel/IO/RestartFile.h
bool cgData(const std::uint8_t* data, std::size_t size);        // Tools/CG/IO/DataFileReader.h
bool cgFstat(const std::uint8_t* data, std::size_t size);       // Tools/CG/IO/FstatFileReader.h
bool cgRestart(const std::uint8_t* data, std::size_t size);     // Tools/CG/IO/RestartFileReader.h
bool commandLine(const std::uint8_t* data, std::size_t size);   // Kernel/IO/CommandLine.h via Simulation

// The readers take paths: the input is written to a scratch file of this process (one per
// target name, in $TMPDIR or /tmp), whose path is returned.
std::string scratchFile(const char* target, const std::uint8_t* data, std::size_t size);

// Throws std::logic_error("accepted garbage: " + what) unless `holds`.
void promise(bool holds, const std::string& what);

}  // namespace talus::fuzz

// What the CG tool takes from a restart file (Talus's, Documentation/FileFormats/restart.md, or
// MercuryDPM's): the density of each species (the .data file has no masses), which directions
// are periodic, and which particles are fixed (the base of a chute), in .data line order.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace talus::cg {

struct RestartInfo {
    std::string writer;                   // "Talus" or "MercuryDPM"
    std::vector<double> speciesDensity;   // by species index
    std::array<bool, 3> periodic{false, false, false};
    // Fixed flag per particle, in the order of the .data lines of the restart's frame
    // (Talus: ascending global id; MercuryDPM: particle index).
    std::vector<bool> fixed;
    double time = 0;
};

// Throws InputError naming file and line for files it cannot understand.
RestartInfo readRestartFile(const std::string& path);

}  // namespace talus::cg

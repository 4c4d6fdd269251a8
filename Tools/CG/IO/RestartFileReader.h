// What the CG tool takes from a restart file (Talus's, Documentation/FileFormats/restart.md, or
// MercuryDPM's): the density of each species (the .data file has no masses), which directions
// are periodic, which particles are fixed (the base of a chute), in .data line order, and the
// cylinder walls of a drum (the default axis of cylindrical coordinates).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace talus::cg {

// A cylinder wall of a Talus restart file (the mantle of a rotating drum, Theory/RotatingDrum.md eq. (2)): a point of
// its axis, the axis direction and the radius.
struct CylinderWall {
    std::array<double, 3> axisPoint{0, 0, 0};
    std::array<double, 3> axisDirection{0, 0, 1};
    double radius = 0;
};

struct RestartInfo {
    std::string writer;                   // "Talus" or "MercuryDPM"
    std::vector<double> speciesDensity;   // by species index
    std::array<bool, 3> periodic{false, false, false};
    // Fixed flag per particle, in the order of the .data lines of the restart's frame
    // (Talus: ascending global id; MercuryDPM: particle index).
    std::vector<bool> fixed;
    std::vector<CylinderWall> cylinders;  // Talus `walls` with radius > 0 (MercuryDPM: not read)
    double time = 0;
};

// Throws InputError naming file and line for files it cannot understand.
RestartInfo readRestartFile(const std::string& path);

}  // namespace talus::cg

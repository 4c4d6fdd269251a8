// What the CG tool takes from a restart file (Talus's, Documentation/FileFormats/restart.md, or
// MercuryDPM's): the density of each species (the .data file has no masses), which directions
// are periodic, which particles are fixed (the base of a chute), in .data line order, the
// cylinder walls of a drum (the default axis of cylindrical coordinates), and from Talus's the
// superquadric shapes of the particles (IO/ParticleShapes.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "IO/ParticleShapes.h"

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
    // Talus: the superquadrics of the `shapes` section, and the particles in ascending id (the
    // order of the .data lines), whose shape indices point into `shapes`. MercuryDPM: empty.
    std::vector<SuperquadricShape> shapes;
    std::vector<RestartParticle> particles;
    double time = 0;
};

// Throws InputError naming file and line for files it cannot understand.
RestartInfo readRestartFile(const std::string& path);

}  // namespace talus::cg

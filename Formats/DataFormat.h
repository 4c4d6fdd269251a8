// The .data file (Documentation/FileFormats/data.md), MercuryDPM's 3-D layout: per frame a header
// line `N t xmin ymin zmin xmax ymax zmax`, then N particle lines of 14 columns. The one
// description of its columns: the kernel's writer (Kernel/IO/MercuryFormats.cc) prints them with
// the line formats below, in column order, and talus-cg's reader (Tools/CG/IO/DataFileReader.cc)
// takes them by these names.
#pragma once

#include "Formats/Conversions.h"

namespace talus::formats::data {

// The fields of a frame header.
enum HeaderField : int {
    particleCount,                   // N, the number of particle lines that follow
    time,                            // t
    lowerCorner,                     // xmin ymin zmin: the domain box (the periodic box along periodic axes)
    upperCorner = lowerCorner + 3,   // xmax ymax zmax
    headerFields = upperCorner + 3,  // 8
};
// MercuryDPM's 2-D layout has a header of 6 fields (N t xmin ymin xmax ymax); talus-cg refuses it.
inline constexpr int headerFields2d = 6;

// The columns of a particle line.
enum Column : int {
    position,                           // x y z: the centre
    velocity = position + 3,            // vx vy vz
    radius = velocity + 3,              // r (a non-spherical particle: its bounding radius)
    orientation,                        // thx thy thz: roll, pitch, yaw (Tait-Bryan Z-Y-X); 0 for spheres
    angularVelocity = orientation + 3,  // wx wy wz, lab frame
    info = angularVelocity + 3,         // the species index
    columns,                            // 14
};

// Positions with 15 significant digits, the rest with 10, as MercuryDPM writes them (the header
// ends with a space before the newline, as MercuryDPM's does).
inline constexpr const char* headerLine = "%zu %.10g %.10g %.10g %.10g %.10g %.10g %.10g \n";
inline constexpr const char* particleLine =
    "%.15g %.15g %.15g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %u\n";
static_assert(conversions(headerLine) == headerFields && conversions(particleLine) == columns);

}  // namespace talus::formats::data

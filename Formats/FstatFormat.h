// The .fstat file (Documentation/FileFormats/fstat.md), MercuryDPM's layout: per frame three
// header lines starting with '#' (`# t 1`, `# xmin ymin zmin xmax ymax zmax`, `# rmin rmax 0 0 0
// 0`), then one line of 16 columns per contact side. The one description of its columns: the
// kernel's writer (Kernel/IO/MercuryFormats.cc) prints them with the line formats below, in
// column order, and talus-cg's reader (Tools/CG/IO/FstatFileReader.cc) takes them by these names.
#pragma once

#include "Formats/Conversions.h"

namespace talus::formats::fstat {

// The first header line `# t marker`: marker 1 says that columns 4-6 hold the contact point
// (older MercuryDPM files wrote 0 and a centre point).
inline constexpr long contactPointMarker = 1;
inline constexpr int headerLines = 3;

enum Column : int {
    time,                      // t, the frame time
    particle,                  // i, the global id of the particle this line describes
    partner,                   // j, the partner's id, or -(w + 1) for wall w
    contactPoint,              // cx cy cz
    overlap = contactPoint + 3,  // dn
    tangentialOverlap,         // dt: minus the length of the tangential spring
    normalForce,               // fn
    tangentialForce,           // |ft|
    normal,                    // nx ny nz: from j to i (walls: into the wall)
    tangent = normal + 3,      // tx ty tz: along the tangential force on i (walls: against it)
    columns = tangent + 3,     // 16
};

// Every real with 10 significant digits, as MercuryDPM writes them.
inline constexpr const char* header = "# %.10g %ld\n# %.10g %.10g %.10g %.10g %.10g %.10g\n# %.10g %.10g 0 0 0 0\n";
inline constexpr int headerValues = 10;  // t, the marker, the box (6), rmin, rmax
inline constexpr const char* contactLine =
    "%.10g %llu %lld %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g\n";
static_assert(conversions(header) == headerValues && conversions(contactLine) == columns);

}  // namespace talus::formats::fstat

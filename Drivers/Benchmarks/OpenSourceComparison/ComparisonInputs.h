// The inputs of the 2024 comparison of open-source DEM codes (Dosta et al., Computer Physics
// Communications 296 (2024) 109066; Documentation/Benchmarks/OpenSourceComparison.md), shared by
// its three drivers: the materials and their pairs (Hertz-Mindlin, SI units), and the readers of
// the published start files (a header line, then radius x y z per particle, in metres) and wall
// triangles.
#pragma once

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "Error.h"
#include "IO/InputNumbers.h"
#include "IO/StlReader.h"
#include "Math/Vector.h"
#include "Species/Materials.h"

namespace talus::comparison {

// M1, M2 and steel with the pairs' restitution and sliding friction of the comparison; the soft
// variant (for a larger time step) takes E = 2e6 Pa for M1 and 1e6 Pa for M2.
inline MaterialTable materials(bool soft) {
    MaterialTable t;
    t.add({"M1", 2500, soft ? 2e6 : 1e9, 0.2});
    t.add({"M2", 2000, soft ? 1e6 : 0.5e9, 0.2});
    t.add({"steel", 7200, 210e9, 0.2});
    t.setPair("M1", "M1", {.restitution = 0.5, .friction = 0.3});
    t.setPair("M1", "M2", {.restitution = 0.45, .friction = 0.2});
    t.setPair("M1", "steel", {.restitution = 0.4, .friction = 0.2});
    t.setPair("M2", "M2", {.restitution = 0.4, .friction = 0.4});
    t.setPair("M2", "steel", {.restitution = 0.4, .friction = 0.2});
    t.setPair("steel", "steel", {.restitution = 0.6, .friction = 0.5});
    return t;
}

struct StartParticle {
    double radius;
    Vec3 position;
};

// A start file: one header line, then "radius x y z" per line, read with the kernel's strict
// numbers (IO/InputNumbers.h); a word that is not a finite number, a line of other than four
// words or a radius that is not positive is an error naming the file and the line. The
// penetration's beds end with a line of six numbers that describes the steel sphere, not a bead
// (MercuryDPM's driver for the comparison drops it too): `lastLineIsNotABead` skips the last line
// that has words, and requires it to have six (a bed without it would lose a bead silently).
inline std::vector<StartParticle> readStartParticles(const std::string& path, bool lastLineIsNotABead = false) {
    std::ifstream in(path);
    require(static_cast<bool>(in), "cannot open the start file '" + path + "' (give its path with --start-file)");
    InputPlace place("start file " + path);
    std::vector<StartParticle> particles;
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::size_t last = lines.size();
    if (lastLineIsNotABead)
        while (last > 1 && lines[last - 1].find_first_not_of(" \t\r") == std::string::npos) --last;
    for (std::size_t k = 0; k < lines.size(); ++k, ++place.line) {
        std::istringstream fields(lines[k]);
        std::vector<std::string> words;
        for (std::string word; fields >> word;) words.push_back(word);
        if (lastLineIsNotABead && k + 1 == last) {
            if (words.size() != 6)
                place.fail("the last line describes the steel sphere (six numbers, as in the published beds), found " +
                           std::to_string(words.size()) + " words");
            continue;
        }
        if (place.line == 1 || words.empty()) continue;  // (the header)
        if (words.size() != 4) place.fail("a particle is 4 numbers (radius x y z), found " + std::to_string(words.size()) + " words");
        StartParticle p{place.real(words[0], "the radius"), Vec3::Zero()};
        if (!(p.radius > 0)) place.fail("the radius must be positive, got " + str(p.radius));
        for (int a = 0; a < 3; ++a) p.position[a] = place.real(words[1 + a], std::string("the ") + "xyz"[a]);
        particles.push_back(p);
    }
    require(!particles.empty(), "the start file '" + path + "' holds no particles");
    return particles;
}

// A case's walls as triangles (--walls): an STL file (a name ending in .stl, ASCII or binary) or
// the comparison's table (Drum/walls.txt, Silo/walls-*-orifice.txt: a header, then the nine
// coordinates of a triangle's corners a line).
inline TriangleMesh readWallTriangles(const std::string& path) {
    const bool stl = path.size() > 4 && path.substr(path.size() - 4) == ".stl";
    return stl ? readStl(path) : readTriangleTable(path);
}

}  // namespace talus::comparison

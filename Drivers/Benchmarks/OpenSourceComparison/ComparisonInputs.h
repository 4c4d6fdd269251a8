// The inputs of the 2024 comparison of open-source DEM codes (Dosta et al., Computer Physics
// Communications 296 (2024) 109066; Documentation/Benchmarks/OpenSourceComparison.md), shared by
// its three drivers: the materials and their pairs (Hertz-Mindlin, SI units), and the readers of
// the published start files (a header line, then radius x y z per particle, in metres).
#pragma once

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "Error.h"
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

// A start file: one header line, then "radius x y z" per line. Every value must be a finite
// number and every radius positive; an error names the file and the line.
inline std::vector<StartParticle> readStartParticles(const std::string& path) {
    std::ifstream in(path);
    require(static_cast<bool>(in), "cannot open the start file '" + path + "' (give its path with --start-file)");
    std::vector<StartParticle> particles;
    std::string line;
    std::getline(in, line);  // the header
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::istringstream fields(line);
        StartParticle p{};
        double x, y, z;
        std::string extra;
        const bool read = static_cast<bool>(fields >> p.radius >> x >> y >> z) && !(fields >> extra);
        require(read && std::isfinite(p.radius) && std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && p.radius > 0,
                path + ":" + std::to_string(number) + ": expected four numbers 'radius x y z' with a positive radius, got '" +
                    line + "'");
        p.position = Vec3(x, y, z);
        particles.push_back(p);
    }
    require(!particles.empty(), "the start file '" + path + "' holds no particles");
    return particles;
}

}  // namespace talus::comparison

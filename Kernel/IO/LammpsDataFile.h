// Reader of LAMMPS data files of atom style sphere (the start files of the peer benchmarks in
// shared/peers/data): the box, and per atom its id, type, diameter, density, position and, from
// an optional Velocities section, velocity and angular velocity. Every malformed line is a
// talus::Error naming the file and line.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Math/Vector.h"

namespace talus {

struct LammpsAtom {
    std::uint64_t id = 0;
    int type = 0;
    double diameter = 0, density = 0;
    Vec3 position = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    Vec3 angularVelocity = Vec3::Zero();
};

struct LammpsData {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
    int types = 0;
    std::vector<LammpsAtom> atoms;  // in file order
};

LammpsData readLammpsData(const std::string& path);

}  // namespace talus

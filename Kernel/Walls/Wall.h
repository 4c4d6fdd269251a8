// An infinite plane wall of any orientation. The normal points into the half-space the particles
// occupy; a sphere of radius r at x touches the wall when (x - point) . normal < r.
// A wall may follow a prescribed motion (motion >= 0), which moves its point and turns its normal.
#pragma once

#include <cstdint>

#include "Math/Vector.h"

namespace talus {

struct PlaneWall {
    Vec3 normal = Vec3::UnitZ();
    Vec3 point = Vec3::Zero();
    std::uint32_t species = 0;
    std::int32_t motion = -1;

    double signedDistance(const Vec3& x) const { return (x - point).dot(normal); }
};

}  // namespace talus

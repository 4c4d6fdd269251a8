// Small fixed-size linear algebra used throughout the kernel (Documentation/Architecture.md "Data layout").
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace talus {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

inline constexpr double pi = 3.14159265358979323846;

inline double degrees(double angleInDegrees) { return angleInDegrees * pi / 180.0; }

inline bool isFinite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

}  // namespace talus

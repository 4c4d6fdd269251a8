// A wall: an infinite plane of any orientation, or the inside of an infinite cylinder (the
// mantle of a rotating drum, Theory/RotatingDrum.md). Both are described by a point, a unit vector
// and a radius:
//   plane (radius 0): `normal` points into the half-space the particles occupy; a sphere of
//     radius r at x touches the wall when (x - point) . normal < r;
//   cylinder (radius R > 0): `point` lies on the axis and `normal` is the axis direction; the
//     particles are inside, and a sphere at distance rho from the axis touches when R - rho < r.
// signedDistance is the distance from the wall, positive on the particles' side, and normalAt
// the unit normal of the wall nearest to x, pointing to the particles' side (for a cylinder:
// towards the axis). A non-spherical particle meets the tangent plane of the wall nearest to its
// centre (the linearisation of Theory/Superquadrics.md "Walls"; its error grows with elongation and
// curvature). A wall may follow a prescribed motion (motion >= 0), which moves its point and turns
// its normal (a drum turning about its own axis keeps both, and its surface moves with the motion).
#pragma once

#include <cmath>
#include <cstdint>

#include "Math/Vector.h"

namespace talus {

struct Wall {
    Vec3 normal = Vec3::UnitZ();  // plane: the normal; cylinder: the axis direction
    Vec3 point = Vec3::Zero();    // plane: a point of it; cylinder: a point of the axis
    std::uint32_t species = 0;
    std::int32_t motion = -1;
    double radius = 0;            // 0: a plane; > 0: the inside of a cylinder of this radius

    bool isCylinder() const { return radius > 0; }

    double signedDistance(const Vec3& x) const {
        if (!isCylinder()) return (x - point).dot(normal);
        return radius - fromAxis(x).norm();
    }

    Vec3 normalAt(const Vec3& x) const {
        if (!isCylinder()) return normal;
        const Vec3 out = fromAxis(x);
        const double rho = out.norm();
        // On the axis every direction is as near: any one perpendicular to it.
        return rho > 0 ? Vec3(-out / rho) : Vec3(normal.unitOrthogonal());
    }

    // Signed distance of y from the tangent plane of the wall at the point nearest to x.
    double tangentPlaneDistance(const Vec3& y, const Vec3& x) const {
        if (!isCylinder()) return signedDistance(y);
        return radius + normalAt(x).dot(y - point);
    }

private:
    // The part of x - point perpendicular to the axis.
    Vec3 fromAxis(const Vec3& x) const {
        const Vec3 d = x - point;
        return d - d.dot(normal) * normal;
    }
};

}  // namespace talus

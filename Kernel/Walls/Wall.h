// A wall: an infinite plane of any orientation, the inside of an infinite cylinder (the mantle
// of a rotating drum, Theory/RotatingDrum.md), or one segment of a surface of revolution (a
// silo's cone, Theory/ContactLaws.md "Surfaces of revolution"). All are described by a point, a
// unit vector and their own numbers:
//   plane (radius 0, no profile): `normal` points into the half-space the particles occupy; a
//     sphere of radius r at x touches the wall when (x - point) . normal < r;
//   cylinder (radius R > 0): `point` lies on the axis and `normal` is the axis direction; the
//     particles are inside, and a sphere at distance rho from the axis touches when R - rho < r;
//   revolved segment (`profile` of non-zero length): `point` lies on the axis and `normal` is the
//     axis direction; the segment from (rho, z) = (profile[0], profile[1]) to (profile[2],
//     profile[3]), in distance rho from the axis and height z along it from `point`, turned about
//     the axis: a frustum of a cone, an annulus or a finite cylinder. Particles may meet either
//     side; the distance is to the segment's nearest point, ends included. Its ends are open rims
//     (circles a particle may touch) or joints with the neighbouring segments of one profile
//     (Scene::addRevolvedWall): a joint is one place of the surface, so the segment it ends counts
//     it, and only where the segment after it (direction `next` from the joint) is nearest there
//     too, and the segment it starts (startJoined) never does.
// signedDistance is the distance from the wall, positive on the particles' side, and normalAt
// the unit normal of the wall nearest to x, pointing to the particles' side (for a cylinder:
// towards the axis). A non-spherical particle meets the tangent plane of the wall nearest to its
// centre (the linearisation of Theory/Superquadrics.md "Walls"; its error grows with elongation and
// curvature). A wall may follow a prescribed motion (motion >= 0), which moves its point and turns
// its normal (a drum turning about its own axis keeps both, and its surface moves with the motion).
// A motion that moves the surface only within itself (slidesInPlaceUnder) leaves the wall where it
// is: the neighbour list takes it as resting (PairList::rebuild) while it slides so.
// A triangle of a mesh (Walls/MeshWalls.h) is met at its point nearest to x, counted by the face,
// edge and vertex rule of Walls/MeshContact.h; it moves with its mesh (MeshWalls::move).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "Math/Vector.h"
#include "Walls/PrescribedMotion.h"

namespace talus {

struct MeshWalls;

struct Wall {
    Vec3 normal = Vec3::UnitZ();  // plane: the normal; cylinder: the axis direction
    Vec3 point = Vec3::Zero();    // plane: a point of it; cylinder: a point of the axis
    std::uint32_t species = 0;
    std::int32_t motion = -1;
    double radius = 0;            // 0: a plane; > 0: the inside of a cylinder of this radius
    // A revolved segment: its ends (rho0, z0, rho1, z1); all 0 for a plane or a cylinder.
    std::array<double, 4> profile{};
    // A revolved segment's end 1: (0, 0) an open rim, else the unit direction (drho, dz) of the
    // next segment from the joint.
    std::array<double, 2> next{};
    bool startJoined = false;     // a revolved segment's end 0 is a joint (which it leaves)
    // A triangle: its mesh and its index there (normal and point: the triangle's normal and first
    // corner); no mesh for the other kinds.
    const MeshWalls* mesh = nullptr;
    std::uint32_t triangle = 0;

    bool isTriangle() const { return mesh != nullptr; }
    // Its motion slid it within its own surface at the last step (set as the walls move,
    // Integration/PlainVerlet.cc); false for a triangle (its mesh moves: Walls/MeshWalls.h).
    bool slidesInPlace = false;

    // Whether motion m moves the wall only within its own surface: a plane translated along itself
    // and turned about its normal, a cylinder translated along and turned about its axis, a revolved
    // segment turned about its axis (a drum's mantle and ends turning with it).
    bool slidesInPlaceUnder(const PrescribedMotion& m) const {
        if (isTriangle()) return false;
        constexpr double parallel = 1e-12;  // (relative: rounding of the vectors' directions)
        const Vec3& w = m.angularVelocity;
        if (w.cross(normal).norm() > parallel * w.norm()) return false;
        if (!isCylinder() && !isRevolved()) return std::abs(m.velocity.dot(normal)) <= parallel * m.velocity.norm();
        const Vec3 offAxis = (m.centre - point).cross(normal);
        if (w != Vec3::Zero() && offAxis.norm() > parallel * (m.centre - point).norm()) return false;
        return isCylinder() ? m.velocity.cross(normal).norm() <= parallel * m.velocity.norm() : m.velocity == Vec3::Zero();
    }

    bool isCylinder() const { return radius > 0; }
    bool isRevolved() const { return profile[0] != profile[2] || profile[1] != profile[3]; }

    // The point of a revolved segment nearest to x, and whether a contact there counts.
    struct RevolvedPoint {
        Vec3 point, normal;   // normal: unit, from the point towards x
        double distance;
        double hoopCurvature;  // of the surface along the circle through the point, seen from x's side
        bool counts;
    };
    RevolvedPoint revolvedPointNearest(const Vec3& x) const;

    // Plane and cylinder: the signed distance, positive on the particles' side. Revolved segment
    // or triangle: the distance to its nearest point, counted or not (the rule for listing
    // candidates).
    double signedDistance(const Vec3& x) const {
        if (isTriangle()) [[unlikely]] return triangleGap(x, 0).distance;
        if (isRevolved()) [[unlikely]] return revolvedPointNearest(x).distance;
        if (!isCylinder()) return (x - point).dot(normal);
        return radius - fromAxis(x).norm();
    }

    // Where a sphere centred at x meets the wall: the distance, the unit normal from the wall
    // towards x, the wall's curvature at its nearest point along the one direction it curves in
    // (0 for a plane; cylinders and surfaces of revolution are straight along their generators),
    // positive where it is concave seen from x, and whether a contact there counts (a revolved
    // segment's joint, above).
    struct Gap {
        double distance;
        Vec3 normal;
        double curvature;
        bool counts;
    };
    Gap gapTo(const Vec3& x) const {
        if (isTriangle()) [[unlikely]] return triangleGap(x, std::numeric_limits<double>::infinity());
        if (isRevolved()) [[unlikely]] {
            const RevolvedPoint q = revolvedPointNearest(x);
            return {q.distance, q.normal, q.hoopCurvature, q.counts};
        }
        if (!isCylinder()) return {(x - point).dot(normal), normal, 0, true};
        return {signedDistance(x), normalAt(x), 1 / radius, true};
    }

    Vec3 normalAt(const Vec3& x) const {
        if (isTriangle()) [[unlikely]] return triangleGap(x, 0).normal;
        if (isRevolved()) [[unlikely]] return revolvedPointNearest(x).normal;
        if (!isCylinder()) return normal;
        const Vec3 out = fromAxis(x);
        const double rho = out.norm();
        // On the axis every direction is as near: any one perpendicular to it.
        return rho > 0 ? Vec3(-out / rho) : Vec3(normal.unitOrthogonal());
    }

    // Signed distance of y from the tangent plane of the wall at the point nearest to x (infinite
    // for a revolved segment whose nearest point to x does not count).
    double tangentPlaneDistance(const Vec3& y, const Vec3& x) const {
        if (isTriangle()) [[unlikely]] {
            const Gap g = triangleGap(x, std::numeric_limits<double>::infinity());
            return g.counts ? g.normal.dot(y - x) + g.distance : std::numeric_limits<double>::infinity();
        }
        if (isRevolved()) [[unlikely]] {
            const RevolvedPoint q = revolvedPointNearest(x);
            return q.counts ? q.normal.dot(y - q.point) : std::numeric_limits<double>::infinity();
        }
        if (!isCylinder()) return signedDistance(y);
        return radius + normalAt(x).dot(y - point);
    }

    // A triangle's gap (Walls/MeshWalls.cc; MeshContact.h triangleGap, whose countWithin it
    // passes on): no curvature (a face is flat; its edges and corners are met as a plane through
    // the nearest point, as LIGGGHTS meets them).
    Gap triangleGap(const Vec3& x, double countWithin) const;

private:

    // The part of x - point perpendicular to the axis.
    Vec3 fromAxis(const Vec3& x) const {
        const Vec3 d = x - point;
        return d - d.dot(normal) * normal;
    }
};

// Theory/ContactLaws.md eq. (6a).
inline Wall::RevolvedPoint Wall::revolvedPointNearest(const Vec3& x) const {
    const Vec3 d = x - point;
    const double z = d.dot(normal);
    const Vec3 radial = d - z * normal;
    const double rho = radial.norm();
    // On the axis every direction is as near: any one perpendicular to it.
    const Vec3 outward = rho > 0 ? Vec3(radial / rho) : Vec3(normal.unitOrthogonal());
    const double sRho = profile[2] - profile[0], sZ = profile[3] - profile[1];
    const double t = std::clamp(((rho - profile[0]) * sRho + (z - profile[1]) * sZ) / (sRho * sRho + sZ * sZ), 0.0, 1.0);
    const double cRho = profile[0] + t * sRho, cZ = profile[1] + t * sZ;
    const double gRho = rho - cRho, gZ = z - cZ;
    RevolvedPoint q;
    q.distance = std::hypot(gRho, gZ);
    // (A centre on the surface takes the segment's normal on the side of increasing rho x dz.)
    const double nRho = q.distance > 0 ? gRho / q.distance : sZ / std::hypot(sRho, sZ);
    const double nZ = q.distance > 0 ? gZ / q.distance : -sRho / std::hypot(sRho, sZ);
    q.normal = nRho * outward + nZ * normal;
    q.point = point + cZ * normal + cRho * outward;
    if (t <= 0)
        q.counts = !startJoined;
    else if (t >= 1)
        q.counts = (next[0] == 0 && next[1] == 0) || gRho * next[0] + gZ * next[1] <= 0;
    else
        q.counts = true;
    // Meusnier (Theory/ContactLaws.md eq. (6b)): the circle of radius cRho through the point
    // curves the surface by -nRho / cRho along it, concave (positive) where x is on the axis's
    // side. A rim or a point on the axis is met as a corner: no curvature of its own.
    q.hoopCurvature = (t > 0 && t < 1 && cRho > 0) ? -nRho / cRho : 0;
    return q;
}

}  // namespace talus

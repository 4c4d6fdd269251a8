// What a contact law needs to know about one contact, and what it returns (Theory/ContactLaws.md
// eq. (1)-(3)). Filled by the force loop for particle-particle and particle-wall contacts alike, so
// that each law is written once for both.
#pragma once

#include <algorithm>
#include <cmath>

#include "Math/Vector.h"

namespace talus {

struct ContactKinematics {
    Vec3 normal;               // unit normal from j (or the wall) to i
    double overlap;            // dn > 0
    Vec3 relativeVelocity;     // vij = vi - vj of the centres (walls: at the contact point)
    double normalVelocity;     // vij . n (negative while approaching)
    Vec3 tangentialVelocity;   // vt of Theory/ContactLaws.md eq. (4), including the spin terms
    double inverseReducedMass; // 1/mi + 1/mj; 1/mi for walls and fixed partners
    // d(vij . n)/dt from all the other forces on the two particles, as of the last step (gravity,
    // other contacts): what the implicit end-of-step speed of the dashpot must include, or a
    // pair at rest under load would see a spurious speed and a spurious damping force.
    double otherAcceleration = 0;
    double effectiveRadius;    // ri rj / (ri + rj); ri for walls
    double inverseDistance;    // 1 / |ri - rj| for particle pairs; 0 for walls (advanceTangentialSpring)
    // Laws with rolling resistance only (set by the force loop for those, else left unset):
    Vec3 relativeSpin;         // wi - wj (walls: wi minus the wall's angular velocity)
    double rollingRadius;      // ri rj / (ri + rj); ri for walls (Theory/ContactLaws.md eq. (21))

    double reducedMass() const { return 1 / inverseReducedMass; }  // mi mj / (mi + mj)
};

struct ContactForce {
    double normalForce;   // signed magnitude along n (positive: repulsive)
    Vec3 tangentialForce;
    Vec3 onI() const { return tangentialForce; }  // normal part added by the caller
};

// The rules below are written on plain numbers, branch-free (selects, and no division inside a
// select, which the compiler would not speculate), so that the batched force loop
// (Contacts/ContactForces.h) can run them on lanes of contacts that the compiler vectorises;
// the Vec3 forms wrap them for the scalar paths.

// Tangential spring: forward Euler of Theory/ContactLaws.md eq. (13), d(xi)/dt = vt - rij (xi .
// vij) / rij^2, which keeps xi in the tangent plane as the contact rotates. A wall's normal only
// turns with the wall, so there (inverseDistance 0) the spring is advanced with vt and projected
// back onto the tangent plane. (n, v, t: normal, relative velocity of the centres, tangential
// velocity.)
[[gnu::always_inline]] inline void advanceTangentialSpring(double& sx, double& sy, double& sz, double nx, double ny,
                                                           double nz, double vx, double vy, double vz, double tx,
                                                           double ty, double tz, double inverseDistance, double dt) {
    const double turn = (sx * vx + sy * vy + sz * vz) * inverseDistance;
    const double rx = sx + dt * (tx - nx * turn), ry = sy + dt * (ty - ny * turn), rz = sz + dt * (tz - nz * turn);
    const double ax = sx + dt * tx, ay = sy + dt * ty, az = sz + dt * tz;
    const double along = ax * nx + ay * ny + az * nz;
    const bool pair = inverseDistance > 0;
    sx = pair ? rx : ax - nx * along;
    sy = pair ? ry : ay - ny * along;
    sz = pair ? rz : az - nz * along;
}
[[gnu::always_inline]] inline void advanceTangentialSpring(Vec3& spring, const ContactKinematics& k, double dt) {
    advanceTangentialSpring(spring.x(), spring.y(), spring.z(), k.normal.x(), k.normal.y(), k.normal.z(),
                            k.relativeVelocity.x(), k.relativeVelocity.y(), k.relativeVelocity.z(),
                            k.tangentialVelocity.x(), k.tangentialVelocity.y(), k.tangentialVelocity.z(),
                            k.inverseDistance, dt);
}

// A superquadric contact's spring, turned into the new tangent plane with its length kept (the
// normal there turns with the bodies' shapes, not only with the line of centres): projected
// onto the plane and stretched back (Denissen 2019, app. 5.A.3). A spring along n is left
// projected.
[[gnu::always_inline]] inline void turnSpringIntoTangentPlane(double& sx, double& sy, double& sz, double nx, double ny,
                                                              double nz) {
    const double length2 = sx * sx + sy * sy + sz * sz, along = sx * nx + sy * ny + sz * nz;
    sx -= along * nx, sy -= along * ny, sz -= along * nz;
    const double projected2 = sx * sx + sy * sy + sz * sz;
    const double ratio = std::sqrt(length2 / std::max(projected2, 1e-300));  // (one square root)
    const double stretch = projected2 > 0 ? ratio : 1.0;
    sx *= stretch, sy *= stretch, sz *= stretch;
}

// Coulomb sliding (Theory/ContactLaws.md eq. (14)): caps |ft| at mu |fn| and resets the spring so
// that it is consistent with the capped force, xi = -(mu |fn| t + gt vt) / kt. A frictionless
// contact (or one without normal force) that would slide keeps no tangential force and no spring.
// Returns whether it slides.
[[gnu::always_inline]] inline bool applyCoulombLimit(double& fx, double& fy, double& fz, double& sx, double& sy,
                                                     double& sz, double normalForce, double friction,
                                                     double tangentialStiffness, double tangentialDamping, double tx,
                                                     double ty, double tz) {
    constexpr double tiny = 1e-300;
    const double limit = friction * std::abs(normalForce);
    const double ft2 = fx * fx + fy * fy + fz * fz;
    const bool slide = ft2 > limit * limit, frictionless = limit <= 0;
    const double ratio = limit / std::sqrt(std::max(ft2, tiny));
    const double scale = slide ? ratio : 1.0;
    fx *= scale, fy *= scale, fz *= scale;
    const double minusInverseKt = -1 / std::max(tangentialStiffness, tiny);
    const bool resetSpring = slide & (tangentialStiffness > 0), clearSpring = slide & frictionless;
    const double qx = (fx + tangentialDamping * tx) * minusInverseKt, qy = (fy + tangentialDamping * ty) * minusInverseKt,
                 qz = (fz + tangentialDamping * tz) * minusInverseKt;
    sx = clearSpring ? 0.0 : (resetSpring ? qx : sx);
    sy = clearSpring ? 0.0 : (resetSpring ? qy : sy);
    sz = clearSpring ? 0.0 : (resetSpring ? qz : sz);
    return slide & !frictionless;
}
[[gnu::always_inline]] inline bool applyCoulombLimit(Vec3& tangentialForce, Vec3& spring, double normalForce, double friction,
                                                     double tangentialStiffness, double tangentialDamping, const Vec3& vt) {
    return applyCoulombLimit(tangentialForce.x(), tangentialForce.y(), tangentialForce.z(), spring.x(), spring.y(),
                             spring.z(), normalForce, friction, tangentialStiffness, tangentialDamping, vt.x(), vt.y(),
                             vt.z());
}

}  // namespace talus

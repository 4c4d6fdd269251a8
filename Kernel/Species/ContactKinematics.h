// What a contact law needs to know about one contact, and what it returns (SPEC.md 1).
// Filled by the force loop for particle-particle and particle-wall contacts alike, so that each
// law is written once for both.
#pragma once

#include "Math/Vector.h"

namespace talus {

struct ContactKinematics {
    Vec3 normal;               // unit normal from j (or the wall) to i
    double overlap;            // dn > 0
    Vec3 relativeVelocity;     // vij = vi - vj of the centres (walls: at the contact point)
    double normalVelocity;     // vij . n (negative while approaching)
    Vec3 tangentialVelocity;   // vt of SPEC.md 1, including the spin terms
    double inverseReducedMass; // 1/mi + 1/mj; 1/mi for walls and fixed partners
    // d(vij . n)/dt from all the other forces on the two particles, as of the last step (gravity,
    // other contacts): what the implicit end-of-step speed of the dashpot must include, or a
    // pair at rest under load would see a spurious speed and a spurious damping force.
    double otherAcceleration = 0;
    double effectiveRadius;    // ri rj / (ri + rj); ri for walls
    double inverseDistance;    // 1 / |ri - rj| for particle pairs; 0 for walls (advanceTangentialSpring)

    double reducedMass() const { return 1 / inverseReducedMass; }  // mi mj / (mi + mj)
};

struct ContactForce {
    double normalForce;   // signed magnitude along n (positive: repulsive)
    Vec3 tangentialForce;
    Vec3 onI() const { return tangentialForce; }  // normal part added by the caller
};

// Tangential spring: forward Euler of SPEC.md 1, d(xi)/dt = vt - rij (xi . vij) / rij^2, which
// keeps xi in the tangent plane as the contact rotates. A wall's normal only turns with the
// wall, so there the spring is advanced with vt and projected back onto the tangent plane.
[[gnu::always_inline]] inline void advanceTangentialSpring(Vec3& spring, const ContactKinematics& k, double dt) {
    if (k.inverseDistance > 0) {
        spring += dt * (k.tangentialVelocity - k.normal * (spring.dot(k.relativeVelocity) * k.inverseDistance));
    } else {
        spring += dt * k.tangentialVelocity;
        spring -= k.normal * spring.dot(k.normal);
    }
}

// Coulomb sliding (SPEC.md 1): caps |ft| at mu |fn| and resets the spring so that it is
// consistent with the capped force, xi = -(mu |fn| t + gt vt) / kt. Returns whether it slides.
[[gnu::always_inline]] inline bool applyCoulombLimit(Vec3& tangentialForce, Vec3& spring, double normalForce, double friction,
                              double tangentialStiffness, double tangentialDamping, const Vec3& vt) {
    const double limit = friction * std::abs(normalForce);
    const double ft2 = tangentialForce.squaredNorm();
    if (ft2 <= limit * limit) return false;
    if (limit == 0) {  // frictionless (or no normal force): no tangential force, no stored energy
        tangentialForce.setZero();
        spring.setZero();
        return false;
    }
    tangentialForce *= limit / std::sqrt(ft2);
    if (tangentialStiffness > 0) spring = (tangentialForce + tangentialDamping * vt) * (-1 / tangentialStiffness);
    return true;
}

}  // namespace talus

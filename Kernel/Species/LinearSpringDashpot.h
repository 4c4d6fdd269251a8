// Linear spring-dashpot normal force with a tangential spring and Coulomb sliding friction
// (SPEC.md 1): fn = kn dn - gn vn, ft = -kt xi - gt vt, |ft| <= mu |fn|.
// The damping coefficient gn is absolute (force per velocity, Luding's convention).
#pragma once

#include <cmath>
#include <string>

#include "Error.h"
#include "Species/ContactKinematics.h"

namespace talus {

struct LinearSpringDashpot {
    double normalStiffness = 0;      // kn
    double normalDamping = 0;        // gn
    double tangentialStiffness = 0;  // kt
    double tangentialDamping = 0;    // gt
    double friction = 0;             // mu

    static constexpr const char* name = "LinearSpringDashpot";

    // SPEC.md 1 inverse formulas for a central collision of reduced mass m:
    // kn = m (pi^2 + ln(e)^2) / tc^2, gn = -2 m ln(e) / tc; and kt = 2/7 kn, gt = gn.
    static LinearSpringDashpot fromCollision(double collisionTime, double restitution, double reducedMass) {
        require(collisionTime > 0, "collision time must be positive, got " + std::to_string(collisionTime));
        require(restitution > 0 && restitution <= 1,
                "restitution must be in (0, 1], got " + std::to_string(restitution));
        require(reducedMass > 0, "reduced mass must be positive, got " + std::to_string(reducedMass));
        const double logE = std::log(restitution);
        LinearSpringDashpot law;
        law.normalStiffness = reducedMass * (pi * pi + logE * logE) / (collisionTime * collisionTime);
        law.normalDamping = -2.0 * reducedMass * logE / collisionTime;
        law.tangentialStiffness = 2.0 / 7.0 * law.normalStiffness;
        law.tangentialDamping = law.normalDamping;
        return law;
    }

    LinearSpringDashpot& withFriction(double mu) { friction = mu; return *this; }

    // SPEC.md 1: tc = pi / sqrt(kn/m - (gn/(2m))^2); infinite when overdamped.
    double collisionTime(double reducedMass) const {
        const double w2 = normalStiffness / reducedMass - std::pow(normalDamping / (2 * reducedMass), 2);
        return w2 > 0 ? pi / std::sqrt(w2) : INFINITY;
    }
    // SPEC.md 1: e = exp(-tc gn / (2m)).
    double restitution(double reducedMass) const {
        return std::exp(-collisionTime(reducedMass) * normalDamping / (2 * reducedMass));
    }

    // Default for a pair of species without explicit parameters: arithmetic means.
    static LinearSpringDashpot mix(const LinearSpringDashpot& a, const LinearSpringDashpot& b) {
        return {0.5 * (a.normalStiffness + b.normalStiffness), 0.5 * (a.normalDamping + b.normalDamping),
                0.5 * (a.tangentialStiffness + b.tangentialStiffness),
                0.5 * (a.tangentialDamping + b.tangentialDamping), 0.5 * (a.friction + b.friction)};
    }

    void validate(const std::string& what) const {
        require(normalStiffness > 0, what + ": normal stiffness must be positive");
        require(normalDamping >= 0, what + ": normal damping must not be negative");
        require(tangentialStiffness >= 0, what + ": tangential stiffness must not be negative");
        require(tangentialDamping >= 0, what + ": tangential damping must not be negative");
        require(friction >= 0, what + ": friction coefficient must not be negative");
    }

    ContactForce force(const ContactKinematics& k, Vec3& spring, double dt) const {
        ContactForce f;
        f.normalForce = normalStiffness * k.overlap - normalDamping * k.normalVelocity;
        advanceTangentialSpring(spring, k, dt);
        f.tangentialForce = -tangentialStiffness * spring - tangentialDamping * k.tangentialVelocity;
        applyCoulombLimit(f.tangentialForce, spring, f.normalForce, friction, tangentialStiffness,
                          tangentialDamping, k.tangentialVelocity);
        return f;
    }

    double elasticEnergy(const ContactKinematics& k, const Vec3& spring) const {
        return 0.5 * normalStiffness * k.overlap * k.overlap + 0.5 * tangentialStiffness * spring.squaredNorm();
    }
};

}  // namespace talus

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

    // The dashpot forces jump at the instants of first touch and of separation (the spring
    // force does not), and the midpoint impulse dt f(t) of velocity Verlet misplaces such a jump
    // by up to dt/2: an O(dt/tc) error in the restitution coefficient. So on the first step of a
    // contact, which began tau = dn/|vn| ago, the dashpot counts for the dt/2 + tau of the
    // impulse window it really acted in (the part before the window was missed by the previous
    // step), and on the first step after separation separationForce() returns the impulse that
    // the last contact step over- or under-counted.
    static double onsetWeight(const ContactKinematics& k, double dt) {
        const double speed = std::abs(k.normalVelocity);
        if (k.overlap >= speed * dt) return 1.5;
        return k.overlap / (speed * dt) + 0.5;
    }

    // Normal force on the first step after the pair separated, at distance gap > 0, opening at
    // speed vn > 0: the last contact step applied the dashpot over the window up to dt/2 past
    // it; the contact ended gap/vn ago, i.e. at dt/2 - gap/vn after that window's end.
    double separationForce(double gap, double normalVelocity, double dt) const {
        if (normalVelocity <= 0 || normalDamping == 0) return 0;
        const double weight = std::max(-0.5, 0.5 - gap / (normalVelocity * dt));
        return -weight * normalDamping * normalVelocity;
    }

    // The normal dashpot acts on the relative velocity at the end of the step, u(n+1), found
    // implicitly for the pair alone: velocity Verlet gives u(n+1) = u + dt/(2m*) f with u the
    // half-step velocity and f = kn dn - w gn u(n+1). Using u itself, as plain velocity Verlet
    // does, lags the damping by dt/2, an error of O(dt/tc) in the restitution coefficient (4% for
    // e = 0.1 at dt = tc/50); this is O((dt/tc)^2) (Documentation/Validation/Restitution.md).
    ContactForce force(const ContactKinematics& k, Vec3& spring, double dt, bool firstStep) const {
        const double weight = firstStep ? onsetWeight(k, dt) : 1.0;
        const double halfStepOverMass = 0.5 * dt / k.reducedMass;
        const double elastic = normalStiffness * k.overlap;
        const double endVelocity = (k.normalVelocity + halfStepOverMass * elastic) /
                                   (1 + halfStepOverMass * weight * normalDamping);
        ContactForce f;
        f.normalForce = elastic - weight * normalDamping * endVelocity;
        advanceTangentialSpring(spring, k, dt);
        f.tangentialForce = -tangentialStiffness * spring - weight * tangentialDamping * k.tangentialVelocity;
        applyCoulombLimit(f.tangentialForce, spring, f.normalForce, friction, tangentialStiffness,
                          tangentialDamping, k.tangentialVelocity);
        return f;
    }

    double elasticEnergy(const ContactKinematics& k, const Vec3& spring) const {
        return 0.5 * normalStiffness * k.overlap * k.overlap + 0.5 * tangentialStiffness * spring.squaredNorm();
    }
};

}  // namespace talus

// Linear spring-dashpot normal force with a tangential spring and Coulomb sliding friction
// (SPEC.md 1): fn = kn dn - gn vn, ft = -kt xi - gt vt, |ft| <= mu |fn|.
// The damping coefficient gn is absolute (force per velocity, Luding's convention).
#pragma once

#include <cmath>
#include <string>

#include "Error.h"
#include "Contacts/ContactHistory.h"
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

    // Velocity Verlet applies the force of step n as the impulse dt f(n) over the window
    // [t - dt/2, t + dt/2]: the midpoint rule, second order only where f is smooth. At the instants
    // of first touch and of separation the dashpot force jumps and the spring force has a kink,
    // and the midpoint rule misplaces them by up to dt/2: an O(dt/tc) error in the restitution
    // (4% for e = 0.1 at dt = tc/50) and an O((dt/tc)^2) one in the energy of elastic contacts.
    // So the impulse from the touch to the first contact step, and from the last contact step to
    // the separation, is integrated by the trapezoidal rule with the force at the touch or
    // separation instant (spring 0, dashpot of the speed then), whose time follows from the
    // overlap and the normal speed (Documentation/Validation/Restitution.md).
    //
    // The normal dashpot also acts on the relative velocity at the end of the step, u(n+1), found
    // implicitly for the pair alone from u(n+1) = u + dt/(2m*) f, u the half-step velocity:
    // plain velocity Verlet uses u itself, which lags the damping by dt/2 (another O(dt/tc) error).
    ContactForce force(const ContactKinematics& k, ContactHistory& history, double dt) const {
        // On the first step the contact began tau = dn/|u| ago (u is still the approach speed):
        // the impulse is tau (f(touch) + f)/2 + dt/2 f = dt (c f + extra f(touch)). Coulomb's
        // limit holds for f and f(touch) each, and so for their combination.
        double c = 1, extra = 0, springStep = dt;
        if (!history.touching) {
            const double speed = std::abs(k.normalVelocity);
            const double tau = k.overlap >= speed * dt ? dt : k.overlap / speed;
            c = 0.5 + 0.5 * tau / dt;
            extra = 0.5 * tau / dt;
            springStep = tau;
        }
        const double halfStepOverMass = 0.5 * dt / k.reducedMass;
        const double touchNormalForce = -normalDamping * k.normalVelocity;
        const double endVelocity =
            (k.normalVelocity + halfStepOverMass * (c * normalStiffness * k.overlap + extra * touchNormalForce)) /
            (1 + halfStepOverMass * c * normalDamping);
        ContactForce f;
        f.normalForce = normalStiffness * k.overlap - normalDamping * endVelocity;
        advanceTangentialSpring(history.spring, k, springStep);
        f.tangentialForce = -tangentialStiffness * history.spring - tangentialDamping * k.tangentialVelocity;
        applyCoulombLimit(f.tangentialForce, history.spring, f.normalForce, friction, tangentialStiffness,
                          tangentialDamping, k.tangentialVelocity);
        if (c < 1) {
            Vec3 touchTangentialForce = -tangentialDamping * k.tangentialVelocity;
            Vec3 noSpring = Vec3::Zero();
            applyCoulombLimit(touchTangentialForce, noSpring, touchNormalForce, friction, 0, 0, k.tangentialVelocity);
            f.normalForce = c * f.normalForce + extra * touchNormalForce;
            f.tangentialForce = c * f.tangentialForce + extra * touchTangentialForce;
        }
        history.normalForce = f.normalForce;  // for separationForce
        history.tangentialForce = f.tangentialForce;
        return f;
    }

    // Force on the first step after the pair separated (c.overlap = -gap < 0, opening at normal
    // speed u > 0): in the trajectory of the last step the contact ended tau' = dt - gap/u after
    // the last contact step, whose half window after it applied dt/2 f(last); the trapezoid gives
    // tau' (f(last) + f(separation))/2. The force now is the difference. The separation speed is
    // the one after this correction, u + dt f/m*, so the normal dashpot force at separation,
    // -gn (u + dt f/m*), is again solved implicitly; the tangential one uses the present vt.
    ContactForce separationForce(const ContactKinematics& c, const ContactHistory& history, double dt) const {
        ContactForce f{0, Vec3::Zero()};
        if (c.normalVelocity <= 0) return f;
        const double contactAfterLastStep = dt - std::min(dt, -c.overlap / c.normalVelocity);
        const double atSeparation = 0.5 * contactAfterLastStep / dt, atLast = atSeparation - 0.5;
        const double separationNormalForce = -normalDamping * c.normalVelocity;
        Vec3 separationTangentialForce = -tangentialDamping * c.tangentialVelocity;
        Vec3 noSpring = Vec3::Zero();
        applyCoulombLimit(separationTangentialForce, noSpring, separationNormalForce, friction, 0, 0,
                          c.tangentialVelocity);
        f.normalForce = (atLast * history.normalForce + atSeparation * separationNormalForce) /
                        (1 + atSeparation * normalDamping * dt / c.reducedMass);
        f.tangentialForce = atLast * history.tangentialForce + atSeparation * separationTangentialForce;
        return f;
    }

    double elasticEnergy(const ContactKinematics& k, const Vec3& spring) const {
        return 0.5 * normalStiffness * k.overlap * k.overlap + 0.5 * tangentialStiffness * spring.squaredNorm();
    }
};

}  // namespace talus

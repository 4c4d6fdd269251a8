// The linear spring-dashpot law with rolling resistance: the elastic-plastic spring-dashpot
// (EPSD) rolling model of Ai, Chen, Rotter & Ooi (2011), in the form MercuryDPM's rolling
// friction and LIGGGHTS's rolling_friction epsd use (Theory/ContactLaws.md "Rolling
// resistance", eq. (21)-(26)). The normal and tangential forces are LinearSpringDashpot's, bit
// for bit; on top, a rolling spring xr per contact, driven by the rolling velocity
// vr = Rr (wi - wj) x n, gives a "rolling force" Fr = -kr xr - gr vr, capped at mu_r |fn| (the
// spring then reset, as Coulomb's limit resets the tangential one), and the torque
// Rr n x Fr on i and its negative on j. The cap makes the largest rolling torque mu_r Rr |fn|.
// Computed pair by pair (batched = false); spheres only (superquadrics roll by their shape).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "Error.h"
#include "Species/LinearSpringDashpot.h"

namespace talus {

struct LinearSpringDashpotRolling : LinearSpringDashpot {
    double rollingStiffness = 0;  // kr (force per length, as kt)
    double rollingDamping = 0;    // gr (force per velocity, as gt)
    double rollingFriction = 0;   // mu_r (dimensionless: the torque's cap is mu_r Rr |fn|)

    static constexpr const char* name = "LinearSpringDashpotRolling";
    static constexpr bool batched = false;  // (the lane paths are LinearSpringDashpot's alone)
    static constexpr bool rollingResistance = true;

    // The linear law `base` with rolling resistance kr, gr, mu_r.
    static LinearSpringDashpotRolling of(const LinearSpringDashpot& base, double rollingStiffness,
                                         double rollingDamping, double rollingFriction) {
        LinearSpringDashpotRolling law;
        static_cast<LinearSpringDashpot&>(law) = base;
        law.rollingStiffness = rollingStiffness;
        law.rollingDamping = rollingDamping;
        law.rollingFriction = rollingFriction;
        return law;
    }

    // LinearSpringDashpot's parameters, then the rolling ones.
    template <class Law, class Visit>
    static void parameters(Law& law, Visit&& visit) {
        LinearSpringDashpot::parameters(law, visit);
        visit("rolling stiffness", law.rollingStiffness);
        visit("rolling damping", law.rollingDamping);
        visit("rolling friction", law.rollingFriction);
    }

    static LinearSpringDashpotRolling mix(const LinearSpringDashpotRolling& a, const LinearSpringDashpotRolling& b) {
        return of(LinearSpringDashpot::mix(a, b), 0.5 * (a.rollingStiffness + b.rollingStiffness),
                  0.5 * (a.rollingDamping + b.rollingDamping), 0.5 * (a.rollingFriction + b.rollingFriction));
    }

    void validate(const std::string& what) const {
        LinearSpringDashpot::validate(what);
        require(rollingStiffness >= 0, what + ": rolling stiffness must not be negative");
        require(rollingDamping >= 0, what + ": rolling damping must not be negative");
        require(rollingFriction >= 0, what + ": rolling friction coefficient must not be negative");
    }

    // The shorter of the normal collision time and half the period of the undamped rolling
    // oscillation, pi / sqrt(5 kr / (2 m*)) (Theory/ContactLaws.md eq. (26)).
    double collisionTimeOfPair(double reducedMass, double effectiveRadius) const {
        const double normal = LinearSpringDashpot::collisionTimeOfPair(reducedMass, effectiveRadius);
        if (!(rollingStiffness > 0)) return normal;
        return std::min(normal, pi / std::sqrt(2.5 * rollingStiffness / reducedMass));
    }

    // The rolling torque on i (on j: its negative) of a touching contact whose normal force is
    // normalForce, with the rolling spring advanced by dt (Theory/ContactLaws.md eq. (22)-(25)).
    // Needs k.relativeSpin and k.rollingRadius, which the force loop sets for laws with
    // rollingResistance.
    Vec3 rollingTorque(const ContactKinematics& k, ContactHistory& history, double normalForce, double dt) const {
        const Vec3 rollingVelocity = k.rollingRadius * k.relativeSpin.cross(k.normal);  // eq. (22)
        // Eq. (23): the tangential spring's rule, which keeps the spring in the tangent plane as
        // the contact turns (pairs) or projects it back onto it (walls).
        Vec3& spring = history.rollingSpring;
        advanceTangentialSpring(spring.x(), spring.y(), spring.z(), k.normal.x(), k.normal.y(), k.normal.z(),
                                k.relativeVelocity.x(), k.relativeVelocity.y(), k.relativeVelocity.z(),
                                rollingVelocity.x(), rollingVelocity.y(), rollingVelocity.z(), k.inverseDistance, dt);
        Vec3 rollingForce = -rollingStiffness * spring - rollingDamping * rollingVelocity;  // eq. (24)
        applyCoulombLimit(rollingForce, spring, normalForce, rollingFriction, rollingStiffness, rollingDamping,
                          rollingVelocity);
        return k.rollingRadius * k.normal.cross(rollingForce);  // eq. (25)
    }
};

}  // namespace talus

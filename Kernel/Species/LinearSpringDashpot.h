// Linear spring-dashpot normal force with a tangential spring and Coulomb sliding friction
// (Theory/ContactLaws.md eq. (7)-(8)): fn = kn dn - gn vn, ft = -kt xi - gt vt, |ft| <= mu |fn|.
// The damping coefficient gn is absolute (force per velocity, Luding's convention).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "Error.h"
#include "Contacts/ContactHistory.h"
#include "Species/ContactKinematics.h"

namespace talus {

// A law as the batched force loop's lanes read it (Contacts/ContactBatch.h): five numbers a pair,
// made once with the pair table (Law::lane) and turned into the lasting-contact step by
// Law::lastingContactInLane.
using LaneLaw = std::array<double, 5>;

struct LinearSpringDashpot {
    double normalStiffness = 0;      // kn
    double normalDamping = 0;        // gn
    double tangentialStiffness = 0;  // kt
    double tangentialDamping = 0;    // gt
    double friction = 0;             // mu
    // true: the ends of a contact are integrated as described below (restitution error
    // O((dt/tc)^2)); false: plain velocity Verlet with the half-step speed in the dashpot, as
    // LAMMPS (gran/hooke/history) and LIGGGHTS do, for comparing with them (error O(dt/tc)).
    bool treatContactEnds = true;

    // The members every contact law has (Species/ContactLaws.h; Documentation/Architecture.md
    // "Adding a part"): its name in restart files, its flags for the force loop, its parameters
    // in the order of the restart file, the mixing rule, validate and collisionTimeOfPair.
    static constexpr const char* name = "LinearSpringDashpot";
    static constexpr bool usesEffectiveRadius = false;
    static constexpr bool rollingResistance = false;

    // visit(label, field) for each parameter, in the order of the restart file (the labels name
    // the field in a reader's errors). Law is this law or a law built on it, const or not.
    template <class Law, class Visit>
    static void parameters(Law& law, Visit&& visit) {
        visit("normal stiffness", law.normalStiffness);
        visit("normal damping", law.normalDamping);
        visit("tangential stiffness", law.tangentialStiffness);
        visit("tangential damping", law.tangentialDamping);
        visit("friction", law.friction);
        visit("contact-end flag", law.treatContactEnds);
    }

    // Theory/ContactLaws.md eq. (12) inverse formulas for a central collision of reduced mass m:
    // kn = m (pi^2 + ln(e)^2) / tc^2, gn = -2 m ln(e) / tc; and kt = 2/7 kn, gt = gn.
    static LinearSpringDashpot fromCollision(double collisionTime, double restitution, double reducedMass) {
        require(collisionTime > 0, "collision time must be positive, got " + str(collisionTime));
        require(restitution > 0 && restitution <= 1,
                "restitution must be in (0, 1], got " + str(restitution));
        require(reducedMass > 0, "reduced mass must be positive, got " + str(reducedMass));
        const double logE = std::log(restitution);
        LinearSpringDashpot law;
        law.normalStiffness = reducedMass * (pi * pi + logE * logE) / (collisionTime * collisionTime);
        law.normalDamping = -2.0 * reducedMass * logE / collisionTime;
        law.tangentialStiffness = 2.0 / 7.0 * law.normalStiffness;
        law.tangentialDamping = law.normalDamping;
        return law;
    }

    LinearSpringDashpot& withFriction(double mu) { friction = mu; return *this; }

    // Theory/ContactLaws.md eq. (10)-(11): tc = pi / sqrt(kn/m - (gn/(2m))^2); infinite when
    // overdamped.
    double collisionTime(double reducedMass) const {
        const double w2 = normalStiffness / reducedMass - std::pow(normalDamping / (2 * reducedMass), 2);
        return w2 > 0 ? pi / std::sqrt(w2) : INFINITY;
    }
    // What the time-step check compares with dt (Theory/Integration.md "The time step and the
    // collision time check").
    double collisionTimeOfPair(double reducedMass, double /*effectiveRadius*/) const {
        return collisionTime(reducedMass);
    }
    // Theory/ContactLaws.md eq. (10)-(11): e = exp(-tc gn / (2m)).
    double restitution(double reducedMass) const {
        return std::exp(-collisionTime(reducedMass) * normalDamping / (2 * reducedMass));
    }

    // Default for a pair of species without explicit parameters: arithmetic means.
    static LinearSpringDashpot mix(const LinearSpringDashpot& a, const LinearSpringDashpot& b) {
        return {0.5 * (a.normalStiffness + b.normalStiffness), 0.5 * (a.normalDamping + b.normalDamping),
                0.5 * (a.tangentialStiffness + b.tangentialStiffness),
                0.5 * (a.tangentialDamping + b.tangentialDamping), 0.5 * (a.friction + b.friction),
                a.treatContactEnds && b.treatContactEnds};
    }

    void validate(const std::string& what) const {
        require(normalStiffness > 0, what + ": normal stiffness must be positive");
        require(normalDamping >= 0, what + ": normal damping must not be negative");
        require(tangentialStiffness >= 0, what + ": tangential stiffness must not be negative");
        require(tangentialDamping >= 0, what + ": tangential damping must not be negative");
        require(friction >= 0, what + ": friction coefficient must not be negative");
    }

    // The ends of a contact. In leapfrog form, velocity Verlet moves a pair over each step with the
    // velocity it gave it for that step, which is right if the impulse P(t) applied since the touch
    // has been, after each step's force, its mean over the next step: the force of step n must be
    // (mean P over [n, n+1] - mean P over [n-1, n]) / dt. Inside a contact that is the force at
    // step n, to second order. At its ends it is not, since the dashpot force jumps at the touch
    // and at the separation and the spring force has a kink there; plain velocity Verlet then
    // errs by O(dt/tc) in the restitution (4% for e = 0.1 at dt = tc/50). So:
    //  - approachForce: a pair that will touch at tau before the next step pushes already with
    //    the mean of P over that step, (f0 tau^2/2 + f0' tau^3/6)/dt, where f0 = -gn u and
    //    f0' = -kn u - gn f0/m* are the force and its rate at the touch;
    //  - force, first contact step: the mean of P over the next step, P(now) + f dt/2 + f' dt^2/6,
    //    minus what went ahead; P(now) is the quadratic (Hermite) rule from the touch,
    //    tau (f0 + f)/2 + tau^2 (f0' - f')/12, and the dashpot acts on the speed now,
    //    u0 + tau (f0 + f)/(2 m*), solved implicitly;
    //  - force, inside the contact: the force now, with the dashpot on the end-of-step speed
    //    u(n+1) = u + dt/2 (f/m* + a), implicit in f, where a is the acceleration the other forces
    //    on the pair gave it at the last step (plain velocity Verlet's half-step speed lags by
    //    dt/2; leaving a out would give a pair at rest under load a spurious damping force);
    //  - separationForce, first step apart: the impulse from the last contact step to the
    //    separation (found from the overlap, speed and force then), by the same Hermite rule,
    //    minus the f dt/2 + f' dt^2/6 that step counted on.
    // The tangential force uses the trapezoidal rule at both ends and no push ahead, except that a
    // sliding contact's tangential impulse is mu times the normal one, push ahead included.
    // What the ends need of the last step is recomputed from the present state (separationForce),
    // so a pair's history is only its spring and state (Contacts/ContactHistory.h).
    // Documentation/Validation/Restitution.md has the measured errors.

    // The force rate df/dt = -kn u - gn f/m* in a contact (d(dn)/dt = -u, du/dt = f/m*).
    double forceRate(double force, double speed, double reducedMass) const {
        return -normalStiffness * speed - normalDamping * force / reducedMass;
    }

    // Normal force on a pair apart (c.overlap = -gap < 0): the push ahead of a touch within the
    // next step, less the push of the last step, which is taken back. Zero for a pair apart with
    // no push pending that does not close its gap within dt at its present speed, which the
    // force loop therefore skips (every law's approachForce must keep to that).
    double approachForce(const ContactKinematics& c, ContactHistory& history, double dt) const {
        if (!treatContactEnds) return 0;
        const double previous = history.isApproaching() ? history.pushAhead() : 0;
        history = ContactHistory{};
        const double u = c.normalVelocity, gap = -c.overlap;
        if (u < 0 && gap < -u * dt) {
            const double tau = dt - gap / -u;  // from the touch to the next step
            const double touchForce = -normalDamping * u;
            const double touchRate = forceRate(touchForce, u, c.reducedMass());
            history.state = ContactHistory::approaching;
            history.pushAhead() = (touchForce * tau * tau / 2 + touchRate * tau * tau * tau / 6) / (dt * dt);
            history.approachSpeed() = u;
            history.overlapBefore() = c.overlap;
        }
        return (history.isApproaching() ? history.pushAhead() : 0) - previous;
    }

    // The force of a touching pair. Inside a contact (the common case, kept small so that it is
    // inlined into the force loop): the dashpot on the end-of-step speed, solved implicitly,
    // u(n+1) = u + dt/2 ((kn dn - gn u(n+1))/m* + a), a from the other forces on the pair.
    [[gnu::always_inline]] ContactForce force(const ContactKinematics& k, ContactHistory& history, double dt) const {
        // (The rare cases get copies, so that k and history never leave registers on the common
        // path.)
        if (!treatContactEnds) [[unlikely]]
            return coldCall(&LinearSpringDashpot::plainForce, k, history, dt);
        if (!history.isTouching()) [[unlikely]]
            return coldCall(&LinearSpringDashpot::firstContactForce, k, history, dt);
        return lastingContactForce(k, history, dt);
    }

    // Inside a lasting contact, with the ends treated: the common case, in one place for the
    // scalar path (walls) and for the batched force loop, which runs it on lanes of plain numbers
    // that the compiler vectorises (Contacts/ContactForces.h; Eigen expressions defeat its
    // vectoriser). Branch-free, as the rules of ContactKinematics.h it uses.
    struct Lane {
        double nx, ny, nz, overlap;             // normal, overlap
        double vx, vy, vz, normalVelocity;      // relative velocity of the centres, its normal part
        double tx, ty, tz;                      // tangential velocity vt (Theory/ContactLaws.md eq. (4))
        double otherAcceleration, inverseReducedMass, inverseDistance;  // (ContactKinematics)
        double sx, sy, sz;                      // spring, advanced in place
        double normalForce, fx, fy, fz;         // out: fn and the tangential force
    };
    static constexpr bool batched = true;
    // Whether the batch takes this pair's lasting contacts (the lane step treats the ends).
    bool lastsInLanes() const { return treatContactEnds; }
    LaneLaw lane() const { return {normalStiffness, normalDamping, tangentialStiffness, tangentialDamping, friction}; }
    static constexpr int laneFriction = 4;  // (mu's place among the lane's numbers)
    // frictionless: for a law of friction 0, whose contacts have no tangential force and no
    // spring (the Coulomb limit of eq. (14) at mu = 0 clears both: applyCoulombLimit), the step
    // without them, to the same bits (ContactBatch::frictionless).
    template <bool frictionless = false>
    [[gnu::always_inline]] static void lastingContactInLane(Lane& c, double dt, const double (&law)[5], double) {
        LinearSpringDashpot{law[0], law[1], law[2], law[3], law[4]}.lastingContact<frictionless>(c, dt);
    }
    template <bool frictionless = false>
    [[gnu::always_inline]] void lastingContact(Lane& c, double dt) const {
        // Normal: the dashpot on the end-of-step speed, u(n+1) = u + dt/2 ((kn dn - gn
        // u(n+1))/m* + a).
        const double halfStepOverMass = 0.5 * dt * c.inverseReducedMass;
        const double elastic = normalStiffness * c.overlap;
        const double speedNow = (c.normalVelocity + 0.5 * dt * c.otherAcceleration + halfStepOverMass * elastic) /
                                (1 + halfStepOverMass * normalDamping);
        c.normalForce = elastic - normalDamping * speedNow;
        if constexpr (frictionless)
            withoutFriction(c);
        else
            tangentialStep(c, dt);
    }
    [[gnu::always_inline]] static void withoutFriction(Lane& c) { c.fx = c.fy = c.fz = 0, c.sx = c.sy = c.sz = 0; }
    // Theory/ContactLaws.md eq. (7)-(8) as plain velocity Verlet evaluates it: the half-step
    // velocities, no treatment of the contact's ends (superquadric contacts, see plainForce;
    // batched in EllipsoidContactBatch.h).
    [[gnu::always_inline]] void plainContact(Lane& c, double dt) const {
        c.normalForce = normalStiffness * c.overlap - normalDamping * c.normalVelocity;
        tangentialStep(c, dt);
    }
    // The spring advanced, the tangential force, the Coulomb limit
    // (Theory/ContactLaws.md eq. (14)).
    [[gnu::always_inline]] void tangentialStep(Lane& c, double dt) const {
        advanceTangentialSpring(c.sx, c.sy, c.sz, c.nx, c.ny, c.nz, c.vx, c.vy, c.vz, c.tx, c.ty, c.tz, c.inverseDistance,
                                dt);
        c.fx = -tangentialStiffness * c.sx - tangentialDamping * c.tx;
        c.fy = -tangentialStiffness * c.sy - tangentialDamping * c.ty;
        c.fz = -tangentialStiffness * c.sz - tangentialDamping * c.tz;
        applyCoulombLimit(c.fx, c.fy, c.fz, c.sx, c.sy, c.sz, c.normalForce, friction, tangentialStiffness,
                          tangentialDamping, c.tx, c.ty, c.tz);
    }
    static Lane laneOf(const ContactKinematics& k, const Vec3& spring) {
        return {k.normal.x(), k.normal.y(), k.normal.z(), k.overlap,
                k.relativeVelocity.x(), k.relativeVelocity.y(), k.relativeVelocity.z(), k.normalVelocity,
                k.tangentialVelocity.x(), k.tangentialVelocity.y(), k.tangentialVelocity.z(),
                k.otherAcceleration, k.inverseReducedMass, k.inverseDistance,
                spring.x(), spring.y(), spring.z(), 0, 0, 0, 0};
    }
    [[gnu::always_inline]] ContactForce lastingContactForce(const ContactKinematics& k, ContactHistory& history,
                                                             double dt) const {
        Lane c = laneOf(k, history.spring);
        lastingContact(c, dt);
        history.spring = Vec3(c.sx, c.sy, c.sz);
        return {c.normalForce, Vec3(c.fx, c.fy, c.fz)};
    }

    // The first step of a contact (see above): from the touch, foreseen or not, to now.
    [[gnu::noinline]] ContactForce firstContactForce(const ContactKinematics& k, ContactHistory& history,
                                                     double dt) const {
        const double elastic = normalStiffness * k.overlap;
        double tau, touchSpeed = k.normalVelocity, pushedAhead = 0;
        if (history.isApproaching()) {  // foreseen on the last step
            touchSpeed = history.approachSpeed();
            tau = dt + history.overlapBefore() / -touchSpeed;
            pushedAhead = history.pushAhead() * dt;
        } else {  // not foreseen: the touch was dn/|u| ago
            const double speed = std::abs(k.normalVelocity);
            tau = k.overlap >= speed * dt ? dt : k.overlap / speed;
        }
        history.spring.setZero();
        // The speed now, u0 + tau (f0 + kn dn - gn u(now))/(2 m*), implicit in the dashpot.
        const double sinceTouchOverMass = 0.5 * tau / k.reducedMass();
        const double speedNow = (touchSpeed + sinceTouchOverMass * (-normalDamping * touchSpeed + elastic)) /
                                (1 + sinceTouchOverMass * normalDamping);
        ContactForce f;
        f.normalForce = elastic - normalDamping * speedNow;
        advanceTangentialSpring(history.spring, k, tau);
        f.tangentialForce = -tangentialStiffness * history.spring - tangentialDamping * k.tangentialVelocity;
        const bool sliding = applyCoulombLimit(f.tangentialForce, history.spring, f.normalForce, friction,
                                               tangentialStiffness, tangentialDamping, k.tangentialVelocity);
        const double touchForce = -normalDamping * touchSpeed;
        const double touchRate = forceRate(touchForce, touchSpeed, k.reducedMass());
        const double rate = forceRate(f.normalForce, speedNow, k.reducedMass());
        const double sinceTouch = 0.5 * tau * (touchForce + f.normalForce) + tau * tau * (touchRate - rate) / 12;
        const double meanOverNextStep = sinceTouch + f.normalForce * dt / 2 + rate * dt * dt / 6;
        if (sliding) {  // |ft| = mu fn: the tangential impulse follows the normal one
            f.tangentialForce *= friction * meanOverNextStep / (dt * f.tangentialForce.norm());
        } else {
            Vec3 touchTangentialForce = -tangentialDamping * k.tangentialVelocity;
            Vec3 noSpring = Vec3::Zero();
            applyCoulombLimit(touchTangentialForce, noSpring, touchForce, friction, 0, 0, k.tangentialVelocity);
            f.tangentialForce = 0.5 * tau / dt * (touchTangentialForce + f.tangentialForce) + 0.5 * f.tangentialForce;
        }
        f.normalForce = (meanOverNextStep - pushedAhead) / dt;
        return f;
    }

    // Force on the first step after the pair separated (c.overlap = -gap < 0). The last contact
    // step's overlap, speed and force follow from the present ones, as velocity Verlet moved the
    // pair: dn = -gap + u dt (the drift), u = u(n+1) + dt/2 (f/m* + a) (the half kick,
    // f = kn dn - gn u, a from the other forces); its tangential force from the spring it left.
    ContactForce separationForce(const ContactKinematics& c, const ContactHistory& history, double dt) const {
        if (!treatContactEnds) return {0, Vec3::Zero()};
        const double m = c.reducedMass(), halfStepOverMass = 0.5 * dt / m;
        const double lastOverlap = std::max(0.0, c.overlap + c.normalVelocity * dt);
        const double lastSpeed =
            (c.normalVelocity - 0.5 * dt * c.otherAcceleration - halfStepOverMass * normalStiffness * lastOverlap) /
            (1 - halfStepOverMass * normalDamping);
        const double lastForce = normalStiffness * lastOverlap - normalDamping * lastSpeed;
        ContactForce f{0, Vec3::Zero()};
        if (c.normalVelocity <= 0) return f;
        // Time s from the last contact step to the separation: dn - u s - f s^2/(2m*) = 0.
        double s = dt;
        const double discriminant = lastSpeed * lastSpeed + 2 * lastForce * lastOverlap / m;
        if (discriminant >= 0 && lastSpeed + std::sqrt(discriminant) > 0)
            s = std::clamp(2 * lastOverlap / (lastSpeed + std::sqrt(discriminant)), 0.0, dt);
        // The speed at separation, us = u + s (f + fs)/(2m*), with fs = -gn us.
        const double untilSeparationOverMass = 0.5 * s / m;
        const double separationSpeed = (lastSpeed + untilSeparationOverMass * lastForce) /
                                       (1 + untilSeparationOverMass * normalDamping);
        const double separationForce = -normalDamping * separationSpeed;
        const double lastRate = forceRate(lastForce, lastSpeed, m);
        const double separationRate = forceRate(separationForce, separationSpeed, m);
        const double afterLastStep = 0.5 * s * (lastForce + separationForce) + s * s * (lastRate - separationRate) / 12;
        const double countedOn = lastForce * dt / 2 + lastRate * dt * dt / 6;
        f.normalForce = (afterLastStep - countedOn) / dt;
        // Tangential: the last force from the spring left; the trapezoid to the separation, where
        // only the dashpot of the present tangential velocity acts; or mu times the normal
        // correction if the contact was sliding.
        Vec3 lastTangentialForce = -tangentialStiffness * history.spring - tangentialDamping * c.tangentialVelocity;
        Vec3 spring = history.spring;
        applyCoulombLimit(lastTangentialForce, spring, lastForce, friction, tangentialStiffness, tangentialDamping,
                          c.tangentialVelocity);
        // Sliding: at the Coulomb limit (the spring was reset to it, up to round-off).
        const double limit = friction * std::abs(lastForce);
        if (limit > 0 && lastTangentialForce.squaredNorm() >= limit * limit * (1 - 1e-9)) {
            f.tangentialForce = lastTangentialForce * (friction * f.normalForce / lastTangentialForce.norm());
        } else {
            Vec3 separationTangentialForce = -tangentialDamping * c.tangentialVelocity;
            Vec3 noSpring = Vec3::Zero();
            applyCoulombLimit(separationTangentialForce, noSpring, separationForce, friction, 0, 0,
                              c.tangentialVelocity);
            const double atSeparation = 0.5 * s / dt;
            f.tangentialForce = (atSeparation - 0.5) * lastTangentialForce + atSeparation * separationTangentialForce;
        }
        return f;
    }

    // (plainContact for the scalar path.)
    [[gnu::noinline]] ContactForce plainForce(const ContactKinematics& k, ContactHistory& history, double dt) const {
        Lane c = laneOf(k, history.spring);
        plainContact(c, dt);
        history.spring = Vec3(c.sx, c.sy, c.sz);
        return {c.normalForce, Vec3(c.fx, c.fy, c.fz)};
    }

    template <class Member>
    ContactForce coldCall(Member member, ContactKinematics k, ContactHistory& history, double dt) const {
        ContactHistory copy = history;
        const ContactForce f = (this->*member)(k, copy, dt);
        history = copy;
        return f;
    }

    double elasticEnergy(const ContactKinematics& k, const Vec3& spring) const {
        return 0.5 * normalStiffness * k.overlap * k.overlap + 0.5 * tangentialStiffness * spring.squaredNorm();
    }
};

}  // namespace talus

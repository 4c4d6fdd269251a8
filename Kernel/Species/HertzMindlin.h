// Hertzian normal force with a Mindlin-type tangential spring and Coulomb sliding friction.
//   fn = 4/3 E* sqrt(R* dn) dn - gn vn,   ft = -St xi - gt vt,   |ft| <= mu |fn|,
//   Sn = 2 E* sqrt(R* dn), St = 8 G* sqrt(R* dn),
//   gn = -2 sqrt(5/6) beta sqrt(Sn m*), gt = -2 sqrt(5/6) beta sqrt(St m*),
//   beta = ln e / sqrt(ln^2 e + pi^2)
// (Tsuji et al. 1992 in the form of Antypov & Elliott 2011; the restitution this damping gives
// does not depend on the impact speed and is e: UnitTests/HertzMindlinTest.cc.)
// E* and G* are the effective moduli of the pair: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
#pragma once

#include <cmath>
#include <string>

#include "Error.h"
#include "Contacts/ContactHistory.h"
#include "Species/ContactKinematics.h"
#include "Species/LinearSpringDashpot.h"

namespace talus {

struct HertzMindlin {
    double effectiveYoungsModulus = 0;  // E*
    double effectiveShearModulus = 0;   // G*
    double restitution = 1;             // e, sets the damping coefficient beta
    double friction = 0;                // mu
    // The speed at which the time-step check evaluates the (speed-dependent) collision time.
    double characteristicVelocity = 1;

    static constexpr const char* name = "HertzMindlin";
    static constexpr bool usesEffectiveRadius = true;
    static constexpr bool batched = true;  // (lasting contacts in lanes: lastingContactInLane)
    static constexpr bool rollingResistance = false;

    // (As LinearSpringDashpot::parameters.)
    template <class Law, class Visit>
    static void parameters(Law& law, Visit&& visit) {
        visit("effective Young's modulus", law.effectiveYoungsModulus);
        visit("effective shear modulus", law.effectiveShearModulus);
        visit("restitution", law.restitution);
        visit("friction", law.friction);
        visit("characteristic velocity", law.characteristicVelocity);
    }

    // The effective moduli of two materials (Theory/ContactLaws.md eq. (20a)):
    // 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2, G = E/(2(1 + nu)).
    static HertzMindlin betweenMaterials(double youngsModulus1, double poissonRatio1, double youngsModulus2,
                                         double poissonRatio2, double restitution) {
        checkMaterial(youngsModulus1, poissonRatio1, "the first material");
        checkMaterial(youngsModulus2, poissonRatio2, "the second material");
        const double shear1 = youngsModulus1 / (2 * (1 + poissonRatio1));
        const double shear2 = youngsModulus2 / (2 * (1 + poissonRatio2));
        HertzMindlin law;
        law.effectiveYoungsModulus = 1 / ((1 - poissonRatio1 * poissonRatio1) / youngsModulus1 +
                                          (1 - poissonRatio2 * poissonRatio2) / youngsModulus2);
        law.effectiveShearModulus = 1 / ((2 - poissonRatio1) / shear1 + (2 - poissonRatio2) / shear2);
        law.restitution = restitution;
        return law;
    }
    // An elastic material Hertz's contact can take: E > 0, -1 < nu < 0.5 (`what` names it).
    static void checkMaterial(double youngsModulus, double poissonRatio, const std::string& what) {
        require(std::isfinite(youngsModulus) && youngsModulus > 0, what + ": Young's modulus must be positive");
        require(poissonRatio > -1 && poissonRatio < 0.5, what + ": Poisson ratio must lie in (-1, 0.5)");
    }
    // Two equal materials: E* = E / (2 (1 - nu^2)), G* = G / (2 (2 - nu)).
    static HertzMindlin fromMaterial(double youngsModulus, double poissonRatio, double restitution) {
        return betweenMaterials(youngsModulus, poissonRatio, youngsModulus, poissonRatio, restitution);
    }

    // Two equal materials of Poisson ratio nu whose elastic central collision at `impactSpeed`
    // lasts `collisionTime` for the given reduced mass and effective radius (collisionTime below,
    // solved for E*), with restitution e; the time-step check takes that speed.
    static HertzMindlin fromCollision(double collisionTime, double restitution, double reducedMass,
                                      double effectiveRadius, double impactSpeed, double poissonRatio) {
        require(collisionTime > 0 && reducedMass > 0 && effectiveRadius > 0 && impactSpeed > 0,
                "Hertz-Mindlin from a collision: collision time, reduced mass, effective radius and impact speed must "
                "be positive");
        const double maxOverlap = collisionTime * impactSpeed / (2 * 0.4 * std::beta(0.4, 0.5));
        const double effectiveModulus =
            15 * reducedMass * impactSpeed * impactSpeed / (16 * std::sqrt(effectiveRadius) * std::pow(maxOverlap, 2.5));
        HertzMindlin law = fromMaterial(2 * (1 - poissonRatio * poissonRatio) * effectiveModulus, poissonRatio, restitution);
        law.characteristicVelocity = impactSpeed;
        return law;
    }

    HertzMindlin& withFriction(double mu) { friction = mu; return *this; }

    double beta() const {
        const double logE = std::log(restitution);
        return logE / std::sqrt(logE * logE + pi * pi);
    }

    // Duration of an elastic central collision at impact speed v:
    // tc = 2 (2/5) B(2/5, 1/2) dmax / v, dmax = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5).
    double collisionTime(double reducedMass, double effectiveRadius, double impactSpeed) const {
        const double maxOverlap = std::pow(
            15 * reducedMass * impactSpeed * impactSpeed / (16 * effectiveYoungsModulus * std::sqrt(effectiveRadius)),
            0.4);
        return 2 * 0.4 * std::beta(0.4, 0.5) * maxOverlap / impactSpeed;
    }

    // What the time-step check compares with dt: the collision time at the characteristic velocity.
    double collisionTimeOfPair(double reducedMass, double effectiveRadius) const {
        return collisionTime(reducedMass, effectiveRadius, characteristicVelocity);
    }

    static HertzMindlin mix(const HertzMindlin& a, const HertzMindlin& b) {
        HertzMindlin m;
        m.effectiveYoungsModulus = 0.5 * (a.effectiveYoungsModulus + b.effectiveYoungsModulus);
        m.effectiveShearModulus = 0.5 * (a.effectiveShearModulus + b.effectiveShearModulus);
        m.restitution = 0.5 * (a.restitution + b.restitution);
        m.friction = 0.5 * (a.friction + b.friction);
        m.characteristicVelocity = std::max(a.characteristicVelocity, b.characteristicVelocity);
        return m;
    }

    void validate(const std::string& what) const {
        require(effectiveYoungsModulus > 0, what + ": effective Young's modulus must be positive");
        require(effectiveShearModulus >= 0, what + ": effective shear modulus must not be negative");
        require(restitution > 0 && restitution <= 1, what + ": restitution must be in (0, 1]");
        require(friction >= 0, what + ": friction coefficient must not be negative");
        require(characteristicVelocity > 0, what + ": characteristic velocity must be positive");
    }

    // The Hertzian forces start and end without a jump (the dashpot vanishes with the overlap),
    // so unlike LinearSpringDashpot no correction at touch and separation is applied; the
    // energy error of an elastic collision is O((dt/tc)^2): 5e-5 at dt = tc/50, 1.4e-7 at tc/500
    // (Documentation/Validation/Restitution.md).
    ContactForce separationForce(const ContactKinematics&, const ContactHistory&, double) const {
        return {0, Vec3::Zero()};
    }
    double approachForce(const ContactKinematics&, ContactHistory&, double) const { return 0; }

    // The batched force loop's numbers of the law (Contacts/ContactBatch.h): E*, G*, the damping
    // factor -2 sqrt(5/6) beta (its logarithm taken once, with the pair table), mu.
    bool lastsInLanes() const { return true; }
    static constexpr int laneFriction = 3;  // (mu's place among the lane's numbers)
    LaneLaw lane() const {
        return {effectiveYoungsModulus, effectiveShearModulus, -2 * std::sqrt(5.0 / 6.0) * beta(), friction, 0};
    }

    // One step of a contact from the lane's numbers (the scalar path and the batch alike): the
    // stiffnesses and dampings of the present overlap, the dashpot on the implicit end-of-step
    // velocity as for the linear law, and the tangential step of a linear spring of stiffness St
    // and damping gt (LinearSpringDashpot::tangentialStep, Theory/ContactLaws.md eq. (14));
    // frictionless: as LinearSpringDashpot::lastingContactInLane.
    template <bool frictionless = false>
    [[gnu::always_inline]] static void lastingContactInLane(LinearSpringDashpot::Lane& c, double dt, const double (&law)[5],
                                                            double effectiveRadius) {
        const double contactRadius = std::sqrt(effectiveRadius * c.overlap);  // sqrt(R* dn)
        const double normalStiffness = 2 * law[0] * contactRadius;              // Sn
        const double tangentialStiffness = 8 * law[1] * contactRadius;          // St
        const double reducedMass = 1 / c.inverseReducedMass;
        const double normalDamping = law[2] * std::sqrt(normalStiffness * reducedMass);
        const double tangentialDamping = law[2] * std::sqrt(tangentialStiffness * reducedMass);
        const double elastic = 2.0 / 3.0 * normalStiffness * c.overlap;
        const double halfStepOverMass = 0.5 * dt * c.inverseReducedMass;
        const double endVelocity = (c.normalVelocity + 0.5 * dt * c.otherAcceleration + halfStepOverMass * elastic) /
                                   (1 + halfStepOverMass * normalDamping);
        c.normalForce = elastic - normalDamping * endVelocity;
        if constexpr (frictionless)
            LinearSpringDashpot::withoutFriction(c);
        else
            LinearSpringDashpot{0, 0, tangentialStiffness, tangentialDamping, law[3]}.tangentialStep(c, dt);
    }

    // (Inlined always, so that each lane form compiles it into its own force loop; out of line the
    // linker keeps one copy, compiled for the baseline processor.)
    [[gnu::always_inline]] ContactForce force(const ContactKinematics& k, ContactHistory& history, double dt) const {
        LinearSpringDashpot::Lane c = LinearSpringDashpot::laneOf(k, history.spring);
        const LaneLaw numbers = lane();
        lastingContactInLane(c, dt, {numbers[0], numbers[1], numbers[2], numbers[3], numbers[4]}, k.effectiveRadius);
        history.spring = Vec3(c.sx, c.sy, c.sz);
        return {c.normalForce, Vec3(c.fx, c.fy, c.fz)};
    }

    // Normal: 8/15 E* sqrt(R*) dn^(5/2); tangential: 1/2 St |xi|^2 at the current overlap.
    double elasticEnergy(const ContactKinematics& k, const Vec3& spring) const {
        const double contactRadius = std::sqrt(k.effectiveRadius * k.overlap);
        return 8.0 / 15.0 * effectiveYoungsModulus * contactRadius * k.overlap * k.overlap +
               4 * effectiveShearModulus * contactRadius * spring.squaredNorm();
    }
};

}  // namespace talus

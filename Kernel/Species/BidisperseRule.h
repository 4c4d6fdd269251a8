// The bidisperse collision rule of Theory/ContactLaws.md "Bidisperse mixtures" (Denissen 2019, app.
// 3.C.2): in a mixture of large spheres (diameter dL) and small ones (dS), every pair type has the
// same restitution e, and the collision time scales with the square root of the pair's diameter,
// tc(d) = tcL sqrt(d/dL), with d = dL, dS and (dL + dS)/2 for LL, SS and LS contacts; kt = 2/7 kn
// and gt = gn. Each pair's stiffness and damping then follow from its reduced mass
// (LinearSpringDashpot::fromCollision). Friction coefficients are kept: the species' own for LL
// and SS, and for LS the mean of the two unless given.
#pragma once

#include <cmath>
#include <optional>

#include "Species/SpeciesTable.h"

namespace talus {

struct BidisperseMixture {
    std::size_t large, small;            // species indices
    double largeDiameter, smallDiameter;
    double largeCollisionTime;           // tc of two large spheres
    double restitution;
    std::optional<double> mixedFriction; // LS friction; default: mean of the two species'
};

inline void applyBidisperseRule(SpeciesTable& species, const BidisperseMixture& mix) {
    require(mix.largeDiameter > 0 && mix.smallDiameter > 0, "bidisperse rule: diameters must be positive");
    auto mass = [&](std::size_t s, double d) { return species[s].density * pi / 6 * d * d * d; };
    auto collisionTime = [&](double d) { return mix.largeCollisionTime * std::sqrt(d / mix.largeDiameter); };
    const double mL = mass(mix.large, mix.largeDiameter), mS = mass(mix.small, mix.smallDiameter);
    auto law = [&](double d, double reducedMass, double friction) {
        return LinearSpringDashpot::fromCollision(collisionTime(d), mix.restitution, reducedMass).withFriction(friction);
    };
    const double muL = std::get<LinearSpringDashpot>(species[mix.large].law).friction;
    const double muS = std::get<LinearSpringDashpot>(species[mix.small].law).friction;
    species[mix.large].law = law(mix.largeDiameter, mL / 2, muL);
    species[mix.small].law = law(mix.smallDiameter, mS / 2, muS);
    species.setPair(mix.large, mix.small, law(0.5 * (mix.largeDiameter + mix.smallDiameter), mL * mS / (mL + mS),
                                              mix.mixedFriction.value_or(0.5 * (muL + muS))));
}

}  // namespace talus

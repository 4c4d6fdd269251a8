#include "Boundaries/InsertionBoundary.h"

#include <cmath>
#include <cstdint>
#include <utility>

#include "Error.h"
#include "Simulation.h"

namespace talus {

InsertionBoundary::InsertionBoundary(const Region& region, SizeDistribution distribution, int maxAttemptsPerParticle)
    : filling_(region, maxAttemptsPerParticle), distribution_(std::move(distribution)) {
    distribution_.validate();
}

InsertionReport InsertionBoundary::insertCount(Simulation& s, std::size_t count) {
    return insert(s, InsertionReport::Target::count, static_cast<double>(count));
}

InsertionReport InsertionBoundary::insertMass(Simulation& s, double mass) {
    require(std::isfinite(mass) && mass >= 0, "insertMass: mass must not be negative, got " + str(mass));
    return insert(s, InsertionReport::Target::mass, mass);
}

InsertionReport InsertionBoundary::fillToVolumeFraction(Simulation& s, double fraction) {
    require(fraction >= 0 && fraction < 1, "fillToVolumeFraction: fraction must lie in [0, 1), got " + str(fraction));
    return insert(s, InsertionReport::Target::packingFraction, fraction);
}

InsertionReport InsertionBoundary::insertAtRate(Simulation& s, double particlesPerTime) {
    require(std::isfinite(particlesPerTime) && particlesPerTime >= 0,
            "insertAtRate: rate must not be negative, got " + str(particlesPerTime));
    const double dt = s.settings().timeStep;
    require(dt > 0, "insertAtRate: no time step (set settings().timeStep first)");
    // Products of the step count, not a running sum of rate dt, whose rounding would lose a
    // particle whenever rate t is a whole number.
    const auto due = [&](std::uint64_t step) { return std::floor(particlesPerTime * (double(step) * dt)); };
    const std::uint64_t n = s.step();
    return insert(s, InsertionReport::Target::count, n == 0 ? 0 : due(n) - due(n - 1));
}

InsertionReport InsertionBoundary::insert(Simulation& s, InsertionReport::Target target, double requested) {
    // The filling works on ranks, but a call every step would gather the whole scene every step
    // on every rank: during a run on ranks it is refused (setupInitialConditions runs on every
    // rank before the scene is split, which is fine).
    require(!s.ranks().isSplit(),
            "insertion boundary: inserting during a run on more than one rank is not supported yet "
            "(insert in setupInitialConditions, or run on one rank; Documentation/Parallel.md)");
    return filling_.fill(s, distribution_, target, requested);
}

}  // namespace talus

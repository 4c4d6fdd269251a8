// Insertion: fills a region with spheres drawn from a size distribution (issue 4; the filling of
// Boundaries/Filling.h, random sequential addition), to a count, a mass, a packing fraction of
// the region, or at a rate during the run. When a particle fails every attempt, insertion stops
// and the report says how far it got; the caller decides whether that is an error.
// Documentation/UserGuide/Insertion.md describes the algorithm and its limits.
#pragma once

#include <cstddef>

#include "Boundaries/Filling.h"
#include "Boundaries/Region.h"
#include "Boundaries/SizeDistribution.h"
#include "Math/Vector.h"

namespace talus {

class Simulation;

// Along an axis where the domain is periodic and the region covers the whole period, centres are
// drawn over the whole period; along every other axis a particle lies wholly inside the region.
// Nothing is printed; print report.describe() if you want it.
class InsertionBoundary {
public:
    InsertionBoundary(const Region& region, SizeDistribution distribution, int maxAttemptsPerParticle = 1000);
    // The box [lo, hi].
    InsertionBoundary(const Vec3& lo, const Vec3& hi, SizeDistribution distribution, int maxAttemptsPerParticle = 1000)
        : InsertionBoundary(Box(lo, hi), std::move(distribution), maxAttemptsPerParticle) {}

    // Velocity of the inserted particles (default zero).
    void setInitialVelocity(const Vec3& velocity) { filling_.setInitialVelocity(velocity); }

    // Inserts `count` particles, or fewer if one fails every attempt.
    InsertionReport insertCount(Simulation& s, std::size_t count);
    // Inserts until the inserted mass reaches `mass` (it exceeds it by less than one particle).
    InsertionReport insertMass(Simulation& s, double mass);
    // Inserts until the packing fraction of the region (old particles with centres in it
    // included) reaches `fraction`, exceeding it by less than one particle's volume.
    InsertionReport fillToVolumeFraction(Simulation& s, double fraction);
    // For a driver's actionsAfterTimeStep(): inserts floor(rate t_n) - floor(rate t_{n-1})
    // particles, t_n = n dt the time of step n (Simulation::step()). Over steps 1..N that sums
    // to floor(rate N dt) exactly, and, as it reads only the step count, a restarted run inserts
    // the same particles. Particles that find no place are reported, not carried to later steps.
    InsertionReport insertAtRate(Simulation& s, double particlesPerTime);

    const Region& region() const { return filling_.region(); }
    const SizeDistribution& distribution() const { return distribution_; }

private:
    InsertionReport insert(Simulation& s, InsertionReport::Target target, double requested);

    Filling filling_;
    SizeDistribution distribution_;
};

}  // namespace talus

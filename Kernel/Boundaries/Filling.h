// The one inserter (Documentation/UserGuide/Insertion.md; Theory/RotatingDrum.md "Filling"):
// random sequential addition of particles into a region (Boundaries/Region.h: a box, a cylinder,
// an annulus). Each particle to place gets up to maxAttemptsPerParticle random centres; the first
// where its bounding sphere lies inside the region, clear of every wall, and overlaps no
// particle's bounding sphere (fixed or mobile, nearest periodic image; touching is allowed) is
// taken. When a particle fails every attempt the filling stops, and its report says how far it
// got, so that a region is never under-filled silently.
//
// Candidates are drawn uniformly in the region shrunk by the particle's own bounding radius
// (Region::randomPoint): every place where it fits. Or, by choice, in the region shrunk by the
// largest bounding radius of the particles the call may place, one set for all of them (a
// smaller particle then keeps the difference in radii further from the faces than it needs to):
// the drum's filling has always drawn so, and keeps its particles by it. Spheres have no
// orientation; a superquadric gets a uniformly random one (a normalised quaternion of four
// Gaussian numbers). Random numbers come from Scene::random(), which the restart file keeps: the
// same seed gives the same particles.
//
// On ranks (Documentation/Parallel.md) every rank draws the same places against the whole scene
// (Sampling/ParticleSums.h gatherParticles) and each particle is added once (Sampling/AddedOnce.h):
// call it on every rank, in setupInitialConditions or during the run.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Boundaries/Region.h"
#include "Boundaries/SizeDistribution.h"
#include "Math/Vector.h"

namespace talus {

class Simulation;

// A kind of particle of Filling::fillInTurn: a species, and a sphere's radius or a superquadric shape.
struct ParticleKind {
    std::size_t species = 0;
    double radius = 0.5;  // of a sphere
    int shape = -1;       // a superquadric shape (Scene::addShape), or -1 for a sphere
    int target = 0;       // particles of this kind wanted in all
};

// What one filling call did. `requested` and `reached` are in the unit of the target: a number
// of particles, a mass, or a packing fraction of the region.
struct InsertionReport {
    enum class Target { count, mass, packingFraction };
    Target target = Target::count;
    double requested = 0;
    double reached = 0;
    std::size_t inserted = 0;  // particles added by this call
    std::size_t attempts = 0;  // candidate positions tried
    double mass = 0, volume = 0;  // of the particles added
    // Volume of every particle (old or new, fixed or mobile) whose centre lies in the region,
    // divided by the region's volume, after the call.
    double packingFraction = 0;
    bool complete = false;
    // When incomplete: the particle that found no free place (its bounding radius), and how
    // often it tried.
    std::size_t failedSpecies = 0;
    double failedRadius = 0;
    int maxAttemptsPerParticle = 0;

    // One line, e.g. "inserted 812 of 1000 particles (mass 406, packing fraction 0.31 of the
    // region) before a particle of species 0 and radius 0.5 failed 1000 attempts in a row".
    std::string describe() const;
    // The reached value of the target from the counts so far.
    double reachedSoFar() const;
};

class Filling {
public:
    enum class CandidateMargin { ownRadius, largestRadius };

    explicit Filling(const Region& region, int maxAttemptsPerParticle = 1000,
                     CandidateMargin margin = CandidateMargin::ownRadius);
    Filling(const Filling& other) : Filling(*other.region_, other.maxAttempts_, other.margin_) {
        velocity_ = other.velocity_;
    }

    // Velocity of the placed particles (default zero).
    void setInitialVelocity(const Vec3& velocity);
    const Region& region() const { return *region_; }

    // Spheres drawn from the distribution until the target is met: a count or a mass of the
    // particles this call adds, or the packing fraction of the region (old particles whose
    // centres lie in it included), each exceeded by less than one particle.
    InsertionReport fill(Simulation& s, const SizeDistribution& distribution, InsertionReport::Target target,
                         double requested) const;
    // The kinds in turn: the next particle is of the kind with the fewest inserted among those
    // below their target (the first on ties), so that the kinds fill alike. `inserted` holds the
    // particles of each kind inserted so far (the caller keeps it, in its restart values, for
    // the next call) and grows with those placed.
    InsertionReport fillInTurn(Simulation& s, const std::vector<ParticleKind>& kinds, std::vector<int>& inserted) const;

private:
    struct Candidate {
        std::size_t species;
        double radius;  // a sphere's, or the shape's bounding radius
        int shape;
    };
    using Next = std::function<std::optional<Candidate>(const InsertionReport& soFar)>;
    // Places the candidates `next` gives, until it gives none or one fails every attempt;
    // largestNew: the largest bounding radius of those it may give.
    InsertionReport place(Simulation& s, double largestNew, const Next& next, InsertionReport report) const;

    std::unique_ptr<Region> region_;
    int maxAttempts_;
    CandidateMargin margin_;
    Vec3 velocity_ = Vec3::Zero();
};

}  // namespace talus

// Insertion: fills a box with spheres drawn from a size distribution at random positions where
// they overlap nothing (issue 4; Theory/RotatingDrum.md "Filling"). Random sequential addition:
// each drawn particle gets up to maxAttemptsPerParticle random centres; the first that overlaps no
// particle (fixed or mobile, nearest periodic image) and no plane wall is taken. When a particle
// fails every attempt, insertion stops and the report says how far it got, so a region is never
// under-filled silently; the caller decides whether that is an error.
// Documentation/UserGuide/Insertion.md describes the algorithm and its limits.
#pragma once

#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "Math/Vector.h"

namespace talus {

class Simulation;

// One class of a size distribution: a species, radii uniform in [minRadius, maxRadius] (equal
// for a monodisperse class), and a weight.
struct SizeClass {
    std::size_t species = 0;
    double minRadius = 0, maxRadius = 0;
    double weight = 1;

    // 4/3 pi <r^3> for r uniform in [minRadius, maxRadius]: <r^3> = (a + b)(a^2 + b^2)/4.
    double meanVolume() const;
};

// A mixture of size classes. The weights are by number (byNumber: class k is drawn with
// probability w_k / sum w) or by volume (byVolume: with probability proportional to
// w_k / meanVolume_k, so that the classes fill volumes in the ratio of their weights). The
// bidisperse mixture of the thesis's table 3.C.1 (equal volumes of d = 1 and d = 0.7937) is
//   SizeDistribution::byVolume().add(large, 0.5).add(small, 0.5 * 0.7937)
class SizeDistribution {
public:
    static SizeDistribution byNumber() { return SizeDistribution(false); }
    static SizeDistribution byVolume() { return SizeDistribution(true); }

    // A monodisperse class; a class of radii uniform in [minRadius, maxRadius]. Both check the
    // class at once (positive radii, minRadius <= maxRadius, weight >= 0).
    SizeDistribution& add(std::size_t species, double radius, double weight = 1);
    SizeDistribution& addRange(std::size_t species, double minRadius, double maxRadius, double weight = 1);

    // Throws unless there is a class and some weight is positive.
    void validate() const;

    struct Draw {
        std::size_t species;
        double radius;
    };
    Draw sample(std::mt19937_64& random) const;

    const std::vector<SizeClass>& classes() const { return classes_; }
    bool weightsByVolume() const { return byVolume_; }
    // The probability that sample() draws class k.
    double probability(std::size_t k) const;
    double largestRadius() const;

private:
    explicit SizeDistribution(bool byVolume) : byVolume_(byVolume) {}

    bool byVolume_;
    std::vector<SizeClass> classes_;
    std::vector<double> cumulative_;  // running sums of the classes' draw weights
};

// What one insertion call did. `requested` and `reached` are in the unit of the target: a number
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
    // When incomplete: the particle that found no free place, and how often it tried.
    std::size_t failedSpecies = 0;
    double failedRadius = 0;
    int maxAttemptsPerParticle = 0;

    // One line, e.g. "inserted 812 of 1000 particles (mass 406, packing fraction 0.31 of the
    // region) before a particle of species 0 and radius 0.5 failed 1000 attempts in a row".
    std::string describe() const;
};

// Inserts into the box [lo, hi]. Along an axis where the domain is periodic and the box covers
// the whole period, centres are drawn over the whole period; along every other axis the box is
// shrunk by the particle's radius, so that the particle lies wholly inside it. Random numbers
// come from Scene::random(), which the restart file stores: the same seed gives the same
// particles. Nothing is printed; print report.describe() if you want it.
class InsertionBoundary {
public:
    InsertionBoundary(const Vec3& lo, const Vec3& hi, SizeDistribution distribution, int maxAttemptsPerParticle = 1000);

    // Velocity of the inserted particles (default zero).
    void setInitialVelocity(const Vec3& velocity);

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

    const Vec3& lo() const { return lo_; }
    const Vec3& hi() const { return hi_; }
    const SizeDistribution& distribution() const { return distribution_; }

private:
    InsertionReport insert(Simulation& s, InsertionReport::Target target, double requested);

    Vec3 lo_, hi_;
    SizeDistribution distribution_;
    int maxAttempts_;
    Vec3 velocity_ = Vec3::Zero();
};

}  // namespace talus

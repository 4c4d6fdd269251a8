#include "Boundaries/InsertionBoundary.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <utility>

#include "Error.h"
#include "Simulation.h"

namespace talus {

namespace {

std::string str(const Vec3& v) {
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

double sphereVolume(double r) { return 4.0 / 3.0 * pi * r * r * r; }

// A number uniform in [0, 1) from the top 53 bits of one draw. std::uniform_real_distribution
// would do, but the standard leaves its algorithm open, and this way a seed gives the same
// particles with every standard library.
double uniform(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

// A uniform grid of cells no smaller than the largest contact distance 2 rmax, so that a
// candidate can touch only particles in its own and the adjacent cells: the overlap test costs
// 27 cells whatever the number of particles. Along a periodic axis of the domain the grid covers
// the whole period and wraps (a particle across the face is a neighbour); along the other axes
// it covers the region widened by one contact distance each side, as particles further out
// cannot touch a particle inside the region.
class OverlapGrid {
public:
    OverlapGrid(const Domain& domain, const Vec3& lo, const Vec3& hi, double contactDistance) : image_(domain) {
        // A dense array of cells: cap its size (16 MB of cell heads) for a huge region of small
        // particles by making the cells larger, which keeps the test exact, only slower.
        const double maxCells = 1 << 22;
        double cell = contactDistance;
        for (;;) {
            double cells = 1;
            for (int a = 0; a < 3; ++a) {
                wraps_[a] = domain.periodic[a];
                origin_[a] = wraps_[a] ? domain.lo[a] : lo[a] - contactDistance;
                const double extent = wraps_[a] ? domain.length(a) : hi[a] - lo[a] + 2 * contactDistance;
                count_[a] = std::max(1, static_cast<int>(std::min(extent / cell, maxCells)));
                size_[a] = extent / count_[a];
                cells *= count_[a];
            }
            if (cells <= maxCells) break;
            cell *= 1.26;  // about 2^(1/3): halves the number of cells
        }
        head_.assign(static_cast<std::size_t>(count_[0]) * count_[1] * count_[2], -1);
    }

    // Whether a particle at x (wrapped into the domain) can touch a candidate in the region.
    bool covers(const Vec3& x) const {
        for (int a = 0; a < 3; ++a)
            if (!wraps_[a] && (x[a] < origin_[a] || x[a] >= origin_[a] + count_[a] * size_[a])) return false;
        return true;
    }

    void add(const Vec3& x, double r) {
        int k[3];
        for (int a = 0; a < 3; ++a) k[a] = cellOf(a, x[a]);
        int& head = head_[index(k[0], k[1], k[2])];
        next_.push_back(head);
        head = static_cast<int>(position_.size());
        position_.push_back(x);
        radius_.push_back(r);
    }

    // True when a sphere of radius r at x overlaps no sphere in the grid (touching is allowed).
    bool isFree(const Vec3& x, double r) const {
        int cells[3][3], n[3];
        for (int a = 0; a < 3; ++a) n[a] = neighbourCells(a, cellOf(a, x[a]), cells[a]);
        for (int i = 0; i < n[0]; ++i)
            for (int j = 0; j < n[1]; ++j)
                for (int k = 0; k < n[2]; ++k)
                    for (int q = head_[index(cells[0][i], cells[1][j], cells[2][k])]; q >= 0; q = next_[q]) {
                        const double reach = r + radius_[q];
                        if (image_.nearest(x - position_[q]).squaredNorm() < reach * reach) return false;
                    }
        return true;
    }

private:
    int cellOf(int a, double x) const {
        const int k = static_cast<int>(std::floor((x - origin_[a]) / size_[a]));
        if (wraps_[a]) return ((k % count_[a]) + count_[a]) % count_[a];
        return std::clamp(k, 0, count_[a] - 1);
    }

    // The cells along axis a within one cell of k (each once, also when the period has fewer
    // than three cells); returns how many.
    int neighbourCells(int a, int k, int* cells) const {
        if (wraps_[a] && count_[a] < 3) {
            for (int c = 0; c < count_[a]; ++c) cells[c] = c;
            return count_[a];
        }
        int n = 0;
        for (int c = k - 1; c <= k + 1; ++c) {
            if (wraps_[a]) cells[n++] = (c + count_[a]) % count_[a];
            else if (c >= 0 && c < count_[a]) cells[n++] = c;
        }
        return n;
    }

    std::size_t index(int i, int j, int k) const {
        return (static_cast<std::size_t>(k) * count_[1] + j) * count_[0] + i;
    }

    PeriodicImage image_;
    bool wraps_[3];
    double origin_[3], size_[3];
    int count_[3];
    std::vector<int> head_;  // first sphere of each cell, -1 if none; next_ links the rest
    std::vector<int> next_;
    std::vector<Vec3> position_;
    std::vector<double> radius_;
};

bool clearOfWalls(const std::vector<Wall>& walls, const Vec3& x, double r) {
    for (const Wall& w : walls)
        if (w.signedDistance(x) < r) return false;
    return true;
}

const char* axisName(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }

// The box as filled: along an axis where the domain is periodic and the box covers the whole
// period it is exactly one period and centres may lie anywhere in it; along the other axes a
// centre keeps one radius from the faces, so that the particle lies wholly inside.
struct Region {
    Vec3 lo, hi;
    bool spans[3];

    Region(const Vec3& boxLo, const Vec3& boxHi, const Domain& domain) : lo(boxLo), hi(boxHi) {
        for (int a = 0; a < 3; ++a) {
            spans[a] = domain.periodic[a] && boxLo[a] <= domain.lo[a] && boxHi[a] >= domain.hi[a];
            if (spans[a]) {
                lo[a] = domain.lo[a];
                hi[a] = domain.hi[a];
            }
        }
    }

    double volume() const { return (hi - lo).prod(); }

    // For the packing fraction: whether a centre (wrapped into the domain) lies in the region.
    bool contains(const Vec3& x) const {
        for (int a = 0; a < 3; ++a)
            if (!spans[a] && (x[a] < lo[a] || x[a] > hi[a])) return false;
        return true;
    }

    // A random centre for a sphere of radius r, before wrapping into the domain.
    Vec3 randomCentre(double r, std::mt19937_64& random) const {
        Vec3 x;
        for (int a = 0; a < 3; ++a) {
            const double margin = spans[a] ? 0 : r;
            x[a] = lo[a] + margin + uniform(random) * (hi[a] - lo[a] - 2 * margin);
        }
        return x;
    }
};

}  // namespace

// --- size distribution ---

double SizeClass::meanVolume() const {
    const double a = minRadius, b = maxRadius;
    return 4.0 / 3.0 * pi * (a + b) * (a * a + b * b) / 4;
}

SizeDistribution& SizeDistribution::add(std::size_t species, double radius, double weight) {
    return addRange(species, radius, radius, weight);
}

SizeDistribution& SizeDistribution::addRange(std::size_t species, double minRadius, double maxRadius, double weight) {
    const std::string which = "size distribution: size class " + std::to_string(classes_.size());
    require(std::isfinite(minRadius) && minRadius > 0, which + ": radius must be positive, got " + str(minRadius));
    require(std::isfinite(maxRadius) && maxRadius > 0, which + ": radius must be positive, got " + str(maxRadius));
    require(minRadius <= maxRadius,
            which + ": minRadius " + str(minRadius) + " is larger than maxRadius " + str(maxRadius));
    require(std::isfinite(weight) && weight >= 0, which + ": weight must not be negative, got " + str(weight));
    const SizeClass c{species, minRadius, maxRadius, weight};
    const double drawWeight = byVolume_ ? weight / c.meanVolume() : weight;
    classes_.push_back(c);
    cumulative_.push_back((cumulative_.empty() ? 0 : cumulative_.back()) + drawWeight);
    return *this;
}

void SizeDistribution::validate() const {
    require(!classes_.empty(), "insertion: empty size distribution (add a size class with SizeDistribution::add)");
    require(cumulative_.back() > 0, "size distribution: all weights are zero (give some size class a positive weight)");
}

SizeDistribution::Draw SizeDistribution::sample(std::mt19937_64& random) const {
    if (cumulative_.empty() || !(cumulative_.back() > 0)) validate();
    const double u = uniform(random) * cumulative_.back();
    // The first class whose running sum exceeds u; classes of weight 0 are never drawn.
    const std::size_t k = std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin();
    const SizeClass& c = classes_[std::min(k, classes_.size() - 1)];
    return {c.species, c.minRadius + uniform(random) * (c.maxRadius - c.minRadius)};
}

double SizeDistribution::probability(std::size_t k) const {
    validate();
    require(k < classes_.size(), "size distribution: size class " + std::to_string(k) + " does not exist");
    return (cumulative_[k] - (k == 0 ? 0 : cumulative_[k - 1])) / cumulative_.back();
}

double SizeDistribution::largestRadius() const {
    double r = 0;
    for (const SizeClass& c : classes_) r = std::max(r, c.maxRadius);
    return r;
}

// --- report ---

std::string InsertionReport::describe() const {
    std::ostringstream m;
    m << "inserted " << inserted;
    switch (target) {
    case Target::count:
        m << " of " << static_cast<std::size_t>(requested) << " particles (mass " << mass << ", packing fraction "
          << packingFraction << " of the region)";
        break;
    case Target::mass:
        m << " particles of mass " << mass << " of the " << requested << " requested (packing fraction "
          << packingFraction << " of the region)";
        break;
    case Target::packingFraction:
        m << " particles of mass " << mass << ", reaching packing fraction " << packingFraction
          << " of the region of the " << requested << " requested";
        break;
    }
    if (complete)
        m << " in " << attempts << " attempts";
    else
        m << " before a particle of species " << failedSpecies << " and radius " << failedRadius << " failed "
          << maxAttemptsPerParticle << " attempts in a row";
    return m.str();
}

// --- insertion ---

InsertionBoundary::InsertionBoundary(const Vec3& lo, const Vec3& hi, SizeDistribution distribution,
                                     int maxAttemptsPerParticle)
    : lo_(lo), hi_(hi), distribution_(std::move(distribution)), maxAttempts_(maxAttemptsPerParticle) {
    require(isFinite(lo) && isFinite(hi) && (hi - lo).minCoeff() > 0,
            "insertion region: the upper corner " + str(hi) + " must lie above the lower corner " + str(lo) +
                " along x, y and z");
    require(maxAttemptsPerParticle >= 1,
            "insertion: maxAttemptsPerParticle must be at least 1, got " + std::to_string(maxAttemptsPerParticle));
    distribution_.validate();
}

void InsertionBoundary::setInitialVelocity(const Vec3& velocity) {
    require(isFinite(velocity), "insertion: the initial velocity is not finite");
    velocity_ = velocity;
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
    // Every rank would insert the same particles: insertion during a run on ranks is not done yet
    // (setupInitialConditions runs on every rank before the scene is split, which is fine).
    require(!s.ranks().isSplit(),
            "insertion boundary: inserting during a run on more than one rank is not supported yet "
            "(insert in setupInitialConditions, or run on one rank; Documentation/Parallel.md)");
    const Domain& domain = s.scene().domain();
    for (std::size_t k = 0; k < distribution_.classes().size(); ++k) {
        const std::size_t species = distribution_.classes()[k].species;
        require(species < s.scene().species().size(), "size distribution: size class " + std::to_string(k) + ": species " +
                                                  std::to_string(species) + " does not exist (add species first)");
    }
    const Region region(lo_, hi_, domain);
    const double diameter = 2 * distribution_.largestRadius();
    for (int a = 0; a < 3; ++a) {
        const double thickness = region.hi[a] - region.lo[a];
        require(region.spans[a] || thickness >= diameter,
                "insertion region: " + str(thickness) + " wide along " + axisName(a) +
                    ", less than the largest particle diameter " + str(diameter));
    }

    InsertionReport report;
    report.target = target;
    report.requested = requested;
    report.maxAttemptsPerParticle = maxAttempts_;
    ParticleStore& p = s.scene().particles();
    double largestRadius = distribution_.largestRadius(), occupied = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        largestRadius = std::max(largestRadius, p.radius[i]);
        Vec3 x = p.position[i];
        domain.wrap(x);
        if (region.contains(x)) occupied += sphereVolume(p.radius[i]);
    }
    const auto reached = [&] {
        switch (target) {
        case InsertionReport::Target::count: return static_cast<double>(report.inserted);
        case InsertionReport::Target::mass: return report.mass;
        case InsertionReport::Target::packingFraction: return occupied / region.volume();
        }
        return 0.0;
    };
    const auto finish = [&](bool complete) {
        report.reached = reached();
        report.packingFraction = occupied / region.volume();
        report.complete = complete;
        return report;
    };
    if (reached() >= requested) return finish(true);  // no grid for a call with nothing to do

    OverlapGrid grid(domain, region.lo, region.hi, 2 * largestRadius);
    for (std::size_t i = 0; i < p.size(); ++i) {
        Vec3 x = p.position[i];
        domain.wrap(x);
        if (grid.covers(x)) grid.add(x, p.radius[i]);
    }
    std::mt19937_64& random = s.scene().random();
    while (reached() < requested) {
        const SizeDistribution::Draw draw = distribution_.sample(random);
        const double r = draw.radius;
        bool placed = false;
        for (int attempt = 0; attempt < maxAttempts_ && !placed; ++attempt) {
            ++report.attempts;
            Vec3 x = region.randomCentre(r, random);
            domain.wrap(x);
            if (!clearOfWalls(s.scene().walls(), x, r) || !grid.isFree(x, r)) continue;
            const std::size_t slot = s.scene().addParticle(x, r, draw.species, velocity_);
            grid.add(x, r);
            ++report.inserted;
            report.mass += p.mass[slot];
            report.volume += sphereVolume(r);
            occupied += sphereVolume(r);
            placed = true;
        }
        if (!placed) {
            report.failedSpecies = draw.species;
            report.failedRadius = r;
            return finish(false);
        }
    }
    return finish(true);
}

}  // namespace talus

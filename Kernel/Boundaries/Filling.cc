#include "Boundaries/Filling.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "Boundaries/OverlapGrid.h"
#include "Error.h"
#include "Sampling/AddedOnce.h"
#include "Sampling/ParticleSums.h"
#include "Simulation.h"
#include "Walls/MeshWalls.h"

namespace talus {

namespace {

double sphereVolume(double r) { return 4.0 / 3.0 * pi * r * r * r; }

// (A mesh's triangles are asked through its grid, only those near x, not one by one: a silo
// of thousands of triangles is filled with thousands of tries.)
bool clearOfWalls(const std::vector<Wall>& walls, const Vec3& x, double r) {
    bool clear = true;
    forEachWallOrMesh(
        walls, [&](std::uint32_t w) { clear = clear && !(walls[w].signedDistance(x) < r); },
        [&](const MeshWalls& mesh) { mesh.forTrianglesWithin(x, r, [&](std::uint32_t) { clear = false; }); });
    return clear;
}

}  // namespace

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

double InsertionReport::reachedSoFar() const {
    switch (target) {
    case Target::count: return static_cast<double>(inserted);
    case Target::mass: return mass;
    case Target::packingFraction: return packingFraction;
    }
    return 0;
}

Filling::Filling(const Region& region, int maxAttemptsPerParticle, CandidateMargin margin)
    : region_(region.clone()), maxAttempts_(maxAttemptsPerParticle), margin_(margin) {
    require(maxAttemptsPerParticle >= 1,
            "insertion: maxAttemptsPerParticle must be at least 1, got " + std::to_string(maxAttemptsPerParticle));
}

void Filling::setInitialVelocity(const Vec3& velocity) {
    require(isFinite(velocity), "insertion: the initial velocity is not finite");
    velocity_ = velocity;
}

InsertionReport Filling::fill(Simulation& s, const SizeDistribution& distribution, InsertionReport::Target target,
                              double requested) const {
    distribution.validate();
    for (std::size_t k = 0; k < distribution.classes().size(); ++k) {
        const std::size_t species = distribution.classes()[k].species;
        require(species < s.scene().species().size(), "size distribution: size class " + std::to_string(k) + ": species " +
                                                           std::to_string(species) + " does not exist (add species first)");
    }
    InsertionReport report;
    report.target = target;
    report.requested = requested;
    const Next next = [&](const InsertionReport& soFar) -> std::optional<Candidate> {
        if (soFar.reachedSoFar() >= requested) return std::nullopt;
        const SizeDistribution::Draw draw = distribution.sample(s.scene().random());
        return Candidate{draw.species, draw.radius, -1};
    };
    return place(s, distribution.largestRadius(), next, report);
}

InsertionReport Filling::fillInTurn(Simulation& s, const std::vector<ParticleKind>& kinds, std::vector<int>& inserted) const {
    require(!kinds.empty(), "insertion: no kind of particle");
    require(inserted.size() == kinds.size(), "insertion: one count of inserted particles per kind");
    std::vector<double> boundingRadius;
    InsertionReport report;
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        const ParticleKind& kind = kinds[k];
        const std::string which = "insertion: particle kind " + std::to_string(k);
        require(kind.species < s.scene().species().size(),
                which + ": species " + std::to_string(kind.species) + " does not exist (add species first)");
        require(kind.shape < static_cast<int>(s.scene().shapes().size()),
                which + ": shape " + std::to_string(kind.shape) + " does not exist (add it with Scene::addShape first)");
        require(kind.shape >= 0 || (std::isfinite(kind.radius) && kind.radius > 0),
                which + ": radius must be positive, got " + str(kind.radius));
        boundingRadius.push_back(kind.shape >= 0 ? s.scene().shapes()[static_cast<std::size_t>(kind.shape)].boundingRadius()
                                                 : kind.radius);
        report.requested += std::max(0, kind.target - inserted[k]);
    }
    std::optional<std::size_t> last;  // the kind of the candidate before: placed, if next is asked again
    const Next next = [&](const InsertionReport&) -> std::optional<Candidate> {
        if (last) ++inserted[*last];
        last.reset();
        for (std::size_t k = 0; k < kinds.size(); ++k)
            if (inserted[k] < kinds[k].target && (!last || inserted[k] < inserted[*last])) last = k;
        if (!last) return std::nullopt;
        return Candidate{kinds[*last].species, boundingRadius[*last], kinds[*last].shape};
    };
    return place(s, *std::max_element(boundingRadius.begin(), boundingRadius.end()), next, report);
}

InsertionReport Filling::place(Simulation& s, double largestNew, const Next& next, InsertionReport report) const {
    const Domain& domain = s.scene().domain();
    region_->checkFits(largestNew, domain);
    report.maxAttemptsPerParticle = maxAttempts_;
    // The whole scene's particles on every rank (a copy only when the scene is split).
    const bool split = s.ranks().isSplit();
    const ParticleStore gathered = split ? gatherParticles(s, allParticles()) : ParticleStore();
    const ParticleStore& p = split ? gathered : s.scene().particles();
    const double regionVolume = region_->volume(domain);
    double largestRadius = largestNew, occupied = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        largestRadius = std::max(largestRadius, p.radius[i]);
        Vec3 x = p.position[i];
        domain.wrap(x);
        if (region_->holds(x, 0, domain)) occupied += particleVolume(s, p, i);
    }
    const auto finish = [&](bool complete) {
        report.packingFraction = occupied / regionVolume;
        report.reached = report.reachedSoFar();
        report.complete = complete;
        return report;
    };
    report.packingFraction = occupied / regionVolume;
    std::optional<Candidate> candidate = next(report);
    if (!candidate) return finish(true);  // no grid for a call with nothing to do

    Vec3 lo, hi;
    region_->bounds(domain, lo, hi);
    OverlapGrid grid(domain, lo, hi, 2 * largestRadius);
    for (std::size_t i = 0; i < p.size(); ++i) {
        Vec3 x = p.position[i];
        domain.wrap(x);
        if (grid.covers(x)) grid.add(x, p.radius[i]);
    }
    std::mt19937_64& random = s.scene().random();
    // (std::normal_distribution's algorithm is the standard library's: a superquadric's
    // orientation may differ from one library to another; the places do not.)
    std::normal_distribution<double> gauss;
    for (; candidate; candidate = next(report)) {
        const double r = candidate->radius;
        const double margin = margin_ == CandidateMargin::ownRadius ? r : largestNew;
        bool placed = false;
        for (int attempt = 0; attempt < maxAttempts_ && !placed; ++attempt) {
            ++report.attempts;
            Vec3 x = region_->randomPoint(margin, domain, random);
            if (!region_->holds(x, r, domain)) continue;
            domain.wrap(x);
            if (!clearOfWalls(s.scene().walls(), x, r) || !grid.isFree(x, r)) continue;
            placed = true;
            double volume = sphereVolume(r);
            if (candidate->shape < 0) {
                addParticleOnce(s, x, r, candidate->species, velocity_);
            } else {
                // Four Gaussian numbers drawn w last (the order in which the drum's filling drew them).
                const double qz = gauss(random), qy = gauss(random), qx = gauss(random), qw = gauss(random);
                const std::size_t shape = static_cast<std::size_t>(candidate->shape);
                addSuperquadricOnce(s, x, shape, candidate->species, Quat(qw, qx, qy, qz).normalized(), velocity_);
                volume = s.scene().shapes()[shape].volume();
            }
            grid.add(x, r);
            ++report.inserted;
            report.mass += s.scene().species()[candidate->species].density * volume;
            report.volume += volume;
            occupied += volume;
            report.packingFraction = occupied / regionVolume;
        }
        if (!placed) {
            report.failedSpecies = candidate->species;
            report.failedRadius = r;
            return finish(false);
        }
    }
    return finish(true);
}

}  // namespace talus

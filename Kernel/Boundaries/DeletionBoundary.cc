#include "Boundaries/DeletionBoundary.h"

#include <cmath>

#include "Error.h"
#include "Simulation.h"

namespace talus {

DeletionBoundary::DeletionBoundary(Made made, Simulation& s, const Vec3& normal, const Vec3& point, std::size_t species,
                                   const std::string& name)
    : Boundary(made), speciesMass_(species, 0), speciesVolume_(species, 0) {
    setPlane(normal, point);
    // The plane too: a driver may set it from its flags in setupInitialConditions, which a
    // restarted run does not call.
    for (int a = 0; a < 3; ++a) {
        s.run().keepInRestart(name + ".normal." + std::to_string(a), normal_[a]);
        s.run().keepInRestart(name + ".point." + std::to_string(a), point_[a]);
    }
    s.run().keepInRestart(name + ".count", count_);
    s.run().keepInRestart(name + ".mass", mass_);
    s.run().keepInRestart(name + ".volume", volume_);
    for (std::size_t k = 0; k < species; ++k) {
        s.run().keepInRestart(name + ".mass." + std::to_string(k), speciesMass_[k]);
        s.run().keepInRestart(name + ".volume." + std::to_string(k), speciesVolume_[k]);
    }
}

void DeletionBoundary::setPlane(const Vec3& normal, const Vec3& point) {
    require(isFinite(normal) && normal.norm() > 0 && isFinite(point),
            "deletion boundary: the plane needs a non-zero normal and a finite point");
    normal_ = normal.normalized();
    point_ = point;
}

std::size_t DeletionBoundary::apply(Simulation& s) {
    const ParticleStore& p = s.scene().particles();
    // What this call removes: count, mass, volume, and per species mass and volume (summed over
    // the ranks on ranks, where each rank removes the particles it owns).
    const std::size_t species = speciesMass_.size();
    std::vector<double> removed(3 + 2 * species, 0.0);
    // From the last slot down: removal moves the last particle into the freed slot.
    for (std::size_t i = p.owned(); i-- > 0;) {
        if (p.fixed[i] || (p.position[i] - point_).dot(normal_) <= 0) continue;
        const double volume = 4.0 / 3.0 * pi * std::pow(p.radius[i], 3);
        removed[0] += 1;
        removed[1] += p.mass[i];
        removed[2] += volume;
        if (p.species[i] < species) {
            removed[3 + p.species[i]] += p.mass[i];
            removed[3 + species + p.species[i]] += volume;
        }
        s.scene().removeParticle(i);
    }
    const auto here = static_cast<std::size_t>(removed[0]);
    s.ranks().sum(removed);
    count_ += removed[0];
    mass_ += removed[1];
    volume_ += removed[2];
    for (std::size_t k = 0; k < species; ++k) {
        speciesMass_[k] += removed[3 + k];
        speciesVolume_[k] += removed[3 + species + k];
    }
    return here;
}

}  // namespace talus

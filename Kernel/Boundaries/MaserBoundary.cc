#include "Boundaries/MaserBoundary.h"

#include <cmath>

#include "Error.h"
#include "Simulation.h"

namespace talus {

MaserBoundary::MaserBoundary(Made made, Simulation& s, double lo, double hi, std::size_t species, const std::string& name)
    : Boundary(made), speciesCount_(species, 0), speciesMass_(species, 0) {
    setBox(lo, hi);
    s.run().keepInRestart(name + ".lo", lo_);  // (a driver sets the box in its set-up, which a restart skips)
    s.run().keepInRestart(name + ".hi", hi_);
    s.run().keepInRestart(name + ".crossings", crossings_);
    s.run().keepInRestart(name + ".mass", mass_);
    s.run().keepInRestart(name + ".backward", backward_);
    s.run().keepInRestart(name + ".seeded", seeded_);
    s.run().keepInRestart(name + ".seededMass", seededMass_);
    for (std::size_t k = 0; k < species; ++k) {
        s.run().keepInRestart(name + ".crossings." + std::to_string(k), speciesCount_[k]);
        s.run().keepInRestart(name + ".mass." + std::to_string(k), speciesMass_[k]);
    }
}

void MaserBoundary::setBox(double lo, double hi) {
    require(std::isfinite(lo) && std::isfinite(hi) && hi > lo,
            "maser box: the downstream end (" + str(hi) + ") must lie downstream of the upstream end (" + str(lo) + ")");
    lo_ = lo;
    hi_ = hi;
}

std::size_t MaserBoundary::maserSpecies(Simulation& s, std::size_t chuteSpecies) {
    require(!active(s), "maser: add its species before activating it");
    require(chuteSpecies < s.scene().species().size(),
            "maser: chute species " + std::to_string(chuteSpecies) + " does not exist");
    const std::size_t copy = s.scene().species().addCopy(chuteSpecies, "maser-" + s.scene().species()[chuteSpecies].name);
    OneWayPeriodicBox& box = s.scene().oneWayBox();
    require(box.outflowSpecies.empty() || (box.lo == lo_ && box.hi == hi_), "maser: the box moved after its species were added");
    box.lo = lo_;
    box.hi = hi_;
    box.outflowSpecies.resize(s.scene().species().size(), -1);
    box.outflowSpecies[copy] = static_cast<std::int32_t>(chuteSpecies);
    return copy;
}

bool MaserBoundary::active(const Simulation& s) const { return s.scene().domain().oneWay.active; }

void MaserBoundary::activate(Simulation& s, double chuteEnd, bool seedChute) {
    require(!active(s), "maser: activated twice");
    OneWayPeriodicBox& box = s.scene().oneWayBox();
    require(box.lo == lo_ && box.hi == hi_, "maser: no maser species (call maserSpecies before activating)");
    require(s.scene().domain().lo.x() == lo_,
            "maser: the domain must start at the box's upstream face x = " + str(lo_) + ", not " + str(s.scene().domain().lo.x()));
    require(std::isfinite(chuteEnd) && chuteEnd > hi_,
            "maser: the chute must end downstream of the box (x = " + str(hi_) + "), got " + str(chuteEnd));
    const ParticleStore& p = s.scene().particles();
    double mobile = 0, largest = 0;
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (!box.isMember(p.species[i])) continue;
        // The one-way pairs across the face and the copies are written for spheres.
        require(!p.isShaped(i), "maser: superquadric particles in the maser box are not supported (particle id " +
                                    std::to_string(p.id[i]) + "); its copies and one-way contacts are for spheres");
        largest = std::max(largest, 2 * p.radius[i]);
        mobile += !p.fixed[i];
    }
    mobile = s.ranks().sum(mobile);
    largest = s.ranks().max(largest);
    require(mobile > 0, "maser: activated on a box with no particles (no mobile particle of a maser species)");
    require(hi_ - lo_ >= 2 * largest, "maser: the box (length " + str(hi_ - lo_) +
                                          ") must be longer than two diameters of its largest particle (" +
                                          str(largest) + ")");
    box.active = true;
    if (seedChute) {
        const std::size_t n = p.owned();
        std::vector<double> seeded = {0, 0};
        for (std::size_t i = 0; i < n; ++i) {
            if (p.fixed[i] || !box.isMember(p.species[i])) continue;
            const Vec3 x = p.position[i] + Vec3(hi_ - lo_, 0, 0), v = p.velocity[i], w = p.angularVelocity[i];
            const std::size_t copy =
                s.scene().addParticle(x, p.radius[i], static_cast<std::size_t>(box.outflowSpecies[p.species[i]]), v, w);
            seeded[0] += 1;
            seeded[1] += p.mass[copy];
        }
        s.ranks().sum(seeded);
        seeded_ += seeded[0];
        seededMass_ += seeded[1];
    }
    setChuteEnd(s, chuteEnd);
    s.scene().setPeriodic(false, s.scene().domain().periodic[1], s.scene().domain().periodic[2]);
}

void MaserBoundary::setChuteEnd(Simulation& s, double chuteEnd) const {
    require(active(s), "maser: the chute's end is set at activation or after");
    require(std::isfinite(chuteEnd) && chuteEnd > hi_,
            "maser: the chute must end downstream of the box (x = " + str(hi_) + "), got " + str(chuteEnd));
    Vec3 hi = s.scene().domain().hi;
    hi.x() = chuteEnd;
    s.scene().setDomain(s.scene().domain().lo, hi);
}

void MaserBoundary::afterDrift(Simulation& s) {
    const OneWayPeriodicBox& box = s.scene().domain().oneWay;
    if (!box.active) return;
    const double length = box.length();
    ParticleStore& p = s.scene().particles();
    // What this step added to the totals: crossings, their mass, backward crossings, and per
    // chute species the count and mass (summed over the ranks on ranks).
    const std::size_t species = speciesCount_.size();
    std::vector<double> added(3 + 2 * species, 0.0);
    const std::size_t n = p.owned();  // the copies, appended, are chute particles
    for (std::size_t i = 0; i < n; ++i) {
        if (p.fixed[i] || !box.isMember(p.species[i])) continue;
        const double x = p.position[i].x();
        if (x >= box.hi) {
            const auto chuteSpecies = static_cast<std::size_t>(box.outflowSpecies[p.species[i]]);
            const std::size_t copy =
                s.scene().addParticle(p.position[i], p.radius[i], chuteSpecies, p.velocity[i], p.angularVelocity[i]);
            p.force[copy] = p.force[i];  // the last step's force, which the next contact forces start from
            added[0] += 1;
            added[1] += p.mass[copy];
            if (chuteSpecies < species) {
                added[3 + chuteSpecies] += 1;
                added[3 + species + chuteSpecies] += p.mass[copy];
            }
            s.scene().moveParticleBy(i, Vec3(-length, 0, 0));
        } else if (x < box.lo - 2 * p.radius[i]) {
            // A diameter behind the upstream face, not at it: a particle just moved back from the
            // downstream face meets the particles in front of it there and may be pushed back a
            // little; moved forward at once it would land on its own copy.
            s.scene().moveParticleBy(i, Vec3(length, 0, 0));
            added[2] += 1;
        }
    }
    s.ranks().sum(added);
    crossings_ += added[0];
    mass_ += added[1];
    backward_ += added[2];
    for (std::size_t k = 0; k < species; ++k) {
        speciesCount_[k] += added[3 + k];
        speciesMass_[k] += added[3 + species + k];
    }
}

}  // namespace talus

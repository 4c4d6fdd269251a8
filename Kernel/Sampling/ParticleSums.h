// Sums and extrema over the particles of a whole scene, or over those a selection picks (a box,
// a species, any predicate), for a driver's measurements. Every function here is collective:
// under mpirun each rank adds up the particles it owns and the results are summed (or their
// extrema taken) over the ranks, so every rank gets the whole scene's value; on one rank it is
// a plain loop. The particles are visited in slot order, so on one rank the result is bitwise
// that of a hand-written loop over them; on two ranks too, the two parts being added in either
// order alike (on more, MPI's reduction chooses the order: round-off, or --id-ordered-sums).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "Math/Vector.h"
#include "Particles/ParticleStore.h"

namespace talus {

class Simulation;

// Which particles a sum covers: a predicate of the store and a slot (an owned particle).
using Selection = std::function<bool(const ParticleStore&, std::size_t)>;
// A per-particle quantity.
using ParticleQuantity = std::function<double(const ParticleStore&, std::size_t)>;

// Common selections; combine them with `both`.
Selection allParticles();
Selection mobileParticles();                   // not fixed
// Of one species (fixed or not). A predicate the compiler sees, so that a template taking it
// (RunningSums::addStepIntegral) inlines it; it converts to a Selection where one is asked for.
inline auto ofSpecies(std::size_t species) {
    return [species](const ParticleStore& p, std::size_t i) { return p.species[i] == species; };
}
Selection inBox(const Vec3& lo, const Vec3& hi);  // centre in [lo, hi)
Selection both(Selection a, Selection b);

// The bulk of the selected particles. Volume: 4/3 pi r^3 of a sphere, the shape's volume of a
// superquadric.
struct Totals {
    double count = 0, mass = 0, volume = 0;
    double translationalEnergy = 0, rotationalEnergy = 0;  // each summed on its own, as Simulation::energies
    double kineticEnergy() const { return translationalEnergy + rotationalEnergy; }
    Vec3 momentum = Vec3::Zero();
    Vec3 massMoment = Vec3::Zero();  // sum of m x
    Vec3 centreOfMass() const { return mass > 0 ? Vec3(massMoment / mass) : Vec3(Vec3::Zero()); }
    // The solid fraction of a region of the given volume that holds these particles' centres.
    double solidFraction(double regionVolume) const { return volume / regionVolume; }
};
// 4/3 pi r^3 of a sphere, the shape's volume of a superquadric.
double particleVolume(const Simulation& simulation, const ParticleStore& particles, std::size_t i);
Totals totalsOver(const Simulation& simulation, const Selection& selection = mobileParticles());

// Sums of several quantities over the same particles, in one pass and one collective.
std::vector<double> sumsOver(const Simulation& simulation, const Selection& selection,
                             const std::vector<ParticleQuantity>& quantities);
double sumOver(const Simulation& simulation, const Selection& selection, const ParticleQuantity& quantity);
// Numbers that each process of the run counts for itself (its memory, the contacts it computed,
// the pairs it listed), summed over the whole run.
std::vector<double> sumOverScene(const Simulation& simulation, std::vector<double> parts);
// Largest and smallest value over the selected particles (-inf and +inf when none is selected).
double maxOver(const Simulation& simulation, const Selection& selection, const ParticleQuantity& quantity);
double minOver(const Simulation& simulation, const Selection& selection, const ParticleQuantity& quantity);

// Calls action(slot) for every selected particle this rank owns, for an action on each particle
// (copy it, change it): every rank acts on its own. Particles the action adds are not visited.
class Simulation;
void forEachSelected(Simulation& simulation, const Selection& selection, const std::function<void(std::size_t)>& action);

// The selected particles of every rank in one store, in id order (position, velocity, angular
// velocity, radius, mass, species, id, fixed, shape and orientation), for a measurement that
// needs the whole scene at once (a coarse-grained field, a surface). On one rank it is a copy of
// the selected particles in slot order, so that a measurement made on it is bitwise the one
// made on the simulation's own store (so also in setupInitialConditions, where every rank holds
// the whole scene). Every rank gets the whole copy.
ParticleStore gatherParticles(const Simulation& simulation, const Selection& selection = mobileParticles());

}  // namespace talus

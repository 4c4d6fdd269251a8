#include "Sampling/AddedOnce.h"

#include "Simulation.h"

namespace talus {

namespace {
bool addsHere(const Simulation& simulation) { return !simulation.ranks().isSplit() || simulation.ranks().rank() == 0; }
}  // namespace

void addParticleOnce(Simulation& simulation, const Vec3& position, double radius, std::size_t species,
                     const Vec3& velocity) {
    if (addsHere(simulation)) simulation.scene().addParticle(position, radius, species, velocity);
}

void addSuperquadricOnce(Simulation& simulation, const Vec3& position, std::size_t shape, std::size_t species,
                         const Quat& orientation, const Vec3& velocity) {
    if (addsHere(simulation))
        simulation.scene().addSuperquadric(position, shape, species, orientation, velocity);
    else
        simulation.scene().enableShapes();  // (the ranks exchange particles in one layout)
}

}  // namespace talus

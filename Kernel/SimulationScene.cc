// Building and editing the scene (Documentation/Architecture.md "The driver contract"): the box, species, particles, walls and prescribed
// motions a driver sets up, and the particles it adds, moves or removes during a run. Part of
// talus::Simulation.
#include <algorithm>
#include <cmath>

#include "Particles/RigidBodyRotation.h"
#include "Simulation.h"

namespace talus {

void Simulation::setDomain(const Vec3& lo, const Vec3& hi) {
    require(isFinite(lo) && isFinite(hi) && (hi - lo).minCoeff() > 0,
            "domain: the upper corner must lie above the lower corner along x, y and z");
    state_.domain.lo = lo;
    state_.domain.hi = hi;
    state_.pairList.valid = false;
}

void Simulation::setPeriodic(bool x, bool y, bool z) {
    state_.domain.periodic = {x, y, z};
    state_.pairList.valid = false;
}

std::size_t Simulation::addSpecies(const std::string& name, double density, const ContactLaw& law) {
    requireWord(name, "species name");
    return state_.species.add(name, density, law);
}

std::size_t Simulation::addParticle(const Vec3& position, double radius, std::size_t species, const Vec3& velocity,
                                    const Vec3& angularVelocity) {
    ParticleStore& p = state_.particles;
    const std::string which = "particle " + std::to_string(state_.nextId);
    require(std::isfinite(radius) && radius > 0, which + ": radius must be positive, got " + str(radius));
    require(isFinite(position), which + ": position is not finite");
    require(isFinite(velocity) && isFinite(angularVelocity), which + ": velocity is not finite");
    require(species < state_.species.size(), which + ": species " + std::to_string(species) +
                                                 " does not exist (add species before particles)");
    const double mass = state_.species[species].density * 4.0 / 3.0 * pi * radius * radius * radius;
    // New particles go before the ghosts: with a valid list they move the ghosts up a slot and
    // have their pairs relisted (PairList::relist); otherwise the ghosts go until the next build.
    const bool beforeGhosts = p.ghostCount > 0 && state_.pairList.valid;
    if (p.ghostCount > 0 && !beforeGhosts) ranks_->releaseGhosts(state_);
    p.position.push_back(position);
    p.velocity.push_back(velocity);
    p.angularVelocity.push_back(angularVelocity);
    p.force.push_back(Vec3::Zero());
    p.torque.push_back(Vec3::Zero());
    p.radius.push_back(radius);
    p.mass.push_back(mass);
    p.invMass.push_back(1.0 / mass);
    p.invInertia.push_back(1.0 / (0.4 * mass * radius * radius));
    p.species.push_back(static_cast<std::uint32_t>(species));
    p.id.push_back(ranks_->idOfNewParticle(state_));  // (on ranks a provisional one)
    p.fixed.push_back(0);
    p.motion.push_back(-1);
    if (p.hasShapes()) {
        p.orientation.push_back(Quat::Identity());
        p.angularMomentum.push_back(Vec3::Zero());
        p.principalInertia.push_back(Vec3::Zero());
        p.shape.push_back(-1);
    }
    const std::size_t slot = beforeGhosts ? p.moveLastBeforeGhosts() : p.size() - 1;
    // The list relists the new particle's pairs at the next force computation (on ranks if no
    // other rank needs it: RankContext::updateNeighbourhood).
    // (p.position[slot], not `position`: that may be a reference into the array the push_back
    // above moved, as the maser's copies are made.)
    state_.pairList.noteInserted(static_cast<std::uint32_t>(slot), p.position[slot]);
    return slot;
}

std::size_t Simulation::addShape(const Superquadric& shape) {
    state_.shapes.push_back(shape);
    return state_.shapes.size() - 1;
}

std::size_t Simulation::addSuperquadric(const Vec3& position, std::size_t shape, std::size_t species,
                                        const Quat& orientation, const Vec3& velocity, const Vec3& angularVelocity) {
    const std::string which = "particle " + std::to_string(state_.nextId);
    require(shape < state_.shapes.size(), which + ": shape " + std::to_string(shape) + " does not exist (addShape first)");
    requireValidOrientation(orientation, which);
    require(species < state_.species.size(), which + ": species " + std::to_string(species) + " does not exist");
    ParticleStore& p = state_.particles;
    if (!p.hasShapes()) {
        p.enableShapes();
        state_.pairList.enableWarmStarts();
    }
    const Superquadric& s = state_.shapes[shape];
    const std::size_t i = addParticle(position, s.boundingRadius(), species, velocity, angularVelocity);
    const double density = state_.species[species].density;
    p.mass[i] = density * s.volume();
    p.invMass[i] = 1 / p.mass[i];
    p.invInertia[i] = 0;  // unused: shaped particles turn by their angular momentum
    p.orientation[i] = orientation.normalized();
    p.principalInertia[i] = s.principalInertia(density);
    p.angularMomentum[i] = angularMomentumFromVelocity(p.orientation[i], angularVelocity, p.principalInertia[i]);
    p.shape[i] = static_cast<std::int32_t>(shape);
    return i;
}

std::size_t Simulation::addFixedParticle(const Vec3& position, double radius, std::size_t species, int motion) {
    requireMotion(motion, "fixed particle");
    return fixParticle(addParticle(position, radius, species), motion);
}

std::size_t Simulation::addFixedSuperquadric(const Vec3& position, std::size_t shape, std::size_t species,
                                             const Quat& orientation, int motion) {
    requireMotion(motion, "fixed superquadric");
    return fixParticle(addSuperquadric(position, shape, species, orientation), motion);
}

void Simulation::requireMotion(int motion, const std::string& what) const {
    require(motion >= -1 && motion < static_cast<int>(state_.motions.size()),
            what + ": motion " + std::to_string(motion) + " does not exist (add it with addMotion first)");
}

// Never integrated (inverse mass and inertia 0: an infinitely heavy partner in its contacts);
// with a motion it moves and turns with it.
std::size_t Simulation::fixParticle(std::size_t i, int motion) {
    ParticleStore& p = state_.particles;
    p.fixed[i] = 1;
    p.invMass[i] = 0;
    p.invInertia[i] = 0;
    p.motion[i] = motion;
    if (motion >= 0) {
        p.velocity[i] = state_.motions[motion].pointVelocity(p.position[i]);
        p.angularVelocity[i] = state_.motions[motion].angularVelocity;
    }
    return i;
}

void Simulation::moveParticleBy(std::size_t slot, const Vec3& jump) {
    require(slot < state_.particles.owned(), "moveParticleBy: slot " + std::to_string(slot) + " does not exist");
    state_.particles.position[slot] += jump;
    // On ranks a particle that another rank holds as a ghost makes the list build anew (its
    // ghost would jump there unseen by that rank's list).
    if (ranks_->isSentAsGhost(slot)) state_.pairList.valid = false;
    else state_.pairList.noteJumped(static_cast<std::uint32_t>(slot), jump);
}

void Simulation::removeParticle(std::size_t slot) {
    require(slot < state_.particles.owned(), "removeParticle: slot " + std::to_string(slot) + " does not exist");
    if (state_.particles.ghostCount > 0) ranks_->releaseGhosts(state_);
    const auto last = static_cast<std::uint32_t>(state_.particles.size() - 1);
    state_.particles.removeBySwap(slot);
    state_.pairList.followRemoval(static_cast<std::uint32_t>(slot), last);
}

std::size_t Simulation::addCylinderWall(const Vec3& axisPoint, const Vec3& axisDirection, double radius,
                                        std::size_t species, int motion) {
    require(std::isfinite(radius) && radius > 0, "cylinder wall: the radius must be positive, got " + str(radius));
    const std::size_t w = addWall(axisDirection, axisPoint, species, motion);
    state_.walls[w].radius = radius;
    return w;
}

std::size_t Simulation::addWall(const Vec3& normal, const Vec3& point, std::size_t species, int motion) {
    require(isFinite(normal) && normal.norm() > 0, "wall: the normal must be a non-zero vector");
    require(isFinite(point), "wall: the point is not finite");
    require(species < state_.species.size(), "wall: species " + std::to_string(species) + " does not exist");
    require(motion >= -1 && motion < static_cast<int>(state_.motions.size()),
            "wall: motion " + std::to_string(motion) + " does not exist");
    state_.walls.push_back({normal.normalized(), point, static_cast<std::uint32_t>(species), motion});
    state_.pairList.valid = false;
    return state_.walls.size() - 1;
}

std::size_t Simulation::addMotion(const PrescribedMotion& motion) {
    require(isFinite(motion.velocity) && isFinite(motion.angularVelocity) && isFinite(motion.centre),
            "prescribed motion: velocity, angular velocity and centre must be finite");
    state_.motions.push_back(motion);
    return state_.motions.size() - 1;
}

}  // namespace talus

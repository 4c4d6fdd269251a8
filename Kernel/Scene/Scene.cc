// Building, editing and checking the scene (Scene.h).
#include "Scene/Scene.h"

#include <algorithm>
#include <cmath>

#include "Particles/RigidBodyRotation.h"
#include "Parallel/RankContext.h"

namespace talus {

void Scene::setGravity(const Vec3& g) {
    require(isFinite(g), "gravity is not finite");
    state_.gravity = g;
}

void Scene::setDomain(const Vec3& lo, const Vec3& hi) {
    require(isFinite(lo) && isFinite(hi) && (hi - lo).minCoeff() > 0,
            "domain: the upper corner must lie above the lower corner along x, y and z");
    state_.domain.lo = lo;
    state_.domain.hi = hi;
    state_.pairList.valid = false;
}

void Scene::setPeriodic(bool x, bool y, bool z) {
    state_.domain.periodic = {x, y, z};
    state_.pairList.valid = false;
}

std::size_t Scene::addSpecies(const std::string& name, double density, const ContactLaw& law) {
    requireWord(name, "species name");
    return state_.species.add(name, density, law);
}

std::size_t Scene::addParticle(const Vec3& position, double radius, std::size_t species, const Vec3& velocity,
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
    if (p.ghostCount > 0 && !beforeGhosts) ranks_.releaseGhosts(state_);
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
    p.id.push_back(ranks_.idOfNewParticle(state_));  // (on ranks a provisional one)
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

std::size_t Scene::addShape(const Superquadric& shape) {
    state_.shapes.push_back(shape);
    return state_.shapes.size() - 1;
}

void Scene::enableShapes() {
    if (state_.particles.hasShapes()) return;
    state_.particles.enableShapes();
    state_.pairList.enableWarmStarts();
}

std::size_t Scene::addSuperquadric(const Vec3& position, std::size_t shape, std::size_t species,
                                        const Quat& orientation, const Vec3& velocity, const Vec3& angularVelocity) {
    const std::string which = "particle " + std::to_string(state_.nextId);
    require(shape < state_.shapes.size(), which + ": shape " + std::to_string(shape) + " does not exist (addShape first)");
    requireValidOrientation(orientation, which);
    require(species < state_.species.size(), which + ": species " + std::to_string(species) + " does not exist");
    const Superquadric& s = state_.shapes[shape];
    if (s.isSphere()) return addParticle(position, s.a(), species, velocity, angularVelocity);
    ParticleStore& p = state_.particles;
    enableShapes();
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

std::size_t Scene::addFixedParticle(const Vec3& position, double radius, std::size_t species, int motion) {
    requireMotion(motion, "fixed particle");
    return fixParticle(addParticle(position, radius, species), motion);
}

std::size_t Scene::addFixedSuperquadric(const Vec3& position, std::size_t shape, std::size_t species,
                                             const Quat& orientation, int motion) {
    requireMotion(motion, "fixed superquadric");
    return fixParticle(addSuperquadric(position, shape, species, orientation), motion);
}

void Scene::requireMotion(int motion, const std::string& what) const {
    require(motion >= -1 && motion < static_cast<int>(state_.motions.size()),
            what + ": motion " + std::to_string(motion) + " does not exist (add it with addMotion first)");
}

// Never integrated (inverse mass and inertia 0: an infinitely heavy partner in its contacts);
// with a motion it moves and turns with it.
std::size_t Scene::fixParticle(std::size_t i, int motion) {
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

void Scene::moveParticleBy(std::size_t slot, const Vec3& jump) {
    require(slot < state_.particles.owned(), "moveParticleBy: slot " + std::to_string(slot) + " does not exist");
    state_.particles.position[slot] += jump;
    // On ranks a particle that another rank holds as a ghost makes the list build anew (its
    // ghost would jump there unseen by that rank's list).
    if (ranks_.isSentAsGhost(slot)) state_.pairList.valid = false;
    else state_.pairList.noteJumped(static_cast<std::uint32_t>(slot), jump);
}

void Scene::removeParticle(std::size_t slot) {
    require(slot < state_.particles.owned(), "removeParticle: slot " + std::to_string(slot) + " does not exist");
    if (state_.particles.ghostCount > 0) ranks_.releaseGhosts(state_);
    const auto last = static_cast<std::uint32_t>(state_.particles.size() - 1);
    state_.particles.removeBySwap(slot);
    state_.pairList.followRemoval(static_cast<std::uint32_t>(slot), last);
}

std::size_t Scene::addCylinderWall(const Vec3& axisPoint, const Vec3& axisDirection, double radius,
                                        std::size_t species, int motion) {
    require(std::isfinite(radius) && radius > 0, "cylinder wall: the radius must be positive, got " + str(radius));
    const std::size_t w = addWall(axisDirection, axisPoint, species, motion);
    state_.walls[w].radius = radius;
    return w;
}

std::size_t Scene::addRevolvedWall(const Vec3& axisPoint, const Vec3& axisDirection,
                                   const std::vector<std::array<double, 2>>& profile, std::size_t species,
                                   int motion) {
    require(profile.size() >= 2, "revolved wall: the profile needs at least two points, got " +
                                     std::to_string(profile.size()));
    for (std::size_t k = 0; k < profile.size(); ++k) {
        const std::string point = "revolved wall: profile point " + std::to_string(k) + " (" +
                                  str(profile[k][0]) + ", " + str(profile[k][1]) + ")";
        require(std::isfinite(profile[k][0]) && std::isfinite(profile[k][1]), point + " is not finite");
        require(profile[k][0] >= 0, point + ": the distance from the axis must not be negative");
        require(k == 0 || profile[k] != profile[k - 1], point + " repeats the point before it");
    }
    const std::size_t segments = profile.size() - 1;
    const bool closed = profile.front() == profile.back();  // (then of two segments at least: no point repeats)
    auto direction = [&](std::size_t s) {  // of segment s, unit, in (rho, z)
        const double dRho = profile[s + 1][0] - profile[s][0], dZ = profile[s + 1][1] - profile[s][1];
        const double length = std::hypot(dRho, dZ);
        return std::array<double, 2>{dRho / length, dZ / length};
    };
    const std::size_t first = state_.walls.size();
    for (std::size_t s = 0; s < segments; ++s) {
        const std::size_t w = addWall(axisDirection, axisPoint, species, motion);
        Wall& wall = state_.walls[w];
        wall.profile = {profile[s][0], profile[s][1], profile[s + 1][0], profile[s + 1][1]};
        wall.startJoined = s > 0 || closed;
        if (s + 1 < segments) wall.next = direction(s + 1);
        else if (closed) wall.next = direction(0);
    }
    return first;
}

std::size_t Scene::addMeshWall(TriangleMesh mesh, std::size_t species, int motion) {
    require(species < state_.species.size(), "mesh wall: species " + std::to_string(species) + " does not exist");
    require(motion >= -1 && motion < static_cast<int>(state_.motions.size()),
            "mesh wall: motion " + std::to_string(motion) + " does not exist");
    require(mesh.triangleCount() > 0, "mesh wall: " + mesh.source().name + " has no triangles");
    const auto first = static_cast<std::uint32_t>(state_.walls.size());
    auto walls = std::make_shared<MeshWalls>(std::move(mesh), static_cast<std::uint32_t>(species), first, motion);
    for (std::uint32_t t = 0; t < walls->mesh.triangleCount(); ++t) {
        Wall wall;
        wall.normal = walls->mesh.normal(t);
        wall.point = walls->mesh.corner(t, 0);
        wall.species = static_cast<std::uint32_t>(species);
        wall.motion = motion;
        wall.mesh = walls.get();
        wall.triangle = t;
        state_.walls.push_back(wall);
    }
    state_.meshes.push_back(std::move(walls));
    state_.pairList.valid = false;
    return first;
}

void Scene::removeWall(std::size_t index) {
    require(index < state_.walls.size(), "removeWall: wall " + std::to_string(index) + " does not exist");
    require(!state_.walls[index].isTriangle(), "removeWall: wall " + std::to_string(index) +
                                                   " is a triangle of a mesh, whose triangles are not removed one by one");
    for (const auto& m : state_.meshes)
        if (m->firstWall > index) --m->firstWall;
    state_.walls.erase(state_.walls.begin() + static_cast<std::ptrdiff_t>(index));
    state_.pairList.followWallRemoval(static_cast<std::uint32_t>(index));
}

std::size_t Scene::addWall(const Vec3& normal, const Vec3& point, std::size_t species, int motion) {
    require(isFinite(normal) && normal.norm() > 0, "wall: the normal must be a non-zero vector");
    require(isFinite(point), "wall: the point is not finite");
    require(species < state_.species.size(), "wall: species " + std::to_string(species) + " does not exist");
    require(motion >= -1 && motion < static_cast<int>(state_.motions.size()),
            "wall: motion " + std::to_string(motion) + " does not exist");
    state_.walls.push_back({normal.normalized(), point, static_cast<std::uint32_t>(species), motion});
    state_.pairList.valid = false;
    return state_.walls.size() - 1;
}

std::size_t Scene::addOpenBox(const Vec3& lo, const Vec3& hi, std::size_t species) {
    require(isFinite(lo) && isFinite(hi) && lo.x() < hi.x() && lo.y() < hi.y(),
            "open box: the corners must be finite, with lo below hi along x and y");
    const std::size_t floor = addWall(Vec3::UnitZ(), lo, species);
    addWall(Vec3::UnitX(), lo, species);
    addWall(-Vec3::UnitX(), Vec3(hi.x(), lo.y(), lo.z()), species);
    addWall(Vec3::UnitY(), lo, species);
    addWall(-Vec3::UnitY(), Vec3(lo.x(), hi.y(), lo.z()), species);
    return floor;
}

std::size_t Scene::addMotion(const PrescribedMotion& motion) {
    require(isFinite(motion.velocity) && isFinite(motion.angularVelocity) && isFinite(motion.centre),
            "prescribed motion: velocity, angular velocity and centre must be finite");
    state_.motions.push_back(motion);
    return state_.motions.size() - 1;
}

double Scene::shortestCollisionTime(std::string* which, double impactSpeed) const {
    // Per species: how many mobile particles, the lightest and the smallest of them, and whether
    // fixed particles or walls of that species can be hit.
    struct Present {
        std::size_t mobile = 0;
        double lightest = INFINITY, smallest = INFINITY;
        bool immobile = false;  // fixed particles or walls
    };
    const std::size_t n = state_.species.size();
    std::vector<Present> present(n);
    const ParticleStore& p = state_.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
        Present& s = present[p.species[i]];
        if (p.fixed[i]) {
            s.immobile = true;
            continue;
        }
        ++s.mobile;
        s.lightest = std::min(s.lightest, p.mass[i]);
        s.smallest = std::min(s.smallest, p.radius[i]);
    }
    for (const Wall& w : state_.walls) present[w.species].immobile = true;

    double shortest = INFINITY;
    auto consider = [&](std::size_t a, std::size_t b, double reducedMass, double effectiveRadius) {
        ContactLaw law = state_.species.pairLaw(a, b);
        const double tc = std::visit(
            [&](auto& l) {
                if constexpr (requires { l.characteristicVelocity; })  // (a speed-dependent collision)
                    if (impactSpeed > 0) l.characteristicVelocity = impactSpeed;
                return l.collisionTimeOfPair(reducedMass, effectiveRadius);
            },
            law);
        if (tc >= shortest) return;
        shortest = tc;
        if (which)
            *which = "species '" + state_.species[a].name + "' with '" + state_.species[b].name + "', reduced mass " +
                     str(reducedMass);
    };
    for (std::size_t a = 0; a < n; ++a) {
        const Present& pa = present[a];
        if (pa.mobile == 0) continue;
        for (std::size_t b = 0; b < n; ++b) {
            const Present& pb = present[b];
            // Two mobile particles (two of them if the species is the same), the lightest ones.
            if (pb.mobile > (a == b ? 1u : 0u) && b >= a)
                consider(a, b, pa.lightest * pb.lightest / (pa.lightest + pb.lightest),
                         pa.smallest * pb.smallest / (pa.smallest + pb.smallest));
            // A mobile particle against a fixed particle or a wall: the reduced mass is its own.
            if (pb.immobile) consider(a, b, pa.lightest, pa.smallest);
        }
    }
    return shortest;
}

double Scene::automaticTimeStep(double stepsPerCollision, double impactSpeed, std::string* reason) const {
    require(std::isfinite(stepsPerCollision) && stepsPerCollision >= 1,
            "steps per collision (--steps-per-collision) must be 1 or more, got " + str(stepsPerCollision));
    require(std::isfinite(impactSpeed) && impactSpeed >= 0,
            "impact speed (--impact-speed) must not be negative, got " + str(impactSpeed));
    std::string which;
    const double tc = shortestCollisionTime(&which, impactSpeed);
    require(std::isfinite(tc), "--dt auto: no particle can collide with anything (no mobile particles), so no "
                               "collision time sets the step: give --dt");
    if (reason)
        *reason = "the shortest collision time " + str(tc) + " (" + which + ") over " + str(stepsPerCollision) +
                  (impactSpeed > 0 ? ", Hertzian contacts at impact speed " + str(impactSpeed) : std::string());
    return tc / stepsPerCollision;
}

std::size_t Scene::slotOf(std::uint64_t id, bool ghosts) const {
    const std::vector<std::uint64_t>& ids = state_.particles.id;
    const auto end = ids.begin() + static_cast<std::ptrdiff_t>(ghosts ? ids.size() : state_.particles.owned());
    const auto it = std::find(ids.begin(), end, id);
    require(it != end, "no particle has id " + std::to_string(id) +
                           (ranks_.isSplit() ? " on rank " + std::to_string(ranks_.rank()) : ""));
    return static_cast<std::size_t>(it - ids.begin());
}

void Scene::validate(double timeStep, double largestStepFraction, double impactSpeed) const {
    state_.species.validate();
    for (const Wall& w : state_.walls)
        require(w.species < state_.species.size(), "wall species " + std::to_string(w.species) + " does not exist");
    if (!state_.meshes.empty() && state_.particles.hasShapes())
        for (std::size_t i = 0; i < state_.particles.size(); ++i)
            require(state_.particles.shape[i] < 0, "a mesh wall (" + state_.meshes[0]->mesh.source().name +
                                                       ") meets spheres only, but particle id " +
                                                       std::to_string(state_.particles.id[i]) + " is a superquadric");
    std::string which;
    const double tc = shortestCollisionTime(&which, impactSpeed);
    if (timeStep > largestStepFraction * tc)
        throw Error("time step " + str(timeStep) + " is larger than " + str(largestStepFraction) +
                    " x the shortest collision time " + str(tc) +
                    " (" + which + "); use --dt " + str(tc / 50) + " (tc/50) or smaller, or --dt auto");
}

}  // namespace talus

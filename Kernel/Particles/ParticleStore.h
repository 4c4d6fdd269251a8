// All particles of a simulation as a structure of arrays (Documentation/Architecture.md "Data
// layout").
//
// Index i is a particle's current slot (it may change when particles are reordered or removed);
// id[i] is its global id, unique for the life of the simulation and written to every output
// file. Spheres carry a radius; mass and inverse inertia are cached from the species density.
// A fixed particle (Flag::fixed) has inverse mass and inverse inertia 0: it is never
// integrated, but it collides, and it may follow a prescribed motion (motion[i] >= 0).
#pragma once

#include <cstdint>
#include <vector>

#include "Math/Vector.h"

namespace talus {

struct ParticleStore {
    std::vector<Vec3> position;
    std::vector<Vec3> velocity;
    std::vector<Vec3> angularVelocity;
    std::vector<Vec3> force;
    std::vector<Vec3> torque;
    std::vector<double> radius;
    std::vector<double> mass;
    std::vector<double> invMass;     // 0 for fixed particles
    std::vector<double> invInertia;  // 0 for fixed particles; sphere: 1 / (2/5 m r^2)
    std::vector<std::uint32_t> species;
    std::vector<std::uint64_t> id;
    std::vector<std::uint8_t> fixed;   // 1: not integrated (still collides)
    std::vector<std::int32_t> motion;  // index into Simulation's prescribed motions, or -1

    // Non-spherical particles (Theory/Superquadrics.md), present only in scenes that have them:
    // these arrays are empty otherwise, so that spheres pay nothing. shape[i] indexes
    // SimulationState::shapes (-1: a sphere); a shaped particle's radius is its bounding radius
    // (what the neighbour search needs), its rotation state the lab angular momentum, from which
    // angularVelocity is derived (Particles/RigidBodyRotation.h), and invInertia is unused.
    std::vector<Quat> orientation;       // body to lab
    std::vector<Vec3> angularMomentum;   // lab frame
    std::vector<Vec3> principalInertia;  // about the body axes (0 for spheres and fixed particles)
    std::vector<std::int32_t> shape;

    // Under an MPI domain split (Parallel/DomainSplit.h) the last ghostCount slots hold copies of
    // particles that other ranks own, near this rank's part of the domain: the force loop sees
    // them as partners, nothing integrates or writes them. Without a split ghostCount is 0.
    std::size_t ghostCount = 0;

    std::size_t size() const { return position.size(); }  // owned particles and ghosts
    std::size_t owned() const { return position.size() - ghostCount; }
    bool empty() const { return position.empty(); }
    bool hasShapes() const { return shapesEnabled_; }
    bool isShaped(std::size_t i) const { return shapesEnabled_ && shape[i] >= 0; }
    // Gives every particle, present and future, the arrays above (spheres: shape -1).
    void enableShapes();

    // Applies f to every per-particle array; the one place that lists them all, so that
    // append, removal, reordering and restart cannot forget a field. The arrays of shapes only
    // when the scene has them.
    template <class F>
    void forEachArray(F&& f) { forEachArrayOf(*this, f); }
    template <class F>
    void forEachArray(F&& f) const { forEachArrayOf(*this, f); }

    // Drops the ghosts (the last ghostCount slots).
    void dropGhosts();
    // The particle just appended (after the ghosts) becomes the last owned one: the ghosts move
    // up a slot. Returns its slot.
    std::size_t moveLastBeforeGhosts();

    // Removes slot i by moving the last particle into it (O(1); changes that particle's slot).
    // Not while there are ghosts (they stay last).
    void removeBySwap(std::size_t i);

    // Reorders so that new slot k holds old slot order[k]; order must be a permutation.
    void permute(const std::vector<std::size_t>& order);

    void reserve(std::size_t n);

private:
    template <class Store, class F>
    static void forEachArrayOf(Store& s, F& f) {
        f(s.position); f(s.velocity); f(s.angularVelocity); f(s.force); f(s.torque);
        f(s.radius); f(s.mass); f(s.invMass); f(s.invInertia);
        f(s.species); f(s.id); f(s.fixed); f(s.motion);
        if (s.hasShapes()) { f(s.orientation); f(s.angularMomentum); f(s.principalInertia); f(s.shape); }
    }

    bool shapesEnabled_ = false;
};

}  // namespace talus

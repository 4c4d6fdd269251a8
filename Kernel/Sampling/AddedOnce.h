// Particles that a driver adds during the run from a decision every rank makes alike (a
// random insertion drawn from the same generator against the whole scene, Sampling/
// ParticleSums.h gatherParticles): every rank calls these with the same arguments, and the
// particle is added once, on the first rank, whence it moves to the rank that owns its place at
// the next neighbour-list build (Parallel/DomainSplit.h). Without a split (on one rank, or in
// setupInitialConditions, which every rank runs on the whole scene) it is a plain add.
#pragma once

#include <cstddef>

#include "Math/Vector.h"

namespace talus {

class Simulation;

void addParticleOnce(Simulation& simulation, const Vec3& position, double radius, std::size_t species,
                     const Vec3& velocity = Vec3::Zero());
void addSuperquadricOnce(Simulation& simulation, const Vec3& position, std::size_t shape, std::size_t species,
                         const Quat& orientation, const Vec3& velocity = Vec3::Zero());

}  // namespace talus

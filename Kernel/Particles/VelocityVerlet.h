// The kicks and the drift of the velocity Verlet (kick-drift-kick) step of the mobile particles
// (Documentation/Theory/Integration.md eq. (3)-(6)): v += (dt/2) F/m, w += (dt/2) T/I, x += dt v. Fixed
// particles are left alone (prescribed motions move them elsewhere). Each pass runs in the lanes
// of the form in use (Math/LaneForm.h; the passes themselves: Particles/VelocityVerletLanes.h).
#pragma once

#include <cstddef>

#include "Math/Vector.h"
#include "Particles/ParticleStore.h"

namespace talus {

// The forces a step starts from, before the contacts add theirs: gravity m g on the mobile
// particles, none on the fixed ones; no torques. (All particles, ghosts included.)
void startForcesWithGravity(ParticleStore& p, const Vec3& gravity);

// The half kick of the mobile particles in slots [first, last): v += (dt/2) F/m, w += (dt/2) T/I.
void halfKick(ParticleStore& p, std::size_t first, std::size_t last, double halfStep);
// The same among the first n.
inline void halfKick(ParticleStore& p, std::size_t n, double halfStep) { halfKick(p, 0, n, halfStep); }

// The first half kick and the drift of the mobile particles among the first n in one pass over
// the translational data (halfKick then drift, the same to the bit).
void halfKickAndDrift(ParticleStore& p, std::size_t n, double halfStep, double dt);

}  // namespace talus

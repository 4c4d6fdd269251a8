// The first half of a velocity Verlet step of spheres (Theory/Integration.md eq. (3)-(6)) in one
// pass over the particles, with everything else that a step reads the positions and velocities for
// before the contacts:
//   1. the half kick v += (dt/2) F/m, w += (dt/2) T/I and the drift x += dt v of the mobile
//      particles (Particles/VelocityVerlet.h halfKickAndDrift, the same arithmetic);
//   2. the wrap into the periodic box (Domain::wrap);
//   3. the pair list's check (PairList::needsRebuild): the largest displacement since the list
//      was built, the largest speed, and whether the motion is sane (PairList.h saneMotion);
//   4. the sweep's points (Contacts/PairSweep.h sweepPointsForStep): each position with its radius
//      grown by 1.000001 |v - u| dt;
//   5. the forces the step starts from (startForcesWithGravity): the last step's forces become
//      `previousForce` by a swap, the array is refilled with m g, the torques with zeros.
// Done pass by pass, these read and write every particle's data six times a step; at 10^6
// particles the arrays are far beyond the caches and each pass streams them from memory
// (Documentation/CacheCliff.md: about a fifth of the developed flow's step). The pass is for the
// scenes whose steps do nothing else between the drift and the forces: spheres only, no
// prescribed motions, no boundaries, nothing noted for relisting; on ranks over the owned slots
// (Integration/DriftPassStepper.cc). Its results are those of the separate passes, except the sweep's frame
// velocity u, which it is given, the mean velocity it measured the step before (any velocity
// common to all keeps the sweep's bound, and the pairs that get forces do not depend on it:
// PairSweep.h).
#pragma once

#include <cstdint>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/PairList.h"
#include "Particles/ParticleStore.h"

namespace talus {

struct DriftPassResult {
    LargestMoves moves;  // for PairList::needsRebuild
    double growth = 0;   // the sweep points' largest growth, 1.000001 |v - u| dt + 1e-12 r (useNearPairs)
    // The mean velocity of the mobile particles after the kick (zero without any, or if not
    // finite): the next step's frame velocity u, in place of a pass over a sample of them
    // (sweepFrameVelocity). Any u keeps the sweep's bound.
    Vec3 meanVelocity = Vec3::Zero();
    // What the mean is made of (to join the results of several ranges of slots).
    double velocitySum[3] = {0, 0, 0};
    std::size_t mobile = 0;
    // positionSum of the slots as the pass found them and as it left them (drifted and wrapped).
    std::uint64_t positionsBefore = 0, positionsAfter = 0;
};

// A checksum of the positions of the first n particles: the sum of the bit patterns of their
// coordinates, modulo 2^64 (the same in any order of the particles and of the additions). The
// near list (NearPairs in Contacts/PairList.h) holds only while the particles move by the steps'
// drifts, whose growths it adds up; a step compares the positions it finds with the ones the
// step before left, so that a particle moved by hand in between (in a driver's hook) unmakes it.
std::uint64_t positionSum(const ParticleStore& p, std::size_t n);

// The start of a step's first half for all particles: the last step's forces become
// `previousForce` (by a swap), and the force and torque arrays and the sweep's points are sized to
// the particles, for the pass below over all of them or over ranges of slots (a wave's first
// level, Contacts/WaveSchedule.h).
void startFirstHalf(ParticleStore& p, std::vector<Vec3>& previousForce, std::vector<SweepPoint>& points);

// reference: the positions at the list's build, or null (no build to compare with: no
// displacement). The particles are all owned (no ghosts): on ranks, the range form below over the
// owned slots (Integration/DriftPassStepper.cc).
DriftPassResult kickDriftAndStartForces(ParticleStore& p, std::vector<Vec3>& previousForce, const Domain& domain,
                                        const std::vector<Vec3>* reference, const Vec3& gravity,
                                        const Vec3& frameVelocity, double dt, std::vector<SweepPoint>& points);

// The largest displacement of the particles from the reference positions (nearest image), in
// the drift pass's arithmetic: what the pass measured after the step that left them there.
double largestDisplacement(const ParticleStore& p, const std::vector<Vec3>& reference, const Domain& domain);

// The same for slots [first, last) alone, kicking with previousForce as it is (the caller has put
// the forces to kick with there: no swap), with the arrays and points already sized to the
// particles: a region's advance in a wave (Contacts/WaveSchedule.h).
DriftPassResult kickDriftAndStartForces(ParticleStore& p, const std::vector<Vec3>& previousForce, const Domain& domain,
                                        const std::vector<Vec3>* reference, const Vec3& gravity,
                                        const Vec3& frameVelocity, double dt, std::vector<SweepPoint>& points,
                                        std::size_t first, std::size_t last);

// The end of a step and the start of the next for slots [first, last) in one pass, where a wave
// advances a region from one step to the next (Contacts/WaveSchedule.h): the second half kick
// with the forces and torques in p (halfKick's arithmetic), the forces copied to previousForce,
// then the pass above with them. The same results, to the bit, as halfKick, the copy and the
// pass above; the particles' data read and written once instead of three times.
DriftPassResult closeKickDriftAndStartForces(ParticleStore& p, std::vector<Vec3>& previousForce, const Domain& domain,
                                             const std::vector<Vec3>* reference, const Vec3& gravity,
                                             const Vec3& frameVelocity, double dt, std::vector<SweepPoint>& points,
                                             std::size_t first, std::size_t last);

}  // namespace talus

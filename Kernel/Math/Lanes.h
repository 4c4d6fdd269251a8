// The lanes of one lane form (Math/LaneForm.h), and the passes' operations on them written once
// for any width. Lanes<4> is four doubles in an AVX2 register (Math/FourLanes.h), Lanes<8> eight
// in an AVX-512 one (Math/EightLanes.h): the only code per instruction set. Each pass's lane
// loop is a template over the width (Particles/VelocityVerletLanes.h, Particles/DriftPass.cc,
// Contacts/PairSweepLanes.h), compiled with the widest lanes its form has, ParticleLanes:
//   scalar form  none (TALUS_LANES_WIDTH 1: the loops alone, as the compiler vectorises them);
//   avx2 form    Lanes<4>;
//   avx512 form  Lanes<8> (and Lanes<4>, which the four-pair sweep uses in every form with lanes).
// Every operation rounds as the scalar loop it stands in for (a multiplyAdd once, as std::fma), so
// that the lanes and the loops give the same results to the bit.
//
// The coordinates are stored particle after particle (x y z, x y z, ...), so W particles' fill
// three vectors of W lanes: lane l of vector c holds coordinate axisOfLane(W, c, l) of particle
// particleOfLane(W, c, l) of the block, (W c + l) mod 3 and (W c + l) / 3. The element-wise work
// (kicks, drifts, the box test) stays in that storage order, with per-particle values spread over
// it (spread); what needs a particle's three coordinates together (a norm, a sweep point) turns
// the three vectors into one per axis (toAxes). The wrappers build their permutations from these
// two functions.
#pragma once

#include <cmath>
#include <cstdint>

#include "Math/LaneNamespace.h"

namespace talus::TALUS_LANES::lanes {

// The rounding that the lanes and the loops they stand in for share, written out: left to the
// compiler, x + s r is contracted to a fused multiply-add or not depending on the code around it
// (a sum of squares compiled in two places gave results one bit apart).
inline double multiplyAdd(double s, double r, double x) {
#ifdef __FMA__
    return std::fma(s, r, x);
#else
    return x + s * r;
#endif
}

// Where the storage order puts lane l of vector c of a block of particles in vectors of W lanes.
constexpr int particleOfLane(int width, int c, int l) { return (width * c + l) / 3; }
constexpr int axisOfLane(int width, int c, int l) { return (width * c + l) % 3; }

template <int width>
struct Lanes;  // (defined for 4 and 8 where the form has the instructions)

}  // namespace talus::TALUS_LANES::lanes

#if defined(__AVX2__) && defined(__FMA__)
#include "Math/FourLanes.h"
#endif
#if defined(__AVX512F__) && defined(__AVX512BW__) && defined(__AVX512VL__) && defined(__BMI2__)
#include "Math/EightLanes.h"
#define TALUS_LANES_WIDTH 8
#elif defined(__AVX2__) && defined(__FMA__)
#define TALUS_LANES_WIDTH 4
#else
#define TALUS_LANES_WIDTH 1
#endif

#if TALUS_LANES_WIDTH > 1
namespace talus::TALUS_LANES::lanes {

// The lanes the passes over the particles take in this form.
using ParticleLanes = Lanes<TALUS_LANES_WIDTH>;

// A per-axis value (x, y, z) in every lane of that axis, in storage order.
template <class L>
void perAxis(const double (&value)[3], L (&out)[3]) {
    double stored[3 * L::width];
    for (int c = 0; c < 3; ++c)
        for (int l = 0; l < L::width; ++l) stored[L::width * c + l] = value[axisOfLane(L::width, c, l)];
    for (int c = 0; c < 3; ++c) out[c] = L::load(stored + L::width * c);
}
template <class L>
void perAxis(double x, double y, double z, L (&out)[3]) {
    perAxis({x, y, z}, out);
}

// A block of W particles for a pass that changes the mobile ones: which particles move
// (fixed[b] == 0, from the block's W bytes of ParticleStore::fixed) and which lanes of the
// three vectors of their coordinates are theirs.
template <class L>
struct MobileLanes {
    typename L::Mask particles, of[3];
    explicit MobileLanes(const std::uint8_t* fixed) : particles(L::mobile(fixed)) { L::spread(particles, of); }
};

// A per-particle value of the block spread over the three vectors of its coordinates.
template <class L>
void spread(L perParticle, L (&out)[3]) {
    L::spread(perParticle, out);
}

// |a|^2 of the particles from one vector per axis (x x, then + y y, then + z z, each a fused
// multiply-add: the scalar loops' squaredNorm).
template <class L>
L squaredNorms(const L (&axis)[3]) {
    return multiplyAdd(axis[2], axis[2], multiplyAdd(axis[1], axis[1], axis[0] * axis[0]));
}

// PeriodicImage::nearest of one axis of separations: d - L above half the length, d + L below
// minus half of it (a NaN stays). (Both tests of d itself: at most one holds, as in the loop's
// if-else, and neither waits for the other's result.)
template <class L>
L nearestOf(L d, L length, L half, L minusHalf) {
    const typename L::Mask above = d > half, below = d < minusHalf;
    return addWhere(below, subtractWhere(above, d, length), length);
}

}  // namespace talus::TALUS_LANES::lanes
#endif

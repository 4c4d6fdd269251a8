// Four particles at a time in AVX2 lanes, for the passes over per-particle coordinates on
// processors without AVX-512 (AMD Zen 2 and 3, Intel before Ice Lake): where
// Math/EightParticleLanes.h is not available.
//
// The coordinates are stored particle after particle (x y z, x y z, ...), so four particles'
// fill three vectors of four lanes in storage order, (x0 y0 z0 x1) (y1 z1 x2 y2) (z2 x3 y3 z3).
// Element-wise work (kicks, drifts, the box test) stays in that order, with per-particle
// values spread over it; what needs a particle's three coordinates together (a norm, a sweep
// point) turns the three vectors into one per axis, (x0 x1 x2 x3) (y0 ...) (z0 ...), with six
// shuffles. On an AVX2 processor the scalar loop of the drift pass took about
// 30 ns per particle, a fifth of the settled chute's step (Documentation/Performance.md).
// The helpers do the same operations as the scalar loops they stand in for (the same results
// to the bit).
#pragma once

#include <cstdint>
#include <cstring>

#include "Math/EightParticleLanes.h"

#if !defined(TALUS_AVX512_LANES) && defined(__AVX2__) && defined(__FMA__)
#define TALUS_AVX2_LANES 1
#include <immintrin.h>

namespace talus::TALUS_LANES::lanes {

// Three vectors in storage order to one per axis.
inline void toAxes(const __m256d (&stored)[3], __m256d (&axis)[3]) {
    const __m256d xy = _mm256_permute2f128_pd(stored[0], stored[1], 0x30);  // x0 y0 | x2 y2
    const __m256d zx = _mm256_permute2f128_pd(stored[0], stored[2], 0x21);  // z0 x1 | z2 x3
    const __m256d yz = _mm256_permute2f128_pd(stored[1], stored[2], 0x30);  // y1 z1 | y3 z3
    axis[0] = _mm256_shuffle_pd(xy, zx, 0b1010);
    axis[1] = _mm256_shuffle_pd(xy, yz, 0b0101);
    axis[2] = _mm256_shuffle_pd(zx, yz, 0b1010);
}

// One vector per axis to three in storage order (toAxes undone).
inline void toStored(const __m256d (&axis)[3], __m256d (&stored)[3]) {
    const __m256d xy = _mm256_shuffle_pd(axis[0], axis[1], 0b0000);  // x0 y0 | x2 y2
    const __m256d zx = _mm256_shuffle_pd(axis[2], axis[0], 0b1010);  // z0 x1 | z2 x3
    const __m256d yz = _mm256_shuffle_pd(axis[1], axis[2], 0b1111);  // y1 z1 | y3 z3
    stored[0] = _mm256_permute2f128_pd(xy, zx, 0x20);
    stored[1] = _mm256_permute2f128_pd(yz, xy, 0x30);
    stored[2] = _mm256_permute2f128_pd(zx, yz, 0x31);
}

// A per-particle value of the four particles spread over the three vectors of their
// coordinates in storage order: particles (0 0 0 1) (1 1 2 2) (2 3 3 3).
inline void spread(__m256d perParticle, __m256d (&out)[3]) {
    out[0] = _mm256_permute4x64_pd(perParticle, _MM_SHUFFLE(1, 0, 0, 0));
    out[1] = _mm256_permute4x64_pd(perParticle, _MM_SHUFFLE(2, 2, 1, 1));
    out[2] = _mm256_permute4x64_pd(perParticle, _MM_SHUFFLE(3, 3, 3, 2));
}

// A per-axis value (x, y, z) in every lane of that axis, in storage order.
inline void perAxis(double x, double y, double z, __m256d (&out)[3]) {
    out[0] = _mm256_setr_pd(x, y, z, x);
    out[1] = _mm256_setr_pd(y, z, x, y);
    out[2] = _mm256_setr_pd(z, x, y, z);
}

// All bits set in the lanes of the four particles that are not fixed (ParticleStore::fixed's
// four bytes), one lane per particle.
inline __m256d mobileOf(const std::uint8_t* fixed) {
    std::int32_t bytes;
    std::memcpy(&bytes, fixed, sizeof bytes);
    const __m256i each = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(bytes));
    return _mm256_castsi256_pd(_mm256_cmpeq_epi64(each, _mm256_setzero_si256()));
}

// x + s r (one rounding, as multiplyAdd) where `where` has all bits set, x elsewhere.
inline __m256d advance(__m256d x, __m256d s, __m256d r, __m256d where) {
    return _mm256_blendv_pd(x, _mm256_fmadd_pd(s, r, x), where);
}

// |a|^2 of the four particles from one vector per axis (DriftPass.cc squaredNorm's rounding).
inline __m256d squaredNorms(const __m256d (&axis)[3]) {
    return _mm256_fmadd_pd(axis[2], axis[2], _mm256_fmadd_pd(axis[1], axis[1], _mm256_mul_pd(axis[0], axis[0])));
}

// The larger of each lane's two 64-bit patterns, unsigned (AVX2 compares signed only: both
// shifted by 2^63 first). For running maxima of non-negative doubles, whose bit patterns are in
// the values' order, with a NaN of either sign larger than all.
inline __m256i largerBits(__m256i a, __m256i b) {
    const __m256i shift = _mm256_set1_epi64x(INT64_MIN);
    const __m256i aLarger = _mm256_cmpgt_epi64(_mm256_xor_si256(a, shift), _mm256_xor_si256(b, shift));
    return _mm256_blendv_epi8(b, a, aLarger);
}
inline std::uint64_t largestBits(__m256i a) {
    alignas(32) std::uint64_t lanes[4];
    _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), a);
    std::uint64_t largest = lanes[0];
    for (int l = 1; l < 4; ++l) largest = largest > lanes[l] ? largest : lanes[l];
    return largest;
}
// The sum of the four 64-bit lanes, modulo 2^64 (a checksum: the same in any order).
inline std::uint64_t sumOfLanes(__m256i a) {
    alignas(32) std::uint64_t lanes[4];
    _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), a);
    return lanes[0] + lanes[1] + lanes[2] + lanes[3];
}

}  // namespace talus::TALUS_LANES::lanes
#endif

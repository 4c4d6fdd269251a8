// Eight particles at a time in AVX-512 lanes, for the passes over per-particle coordinates
// (Particles/VelocityVerlet.h, Boundaries/Domain.h).
//
// The coordinates are stored particle after particle (x y z, x y z, ...), so eight particles'
// fill three vectors of eight lanes: lane l of vector c holds coordinate (8c + l) mod 3 of particle
// (8c + l) / 3 of the block. GCC's own vectorisation of such loops shuffled every vector into
// place and took about 4 ns per particle and pass on an AVX-512 processor (15% of the developed chute
// flow's step, Documentation/Performance.md); written by hand a pass takes about 1.5 ns. The
// helpers here do the same operations as the scalar loops they stand in for (the results are
// the same to the bit).
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

}  // namespace talus::TALUS_LANES::lanes

#if defined(__AVX512F__) && defined(__AVX512BW__) && defined(__AVX512VL__) && defined(__BMI2__)
#define TALUS_AVX512_LANES 1
#include <immintrin.h>

namespace talus::TALUS_LANES::lanes {

// A per-particle value of the block's eight particles (one vector) spread over the three
// vectors of their coordinates. (The zero-masking form: GCC 12 warns, wrongly, of an
// uninitialised operand in the plain one.)
inline void spread(__m512d perParticle, __m512d (&out)[3]) {
    out[0] = _mm512_maskz_permutexvar_pd(0xff, _mm512_set_epi64(2, 2, 1, 1, 1, 0, 0, 0), perParticle);
    out[1] = _mm512_maskz_permutexvar_pd(0xff, _mm512_set_epi64(5, 4, 4, 4, 3, 3, 3, 2), perParticle);
    out[2] = _mm512_maskz_permutexvar_pd(0xff, _mm512_set_epi64(7, 7, 7, 6, 6, 6, 5, 5), perParticle);
}

// A per-axis value (x, y, z) in every lane of that axis.
inline void perAxis(double x, double y, double z, __m512d (&out)[3]) {
    out[0] = _mm512_set_pd(y, x, z, y, x, z, y, x);
    out[1] = _mm512_set_pd(x, z, y, x, z, y, x, z);
    out[2] = _mm512_set_pd(z, y, x, z, y, x, z, y);
}

// A block of eight particles for a pass that changes the mobile ones: which lanes of the three
// vectors belong to particles that move (fixed[b] == 0, from the block's eight bytes of
// ParticleStore::fixed), and the per-particle factor step * perParticle[b] spread over them.
struct MobileLanes {
    __mmask8 of[3];
    __m512d factor[3];

    MobileLanes(const std::uint8_t* fixed, double step, const double* perParticle) {
        const __m128i f = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(fixed));
        const unsigned mobile = ~static_cast<unsigned>(_mm_cmpneq_epi8_mask(f, _mm_setzero_si128())) & 0xffu;
        // Particle b's bit to lanes 3b, 3b + 1, 3b + 2 of the 24 (bits three apart, times 0b111).
        const unsigned lanes = _pdep_u32(mobile, 0x249249u) * 7u;
        for (int c = 0; c < 3; ++c) of[c] = static_cast<__mmask8>(lanes >> (8 * c));
        spread(_mm512_mul_pd(_mm512_set1_pd(step), _mm512_loadu_pd(perParticle)), factor);
    }
    // x + s r in the mobile lanes of vector c (one rounding, as multiplyAdd), x in the others.
    __m512d advance(__m512d x, __m512d s, __m512d r, int c) const { return _mm512_mask3_fmadd_pd(s, r, x, of[c]); }
};

}  // namespace talus::TALUS_LANES::lanes
#endif

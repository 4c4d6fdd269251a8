// What the neighbour list's check of every step (PairList::needsRebuild) needs from all
// particles: how far the farthest has moved since the build, the largest speed, and whether
// every position and velocity is finite.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "Boundaries/Domain.h"
#include "Math/EightParticleLanes.h"

namespace talus {

struct LargestMoves {
    double displacement2, speed2;
    bool finite;
};

// The largest squared displacement from the reference positions (nearest image), the largest
// squared speed, and the largest |x|^2 + |v|^2 (not finite if any coordinate is not) of the
// particles [0, n), over plain arrays. Squares are never negative, and for such doubles the order
// of the bit patterns is the order of the values, NaN (all exponent bits set) above everything:
// so the maxima are taken as unsigned integers, which vectorise where a floating-point maximum
// would not (NaN semantics), and a NaN wins them. This pass runs every step over every particle
// (6% of a dilute flow's step when it was scalar); with AVX-512 it takes eight particles at a
// time, their coordinates sorted by axis (Math/EightParticleLanes.h), with the sums of squares
// rounded as lanes::sumOfSquares rounds them in the loop, so that both give the same bits
// (UnitTests/VelocityVerletTest.cc checks it).
inline LargestMoves largestMoves(const double* __restrict x, const double* __restrict reference,
                                 const double* __restrict v, std::size_t n, const PeriodicImage& image) {
    const double length[3] = {image.length(0), image.length(1), image.length(2)};
    const double half[3] = {image.halfLength(0), image.halfLength(1), image.halfLength(2)};
    std::uint64_t displacement2 = 0, speed2 = 0, magnitude2 = 0;
    std::size_t i = 0;
#ifdef TALUS_AVX512_LANES
    __m512i laneDisplacement2 = _mm512_setzero_si512(), laneSpeed2 = laneDisplacement2, laneMagnitude2 = laneDisplacement2;
    auto sumOfSquares = [](const __m512d (&c)[3]) {  // as lanes::sumOfSquares
        return _mm512_fmadd_pd(c[2], c[2], _mm512_fmadd_pd(c[0], c[0], _mm512_mul_pd(c[1], c[1])));
    };
    for (; i + 8 <= n; i += 8) {
        __m512d xi[3], ri[3], vi[3], d[3];
        lanes::loadByAxis(x + 3 * i, xi);
        lanes::loadByAxis(reference + 3 * i, ri);
        lanes::loadByAxis(v + 3 * i, vi);
        for (int a = 0; a < 3; ++a) {  // PeriodicImage::nearest
            const __m512d raw = _mm512_sub_pd(xi[a], ri[a]), h = _mm512_set1_pd(half[a]), l = _mm512_set1_pd(length[a]);
            const __mmask8 above = _mm512_cmp_pd_mask(raw, h, _CMP_GT_OQ);
            const __mmask8 below = _mm512_cmp_pd_mask(raw, _mm512_set1_pd(-half[a]), _CMP_LT_OQ);
            d[a] = _mm512_mask_add_pd(_mm512_mask_sub_pd(raw, above, raw, l), below, raw, l);
        }
        const __m512d s2 = sumOfSquares(vi);
        // (The zero-masking form: GCC 12 warns, wrongly, of an uninitialised
        // operand in the plain ones.)
        laneDisplacement2 = _mm512_maskz_max_epu64(0xff, laneDisplacement2, _mm512_castpd_si512(sumOfSquares(d)));
        laneSpeed2 = _mm512_maskz_max_epu64(0xff, laneSpeed2, _mm512_castpd_si512(s2));
        laneMagnitude2 = _mm512_maskz_max_epu64(0xff, laneMagnitude2, _mm512_castpd_si512(_mm512_add_pd(s2, sumOfSquares(xi))));
    }
    alignas(64) std::uint64_t lane[3][8];
    _mm512_store_si512(lane[0], laneDisplacement2);
    _mm512_store_si512(lane[1], laneSpeed2);
    _mm512_store_si512(lane[2], laneMagnitude2);
    for (int l = 0; l < 8; ++l) {
        displacement2 = std::max(displacement2, lane[0][l]);
        speed2 = std::max(speed2, lane[1][l]);
        magnitude2 = std::max(magnitude2, lane[2][l]);
    }
#endif
    for (; i < n; ++i) {
        double d[3];
        for (int a = 0; a < 3; ++a) {  // PeriodicImage::nearest
            const double raw = x[3 * i + a] - reference[3 * i + a];
            d[a] = raw > half[a] ? raw - length[a] : raw < -half[a] ? raw + length[a] : raw;
        }
        const double* xi = x + 3 * i;
        const double* vi = v + 3 * i;
        const double s2 = lanes::sumOfSquares(vi[0], vi[1], vi[2]);
        displacement2 = std::max(displacement2, std::bit_cast<std::uint64_t>(lanes::sumOfSquares(d[0], d[1], d[2])));
        speed2 = std::max(speed2, std::bit_cast<std::uint64_t>(s2));
        magnitude2 = std::max(magnitude2, std::bit_cast<std::uint64_t>(s2 + lanes::sumOfSquares(xi[0], xi[1], xi[2])));
    }
    return {std::bit_cast<double>(displacement2), std::bit_cast<double>(speed2),
            magnitude2 < std::bit_cast<std::uint64_t>(std::numeric_limits<double>::infinity())};
}

}  // namespace talus

// Lanes<8>: eight doubles in an AVX-512 register (Math/Lanes.h), with a bit mask per vector.
// Included by Math/Lanes.h only. (Several operations use the zero-masking form of their
// instruction with all lanes selected: GCC 12 warns, wrongly, of an uninitialised operand in the
// plain one.)
#pragma once

#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <cstdint>

namespace talus::TALUS_LANES::lanes {

template <>
struct Lanes<8> {
    static constexpr int width = 8;
    __m512d v;

    struct Mask {
        __mmask8 bits;
        friend Mask operator|(Mask a, Mask b) { return {static_cast<__mmask8>(a.bits | b.bits)}; }
    };

    static Lanes load(const double* p) { return {_mm512_loadu_pd(p)}; }
    void store(double* p) const { _mm512_storeu_pd(p, v); }
    static Lanes broadcast(double x) { return {_mm512_set1_pd(x)}; }
    static Lanes zero() { return {_mm512_setzero_pd()}; }

    friend Lanes operator+(Lanes a, Lanes b) { return {_mm512_add_pd(a.v, b.v)}; }
    friend Lanes operator-(Lanes a, Lanes b) { return {_mm512_sub_pd(a.v, b.v)}; }
    friend Lanes operator*(Lanes a, Lanes b) { return {_mm512_mul_pd(a.v, b.v)}; }
    // s r + x, rounded once.
    friend Lanes multiplyAdd(Lanes s, Lanes r, Lanes x) { return {_mm512_fmadd_pd(s.v, r.v, x.v)}; }
    friend Lanes sqrt(Lanes a) { return {_mm512_maskz_sqrt_pd(0xff, a.v)}; }
    // The larger of a and b, b where either is a NaN (std::max(b, a) of the loops).
    friend Lanes max(Lanes a, Lanes b) { return {_mm512_maskz_max_pd(0xff, a.v, b.v)}; }

    // (Ordered comparisons: false for a NaN.)
    friend Mask operator<(Lanes a, Lanes b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)}; }
    friend Mask operator>(Lanes a, Lanes b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)}; }
    friend Mask operator>=(Lanes a, Lanes b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GE_OQ)}; }
    friend bool any(Mask m) { return m.bits != 0; }
    friend unsigned bitsOf(Mask m) { return m.bits; }
    friend int count(Mask m) { return std::popcount(static_cast<unsigned>(m.bits)); }
    // a where m, b elsewhere.
    friend Lanes select(Mask m, Lanes a, Lanes b) { return {_mm512_mask_blend_pd(m.bits, b.v, a.v)}; }
    // s r + x (rounded once) where m, x elsewhere.
    friend Lanes multiplyAddWhere(Mask m, Lanes s, Lanes r, Lanes x) {
        return {_mm512_mask3_fmadd_pd(s.v, r.v, x.v, m.bits)};
    }
    // a b where m, +0 elsewhere.
    friend Lanes multiplyWhere(Mask m, Lanes a, Lanes b) { return {_mm512_maskz_mul_pd(m.bits, a.v, b.v)}; }
    // x + b where m, x elsewhere.
    friend Lanes addWhere(Mask m, Lanes x, Lanes b) { return {_mm512_mask_add_pd(x.v, m.bits, x.v, b.v)}; }

    // x - b where m, x elsewhere.
    friend Lanes subtractWhere(Mask m, Lanes x, Lanes b) { return {_mm512_mask_sub_pd(x.v, m.bits, x.v, b.v)}; }

    // --- the lanes as 64-bit patterns (Math/FourLanes.h) ---
    friend Lanes largerBits(Lanes a, Lanes b) {
        return {_mm512_castsi512_pd(_mm512_maskz_max_epu64(0xff, _mm512_castpd_si512(a.v), _mm512_castpd_si512(b.v)))};
    }
    friend Lanes addBits(Lanes a, Lanes b) {
        return {_mm512_castsi512_pd(_mm512_add_epi64(_mm512_castpd_si512(a.v), _mm512_castpd_si512(b.v)))};
    }
    friend Lanes magnitude(Lanes a) {
        return {_mm512_castsi512_pd(_mm512_and_si512(_mm512_castpd_si512(a.v), _mm512_set1_epi64(INT64_MAX)))};
    }
    friend std::uint64_t largestBits(Lanes a) {
        alignas(64) std::uint64_t lanes[8];
        _mm512_store_si512(lanes, _mm512_castpd_si512(a.v));
        return *std::max_element(lanes, lanes + 8);
    }
    // (Not _mm512_reduce_add_epi64, which adds them as signed numbers: an overflow, for UBSan.)
    friend std::uint64_t sumOfBits(Lanes a) {
        alignas(64) std::uint64_t lanes[8];
        _mm512_store_si512(lanes, _mm512_castpd_si512(a.v));
        std::uint64_t sum = 0;
        for (const std::uint64_t lane : lanes) sum += lane;
        return sum;
    }
    // The sum of the lanes, in pairs: ((0 + 1) + (2 + 3)) + ((4 + 5) + (6 + 7)).
    friend double sum(Lanes a) {
        alignas(64) double lanes[8];
        _mm512_store_pd(lanes, a.v);
        return ((lanes[0] + lanes[1]) + (lanes[2] + lanes[3])) + ((lanes[4] + lanes[5]) + (lanes[6] + lanes[7]));
    }

    // --- blocks of eight particles in storage order (Math/Lanes.h) ---
    // A vector of eight 64-bit indices, index(l) in lane l.
    template <class Index>
    static __m512i indices(Index index) {
        return _mm512_setr_epi64(index(0), index(1), index(2), index(3), index(4), index(5), index(6), index(7));
    }
    // The particles' mobile lanes, one bit per particle, from ParticleStore::fixed's eight bytes.
    static Mask mobile(const std::uint8_t* fixed) {
        const __m128i f = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(fixed));
        return {static_cast<__mmask8>(~_mm_cmpneq_epi8_mask(f, _mm_setzero_si128()))};
    }
    // A per-particle mask over the three vectors: particle b's bit to lanes 3b, 3b + 1, 3b + 2 of
    // the 24 (its bit deposited three apart, times 0b111).
    static void spread(Mask perParticle, Mask (&out)[3]) {
        const unsigned lanes = _pdep_u32(perParticle.bits, 0x249249u) * 7u;
        for (int c = 0; c < 3; ++c) out[c] = {static_cast<__mmask8>(lanes >> (8 * c))};
    }
    // A per-particle value over the three vectors: lane l of vector c from lane
    // particleOfLane(8, c, l), one permutation each.
    template <int c>
    static Lanes spreadTo(Lanes perParticle) {
        return {_mm512_maskz_permutexvar_pd(0xff, indices([](int l) { return particleOfLane(8, c, l); }), perParticle.v)};
    }
    static void spread(Lanes perParticle, Lanes (&out)[3]) {
        out[0] = spreadTo<0>(perParticle), out[1] = spreadTo<1>(perParticle), out[2] = spreadTo<2>(perParticle);
    }
    // The particles' values of one axis from the three vectors in storage order: particle b's is
    // element 3b + axis of the 24, taken from the first two vectors by one two-source
    // permutation and the rest from the third by another.
    template <int axis>
    static Lanes axisOf(const Lanes (&stored)[3]) {
        const __m512i first = indices([](int b) { return 3 * b + axis < 16 ? 3 * b + axis : 0; });
        const __m512i second = indices([](int b) { return 3 * b + axis < 16 ? b : 8 + 3 * b + axis - 16; });
        return {_mm512_permutex2var_pd(_mm512_permutex2var_pd(stored[0].v, first, stored[1].v), second, stored[2].v)};
    }
    static void toAxes(const Lanes (&stored)[3], Lanes (&axis)[3]) {
        axis[0] = axisOf<0>(stored), axis[1] = axisOf<1>(stored), axis[2] = axisOf<2>(stored);
    }
    // The eight points (x, y, z, w) of the particles, 32 doubles from out on, two per vector:
    // points 2k and 2k + 1 are elements 6k to 6k + 5 of the coordinates, from vector 6k / 8 and
    // the next, with w's lanes 2k and 2k + 1 put in lanes 3 and 7.
    template <int k>
    static void storePointPair(const Lanes (&stored)[3], Lanes w, double* out) {
        constexpr int low = 6 * k / 8, high = std::min(low + 1, 2);
        const __m512i pick = indices([](int l) { return l % 4 == 3 ? 0 : 6 * k + 3 * (l / 4) + l % 4 - 8 * low; });
        const __m512i wLane = indices([](int l) { return l == 3 ? 2 * k : l == 7 ? 2 * k + 1 : 0; });
        const __m512d coordinates = _mm512_permutex2var_pd(stored[low].v, pick, stored[high].v);
        _mm512_storeu_pd(out + 8 * k, _mm512_mask_permutexvar_pd(coordinates, 0x88, wLane, w.v));
    }
    static void storePoints(const Lanes (&stored)[3], Lanes w, double* out) {
        storePointPair<0>(stored, w, out), storePointPair<1>(stored, w, out);
        storePointPair<2>(stored, w, out), storePointPair<3>(stored, w, out);
    }

    // --- lanes of other types, and packing (the sweep, Contacts/PairSweepLanes.h) ---
    struct Words {  // eight 64-bit words
        __m512i v;
    };
    struct Indices {  // eight 32-bit numbers
        __m256i v;
    };
    static Words loadWords(const void* p) { return {_mm512_loadu_si512(p)}; }
    // first, first + 1, ..., first + 7.
    static Indices consecutive(std::uint32_t first) {
        return {_mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(first)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7))};
    }
    // The lanes whose bytes from `bytes` on are not zero.
    static unsigned nonZeroBytes(const std::uint8_t* bytes) {
        const __m256i each = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bytes)));
        return _mm256_test_epi32_mask(each, each);
    }
    // The lanes whose bits `pick` has, stored one after the other in the order of their lanes.
    class Packing {
    public:
        explicit Packing(unsigned pick) : pick_(static_cast<__mmask8>(pick)) {}
        void store(Lanes a, double* out) const { _mm512_mask_compressstoreu_pd(out, pick_, a.v); }
        void store(Words a, void* out) const { _mm512_mask_compressstoreu_epi64(out, pick_, a.v); }
        void store(Indices a, std::uint32_t* out) const { _mm256_mask_compressstoreu_epi32(out, pick_, a.v); }

    private:
        __mmask8 pick_;
    };
    // Eight pairs (i, j) of points (x, y, z, w: four doubles each, point p at numbers + 4 p),
    // each pair a 64-bit word with i in its low half and j in its high one, gathered: the
    // differences of their coordinates, point i's less point j's, one vector per axis, and the
    // sums of their w. (Indices 4 p in 32 bits: fewer than 2^29 points. GCC 12 warns about the
    // gathers' own undefined pass-through operands.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
    static void gatheredDifferences(Words pairs, const double* numbers, Lanes (&axis)[3], Lanes& wSum) {
        const __m512i evenLanes = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15);
        const __m512i ij = _mm512_permutexvar_epi32(evenLanes, pairs.v);  // i in the low eight 32-bit lanes, j in the high
        const __m256i i4 = _mm256_slli_epi32(_mm512_castsi512_si256(ij), 2);
        const __m256i j4 = _mm256_slli_epi32(_mm512_extracti64x4_epi64(ij, 1), 2);
        for (int a = 0; a < 3; ++a)
            axis[a] = {_mm512_sub_pd(_mm512_i32gather_pd(i4, numbers + a, 8), _mm512_i32gather_pd(j4, numbers + a, 8))};
        wSum = {_mm512_add_pd(_mm512_i32gather_pd(i4, numbers + 3, 8), _mm512_i32gather_pd(j4, numbers + 3, 8))};
    }
#pragma GCC diagnostic pop
};

}  // namespace talus::TALUS_LANES::lanes

// Lanes<4>: four doubles in an AVX2 register (Math/Lanes.h), for the passes on processors without
// AVX-512 (AMD Zen 2 and 3, Intel before Ice Lake) and for the four-pair sweep. A mask is a vector
// with all bits set in its lanes (AVX2 compares give no bit masks). Included by Math/Lanes.h only.
#pragma once

#include <immintrin.h>

#include <bit>
#include <cstdint>
#include <cstring>

namespace talus::TALUS_LANES::lanes {

namespace detail {
// AVX2 has no compress-store: the picked lanes of four are packed to the front by a permutation
// chosen by their mask. For each mask, the picked lanes' numbers in order (the rest after them),
// as the 32-bit elements of 64-bit lanes (lane l: 2l, 2l + 1) and as lane numbers.
struct alignas(32) LeftPacking {
    std::int32_t wide[16][8];
    std::int32_t narrow[16][4];
};
constexpr LeftPacking makeLeftPacking() {
    LeftPacking packing{};
    for (int mask = 0; mask < 16; ++mask) {
        int to = 0;
        for (int pass = 0; pass < 2; ++pass)  // the picked lanes, then the others
            for (int lane = 0; lane < 4; ++lane)
                if (((mask >> lane) & 1) == (pass == 0)) {
                    packing.narrow[mask][to] = lane;
                    packing.wide[mask][2 * to] = 2 * lane, packing.wide[mask][2 * to + 1] = 2 * lane + 1;
                    ++to;
                }
    }
    return packing;
}
inline constexpr LeftPacking leftPacking = makeLeftPacking();
}  // namespace detail

template <>
struct Lanes<4> {
    static constexpr int width = 4;
    __m256d v;

    struct Mask {
        __m256d bits;
        friend Mask operator|(Mask a, Mask b) { return {_mm256_or_pd(a.bits, b.bits)}; }
    };

    static Lanes load(const double* p) { return {_mm256_loadu_pd(p)}; }
    void store(double* p) const { _mm256_storeu_pd(p, v); }
    static Lanes broadcast(double x) { return {_mm256_set1_pd(x)}; }
    static Lanes zero() { return {_mm256_setzero_pd()}; }

    friend Lanes operator+(Lanes a, Lanes b) { return {_mm256_add_pd(a.v, b.v)}; }
    friend Lanes operator-(Lanes a, Lanes b) { return {_mm256_sub_pd(a.v, b.v)}; }
    friend Lanes operator*(Lanes a, Lanes b) { return {_mm256_mul_pd(a.v, b.v)}; }
    // s r + x, rounded once.
    friend Lanes multiplyAdd(Lanes s, Lanes r, Lanes x) { return {_mm256_fmadd_pd(s.v, r.v, x.v)}; }
    friend Lanes sqrt(Lanes a) { return {_mm256_sqrt_pd(a.v)}; }
    // The larger of a and b, b where either is a NaN (std::max(b, a) of the loops).
    friend Lanes max(Lanes a, Lanes b) { return {_mm256_max_pd(a.v, b.v)}; }

    // (Ordered comparisons: false for a NaN.)
    friend Mask operator<(Lanes a, Lanes b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }
    friend Mask operator>(Lanes a, Lanes b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)}; }
    friend Mask operator>=(Lanes a, Lanes b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)}; }
    friend bool any(Mask m) { return _mm256_movemask_pd(m.bits) != 0; }
    friend unsigned bitsOf(Mask m) { return static_cast<unsigned>(_mm256_movemask_pd(m.bits)); }
    friend int count(Mask m) { return std::popcount(static_cast<unsigned>(_mm256_movemask_pd(m.bits))); }
    // a where m, b elsewhere.
    friend Lanes select(Mask m, Lanes a, Lanes b) { return {_mm256_blendv_pd(b.v, a.v, m.bits)}; }
    // s r + x (rounded once) where m, x elsewhere.
    friend Lanes multiplyAddWhere(Mask m, Lanes s, Lanes r, Lanes x) {
        return {_mm256_blendv_pd(x.v, _mm256_fmadd_pd(s.v, r.v, x.v), m.bits)};
    }
    // a b where m, +0 elsewhere.
    friend Lanes multiplyWhere(Mask m, Lanes a, Lanes b) { return {_mm256_and_pd(_mm256_mul_pd(a.v, b.v), m.bits)}; }
    // x + b where m, x elsewhere.
    friend Lanes addWhere(Mask m, Lanes x, Lanes b) { return {_mm256_blendv_pd(x.v, _mm256_add_pd(x.v, b.v), m.bits)}; }

    // x - b where m, x elsewhere.
    friend Lanes subtractWhere(Mask m, Lanes x, Lanes b) {
        return {_mm256_blendv_pd(x.v, _mm256_sub_pd(x.v, b.v), m.bits)};
    }

    // --- the lanes as 64-bit patterns (of non-negative doubles, whose patterns are in the
    // values' order, with a NaN of either sign larger than all; and checksums) ---
    // The larger of each lane's two patterns, unsigned (AVX2 compares signed only: both shifted
    // by 2^63 first).
    friend Lanes largerBits(Lanes a, Lanes b) {
        const __m256i shift = _mm256_set1_epi64x(INT64_MIN), ai = _mm256_castpd_si256(a.v), bi = _mm256_castpd_si256(b.v);
        const __m256i aLarger = _mm256_cmpgt_epi64(_mm256_xor_si256(ai, shift), _mm256_xor_si256(bi, shift));
        return {_mm256_castsi256_pd(_mm256_blendv_epi8(bi, ai, aLarger))};
    }
    // The sums of the patterns, modulo 2^64.
    friend Lanes addBits(Lanes a, Lanes b) {
        return {_mm256_castsi256_pd(_mm256_add_epi64(_mm256_castpd_si256(a.v), _mm256_castpd_si256(b.v)))};
    }
    // |a| (the pattern without its sign bit).
    friend Lanes magnitude(Lanes a) {
        return {_mm256_castsi256_pd(_mm256_and_si256(_mm256_castpd_si256(a.v), _mm256_set1_epi64x(INT64_MAX)))};
    }
    friend std::uint64_t largestBits(Lanes a) {
        alignas(32) std::uint64_t lanes[4];
        _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), _mm256_castpd_si256(a.v));
        std::uint64_t largest = lanes[0];
        for (int l = 1; l < 4; ++l) largest = largest > lanes[l] ? largest : lanes[l];
        return largest;
    }
    friend std::uint64_t sumOfBits(Lanes a) {
        alignas(32) std::uint64_t lanes[4];
        _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), _mm256_castpd_si256(a.v));
        return lanes[0] + lanes[1] + lanes[2] + lanes[3];
    }
    // The sum of the lanes, in pairs: (0 + 1) + (2 + 3).
    friend double sum(Lanes a) {
        alignas(32) double lanes[4];
        _mm256_store_pd(lanes, a.v);
        return (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
    }

    // --- blocks of four particles in storage order (Math/Lanes.h):
    // (x0 y0 z0 x1) (y1 z1 x2 y2) (z2 x3 y3 z3) ---
    // The particles' mobile lanes, one per particle, from ParticleStore::fixed's four bytes.
    static Mask mobile(const std::uint8_t* fixed) {
        std::int32_t bytes;
        std::memcpy(&bytes, fixed, sizeof bytes);
        const __m256i each = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(bytes));
        return {_mm256_castsi256_pd(_mm256_cmpeq_epi64(each, _mm256_setzero_si256()))};
    }
    // A per-particle value (or mask) over the three vectors of the particles' coordinates: one
    // permutation each, lane l of vector c from lane particleOfLane(4, c, l).
    template <int c>
    static constexpr int spreadOrder = particleOfLane(4, c, 0) | particleOfLane(4, c, 1) << 2 |
                                       particleOfLane(4, c, 2) << 4 | particleOfLane(4, c, 3) << 6;
    static void spread(__m256d perParticle, __m256d (&out)[3]) {
        out[0] = _mm256_permute4x64_pd(perParticle, spreadOrder<0>);
        out[1] = _mm256_permute4x64_pd(perParticle, spreadOrder<1>);
        out[2] = _mm256_permute4x64_pd(perParticle, spreadOrder<2>);
    }
    static void spread(Lanes perParticle, Lanes (&out)[3]) {
        __m256d spreadOut[3];
        spread(perParticle.v, spreadOut);
        for (int c = 0; c < 3; ++c) out[c] = {spreadOut[c]};
    }
    static void spread(Mask perParticle, Mask (&out)[3]) {
        __m256d spreadOut[3];
        spread(perParticle.bits, spreadOut);
        for (int c = 0; c < 3; ++c) out[c] = {spreadOut[c]};
    }
    // The three vectors in storage order to one per axis, (x0 x1 x2 x3) (y0 ...) (z0 ...): six
    // shuffles.
    static void toAxes(const Lanes (&stored)[3], Lanes (&axis)[3]) {
        const __m256d xy = _mm256_permute2f128_pd(stored[0].v, stored[1].v, 0x30);  // x0 y0 | x2 y2
        const __m256d zx = _mm256_permute2f128_pd(stored[0].v, stored[2].v, 0x21);  // z0 x1 | z2 x3
        const __m256d yz = _mm256_permute2f128_pd(stored[1].v, stored[2].v, 0x30);  // y1 z1 | y3 z3
        axis[0] = {_mm256_shuffle_pd(xy, zx, 0b1010)};
        axis[1] = {_mm256_shuffle_pd(xy, yz, 0b0101)};
        axis[2] = {_mm256_shuffle_pd(zx, yz, 0b1010)};
    }
    // The four points (x, y, z, w) of the particles, 16 doubles from out on: their coordinates
    // (storage order) to one vector per axis, then a 4 x 4 transposition with w.
    static void storePoints(const Lanes (&stored)[3], Lanes w, double* out) {
        Lanes axis[3];
        toAxes(stored, axis);
        const __m256d xy0 = _mm256_unpacklo_pd(axis[0].v, axis[1].v), xy1 = _mm256_unpackhi_pd(axis[0].v, axis[1].v);
        const __m256d zw0 = _mm256_unpacklo_pd(axis[2].v, w.v), zw1 = _mm256_unpackhi_pd(axis[2].v, w.v);
        _mm256_storeu_pd(out, _mm256_permute2f128_pd(xy0, zw0, 0x20));
        _mm256_storeu_pd(out + 4, _mm256_permute2f128_pd(xy1, zw1, 0x20));
        _mm256_storeu_pd(out + 8, _mm256_permute2f128_pd(xy0, zw0, 0x31));
        _mm256_storeu_pd(out + 12, _mm256_permute2f128_pd(xy1, zw1, 0x31));
    }

    // --- lanes of other types, and packing (the sweep, Contacts/PairSweepLanes.h) ---
    struct Words {  // four 64-bit words
        __m256i v;
    };
    struct Indices {  // four 32-bit numbers
        __m128i v;
    };
    static Words words(const std::uint64_t (&w)[4]) {
        return {_mm256_setr_epi64x(static_cast<long long>(w[0]), static_cast<long long>(w[1]),
                                   static_cast<long long>(w[2]), static_cast<long long>(w[3]))};
    }
    static Indices indices(const std::uint32_t (&k)[4]) {
        return {_mm_setr_epi32(static_cast<int>(k[0]), static_cast<int>(k[1]), static_cast<int>(k[2]),
                               static_cast<int>(k[3]))};
    }
    // The lanes whose bits `pick` has, stored one after the other in the order of their lanes
    // (whole vectors: the caller leaves room for four).
    class Packing {
    public:
        explicit Packing(unsigned pick)
            : wide_(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(detail::leftPacking.wide[pick]))),
              narrow_(_mm_loadu_si128(reinterpret_cast<const __m128i*>(detail::leftPacking.narrow[pick]))) {}
        void store(Lanes a, double* out) const {
            _mm256_storeu_pd(out, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(a.v), wide_)));
        }
        void store(Words a, void* out) const {
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_permutevar8x32_epi32(a.v, wide_));
        }
        void store(Indices a, std::uint32_t* out) const {
            _mm_storeu_si128(reinterpret_cast<__m128i*>(out),
                             _mm_castps_si128(_mm_permutevar_ps(_mm_castsi128_ps(a.v), narrow_)));
        }

    private:
        __m256i wide_;
        __m128i narrow_;
    };
    // Four pairs of points (x, y, z, w: four doubles each) a[l] and b[l], each loaded whole (no
    // gathers): their differences a - b in x, y and z, one vector per axis, and the sums of their
    // w. (b negated in its first three lanes: a + (-b) is a - b to the bit; then a 4 x 4
    // transposition.)
    static void pointDifferences(const double* const (&a)[4], const double* const (&b)[4], Lanes (&axis)[3],
                                 Lanes& wSum) {
        const __m256d negateXyz = _mm256_setr_pd(-0.0, -0.0, -0.0, 0.0);
        __m256d d[4];
        for (int l = 0; l < 4; ++l) d[l] = _mm256_add_pd(_mm256_loadu_pd(a[l]), _mm256_xor_pd(_mm256_loadu_pd(b[l]), negateXyz));
        const __m256d t0 = _mm256_unpacklo_pd(d[0], d[1]), t1 = _mm256_unpackhi_pd(d[0], d[1]);
        const __m256d t2 = _mm256_unpacklo_pd(d[2], d[3]), t3 = _mm256_unpackhi_pd(d[2], d[3]);
        axis[0] = {_mm256_permute2f128_pd(t0, t2, 0x20)};
        axis[1] = {_mm256_permute2f128_pd(t1, t3, 0x20)};
        axis[2] = {_mm256_permute2f128_pd(t0, t2, 0x31)};
        wSum = {_mm256_permute2f128_pd(t1, t3, 0x31)};
    }
};

}  // namespace talus::TALUS_LANES::lanes

// The sweep of the force loop (Contacts/PairSweep.h) in the lanes of one form
// (Math/LaneKernels.h): the scalar rule, four pairs at a time in AVX2 lanes, eight at a time
// with AVX-512 gathers, and the sweep points and the near list they read.
#pragma once

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#if defined(__AVX512F__) && defined(__AVX512VL__)
#define TALUS_AVX512_SWEEP 1
#include <immintrin.h>
#endif
#if defined(__AVX2__) && defined(__FMA__)
#define TALUS_AVX2_SWEEP 1
#include <immintrin.h>
#endif

#include "Contacts/PairSweep.h"
#include "Math/LaneNamespace.h"

namespace talus::TALUS_LANES {

// The forms this build has, the scalar loop first.
inline std::vector<SweepForm> availableSweepForms() {
    std::vector<SweepForm> forms{SweepForm::scalar};
#ifdef TALUS_AVX2_SWEEP
    forms.push_back(SweepForm::lanes);
#endif
#ifdef TALUS_AVX512_SWEEP
    forms.push_back(SweepForm::gathers);
#endif
    return forms;
}
inline SweepForm& sweepForm() {
    static SweepForm form = [] {
        if (availableSweepForms().size() == 1) return SweepForm::scalar;
        const char* fixed = std::getenv("TALUS_SWEEP");
        if (!fixed) return SweepForm::undecided;
        for (const SweepForm f : availableSweepForms())
            if (std::strcmp(fixed, sweepFormName(f)) == 0) return f;
        return SweepForm::scalar;
    }();
    return form;
}


// The scalar rule for pair k of the list, `pair`: its separation into out at `picked`, which moves on if it is picked.
template <bool nearestImage>
[[gnu::always_inline]] inline void sweepPair(ParticlePair pair, std::size_t k, const SweepPoint* points,
                                             const ContactHistory::State* states, const PeriodicImage& image,
                                             SweptPairs& out, std::size_t& picked) {
    const SweepPoint &a = points[pair.i], &b = points[pair.j];
    Vec3 d(a.x - b.x, a.y - b.y, a.z - b.z);
    if constexpr (nearestImage) d = image.nearest(d);
    const double limit = a.radius + b.radius;
#ifdef __FMA__
    const double r2 = std::fma(d.z(), d.z(), std::fma(d.y(), d.y(), d.x() * d.x()));  // as the AVX-512 lanes
#else
    const double r2 = d.x() * d.x() + d.y() * d.y() + d.z() * d.z();
#endif
    out.pair[picked] = static_cast<std::uint32_t>(k);
    out.particles[picked] = pair;
    out.dx[picked] = d.x(), out.dy[picked] = d.y(), out.dz[picked] = d.z();
    picked += (r2 < limit * limit) | (states[k] != ContactHistory::apart);
}

#ifdef TALUS_AVX2_SWEEP
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

// The rule for four pairs at a time, from `begin` on while four are left before `end`; returns
// where it stopped. pairAt(m) gives the m-th pair to sweep and its place k in the whole list.
// Each pair's two points are loaded whole (x, y, z, radius: one 32-byte load each, no gathers),
// subtracted with the radii added (b negated in its first three lanes: a + (-b) is a - b to
// the bit), and the four differences turned into one vector per axis; the nearest image, the
// distance and the pick as in sweepPair. Same decisions and separations, bit for bit.
template <bool nearestImage, class PairAt>
inline std::size_t sweepInFourPairLanes(PairAt pairAt, std::size_t begin, std::size_t end, const SweepPoint* points,
                                        const ContactHistory::State* states, const PeriodicImage& image,
                                        SweptPairs& out, std::size_t& picked) {
    __m256d length[3], half[3], minusHalf[3];
    for (int a = 0; a < 3; ++a) {
        length[a] = _mm256_set1_pd(image.length(a));
        half[a] = _mm256_set1_pd(image.halfLength(a));
        minusHalf[a] = _mm256_set1_pd(-image.halfLength(a));
    }
    const __m256d negateXyz = _mm256_setr_pd(-0.0, -0.0, -0.0, 0.0);
    std::size_t m = begin;
    for (; m + 4 <= end; m += 4) {
        // (The pairs and places go into vectors from registers: stored one by one and loaded
        // whole, the load cannot take the stores' data on the way and waits for them, the
        // hottest instruction of the wave's force loop in a profile at 108000 particles. Measured:
        // 3% faster at 3000 in single steps, 6% at 12000 in waves, unchanged at 108000.)
        long long pair[4];
        std::uint32_t index[4];
        __m256d d[4];  // xi - xj, yi - yj, zi - zj, ri + rj
        for (int l = 0; l < 4; ++l) {
            const auto [particles, k] = pairAt(m + static_cast<std::size_t>(l));
            pair[l] = std::bit_cast<long long>(particles), index[l] = static_cast<std::uint32_t>(k);
            d[l] = _mm256_add_pd(_mm256_loadu_pd(&points[particles.i].x),
                                 _mm256_xor_pd(_mm256_loadu_pd(&points[particles.j].x), negateXyz));
        }
        const __m256d t0 = _mm256_unpacklo_pd(d[0], d[1]), t1 = _mm256_unpackhi_pd(d[0], d[1]);
        const __m256d t2 = _mm256_unpacklo_pd(d[2], d[3]), t3 = _mm256_unpackhi_pd(d[2], d[3]);
        __m256d axis[3] = {_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_permute2f128_pd(t1, t3, 0x20),
                           _mm256_permute2f128_pd(t0, t2, 0x31)};
        const __m256d limit = _mm256_permute2f128_pd(t1, t3, 0x31);
        if constexpr (nearestImage)
            for (int a = 0; a < 3; ++a) {
                const __m256d above = _mm256_cmp_pd(axis[a], half[a], _CMP_GT_OQ);
                const __m256d below = _mm256_cmp_pd(axis[a], minusHalf[a], _CMP_LT_OQ);
                axis[a] = _mm256_blendv_pd(_mm256_blendv_pd(axis[a], _mm256_sub_pd(axis[a], length[a]), above),
                                           _mm256_add_pd(axis[a], length[a]), below);
            }
        const __m256d r2 =
            _mm256_fmadd_pd(axis[2], axis[2], _mm256_fmadd_pd(axis[1], axis[1], _mm256_mul_pd(axis[0], axis[0])));
        const __m256d near = _mm256_cmp_pd(r2, _mm256_mul_pd(limit, limit), _CMP_LT_OQ);
        const int pending = (states[index[0]] != ContactHistory::apart) | (states[index[1]] != ContactHistory::apart) << 1 |
                            (states[index[2]] != ContactHistory::apart) << 2 | (states[index[3]] != ContactHistory::apart) << 3;
        const int pick = _mm256_movemask_pd(near) | pending;
        const __m256i wide = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(detail::leftPacking.wide[pick]));
        const __m128i narrow = _mm_loadu_si128(reinterpret_cast<const __m128i*>(detail::leftPacking.narrow[pick]));
        const auto pack = [&](__m256d v) { return _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(v), wide)); };
        // (Whole vectors stored: picked + 4 <= m + 4 - begin <= SweptPairs::capacity.)
        const __m256i pairs = _mm256_setr_epi64x(pair[0], pair[1], pair[2], pair[3]);
        const __m128i places = _mm_setr_epi32(static_cast<int>(index[0]), static_cast<int>(index[1]),
                                              static_cast<int>(index[2]), static_cast<int>(index[3]));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.particles + picked), _mm256_permutevar8x32_epi32(pairs, wide));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out.pair + picked),
                         _mm_castps_si128(_mm_permutevar_ps(_mm_castsi128_ps(places), narrow)));
        _mm256_storeu_pd(out.dx + picked, pack(axis[0]));
        _mm256_storeu_pd(out.dy + picked, pack(axis[1]));
        _mm256_storeu_pd(out.dz + picked, pack(axis[2]));
        picked += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(pick)));
    }
    return m;
}
#endif

// Pairs [begin, end) of the list, at most SweptPairs::capacity of them, in the given form
// (gathers: the AVX-512 lanes, for as many whole groups of eight as fit; lanes: four-pair lanes).
// Without nearestImage the separation is the direct difference xi - xj: for the pairs that a
// build found to keep it as their nearest image (PairList::interiorPairs).
template <bool nearestImage = true>
inline void sweepPairs(const ParticlePair* pairs, std::size_t begin, std::size_t end, const SweepPoint* points,
                       [[maybe_unused]] std::size_t particleCount, const ContactHistory::State* states,
                       const PeriodicImage& image, SweptPairs& out, [[maybe_unused]] SweepForm form = sweepForm()) {
    std::size_t picked = 0, k = begin;
#ifdef TALUS_AVX512_SWEEP
    // (The gathers index the records' numbers with 32-bit 4 i; GCC 12 warns about the intrinsics'
    // own undefined pass-through operands.)
    const std::size_t vectorEnd = form == SweepForm::gathers && particleCount < (std::size_t{1} << 31) / 4 ? end : begin;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
    static_assert(sizeof(ParticlePair) == 8 && sizeof(ContactHistory::State) == 1);
    const double* numbers = &points[0].x;  // x, y, z, radius of each particle in turn
    __m512d length[3], half[3], minusHalf[3];
    for (int a = 0; a < 3; ++a) {
        length[a] = _mm512_set1_pd(image.length(a));
        half[a] = _mm512_set1_pd(image.halfLength(a));
        minusHalf[a] = _mm512_set1_pd(-image.halfLength(a));
    }
    const __m512i evenLanes = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15);
    const __m256i laneOffsets = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    double* separation[3] = {out.dx, out.dy, out.dz};
    for (; k + 8 <= vectorEnd; k += 8) {
        // i in the low eight 32-bit lanes, j in the high eight.
        const __m512i listed = _mm512_loadu_si512(pairs + k);
        const __m512i ij = _mm512_permutexvar_epi32(evenLanes, listed);
        const __m256i i = _mm512_castsi512_si256(ij), j = _mm512_extracti64x4_epi64(ij, 1);
        const __m256i i4 = _mm256_slli_epi32(i, 2), j4 = _mm256_slli_epi32(j, 2);
        __m512d d[3];
        for (int a = 0; a < 3; ++a) {
            d[a] = _mm512_sub_pd(_mm512_i32gather_pd(i4, numbers + a, 8), _mm512_i32gather_pd(j4, numbers + a, 8));
            if constexpr (nearestImage) {
                d[a] = _mm512_mask_sub_pd(d[a], _mm512_cmp_pd_mask(d[a], half[a], _CMP_GT_OQ), d[a], length[a]);
                d[a] = _mm512_mask_add_pd(d[a], _mm512_cmp_pd_mask(d[a], minusHalf[a], _CMP_LT_OQ), d[a], length[a]);
            }
        }
        const __m512d r2 = _mm512_fmadd_pd(d[2], d[2], _mm512_fmadd_pd(d[1], d[1], _mm512_mul_pd(d[0], d[0])));
        const __m512d limit = _mm512_add_pd(_mm512_i32gather_pd(i4, numbers + 3, 8), _mm512_i32gather_pd(j4, numbers + 3, 8));
        const __mmask8 near = _mm512_cmp_pd_mask(r2, _mm512_mul_pd(limit, limit), _CMP_LT_OQ);
        const __m256i state = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(states + k)));
        const __mmask8 pick = near | _mm256_test_epi32_mask(state, state);
        _mm256_mask_compressstoreu_epi32(out.pair + picked, pick,
                                         _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(k)), laneOffsets));
        _mm512_mask_compressstoreu_epi64(out.particles + picked, pick, listed);
        for (int a = 0; a < 3; ++a) _mm512_mask_compressstoreu_pd(separation[a] + picked, pick, d[a]);
        picked += static_cast<std::size_t>(__builtin_popcount(pick));
    }
#pragma GCC diagnostic pop
#endif
#ifdef TALUS_AVX2_SWEEP
    if (form == SweepForm::lanes)
        k = sweepInFourPairLanes<nearestImage>([pairs](std::size_t m) { return std::pair(pairs[m], m); }, k, end,
                                               points, states, image, out, picked);
#endif
    for (; k < end; ++k) sweepPair<nearestImage>(pairs[k], k, points, states, image, out, picked);
    out.count = picked;
}

// The same rule for the m-th pairs of a selection, m in [begin, end), at most
// SweptPairs::capacity of them; pairAt(m) gives the pair and its place k in the whole list, which
// out.pair holds. In four-pair lanes unless the form is the scalar loop (a selection's pairs
// are not in one array for the gathers).
template <bool nearestImage, class PairAt>
inline void sweepSelectedPairs(PairAt pairAt, std::size_t begin, std::size_t end, const SweepPoint* points,
                               const ContactHistory::State* states, const PeriodicImage& image, SweptPairs& out,
                               [[maybe_unused]] SweepForm form = sweepForm()) {
    std::size_t picked = 0, m = begin;
#ifdef TALUS_AVX2_SWEEP
    if (form == SweepForm::lanes || form == SweepForm::gathers)
        m = sweepInFourPairLanes<nearestImage>(pairAt, m, end, points, states, image, out, picked);
#endif
    for (; m < end; ++m) {
        const auto [pair, k] = pairAt(m);
        sweepPair<nearestImage>(pair, k, points, states, image, out, picked);
    }
    out.count = picked;
}

// The pairs [begin, end) of a near list (NearPairs).
template <bool nearestImage>
inline void sweepNearPairs(const NearPairs& near, std::size_t begin, std::size_t end, const SweepPoint* points,
                           const ContactHistory::State* states, const PeriodicImage& image, SweptPairs& out,
                           SweepForm form = sweepForm()) {
    sweepSelectedPairs<nearestImage>(
        [&near](std::size_t m) { return std::pair(near.pairs[m].particles, std::size_t{near.pairs[m].index}); }, begin,
        end, points, states, image, out, form);
}

// The pairs index[begin, end) of the list (a region of a wave, Contacts/WaveSchedule.h).
template <bool nearestImage>
inline void sweepIndexedPairs(const ParticlePair* pairs, const std::uint32_t* index, std::size_t begin, std::size_t end,
                              const SweepPoint* points, const ContactHistory::State* states, const PeriodicImage& image,
                              SweptPairs& out, SweepForm form = sweepForm()) {
    sweepSelectedPairs<nearestImage>(
        [pairs, index](std::size_t m) { return std::pair(pairs[index[m]], std::size_t{index[m]}); }, begin, end, points,
        states, image, out, form);
}

// The sweep points of a step (Contacts/PairSweep.h).
inline double sweepPointsForStep(const ParticleStore& p, double dt, const Vec3& frameVelocity,
                                 std::vector<SweepPoint>& points) {
    points.resize(p.size());
    if (points.empty()) return 0;
    SweepPoint* __restrict out = points.data();  // (plain arrays: the loops vectorise)
    const double* __restrict radius = p.radius.data();
    const double* __restrict x = p.position[0].data();
    const double* __restrict v = p.velocity[0].data();
    const double reachPerSpeed = sweepReachMargin * dt;
    const double u0 = frameVelocity.x(), u1 = frameVelocity.y(), u2 = frameVelocity.z();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double w0 = v[3 * i] - u0, w1 = v[3 * i + 1] - u1, w2 = v[3 * i + 2] - u2;
        out[i] = {x[3 * i], x[3 * i + 1], x[3 * i + 2],
                  radius[i] * sweepRadiusMargin + reachPerSpeed * std::sqrt(w0 * w0 + w1 * w1 + w2 * w2)};
    }
    // The largest of the non-negative growths as bit patterns (the order of the values, and
    // vectorised where a floating-point maximum is not); a NaN wins.
    std::uint64_t largest = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
        largest = std::max(largest, std::bit_cast<std::uint64_t>(std::max(out[i].radius - radius[i], 0.0)));
    return std::bit_cast<double>(largest);
}


// The near list (NearPairs): the pairs of `list` that the sweep's rule picks with every radius
// grown by skin / 2 (closer than ri + rj + skin, or pending), in list order. Until a particle
// may have moved so far that a pair left out could come within the pick of a step, sweeping it
// picks exactly the pairs the whole list's sweep picks, in the same order (ContactForces.h).
inline void makeNearPairs(PairList& list, const Vec3* position, std::size_t particleCount, const double* radius,
                          double skin, const PeriodicImage& image, std::vector<SweepPoint>& grownScratch,
                          SweptPairs& scratch) {
    NearPairs& near = list.near;
    grownScratch.resize(particleCount);
    for (std::size_t i = 0; i < particleCount; ++i)
        grownScratch[i] = {position[i].x(), position[i].y(), position[i].z(), radius[i] + 0.5 * skin};
    near.pairs.clear();
    const std::size_t interior = std::min(list.interiorPairs, list.pairs.size());
    for (std::size_t begin = 0; begin < list.pairs.size(); begin += SweptPairs::capacity) {
        const std::size_t end = std::min(list.pairs.size(), begin + SweptPairs::capacity);
        // (A chunk across the end of the interior pairs: the image for all of it, which leaves
        // an interior pair's direct difference as it is.)
        if (end <= interior)
            sweepPairs<false>(list.pairs.data(), begin, end, grownScratch.data(), particleCount, list.history.states(),
                              image, scratch);
        else
            sweepPairs<true>(list.pairs.data(), begin, end, grownScratch.data(), particleCount, list.history.states(),
                             image, scratch);
        for (std::size_t a = 0; a < scratch.count; ++a) near.pairs.push_back({scratch.particles[a], scratch.pair[a]});
    }
    near.interior = static_cast<std::size_t>(
        std::partition_point(near.pairs.begin(), near.pairs.end(),
                             [&](const NearPairs::Pair& pair) { return pair.index < interior; }) -
        near.pairs.begin());
    near.skin = skin;
    near.moved = 0;
    near.made = true;
    near.builds = list.builds;
    near.relisted = list.relistedParticles;
    near.listed = list.pairs.size();
    ++near.makes;
}

// Decides sweepForm() if undecided: sweeps the first chunk of a list in each form the build has,
// in turn, and keeps the fastest (the fastest of 30 sweeps each, so that a busy machine's
// interruptions do not decide). Called by the force loop on the first list long enough (a few chunks) for
// the sweep to matter; the picks are the same either way, so only the speed depends on it.
inline void chooseSweepForm(const ParticlePair* pairs, std::size_t count, const SweepPoint* points,
                            std::size_t particleCount, const ContactHistory::State* states,
                            const PeriodicImage& image, SweptPairs& scratch) {
    if (sweepForm() != SweepForm::undecided) return;
    using Clock = std::chrono::steady_clock;
    const std::size_t end = std::min(count, SweptPairs::capacity);
    const std::vector<SweepForm> forms = availableSweepForms();
    std::vector<Clock::duration> fastest(forms.size(), Clock::duration::max());
    for (int round = 0; round < 30; ++round)
        for (std::size_t f = 0; f < forms.size(); ++f) {
            const Clock::time_point start = Clock::now();
            sweepPairs(pairs, 0, end, points, particleCount, states, image, scratch, forms[f]);
            fastest[f] = std::min(fastest[f], Clock::now() - start);
        }
    sweepForm() = forms[static_cast<std::size_t>(std::min_element(fastest.begin(), fastest.end()) - fastest.begin())];
}

}  // namespace talus::TALUS_LANES

// The sweep of the force loop (Contacts/PairSweep.h) in the lanes of one form
// (Math/LaneKernels.h): the scalar rule, and the same rule for W pairs at a time written once over
// the lanes (Math/Lanes.h), four at a time from points loaded whole or eight at a time from
// AVX-512 gathers; and the sweep points and the near list they read.
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

#include "Contacts/PairSweep.h"
#include "Math/LaneNamespace.h"
#include "Math/Lanes.h"

namespace talus::TALUS_LANES {

// The forms this build has, the scalar loop first.
inline std::vector<SweepForm> availableSweepForms() {
    std::vector<SweepForm> forms{SweepForm::scalar};
#if TALUS_LANES_WIDTH > 1
    forms.push_back(SweepForm::lanes);
#endif
#if TALUS_LANES_WIDTH == 8
    forms.push_back(SweepForm::gathers);
#endif
    return forms;
}
// The form in use: the one the run asks for (requestedSweepForm) where this lane form has it, else
// the scalar loop; undecided (to be chosen by timing) where the run asks for none.
inline SweepForm& sweepForm() {
    static const bool scalarOnly = availableSweepForms().size() == 1;
    static SweepForm form = scalarOnly ? SweepForm::scalar : SweepForm::undecided, asked = SweepForm::undecided;
    if (requestedSweepForm() != asked && !scalarOnly) [[unlikely]] {
        asked = requestedSweepForm();
        const std::vector<SweepForm> forms = availableSweepForms();
        form = asked == SweepForm::undecided || std::find(forms.begin(), forms.end(), asked) != forms.end()
                   ? asked : SweepForm::scalar;
    }
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

#if TALUS_LANES_WIDTH > 1
// W pairs of the sweep in lanes L (Math/Lanes.h): their separations xi - xj, one vector per axis,
// and radius sums, which of them have something pending (a contact history that is not apart),
// the pairs themselves and their places k in the whole list.
template <class L>
struct PairLanes {
    L d[3], limit;
    unsigned pending;
    typename L::Words pairs;
    typename L::Indices places;
};

// The periodic box per axis, in every lane.
template <class L>
struct ImageLanes {
    L length[3], half[3], minusHalf[3];
    explicit ImageLanes(const PeriodicImage& image) {
        for (int a = 0; a < 3; ++a) {
            length[a] = L::broadcast(image.length(a));
            half[a] = L::broadcast(image.halfLength(a)), minusHalf[a] = L::broadcast(-image.halfLength(a));
        }
    }
};

// The rule of sweepPair for W pairs at once, written once for every width: the nearest image,
// the distance (the same fused multiply-adds) and the pick; the picked pairs' places, particles
// and separations stored from out's `picked` on, which moves on by their number. (Whole vectors
// stored: picked + W <= SweptPairs::capacity while W pairs of a chunk are left.)
template <bool nearestImage, class L>
[[gnu::always_inline]] inline void pickInLanes(PairLanes<L>& block, const ImageLanes<L>& image, SweptPairs& out,
                                               std::size_t& picked) {
    if constexpr (nearestImage)
        for (int a = 0; a < 3; ++a)
            block.d[a] = lanes::nearestOf(block.d[a], image.length[a], image.half[a], image.minusHalf[a]);
    const L r2 = lanes::squaredNorms(block.d);
    const unsigned pick = bitsOf(r2 < block.limit * block.limit) | block.pending;
    const typename L::Packing packing(pick);
    packing.store(block.places, out.pair + picked);
    packing.store(block.pairs, out.particles + picked);
    packing.store(block.d[0], out.dx + picked);
    packing.store(block.d[1], out.dy + picked);
    packing.store(block.d[2], out.dz + picked);
    picked += static_cast<std::size_t>(std::popcount(pick));
}

// The rule for four pairs at a time, from `begin` on while four are left before `end`; returns
// where it stopped. pairAt(m) gives the m-th pair to sweep and its place k in the whole list.
// Each pair's two points are loaded whole (x, y, z, radius: one 32-byte load each, no gathers:
// Lanes<4>::pointDifferences). Same decisions and separations as sweepPair, bit for bit.
template <bool nearestImage, class PairAt>
inline std::size_t sweepInFourPairLanes(PairAt pairAt, std::size_t begin, std::size_t end, const SweepPoint* points,
                                        const ContactHistory::State* states, const PeriodicImage& image,
                                        SweptPairs& out, std::size_t& picked) {
    using L = lanes::Lanes<4>;
    const ImageLanes<L> box(image);
    std::size_t m = begin;
    for (; m + 4 <= end; m += 4) {
        // (The pairs and places go into vectors from registers: stored one by one and loaded
        // whole, the load cannot take the stores' data on the way and waits for them, the
        // hottest instruction of the wave's force loop in a profile at 108000 particles. Measured:
        // 3% faster at 3000 in single steps, 6% at 12000 in waves, unchanged at 108000.)
        std::uint64_t pair[4];
        std::uint32_t index[4];
        const double *a[4], *b[4];
        PairLanes<L> block;
        block.pending = 0;
        for (int l = 0; l < 4; ++l) {
            const auto [particles, k] = pairAt(m + static_cast<std::size_t>(l));
            pair[l] = std::bit_cast<std::uint64_t>(particles), index[l] = static_cast<std::uint32_t>(k);
            a[l] = &points[particles.i].x, b[l] = &points[particles.j].x;
            block.pending |= static_cast<unsigned>(states[k] != ContactHistory::apart) << l;
        }
        L::pointDifferences(a, b, block.d, block.limit);
        block.pairs = L::words(pair), block.places = L::indices(index);
        pickInLanes<nearestImage>(block, box, out, picked);
    }
    return m;
}
#endif

#if TALUS_LANES_WIDTH == 8
// The rule for eight pairs [k, k + 8) of the list at a time while eight are left before `end`,
// their points gathered (Lanes<8>::gatheredDifferences); returns where it stopped.
template <bool nearestImage>
inline std::size_t sweepInGatheredLanes(const ParticlePair* pairs, std::size_t k, std::size_t end,
                                        const SweepPoint* points, const ContactHistory::State* states,
                                        const PeriodicImage& image, SweptPairs& out, std::size_t& picked) {
    using L = lanes::Lanes<8>;
    static_assert(sizeof(ParticlePair) == 8 && sizeof(ContactHistory::State) == 1);
    const ImageLanes<L> box(image);
    const double* numbers = &points[0].x;  // x, y, z, radius of each particle in turn
    for (; k + 8 <= end; k += 8) {
        PairLanes<L> block;
        block.pairs = L::loadWords(pairs + k);
        L::gatheredDifferences(block.pairs, numbers, block.d, block.limit);
        block.pending = L::nonZeroBytes(reinterpret_cast<const std::uint8_t*>(states + k));
        block.places = L::consecutive(static_cast<std::uint32_t>(k));
        pickInLanes<nearestImage>(block, box, out, picked);
    }
    return k;
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
#if TALUS_LANES_WIDTH == 8
    // (The gathers index the points' numbers with 32-bit 4 i.)
    if (form == SweepForm::gathers && particleCount < (std::size_t{1} << 31) / 4)
        k = sweepInGatheredLanes<nearestImage>(pairs, k, end, points, states, image, out, picked);
#endif
#if TALUS_LANES_WIDTH > 1
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
#if TALUS_LANES_WIDTH > 1
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
// Of the slots [first, last) (the points array sized for all), returning the largest growth among
// them: on ranks the owned particles' points are made before the ghosts' states have arrived.
inline double sweepPointsForStep(const ParticleStore& p, std::size_t first, std::size_t last, double dt,
                                 const Vec3& frameVelocity, std::vector<SweepPoint>& points) {
    points.resize(p.size());
    if (first >= last) return 0;
    SweepPoint* __restrict out = points.data();  // (plain arrays: the loops vectorise)
    const double* __restrict radius = p.radius.data();
    const double* __restrict x = p.position[0].data();
    const double* __restrict v = p.velocity[0].data();
    const double reachPerSpeed = sweepReachMargin * dt;
    const double u0 = frameVelocity.x(), u1 = frameVelocity.y(), u2 = frameVelocity.z();
    for (std::size_t i = first; i < last; ++i) {
        const double w0 = v[3 * i] - u0, w1 = v[3 * i + 1] - u1, w2 = v[3 * i + 2] - u2;
        out[i] = {x[3 * i], x[3 * i + 1], x[3 * i + 2],
                  radius[i] * sweepRadiusMargin + reachPerSpeed * std::sqrt(w0 * w0 + w1 * w1 + w2 * w2)};
    }
    // The largest of the non-negative growths as bit patterns (the order of the values, and
    // vectorised where a floating-point maximum is not); a NaN wins.
    std::uint64_t largest = 0;
    for (std::size_t i = first; i < last; ++i)
        largest = std::max(largest, std::bit_cast<std::uint64_t>(std::max(out[i].radius - radius[i], 0.0)));
    return std::bit_cast<double>(largest);
}
inline double sweepPointsForStep(const ParticleStore& p, double dt, const Vec3& frameVelocity,
                                 std::vector<SweepPoint>& points) {
    return sweepPointsForStep(p, 0, p.size(), dt, frameVelocity, points);
}
// The larger of two growths as sweepPointsForStep compares them (as bit patterns; a NaN wins).
inline double largerGrowth(double a, double b) {
    return std::bit_cast<double>(std::max(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b)));
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
    near.edits = list.edits;
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

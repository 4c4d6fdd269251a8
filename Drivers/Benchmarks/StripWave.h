// Time skewing for the model of LayoutProbe (Drivers/Benchmarks/LayoutProbe.cc): the particles
// advanced several steps while their data is in the caches, instead of one step per pass over
// all of them (Performance.md, "Scaling and memory"). A step of a pair force and a kick-drift
// per particle depends only on the particle's partners at the step before, so a region can be
// advanced from step t to t + 1 as soon as it and its partners have reached step t, and before
// its partners go on to t + 1. The wave below orders such advances so that each stretch of a
// strip is advanced k steps while it is cached (Wonnacott 2000, "time skewing"; with the
// periodic seams handled as in the trapezoid tilings of Frigo and Strumpen 2005).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "LayoutModel.h"

// Internal to the one program that includes it, as the compiler inlines such functions more
// readily (the model's timings depend on it).
namespace layoutModel {
namespace {

// The model's chute bed (a jittered cubic lattice of spacing 1, 12 layers deep, periodic along x
// and y) in the order of the wave: strips `width` lattice rows wide along y; within a strip row
// by row along x, across the strip, then up. Every pair closer than 1.25 is listed once (lower
// slot first), so pairs join only neighbouring rows along x and y.
struct StripScene {
    static constexpr int layers = 12;
    int side = 0, width = 0, strips = 0;
    std::size_t n = 0;
    std::vector<double> x;    // 3 n
    std::vector<Pair> pairs;  // grouped by the lower slot
    std::size_t slot(int a, int b, int c) const {
        return ((static_cast<std::size_t>(b / width) * side + a) * width + b % width) * layers + c;
    }
};

inline StripScene makeStripScene(std::size_t target, int width) {
    StripScene s;
    s.width = width;
    s.strips = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(target) / s.layers) / width)));
    s.side = s.strips * width;
    s.n = static_cast<std::size_t>(s.side) * s.side * s.layers;
    s.x.resize(3 * s.n);
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    for (int a = 0; a < s.side; ++a)
        for (int b = 0; b < s.side; ++b)
            for (int c = 0; c < s.layers; ++c) {
                double* p = &s.x[3 * s.slot(a, b, c)];
                p[0] = a + 0.5 + jitter(random), p[1] = b + 0.5 + jitter(random), p[2] = c + 0.5 + jitter(random);
            }
    constexpr double listed = 1.25;
    for (std::size_t k = 0; k < s.n; ++k) {
        const int c = static_cast<int>(k % s.layers), b0 = static_cast<int>(k / s.layers % width);
        const int a = static_cast<int>(k / s.layers / width % s.side), b = static_cast<int>(k / s.layers / width / s.side) * width + b0;
        for (int da = -1; da <= 1; ++da)
            for (int db = -1; db <= 1; ++db)
                for (int dc = -1; dc <= 1; ++dc) {
                    if (c + dc < 0 || c + dc >= s.layers) continue;
                    const std::size_t m = s.slot((a + da + s.side) % s.side, (b + db + s.side) % s.side, c + dc);
                    if (m <= k) continue;
                    double d[3];
                    separation(&s.x[3 * k], &s.x[3 * m], s.side, d);
                    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < listed * listed)
                        s.pairs.push_back({static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(m)});
                }
    }
    return s;
}

// k steps of a StripScene as a sequence of regions, each a row (along x) of a strip's stretch
// advanced by one step with the pairs it computes; made once, replayed every k steps.
//
// At level t (0 <= t < k) of the k steps a particle is inside if its row is more than t rows from
// the periodic seam along x and from its strip's edges along y (depth >= t + 1), else in a seam.
// Four phases run in turn: inside along both; in the x seam only; in a y seam only; in both. In
// each, every strip (or the seam between strips q and q + 1) goes in a wave along x: region (row
// u, level t) in the order of u + t, then t. A pair is computed at level t by the first region
// holding either of its particles at that level, when both are at step t (the making checks this
// with a step counter per particle and stops if it ever fails), and its forces go to both.
class WaveSchedule {
public:
    WaveSchedule(const StripScene& s, int levels) : levels_(levels) {
        if (levels < 1 || s.width < 2 * levels + 1) {
            std::fprintf(stderr, "WaveSchedule: %d steps per wave need strips at least %d rows wide, got %d\n", levels,
                         2 * levels + 1, s.width);
            std::exit(2);
        }
        std::vector<std::uint32_t> first(s.n + 1, 0), partner(2 * s.pairs.size()), pairOf(2 * s.pairs.size());
        for (const Pair& p : s.pairs) ++first[p.i + 1], ++first[p.j + 1];
        for (std::size_t k = 0; k < s.n; ++k) first[k + 1] += first[k];
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::uint32_t id = 0; id < s.pairs.size(); ++id) {
            const Pair& p = s.pairs[id];
            partner[fill[p.i]] = p.j, pairOf[fill[p.i]++] = id;
            partner[fill[p.j]] = p.i, pairOf[fill[p.j]++] = id;
        }
        std::vector<std::uint32_t> step(s.n, 0);
        const int side = s.side;
        for (int phase = 0; phase < 4; ++phase) {
            const bool xSeam = phase & 1, ySeam = phase & 2;
            for (int q = 0; q < s.strips; ++q)
                for (int wave = 0; wave <= 2 * side + 2 * levels; ++wave)
                    for (int t = 0; t < levels; ++t) {
                        const int u = wave - t;  // the row along x, unwrapped across the seam
                        if (xSeam ? u < side - 1 - t || u > side + t : u < t + 1 || u > side - 2 - t) continue;
                        const int b = ySeam ? (q + 1) * s.width - 1 - t : q * s.width + t + 1;
                        const int across = ySeam ? 2 * t + 2 : s.width - 2 - 2 * t;
                        addRegion(s, first, partner, pairOf, step, u % side, b, across, static_cast<std::uint32_t>(t));
                    }
        }
    }

    int levels() const { return levels_; }
    // Bytes of the schedule per particle of the scene.
    double bytesPerParticle(const StripScene& s) const {
        return static_cast<double>(pairs_.size() * (sizeof(Pair) + sizeof(std::uint32_t)) + runs_.size() * sizeof(Pair) +
                                   regions_.size() * sizeof(Region)) / static_cast<double>(s.n);
    }

    // Advances every particle by levels() steps.
    template <class Data>
    void advance(const StripScene& s, Data& data, std::vector<History>& history) const {
        std::size_t e = 0, r = 0;
        for (const Region& region : regions_) {
            for (; e < region.pairsEnd; ++e) pairForce(pairs_[e], s.side, history[historyOf_[e]], data);
            for (; r < region.runsEnd; ++r) data.integrate(runs_[r].i, runs_[r].j);
        }
    }

private:
    struct Region {
        std::uint32_t pairsEnd, runsEnd;
    };
    static constexpr std::uint32_t advancing = 0xffffffffu;

    // Row `a`, columns b .. b + across - 1 (wrapped) of the bed at level t.
    void addRegion(const StripScene& s, const std::vector<std::uint32_t>& first, const std::vector<std::uint32_t>& partner,
                   const std::vector<std::uint32_t>& pairOf, std::vector<std::uint32_t>& step, int a, int b, int across,
                   std::uint32_t t) {
        const auto column = [&](int k) { return static_cast<std::uint32_t>(s.slot(a, (b + k + s.side) % s.side, 0)); };
        for (int k = 0; k < across; ++k)
            for (std::uint32_t i = column(k); i < column(k) + s.layers; ++i) step[i] = advancing;
        for (int k = 0; k < across; ++k)
            for (std::uint32_t i = column(k); i < column(k) + s.layers; ++i)
                for (std::uint32_t e = first[i]; e < first[i + 1]; ++e) {
                    const std::uint32_t j = partner[e];
                    if (step[j] == advancing ? j < i : step[j] != t) {
                        if (step[j] != advancing && step[j] != t + 1) {
                            std::fprintf(stderr, "WaveSchedule: particle %u at step %u when %u advances from step %u\n", j,
                                         step[j], i, t);
                            std::exit(1);
                        }
                        continue;  // computed already: by this region, or by the one that advanced j
                    }
                    const Pair& p = s.pairs[pairOf[e]];
                    pairs_.push_back(p);
                    historyOf_.push_back(pairOf[e]);
                }
        for (int k = 0; k < across; ++k) {
            const std::uint32_t i = column(k);
            if (!runs_.empty() && runs_.back().j == i) runs_.back().j += s.layers;
            else runs_.push_back({i, i + s.layers});
            for (std::uint32_t m = i; m < i + s.layers; ++m) step[m] = t + 1;
        }
        regions_.push_back({static_cast<std::uint32_t>(pairs_.size()), static_cast<std::uint32_t>(runs_.size())});
    }

    int levels_;
    std::vector<Pair> pairs_;               // the pairs each region computes, in turn
    std::vector<std::uint32_t> historyOf_;  // their places in the history
    std::vector<Pair> runs_;  // [i, j): particles to integrate
    std::vector<Region> regions_;
};

}  // namespace
}  // namespace layoutModel

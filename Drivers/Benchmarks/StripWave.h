// Time skewing for the model of LayoutProbe (Drivers/Benchmarks/LayoutProbe.cc): the particles
// advanced several steps while their data is in the caches, instead of one step per pass over
// all of them (Documentation/CacheCliff.md). A step of a pair force and a kick-drift
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
    LatticeBed bed = makeLatticeBed(s.side, s.layers, [&](int a, int b, int c) { return s.slot(a, b, c); }, false);
    s.n = bed.n, s.x = std::move(bed.x), s.pairs = std::move(bed.pairs);
    return s;
}

// The particles of row a, columns b .. b + across - 1 (wrapped): runs(begin, end) for each run of
// consecutive slots, up to the edge of a strip, where a seam between strips goes on in the next.
template <class Runs>
void forEachRun(const StripScene& s, int a, int b, int across, Runs runs) {
    const int b0 = (b + s.side) % s.side, inFirst = std::min(across, s.width - b0 % s.width);
    const std::size_t begin = s.slot(a, b0, 0);
    runs(begin, begin + static_cast<std::size_t>(inFirst) * s.layers);
    if (inFirst < across) {
        const std::size_t next = s.slot(a, (b0 + inFirst) % s.side, 0);
        runs(next, next + static_cast<std::size_t>(across - inFirst) * s.layers);
    }
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
//
// Stored lean: a row of a phase and strip (a host) computes each of its pairs over a run of
// levels, 1.6 hosts per pair on average with strips 32 wide and 8 levels (not 8 copies, one per
// level). A host lists its pairs in three groups: those it computes from level 0 up to some last
// level, by that level descending; those from some first level to the last, by the first
// ascending; and the few others with their levels. At level t the first two groups' pairs are a
// leading range each, whose lengths the host keeps per level.
class WaveSchedule {
public:
    WaveSchedule(const StripScene& s, int levels) : levels_(levels) {
        if (levels < 1 || levels > 255 || s.width < 2 * levels + 1) {
            std::fprintf(stderr, "WaveSchedule: waves of 1 to 255 steps, in strips at least 2 steps + 1 rows wide; got %d steps, %d rows\n",
                         levels, s.width);
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
        // Each pair's current run of levels in one host, closed when the pair moves to another.
        std::vector<Run> open(s.pairs.size(), Run{none, 0, 0, 0}), runs;
        const auto compute = [&](std::uint32_t host, std::uint32_t id, int t) {
            Run& r = open[id];
            if (r.host == host && r.last + 1 == t) return void(++r.last);
            if (r.host != none) runs.push_back(r);
            r = {host, id, static_cast<std::uint8_t>(t), static_cast<std::uint8_t>(t)};
        };
        std::vector<std::uint32_t> step(s.n, 0);
        forEachRegion(s, [&](std::uint32_t host, int a, int b, int across, int t) {
            forEachRun(s, a, b, across, [&](std::size_t begin, std::size_t end) {
                std::fill(step.begin() + static_cast<std::ptrdiff_t>(begin), step.begin() + static_cast<std::ptrdiff_t>(end), advancing);
            });
            forEachRun(s, a, b, across, [&](std::size_t begin, std::size_t end) {
                for (auto i = static_cast<std::uint32_t>(begin); i < end; ++i)
                    for (std::uint32_t e = first[i]; e < first[i + 1]; ++e) {
                        const std::uint32_t j = partner[e];
                        if (step[j] == advancing ? j < i : step[j] != static_cast<std::uint32_t>(t)) {
                            if (step[j] != advancing && step[j] != static_cast<std::uint32_t>(t) + 1) {
                                std::fprintf(stderr, "WaveSchedule: particle %u at step %u when %u advances from step %d\n",
                                             j, step[j], i, t);
                                std::exit(1);
                            }
                            continue;  // computed already: by this region, or by the one that advanced j
                        }
                        compute(host, pairOf[e], t);
                    }
            });
            forEachRun(s, a, b, across, [&](std::size_t begin, std::size_t end) {
                std::fill(step.begin() + static_cast<std::ptrdiff_t>(begin), step.begin() + static_cast<std::ptrdiff_t>(end),
                          static_cast<std::uint32_t>(t) + 1);
            });
        });
        for (const Run& r : open)
            if (r.host != none) runs.push_back(r);
        store(s, runs);
    }

    int levels() const { return levels_; }
    // Bytes of the schedule per particle of the scene.
    double bytesPerParticle(const StripScene& s) const {
        return static_cast<double>(pairs_.size() * (sizeof(Pair) + sizeof(std::uint32_t)) + counts_.size() * sizeof(std::uint32_t) +
                                   hosts_.size() * sizeof(Host) + levelsOfOthers_.size() * 2) / static_cast<double>(s.n);
    }

    // Advances every particle by levels() steps.
    template <class Data>
    void advance(const StripScene& s, Data& data, std::vector<History>& history) const {
        forEachRegion(s, [&](std::uint32_t host, int a, int b, int across, int t) {
            const Host& h = hosts_[host];
            const std::uint32_t* count = &counts_[2 * (static_cast<std::size_t>(host) * levels_ + t)];
            for (std::uint32_t e = h.fromStart; e < h.fromStart + count[0]; ++e) pairForce(pairs_[e], s.side, history[historyOf_[e]], data);
            for (std::uint32_t e = h.toEnd; e < h.toEnd + count[1]; ++e) pairForce(pairs_[e], s.side, history[historyOf_[e]], data);
            for (std::uint32_t e = h.others; e < h.end; ++e) {
                const std::uint8_t* l = &levelsOfOthers_[2 * (e - h.others + h.othersAt)];
                if (l[0] <= t && t <= l[1]) pairForce(pairs_[e], s.side, history[historyOf_[e]], data);
            }
            forEachRun(s, a, b, across, [&](std::size_t begin, std::size_t end) { data.integrate(begin, end); });
        });
    }

private:
    struct Run {  // a pair computed by one host at levels first .. last
        std::uint32_t host, pair;
        std::uint8_t first, last;
    };
    struct Host {  // its pairs: [fromStart, toEnd), [toEnd, others), [others, end)
        std::uint32_t fromStart, toEnd, others, end, othersAt;
    };
    static constexpr std::uint32_t advancing = 0xffffffffu, none = 0xffffffffu;

    // Calls visit(host, row a, first column b, columns, level t) for every region in turn.
    template <class Visit>
    void forEachRegion(const StripScene& s, Visit visit) const {
        const int side = s.side;
        for (int phase = 0; phase < 4; ++phase) {
            const bool xSeam = phase & 1, ySeam = phase & 2;
            for (int q = 0; q < s.strips; ++q)
                for (int wave = 0; wave <= 2 * side + 2 * levels_; ++wave)
                    for (int t = 0; t < levels_; ++t) {
                        const int u = wave - t;  // the row along x, unwrapped across the seam
                        if (xSeam ? u < side - 1 - t || u > side + t : u < t + 1 || u > side - 2 - t) continue;
                        const int b = ySeam ? (q + 1) * s.width - 1 - t : q * s.width + t + 1;
                        const int across = ySeam ? 2 * t + 2 : s.width - 2 - 2 * t;
                        const auto host = static_cast<std::uint32_t>((phase * s.strips + q) * side + u % side);
                        visit(host, u % side, b, across, t);
                    }
        }
    }

    // The runs as the hosts' three groups of pairs, with the lengths of the first two per level.
    void store(const StripScene& s, std::vector<Run>& runs) {
        const int last = levels_ - 1;
        const auto group = [last](const Run& r) { return r.first == 0 ? 0 : r.last == last ? 1 : 2; };
        std::sort(runs.begin(), runs.end(), [&](const Run& x, const Run& y) {
            if (x.host != y.host) return x.host < y.host;
            if (group(x) != group(y)) return group(x) < group(y);
            if (group(x) == 0 && x.last != y.last) return x.last > y.last;
            if (group(x) == 1 && x.first != y.first) return x.first < y.first;
            return x.pair < y.pair;
        });
        const std::size_t hosts = static_cast<std::size_t>(4 * s.strips) * s.side;
        hosts_.assign(hosts, Host{});
        counts_.assign(2 * hosts * levels_, 0);
        std::size_t r = 0;
        for (std::uint32_t h = 0; h < hosts; ++h) {
            Host& host = hosts_[h];
            host.fromStart = static_cast<std::uint32_t>(pairs_.size());
            for (int g = 0; g < 3; ++g) {
                if (g == 1) host.toEnd = static_cast<std::uint32_t>(pairs_.size());
                if (g == 2) host.others = static_cast<std::uint32_t>(pairs_.size()), host.othersAt = static_cast<std::uint32_t>(levelsOfOthers_.size() / 2);
                for (; r < runs.size() && runs[r].host == h && group(runs[r]) == g; ++r) {
                    pairs_.push_back(s.pairs[runs[r].pair]);
                    historyOf_.push_back(runs[r].pair);
                    for (int t = runs[r].first; t <= runs[r].last && g < 2; ++t) ++counts_[2 * (h * static_cast<std::size_t>(levels_) + t) + g];
                    if (g == 2) levelsOfOthers_.insert(levelsOfOthers_.end(), {runs[r].first, runs[r].last});
                }
            }
            host.end = static_cast<std::uint32_t>(pairs_.size());
        }
    }

    int levels_;
    std::vector<Pair> pairs_;                   // the pairs of each host, in its three groups
    std::vector<std::uint32_t> historyOf_;      // their places in the history
    std::vector<Host> hosts_;                   // by (phase, strip, row)
    std::vector<std::uint32_t> counts_;         // per host and level: the first two groups' pairs computed
    std::vector<std::uint8_t> levelsOfOthers_;  // the third group's first and last levels
};

}  // namespace
}  // namespace layoutModel

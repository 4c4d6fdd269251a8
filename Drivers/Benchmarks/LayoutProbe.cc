// A model of the step's memory traffic, to tell which data layout could keep the time per
// particle-step flat from 10^3 to 10^6 particles on the machine at hand (issue 3's goal;
// Documentation/CacheCliff.md). Not Talus's code: a few dozen lines of
// force loop and integration, so that layouts can be swapped in an afternoon, not in a rewrite.
//
//   LayoutProbe [largest number of particles, default 1000000: 3000, 12000, 108000, 972000]
//               [particle-steps per run, default 3000000]
//               [steps per wave, default 8] [strip width, default 32]
//
// The scene: spheres of radius 0.5 on a jittered cubic lattice of spacing 1 (+-0.1), 12 layers
// deep and periodic sideways (a chute bed), in Morton order as Talus orders its particles; every
// pair closer than 1.25 is listed once (3 per particle, 1.4 of them touching), with a 32-byte
// history each. A step: the pair forces (a linear spring-dashpot with a tangential spring, about
// the arithmetic of Talus's contact), then the kick and drift of every particle, with a time step
// so small that the contacts stay as they are. Each row times four layouts of the same work:
//   arrays   the particle data in separate arrays (position, velocity, spin, force, torque,
//            radius, inverse mass, inverse inertia), as Talus's ParticleStore;
//   records  the same data in two records per particle (position, radius, velocity, inverse
//            mass, spin and inverse inertia: 96 bytes; force and torque: 48 bytes);
// each with every pair's partner after i in the particle order (as Talus listed them at first)
// or before it (as it does now), and with the integration as its own pass or fused into the
// force loop block by block (a block of 128 particles is integrated as soon as its forces are
// complete: with partners after i, once the block's own pairs are done).
// Two more columns time the same bed ordered in strips (StripWave.h): records, one step per pass
// over all particles, and records advanced k steps at a time in waves along the strips (time
// skewing; k and the strip width are the third and fourth arguments; a bed narrower than the
// strips is one strip, with k as large as its width allows). The waves' velocities, spins and
// springs after 2 k steps must equal those of 2 k single steps to round-off, or the program stops.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "LayoutModel.h"
#include "StripWave.h"
#include "WholeArgument.h"

namespace {

using namespace layoutModel;

using Clock = std::chrono::steady_clock;

struct Scene {
    std::size_t n = 0;
    double side = 0;                       // periodic length along x and y
    std::vector<double> x;                 // 3 n, in Morton order
    std::vector<Pair> pairs;               // grouped by i
    std::vector<std::uint32_t> firstPair;  // pairs of i: [firstPair[i], firstPair[i + 1])
    double touching = 0;                   // pairs closer than 1, per particle
};

std::uint64_t spreadBits(std::uint64_t v) {
    std::uint64_t spread = 0;
    for (int b = 0; b < 21; ++b) spread |= ((v >> b) & 1) << (3 * b);
    return spread;
}

Scene makeScene(std::size_t target, bool partnerBefore) {
    constexpr int layers = 12;
    const int side = std::max(4, static_cast<int>(std::lround(std::sqrt(static_cast<double>(target) / layers))));
    // Each site's slot: its rank in the Morton order of (a, b, c).
    const auto cell = [&](int a, int b, int c) { return (static_cast<std::size_t>(a) * side + b) * layers + c; };
    std::vector<std::uint64_t> keyOf(static_cast<std::size_t>(side) * side * layers);
    for (int a = 0; a < side; ++a)
        for (int b = 0; b < side; ++b)
            for (int c = 0; c < layers; ++c) keyOf[cell(a, b, c)] = spreadBits(a) | spreadBits(b) << 1 | spreadBits(c) << 2;
    std::vector<std::uint32_t> byKey(keyOf.size()), slot(keyOf.size());
    for (std::uint32_t k = 0; k < byKey.size(); ++k) byKey[k] = k;
    std::sort(byKey.begin(), byKey.end(), [&](std::uint32_t p, std::uint32_t q) { return keyOf[p] < keyOf[q]; });
    for (std::uint32_t k = 0; k < byKey.size(); ++k) slot[byKey[k]] = k;
    LatticeBed bed = makeLatticeBed(side, layers, [&](int a, int b, int c) { return slot[cell(a, b, c)]; }, partnerBefore);
    Scene s;
    s.n = bed.n, s.side = side, s.x = std::move(bed.x), s.pairs = std::move(bed.pairs), s.touching = bed.touching;
    s.firstPair.assign(s.n + 1, 0);
    for (const Pair& pair : s.pairs) ++s.firstPair[pair.i + 1];
    for (std::size_t k = 0; k < s.n; ++k) s.firstPair[k + 1] += s.firstPair[k];
    return s;
}

// One step: the forces of all pairs in the order listed, then the kick and drift of all particles.
template <class Data>
void singleStep(const std::vector<Pair>& pairs, double side, std::vector<History>& history, Data& data, std::size_t n) {
    for (std::size_t k = 0; k < pairs.size(); ++k) pairForce(pairs[k], side, history[k], data);
    data.integrate(0, n);
}

// Nanoseconds per particle-step of n particles: the fastest of three runs of run(), which
// advances them by `steps` steps.
template <class Run>
double fastestOfThree(std::size_t n, int steps, Run run) {
    double fastest = INFINITY;
    for (int round = 0; round < 3; ++round) {
        const Clock::time_point start = Clock::now();
        run();
        fastest = std::min(fastest, std::chrono::duration<double>(Clock::now() - start).count());
    }
    return fastest / steps / static_cast<double>(n) * 1e9;
}

template <class Data>
double timeSteps(const Scene& s, bool fused, int steps) {
    Data data(s);
    std::vector<History> history(s.pairs.size(), History{{0, 0, 0}, 0});
    return fastestOfThree(s.n, steps, [&] {
        for (int step = 0; step < steps; ++step) {
            if (!fused) {
                singleStep(s.pairs, s.side, history, data, s.n);
                continue;
            }
            constexpr std::size_t block = 128;
            for (std::size_t begin = 0; begin < s.n; begin += block) {
                const std::size_t end = std::min(s.n, begin + block);
                for (std::size_t k = s.firstPair[begin]; k < s.firstPair[end]; ++k)
                    pairForce(s.pairs[k], s.side, history[k], data);
                data.integrate(begin, end);
            }
        }
    });
}

// The same for the bed in strips (records): one step per pass, or (waves) k steps at a time.
template <bool waves>
double timeStrips(const StripScene& s, const WaveSchedule& wave, int steps) {
    Records data(s);
    std::vector<History> history(s.pairs.size(), History{{0, 0, 0}, 0});
    steps = (steps + wave.levels() - 1) / wave.levels() * wave.levels();
    return fastestOfThree(s.n, steps, [&] {
        if constexpr (waves)
            for (int w = 0; w < steps / wave.levels(); ++w) wave.advance(s, data, history);
        else
            for (int step = 0; step < steps; ++step) singleStep(s.pairs, s.side, history, data, s.n);
    });
}

// The largest difference between two waves and 2 k single steps from the same start, in the
// velocities, spins and springs, relative to the largest of each.
double waveDeviation(const StripScene& s, const WaveSchedule& wave) {
    Records single(s), waved(s);
    std::vector<History> singleHistory(s.pairs.size(), History{{0, 0, 0}, 0}), wavedHistory = singleHistory;
    for (int step = 0; step < 2 * wave.levels(); ++step) singleStep(s.pairs, s.side, singleHistory, single, s.n);
    for (int w = 0; w < 2; ++w) wave.advance(s, waved, wavedHistory);
    double largest[3] = {}, difference[3] = {};
    const auto compare = [&](int kind, const double* a, const double* b) {
        for (int e = 0; e < 3; ++e)
            largest[kind] = std::max(largest[kind], std::fabs(a[e])), difference[kind] = std::max(difference[kind], std::fabs(a[e] - b[e]));
    };
    for (std::uint32_t i = 0; i < s.n; ++i) compare(0, single.v(i), waved.v(i)), compare(1, single.w(i), waved.w(i));
    for (std::size_t k = 0; k < s.pairs.size(); ++k) compare(2, singleHistory[k].spring, wavedHistory[k].spring);
    double worst = 0;
    for (int kind = 0; kind < 3; ++kind) worst = std::max(worst, largest[kind] > 0 ? difference[kind] / largest[kind] : difference[kind]);
    return worst;
}

}  // namespace

int main(int argc, char** argv) {
    const auto largest = static_cast<std::size_t>(wholeArgument(argc, argv, 1, 1000000, 1000, 20000000, "LayoutProbe", "the largest number of particles"));
    const auto perRun = static_cast<std::size_t>(wholeArgument(argc, argv, 2, 3000000, 1000, 1000000000, "LayoutProbe", "the particle-steps per run"));
    const int levels = static_cast<int>(wholeArgument(argc, argv, 3, 8, 1, 100, "LayoutProbe", "the steps per wave"));
    const int stripWidth = static_cast<int>(wholeArgument(argc, argv, 4, 32, 2 * levels + 1, 1000, "LayoutProbe", "the strip width (at least 2 steps per wave + 1)"));
    std::printf("ns per particle-step (the fastest of 3 runs of about %zu particle-steps); in brackets: against the first row\n\n", perRun);
    std::printf("| particles | pairs, touching per particle | arrays, partner after | fused | records, partner after | fused | arrays, partner before | records, partner before "
                "| in strips: particles (strip width, steps per wave) | records, a step per pass | in waves | the wave's schedule, bytes per particle | its deviation from single steps |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    double first[8] = {};
    for (const std::size_t target : {3000, 12000, 108000, 972000, 8748000}) {  // as Drivers/Benchmarks/scaling.sh, then 9x
        if (target > largest) break;
        const Scene after = makeScene(target, false), before = makeScene(target, true);
        const int steps = static_cast<int>(std::max<std::size_t>(3, perRun / after.n));
        const double t6[6] = {timeSteps<Arrays>(after, false, steps), timeSteps<Arrays>(after, true, steps),
                             timeSteps<Records>(after, false, steps), timeSteps<Records>(after, true, steps),
                             timeSteps<Arrays>(before, false, steps), timeSteps<Records>(before, false, steps)};
        // A bed narrower than the strips is one strip, its waves as long as that width allows.
        const int width = std::min(stripWidth, static_cast<int>(std::lround(std::sqrt(static_cast<double>(target) / StripScene::layers))));
        const StripScene strips = makeStripScene(target, width);
        const WaveSchedule wave(strips, std::min(levels, (width - 1) / 2));
        const double deviation = waveDeviation(strips, wave);
        const int stripSteps = static_cast<int>(std::max<std::size_t>(3, perRun / strips.n));
        const double t[8] = {t6[0], t6[1], t6[2], t6[3], t6[4], t6[5], timeStrips<false>(strips, wave, stripSteps),
                             timeStrips<true>(strips, wave, stripSteps)};
        if (first[0] == 0) std::copy(t, t + 8, first);
        std::printf("| %zu | %.2f, %.2f |", after.n, static_cast<double>(after.pairs.size()) / static_cast<double>(after.n),
                    after.touching);
        for (int c = 0; c < 6; ++c) std::printf(" %.1f (%.2fx) |", t[c], t[c] / first[c]);
        std::printf(" %zu (%d, %d) |", strips.n, width, wave.levels());
        for (int c = 6; c < 8; ++c) std::printf(" %.1f (%.2fx) |", t[c], t[c] / first[c]);
        std::printf(" %.0f | %.1e |\n", wave.bytesPerParticle(strips), deviation);
        if (!(deviation < 1e-12)) {
            std::fprintf(stderr, "LayoutProbe: the wave of %d steps differs from single steps by %.2e (relative): its schedule is wrong\n",
                         wave.levels(), deviation);
            return 1;
        }
        std::fflush(stdout);
    }
    std::printf("LayoutProbe: done\n");
}

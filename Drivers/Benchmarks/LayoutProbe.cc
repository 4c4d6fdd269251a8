// A model of the step's memory traffic, to tell which data layout could keep the time per
// particle-step flat from 10^3 to 10^6 particles on the machine at hand (issue 3's goal;
// Documentation/Performance.md "Scaling and memory"). Not Talus's code: a few dozen lines of
// force loop and integration, so that layouts can be swapped in an afternoon, not in a rewrite.
//
//   LayoutProbe [largest number of particles, default 1000000: 3000, 12000, 108000, 972000]
//               [particle-steps per run, default 3000000]
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
// each with every pair's partner after i in the particle order (as Talus listed them until
// 2026-12-03) or before it (since), and with the integration as its own pass or fused into the
// force loop block by block (a block of 128 particles is integrated as soon as its forces are
// complete: with partners after i, once the block's own pairs are done).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "WholeArgument.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Pair {
    std::uint32_t i, j;
};
struct History {
    double spring[3], lastNormalForce;
};

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

// The separation of i and j, nearest image along x and y.
void separation(const double* xi, const double* xj, double side, double d[3]) {
    for (int e = 0; e < 3; ++e) d[e] = xi[e] - xj[e];
    for (int e = 0; e < 2; ++e) d[e] -= d[e] > 0.5 * side ? side : d[e] < -0.5 * side ? -side : 0;
}

Scene makeScene(std::size_t target, bool partnerBefore) {
    constexpr int layers = 12;
    Scene s;
    const int side = std::max(4, static_cast<int>(std::lround(std::sqrt(static_cast<double>(target) / layers))));
    s.side = side;
    struct Site {
        std::uint64_t key;
        int a, b, c;
        double x[3];
    };
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    std::vector<Site> sites;
    for (int a = 0; a < side; ++a)
        for (int b = 0; b < side; ++b)
            for (int c = 0; c < layers; ++c)
                sites.push_back({spreadBits(a) | spreadBits(b) << 1 | spreadBits(c) << 2, a, b, c,
                                 {a + 0.5 + jitter(random), b + 0.5 + jitter(random), c + 0.5 + jitter(random)}});
    std::sort(sites.begin(), sites.end(), [](const Site& p, const Site& q) { return p.key < q.key; });
    s.n = sites.size();
    const auto cell = [&](int a, int b, int c) { return (static_cast<std::size_t>(a) * side + b) * layers + c; };
    std::vector<std::uint32_t> slot(s.n);
    s.x.resize(3 * s.n);
    for (std::size_t k = 0; k < s.n; ++k) {
        slot[cell(sites[k].a, sites[k].b, sites[k].c)] = static_cast<std::uint32_t>(k);
        std::copy(sites[k].x, sites[k].x + 3, &s.x[3 * k]);
    }
    constexpr double listed = 1.25;
    std::size_t touching = 0;
    for (std::size_t k = 0; k < s.n; ++k)
        for (int da = -1; da <= 1; ++da)
            for (int db = -1; db <= 1; ++db)
                for (int dc = -1; dc <= 1; ++dc) {
                    const int c = sites[k].c + dc;
                    if (c < 0 || c >= layers) continue;
                    const std::uint32_t m = slot[cell((sites[k].a + da + side) % side, (sites[k].b + db + side) % side, c)];
                    if (partnerBefore ? m >= k : m <= k) continue;  // each pair once
                    double d[3];
                    separation(&s.x[3 * k], &s.x[3 * m], s.side, d);
                    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                    if (r2 < listed * listed) s.pairs.push_back({static_cast<std::uint32_t>(k), m});
                    touching += r2 < 1;
                }
    s.touching = static_cast<double>(touching) / static_cast<double>(s.n);
    s.firstPair.assign(s.n + 1, 0);
    for (const Pair& p : s.pairs) ++s.firstPair[p.i + 1];
    for (std::size_t k = 0; k < s.n; ++k) s.firstPair[k + 1] += s.firstPair[k];
    return s;
}

constexpr double stiffness = 2e5, normalDamping = 50, tangentialDamping = 10, dt = 1e-7;

// The force of pair (i, j) on both, through an accessor of the layout.
template <class Data>
inline void pairForce(const Pair& pair, double side, History& h, Data& p) {
    const std::uint32_t i = pair.i, j = pair.j;
    double d[3];
    separation(p.x(i), p.x(j), side, d);
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], ri = p.radius(i), rj = p.radius(j);
    if (r2 >= (ri + rj) * (ri + rj)) {
        h.lastNormalForce = 0;
        return;
    }
    const double r = std::sqrt(r2), inverse = 1 / r, n[3] = {d[0] * inverse, d[1] * inverse, d[2] * inverse};
    const double *vi = p.v(i), *vj = p.v(j), *wi = p.w(i), *wj = p.w(j);
    double v[3], spin[3];
    for (int e = 0; e < 3; ++e) v[e] = vi[e] - vj[e], spin[e] = ri * wi[e] + rj * wj[e];
    const double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    const double turn[3] = {spin[1] * n[2] - spin[2] * n[1], spin[2] * n[0] - spin[0] * n[2], spin[0] * n[1] - spin[1] * n[0]};
    const double reducedMass = 1 / (p.invMass(i) + p.invMass(j));
    const double fn = stiffness * (ri + rj - r) - normalDamping * reducedMass * vn;
    double f[3];
    for (int e = 0; e < 3; ++e) {
        const double vt = v[e] - vn * n[e] - turn[e];
        h.spring[e] += vt * dt;
        f[e] = fn * n[e] - tangentialDamping * reducedMass * vt - 0.1 * stiffness * h.spring[e];
    }
    h.lastNormalForce = fn;
    const double arm[3] = {n[1] * f[2] - n[2] * f[1], n[2] * f[0] - n[0] * f[2], n[0] * f[1] - n[1] * f[0]};
    double *fi = p.f(i), *fj = p.f(j), *ti = p.t(i), *tj = p.t(j);
    for (int e = 0; e < 3; ++e) fi[e] += f[e], fj[e] -= f[e], ti[e] -= ri * arm[e], tj[e] -= rj * arm[e];
}

struct Arrays {
    std::vector<double> position, velocity, spin, force, torque, radii, inverseMass, inverseInertia;
    explicit Arrays(const Scene& s)
        : position(s.x), velocity(3 * s.n, 0.01), spin(3 * s.n, 0), force(3 * s.n, 0), torque(3 * s.n, 0),
          radii(s.n, 0.5), inverseMass(s.n, 1.9), inverseInertia(s.n, 19) {}
    const double* x(std::uint32_t i) const { return &position[3 * i]; }
    const double* v(std::uint32_t i) const { return &velocity[3 * i]; }
    const double* w(std::uint32_t i) const { return &spin[3 * i]; }
    double* f(std::uint32_t i) { return &force[3 * i]; }
    double* t(std::uint32_t i) { return &torque[3 * i]; }
    double radius(std::uint32_t i) const { return radii[i]; }
    double invMass(std::uint32_t i) const { return inverseMass[i]; }
    void integrate(std::size_t begin, std::size_t end) {
        // (Plain restrict pointers, as Talus's integration: over the vectors the compiler must
        // assume that the stores may move their data and checks it for every block.)
        double* __restrict x = position.data();
        double* __restrict v = velocity.data();
        double* __restrict w = spin.data();
        double* __restrict f = force.data();
        double* __restrict t = torque.data();
        const double* __restrict m = inverseMass.data();
        const double* __restrict I = inverseInertia.data();
        for (std::size_t i = begin; i < end; ++i)
            for (std::size_t c = 3 * i; c < 3 * i + 3; ++c) {
                v[c] += dt * m[i] * f[c];
                x[c] += dt * v[c];
                w[c] += dt * I[i] * t[c];
                f[c] = t[c] = 0;
            }
    }
};

struct Records {
    struct alignas(32) Motion {
        double x[3], radius, v[3], invMass, w[3], invInertia;
    };
    struct alignas(16) Load {
        double f[3], t[3];
    };
    std::vector<Motion> motion;
    std::vector<Load> load;
    explicit Records(const Scene& s) : motion(s.n), load(s.n, Load{{0, 0, 0}, {0, 0, 0}}) {
        for (std::size_t i = 0; i < s.n; ++i)
            motion[i] = {{s.x[3 * i], s.x[3 * i + 1], s.x[3 * i + 2]}, 0.5, {0.01, 0.01, 0.01}, 1.9, {0, 0, 0}, 19};
    }
    const double* x(std::uint32_t i) const { return motion[i].x; }
    const double* v(std::uint32_t i) const { return motion[i].v; }
    const double* w(std::uint32_t i) const { return motion[i].w; }
    double* f(std::uint32_t i) { return load[i].f; }
    double* t(std::uint32_t i) { return load[i].t; }
    double radius(std::uint32_t i) const { return motion[i].radius; }
    double invMass(std::uint32_t i) const { return motion[i].invMass; }
    void integrate(std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            Motion& m = motion[i];
            Load& l = load[i];
            for (int c = 0; c < 3; ++c) {
                m.v[c] += dt * m.invMass * l.f[c];
                m.x[c] += dt * m.v[c];
                m.w[c] += dt * m.invInertia * l.t[c];
                l.f[c] = l.t[c] = 0;
            }
        }
    }
};

// Nanoseconds per particle-step, the fastest of three runs of `steps` steps.
template <class Data>
double timeSteps(const Scene& s, bool fused, int steps) {
    Data data(s);
    std::vector<History> history(s.pairs.size(), History{{0, 0, 0}, 0});
    double fastest = INFINITY;
    for (int run = 0; run < 3; ++run) {
        const Clock::time_point start = Clock::now();
        for (int step = 0; step < steps; ++step) {
            if (!fused) {
                for (std::size_t k = 0; k < s.pairs.size(); ++k) pairForce(s.pairs[k], s.side, history[k], data);
                data.integrate(0, s.n);
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
        fastest = std::min(fastest, std::chrono::duration<double>(Clock::now() - start).count());
    }
    return fastest / steps / static_cast<double>(s.n) * 1e9;
}

}  // namespace

int main(int argc, char** argv) {
    const auto largest = static_cast<std::size_t>(wholeArgument(argc, argv, 1, 1000000, 1000, 20000000, "LayoutProbe", "the largest number of particles"));
    const auto perRun = static_cast<std::size_t>(wholeArgument(argc, argv, 2, 3000000, 1000, 1000000000, "LayoutProbe", "the particle-steps per run"));
    std::printf("ns per particle-step (the fastest of 3 runs of about %zu particle-steps); in brackets: against the first row\n\n", perRun);
    std::printf("| particles | pairs, touching per particle | arrays, partner after | fused | records, partner after | fused | arrays, partner before | records, partner before |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    double first[6] = {};
    for (const std::size_t target : {3000, 12000, 108000, 972000, 8748000}) {  // as Drivers/Benchmarks/scaling.sh, then 9x
        if (target > largest) break;
        const Scene after = makeScene(target, false), before = makeScene(target, true);
        const int steps = static_cast<int>(std::max<std::size_t>(3, perRun / after.n));
        const double t[6] = {timeSteps<Arrays>(after, false, steps), timeSteps<Arrays>(after, true, steps),
                             timeSteps<Records>(after, false, steps), timeSteps<Records>(after, true, steps),
                             timeSteps<Arrays>(before, false, steps), timeSteps<Records>(before, false, steps)};
        if (first[0] == 0) std::copy(t, t + 6, first);
        std::printf("| %zu | %.2f, %.2f |", after.n, static_cast<double>(after.pairs.size()) / static_cast<double>(after.n),
                    after.touching);
        for (int c = 0; c < 6; ++c) std::printf(" %.1f (%.2fx) |", t[c], t[c] / first[c]);
        std::printf("\n");
        std::fflush(stdout);
    }
    std::printf("LayoutProbe: done\n");
}

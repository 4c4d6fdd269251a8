// The model of LayoutProbe (Drivers/Benchmarks/LayoutProbe.cc): its chute bed, a pair of spheres,
// its contact history and force, and the particle data in the two layouts it compares. Any scene
// with the particle count `n` and positions `x` (3 n) can be loaded into either layout.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

// Internal to the one program that includes it, as the compiler inlines such functions more
// readily (the model's timings depend on it).
namespace layoutModel {
namespace {

struct Pair {
    std::uint32_t i, j;
};
struct History {
    double spring[3], lastNormalForce;
};

// The separation of i and j, nearest image along x and y.
inline void separation(const double* xi, const double* xj, double side, double d[3]) {
    for (int e = 0; e < 3; ++e) d[e] = xi[e] - xj[e];
    for (int e = 0; e < 2; ++e) d[e] -= d[e] > 0.5 * side ? side : d[e] < -0.5 * side ? -side : 0;
}

// The model's chute bed: spheres of radius 0.5 on a jittered cubic lattice of spacing 1 (+-0.1),
// `layers` deep and `side` sites along x and y (periodic), site (a, b, c) at slot slotOf(a, b, c).
// Every pair closer than 1.25 is listed once, grouped by the slot that lists it, with its
// partner after it in the slot order (or before it: partnerBefore).
struct LatticeBed {
    std::size_t n = 0;
    std::vector<double> x;    // 3 n
    std::vector<Pair> pairs;  // grouped by i
    double touching = 0;      // pairs closer than 1, per particle
};

template <class SlotOf>
LatticeBed makeLatticeBed(int side, int layers, SlotOf slotOf, bool partnerBefore) {
    LatticeBed bed;
    bed.n = static_cast<std::size_t>(side) * side * layers;
    bed.x.resize(3 * bed.n);
    std::vector<int> site(3 * bed.n);  // (a, b, c) of each slot
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    for (int a = 0; a < side; ++a)
        for (int b = 0; b < side; ++b)
            for (int c = 0; c < layers; ++c) {
                const std::size_t k = slotOf(a, b, c);
                double* p = &bed.x[3 * k];
                p[0] = a + 0.5 + jitter(random), p[1] = b + 0.5 + jitter(random), p[2] = c + 0.5 + jitter(random);
                site[3 * k] = a, site[3 * k + 1] = b, site[3 * k + 2] = c;
            }
    constexpr double listed = 1.25;
    std::size_t touching = 0;
    for (std::size_t k = 0; k < bed.n; ++k)
        for (int da = -1; da <= 1; ++da)
            for (int db = -1; db <= 1; ++db)
                for (int dc = -1; dc <= 1; ++dc) {
                    const int c = site[3 * k + 2] + dc;
                    if (c < 0 || c >= layers) continue;
                    const std::size_t m = slotOf((site[3 * k] + da + side) % side, (site[3 * k + 1] + db + side) % side, c);
                    if (partnerBefore ? m >= k : m <= k) continue;  // each pair once
                    double d[3];
                    separation(&bed.x[3 * k], &bed.x[3 * m], side, d);
                    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                    if (r2 < listed * listed) bed.pairs.push_back({static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(m)});
                    touching += r2 < 1;
                }
    bed.touching = static_cast<double>(touching) / static_cast<double>(bed.n);
    return bed;
}

constexpr double stiffness = 2e5, normalDamping = 50, tangentialDamping = 10, dt = 1e-7;

// The force of pair (i, j) on both, through an accessor of the layout. Always inlined: the
// variants call it from different loops, and a call in one of them would time the call.
template <class Data>
[[gnu::always_inline]] inline void pairForce(const Pair& pair, double side, History& h, Data& p) {
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
    template <class Scene>
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
    template <class Scene>
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

}  // namespace
}  // namespace layoutModel

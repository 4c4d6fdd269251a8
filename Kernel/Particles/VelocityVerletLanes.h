// The passes of Particles/VelocityVerlet.h and Domain::wrap in the lanes of one form
// (Math/LaneKernels.h): v += (dt/2) F/m, w += (dt/2) T/I, x += dt v for the mobile particles.
//
// The loops run over the coordinates as plain arrays. Written over std::vector<Vec3>, the
// compiler has to assume that every store into a particle's coordinates may change the vectors'
// own data pointers, reloads them for every particle and keeps the loops scalar: they took 15%
// of a dilute chute flow's step (Documentation/Performance.md). Here they vectorise, with the
// same arithmetic per particle as before (the results are the same to the bit).
//
// In the forms with lanes they take W particles at a time (eight with AVX-512, four with AVX2:
// Math/Lanes.h), each lane loop written once for any width; with AVX-512 2.5x faster than GCC's
// vectorisation of the loops below, which is left for the last few particles (and is the whole of
// the scalar form).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#include "Boundaries/Domain.h"
#include "Math/LaneNamespace.h"
#include "Math/Lanes.h"
#include "Particles/ParticleStore.h"

namespace talus::TALUS_LANES {

namespace detail {
// x unless keep (all bits set), then `moved`. The fixed particles keep x by this bit mask: with a
// branch or a conditional expression GCC 12 does not vectorise the loop, and with a zero step
// instead x + 0 r would turn -0 into +0.
inline double unlessKept(double x, double moved, std::uint64_t keep) {
    return std::bit_cast<double>((std::bit_cast<std::uint64_t>(x) & keep) | (std::bit_cast<std::uint64_t>(moved) & ~keep));
}

// x[c] += step * scale[i] * rate[c] for the three coordinates c of every particle i in [0, n)
// that is not fixed.
inline void advanceMobile(double* __restrict x, const double* __restrict rate, const double* __restrict scale,
                          const std::uint8_t* __restrict fixed, std::size_t n, double step) {
    std::size_t i = 0;
#if TALUS_LANES_WIDTH > 1
    using L = lanes::ParticleLanes;
    constexpr std::size_t W = L::width;
    for (; i + W <= n; i += W) {
        const lanes::MobileLanes<L> mobile(fixed + i);
        L factor[3];
        lanes::spread(L::broadcast(step) * L::load(scale + i), factor);
        for (int c = 0; c < 3; ++c) {
            double* xc = x + 3 * i + W * c;
            multiplyAddWhere(mobile.of[c], factor[c], L::load(rate + 3 * i + W * c), L::load(xc)).store(xc);
        }
    }
#endif
    for (; i < n; ++i) {
        const double s = step * scale[i];
        const std::uint64_t keep = fixed[i] ? ~std::uint64_t{0} : 0;
        // (Three statements, not a loop of three: GCC would vectorise that inner loop instead.)
        double* xi = x + 3 * i;
        const double* ri = rate + 3 * i;
        xi[0] = unlessKept(xi[0], lanes::multiplyAdd(s, ri[0], xi[0]), keep);
        xi[1] = unlessKept(xi[1], lanes::multiplyAdd(s, ri[1], xi[1]), keep);
        xi[2] = unlessKept(xi[2], lanes::multiplyAdd(s, ri[2], xi[2]), keep);
    }
}

// The half kick of the velocities and the drift in one pass: v += step F/m as advanceMobile does
// it, then x += dt v (the same results to the bit as a kick pass and a drift pass), the
// velocities read once.
inline void kickAndDriftMobile(double* __restrict x, double* __restrict v, const double* __restrict force,
                               const double* __restrict invMass, const std::uint8_t* __restrict fixed, std::size_t n,
                               double step, double dt) {
    std::size_t i = 0;
#if TALUS_LANES_WIDTH > 1
    using L = lanes::ParticleLanes;
    constexpr std::size_t W = L::width;
    const L drift = L::broadcast(dt);
    for (; i + W <= n; i += W) {
        const lanes::MobileLanes<L> mobile(fixed + i);
        L factor[3];
        lanes::spread(L::broadcast(step) * L::load(invMass + i), factor);
        for (int c = 0; c < 3; ++c) {
            double* vc = v + 3 * i + W * c;
            double* xc = x + 3 * i + W * c;
            const L kicked = multiplyAddWhere(mobile.of[c], factor[c], L::load(force + 3 * i + W * c), L::load(vc));
            kicked.store(vc);
            multiplyAddWhere(mobile.of[c], drift, kicked, L::load(xc)).store(xc);
        }
    }
#endif
    for (; i < n; ++i) {
        const double s = step * invMass[i];
        const std::uint64_t keep = fixed[i] ? ~std::uint64_t{0} : 0;
        double* xi = x + 3 * i;
        double* vi = v + 3 * i;
        const double* fi = force + 3 * i;
        const double v0 = unlessKept(vi[0], lanes::multiplyAdd(s, fi[0], vi[0]), keep),
                     v1 = unlessKept(vi[1], lanes::multiplyAdd(s, fi[1], vi[1]), keep),
                     v2 = unlessKept(vi[2], lanes::multiplyAdd(s, fi[2], vi[2]), keep);
        vi[0] = v0, vi[1] = v1, vi[2] = v2;
        xi[0] = unlessKept(xi[0], lanes::multiplyAdd(dt, v0, xi[0]), keep);
        xi[1] = unlessKept(xi[1], lanes::multiplyAdd(dt, v1, xi[1]), keep);
        xi[2] = unlessKept(xi[2], lanes::multiplyAdd(dt, v2, xi[2]), keep);
    }
}
}  // namespace detail

// The forces a step starts from, before the contacts add theirs: gravity m g on the mobile
// particles, none on the fixed ones; no torques. (All particles, ghosts included.)
inline void startForcesWithGravity(ParticleStore& p, const Vec3& gravity) {
    const std::size_t n = p.size();
    p.force.resize(n);
    p.torque.resize(n);
    if (n == 0) return;
    double* __restrict force = p.force[0].data();
    double* __restrict torque = p.torque[0].data();
    const double* __restrict mass = p.mass.data();
    const std::uint8_t* __restrict fixed = p.fixed.data();
    std::size_t i = 0;
#if TALUS_LANES_WIDTH > 1
    using L = lanes::ParticleLanes;
    constexpr std::size_t W = L::width;
    L g[3];
    lanes::perAxis(gravity.x(), gravity.y(), gravity.z(), g);
    for (; i + W <= n; i += W) {
        const lanes::MobileLanes<L> mobile(fixed + i);
        L weight[3];
        lanes::spread(L::load(mass + i), weight);
        for (int c = 0; c < 3; ++c) {
            multiplyWhere(mobile.of[c], weight[c], g[c]).store(force + 3 * i + W * c);
            L::zero().store(torque + 3 * i + W * c);
        }
    }
#endif
    for (; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            force[3 * i + c] = fixed[i] ? 0.0 : mass[i] * gravity[c];
            torque[3 * i + c] = 0;
        }
    }
}

// The half kick of the mobile particles in slots [first, last): v += (dt/2) F/m, w += (dt/2) T/I.
inline void halfKick(ParticleStore& p, std::size_t first, std::size_t last, double halfStep) {
    if (first >= last) return;
    const std::size_t n = last - first;
    detail::advanceMobile(p.velocity[first].data(), p.force[first].data(), p.invMass.data() + first,
                          p.fixed.data() + first, n, halfStep);
    detail::advanceMobile(p.angularVelocity[first].data(), p.torque[first].data(), p.invInertia.data() + first,
                          p.fixed.data() + first, n, halfStep);
}
// The same among the first n.
inline void halfKick(ParticleStore& p, std::size_t n, double halfStep) { TALUS_LANES::halfKick(p, 0, n, halfStep); }

// The first half kick and the drift of the mobile particles among the first n in one pass over
// the translational data (halfKick then drift, the same to the bit).
inline void halfKickAndDrift(ParticleStore& p, std::size_t n, double halfStep, double dt) {
    if (n == 0) return;
    detail::kickAndDriftMobile(p.position[0].data(), p.velocity[0].data(), p.force[0].data(), p.invMass.data(),
                               p.fixed.data(), n, halfStep, dt);
    detail::advanceMobile(p.angularVelocity[0].data(), p.torque[0].data(), p.invInertia.data(), p.fixed.data(),
                                n, halfStep);
}

// Domain::wrap of the first n of an array of positions. In the lanes, W particles at a time are
// only compared with the box, and the few blocks with a particle outside wrapped one by one;
// otherwise an axis at a time with the box read once (the compiler cannot keep lo and hi in
// registers across stores into a Vec3&).
inline void wrapPositions(const Domain& domain, Vec3* x, std::size_t n) {
    std::size_t first = 0;
#if TALUS_LANES_WIDTH > 1
    using L = lanes::ParticleLanes;
    constexpr std::size_t W = L::width;
    L low[3], high[3];
    const Domain::WrapBounds bounds = domain.wrapBounds();
    lanes::perAxis(bounds.low, low);
    lanes::perAxis(bounds.high, high);
    for (; first + W <= n; first += W) {
        const double* block = x[first].data();
        L::Mask outside{};
        for (int c = 0; c < 3; ++c) {
            const L coordinates = L::load(block + W * c);
            outside = outside | (coordinates >= high[c]) | (coordinates < low[c]);
        }
        if (any(outside)) [[unlikely]]
            for (std::size_t i = first; i < first + W; ++i) domain.wrap(x[i]);
    }
#endif
    for (int a = 0; a < 3; ++a) {
        if (!domain.periodic[a]) continue;
        const double l = domain.lo[a], h = domain.hi[a], L = domain.length(a);
        for (std::size_t i = first; i < n; ++i) Domain::wrapCoordinate(x[i][a], l, h, L);
    }
}

}  // namespace talus::TALUS_LANES

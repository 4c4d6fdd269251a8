// Particles/DriftPass.h in the lanes of one form: compiled once per form (Math/LaneKernels.h).
#include "Particles/DriftPass.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "Contacts/PairSweepLanes.h"
#include "Math/LaneKernels.h"
#include "Math/LaneNamespace.h"
#include "Math/Lanes.h"
#include "Particles/VelocityVerletLanes.h"

namespace talus::TALUS_LANES {

namespace {

constexpr double radiusMargin = sweepRadiusMargin, reachMargin = sweepReachMargin;  // (PairSweep.h)

// |a|^2 with one rounding order, the same in the lanes and the loop.
inline double squaredNorm(double a0, double a1, double a2) {
    return lanes::multiplyAdd(a2, a2, lanes::multiplyAdd(a1, a1, a0 * a0));
}

// PeriodicImage::nearest of one coordinate of a separation.
inline double nearestOf(double raw, const PeriodicImage& image, int c) {
    return raw > image.halfLength(c) ? raw - image.length(c) : raw < -image.halfLength(c) ? raw + image.length(c) : raw;
}

// The running maxima, as bit patterns of non-negative doubles (their order is the values' order,
// and a NaN, all exponent bits set, wins: PairList.cc largestMoves).
struct Maxima {
    std::uint64_t displacement2 = 0, speed2 = 0, coordinate = 0, growth = 0;
    double velocitySum[3] = {0, 0, 0};  // of the mobile particles, for the next step's frame
    std::size_t mobile = 0;
    std::uint64_t positionsBefore = 0, positionsAfter = 0;  // (positionSum, before and after the pass)
};

// One particle, as the separate passes do it (the lanes below do the same for W at a time).
struct OneParticle {
    double* x;
    double* v;
    double* w;
    const double* oldForce;
    double* force;
    double* keptForce;  // Close: the forces kicked with are kept here (previousForce)
    double* torque;
    const double *invMass, *invInertia, *mass, *radius, *reference;
    const std::uint8_t* fixed;
    SweepPoint* points;
    const Domain& domain;
    PeriodicImage image;
    Vec3 gravity, frame;
    double half, dt;

    // Close: first the second half kick of the step before, with the same forces and torques
    // (halfKick's arithmetic), the forces kept.
    template <bool Close>
    void operator()(std::size_t i, Maxima& m) const {
        using detail::unlessKept;
        const std::uint64_t keep = fixed[i] ? ~std::uint64_t{0} : 0;
        double* xi = x + 3 * i;
        double* vi = v + 3 * i;
        double* wi = w + 3 * i;
        const double kick = half * invMass[i], turn = half * invInertia[i];
        for (int c = 0; c < 3; ++c) m.positionsBefore += std::bit_cast<std::uint64_t>(xi[c]);
        for (int c = 0; c < 3; ++c) {
            if constexpr (Close) {
                vi[c] = unlessKept(vi[c], lanes::multiplyAdd(kick, oldForce[3 * i + c], vi[c]), keep);
                wi[c] = unlessKept(wi[c], lanes::multiplyAdd(turn, torque[3 * i + c], wi[c]), keep);
                keptForce[3 * i + c] = oldForce[3 * i + c];
            }
            vi[c] = unlessKept(vi[c], lanes::multiplyAdd(kick, oldForce[3 * i + c], vi[c]), keep);
            xi[c] = unlessKept(xi[c], lanes::multiplyAdd(dt, vi[c], xi[c]), keep);
            wi[c] = unlessKept(wi[c], lanes::multiplyAdd(turn, torque[3 * i + c], wi[c]), keep);
            torque[3 * i + c] = 0;
            force[3 * i + c] = fixed[i] ? 0.0 : mass[i] * gravity[c];
        }
        for (int c = 0; c < 3; ++c) {
            if (domain.periodic[c]) Domain::wrapCoordinate(xi[c], domain.lo[c], domain.hi[c], domain.length(c));
            m.positionsAfter += std::bit_cast<std::uint64_t>(xi[c]);
        }
        double d[3] = {0, 0, 0};
        if (reference)
            for (int c = 0; c < 3; ++c) d[c] = nearestOf(xi[c] - reference[3 * i + c], image, c);
        const double s2 = squaredNorm(vi[0], vi[1], vi[2]);
        m.displacement2 = std::max(m.displacement2, std::bit_cast<std::uint64_t>(squaredNorm(d[0], d[1], d[2])));
        m.speed2 = std::max(m.speed2, std::bit_cast<std::uint64_t>(s2));
        for (int c = 0; c < 3; ++c) m.coordinate = std::max(m.coordinate, std::bit_cast<std::uint64_t>(std::abs(xi[c])));
        if (!fixed[i]) {
            for (int c = 0; c < 3; ++c) m.velocitySum[c] += vi[c];
            ++m.mobile;
        }
        const double relative = std::sqrt(squaredNorm(vi[0] - frame[0], vi[1] - frame[1], vi[2] - frame[2]));
        const double grown = lanes::multiplyAdd(reachMargin * dt, relative, radius[i] * radiusMargin);
        points[i] = {xi[0], xi[1], xi[2], grown};
        m.growth = std::max(m.growth, std::bit_cast<std::uint64_t>(std::max(grown - radius[i], 0.0)));
    }
};

#if TALUS_LANES_WIDTH > 1
// The blocks of W particles of the pass in lanes L (Math/Lanes.h): the kicks, the drift and the
// forces in storage order, the norms and the sweep points per axis; the same operations as
// OneParticle, to the bit. Slots [first, n) while whole blocks are left; returns where it stopped.
template <bool Close, class L>
std::size_t inParticleLanes(const OneParticle& one, const Domain& domain, ParticleStore& p, Maxima& m, std::size_t first,
                            std::size_t n) {
    constexpr std::size_t W = L::width;
    std::size_t i = first;
    // The box as the lanes compare with it, axis by axis: the wrap's bounds (lo and hi along the
    // periodic axes, -inf and +inf along the others: never outside), and the nearest image's
    // lengths and half lengths.
    const Domain::WrapBounds bounds = domain.wrapBounds();
    const double lengths[3] = {one.image.length(0), one.image.length(1), one.image.length(2)};
    const double halves[3] = {one.image.halfLength(0), one.image.halfLength(1), one.image.halfLength(2)};
    const double minusHalves[3] = {-halves[0], -halves[1], -halves[2]};
    L low[3], high[3], length[3], half[3], minusHalf[3], g[3];  // (in storage order)
    lanes::perAxis(bounds.low, low), lanes::perAxis(bounds.high, high);
    lanes::perAxis(lengths, length), lanes::perAxis(halves, half), lanes::perAxis(minusHalves, minusHalf);
    lanes::perAxis(one.gravity.x(), one.gravity.y(), one.gravity.z(), g);
    const L u[3] = {L::broadcast(one.frame.x()), L::broadcast(one.frame.y()), L::broadcast(one.frame.z())};  // (per axis)
    const L drift = L::broadcast(one.dt), halfStep = L::broadcast(one.half), zero = L::zero();
    const L reach = L::broadcast(reachMargin * one.dt), margin = L::broadcast(radiusMargin);
    L displacement2 = zero, speed2 = zero, coordinate = zero, growth = zero;  // (bit patterns)
    L velocitySum[3] = {zero, zero, zero};                                    // (per axis)
    L positionsBefore = zero, positionsAfter = zero;                          // (bit patterns)
    for (; i + W <= n; i += W) {
        const lanes::MobileLanes<L> mobile(one.fixed + i);
        m.mobile += static_cast<std::size_t>(count(mobile.particles));
        L kick[3], turn[3], weight[3];
        lanes::spread(halfStep * L::load(one.invMass + i), kick);
        lanes::spread(halfStep * L::load(one.invInertia + i), turn);
        lanes::spread(L::load(one.mass + i), weight);
        L x[3], v[3];
        for (int c = 0; c < 3; ++c) {
            const std::size_t at = 3 * i + W * c;
            const typename L::Mask moves = mobile.of[c];
            const L f = L::load(one.oldForce + at), t = L::load(one.torque + at);
            v[c] = L::load(one.v + at);
            L w = L::load(one.w + at);
            if constexpr (Close) {
                v[c] = multiplyAddWhere(moves, kick[c], f, v[c]);
                w = multiplyAddWhere(moves, turn[c], t, w);
                f.store(one.keptForce + at);
            }
            v[c] = multiplyAddWhere(moves, kick[c], f, v[c]);
            v[c].store(one.v + at);
            const L before = L::load(one.x + at);
            positionsBefore = addBits(positionsBefore, before);
            x[c] = multiplyAddWhere(moves, drift, v[c], before);
            multiplyAddWhere(moves, turn[c], t, w).store(one.w + at);
            zero.store(one.torque + at);
            multiplyWhere(moves, weight[c], g[c]).store(one.force + at);
        }
        typename L::Mask outside{};
        for (int c = 0; c < 3; ++c) {
            x[c].store(one.x + 3 * i + W * c);
            outside = outside | (x[c] >= high[c]) | (x[c] < low[c]);
        }
        if (any(outside)) [[unlikely]] {  // (few blocks a step: wrapped one by one, then read back)
            domain.wrap(p.position.data() + i, W);
            for (int c = 0; c < 3; ++c) x[c] = L::load(one.x + 3 * i + W * c);
        }
        for (int c = 0; c < 3; ++c) positionsAfter = addBits(positionsAfter, x[c]);
        if (one.reference) {
            L d[3], dAxis[3];
            for (int c = 0; c < 3; ++c)
                d[c] = lanes::nearestOf(x[c] - L::load(one.reference + 3 * i + W * c), length[c], half[c], minusHalf[c]);
            L::toAxes(d, dAxis);
            displacement2 = largerBits(displacement2, lanes::squaredNorms(dAxis));
        }
        L vAxis[3], relative[3];
        L::toAxes(v, vAxis);
        speed2 = largerBits(speed2, lanes::squaredNorms(vAxis));
        for (int c = 0; c < 3; ++c) {
            coordinate = largerBits(coordinate, magnitude(x[c]));
            velocitySum[c] = addWhere(mobile.particles, velocitySum[c], vAxis[c]);
            relative[c] = vAxis[c] - u[c];
        }
        const L radius = L::load(one.radius + i);
        const L grown = multiplyAdd(reach, sqrt(lanes::squaredNorms(relative)), radius * margin);
        L::storePoints(x, grown, reinterpret_cast<double*>(one.points + i));
        // (max(0, g) is g for a NaN g, as std::max(g, 0.0) is.)
        growth = largerBits(growth, max(zero, grown - radius));
    }
    m.displacement2 = largestBits(displacement2);
    m.positionsBefore += sumOfBits(positionsBefore);
    m.positionsAfter += sumOfBits(positionsAfter);
    m.speed2 = largestBits(speed2);
    m.coordinate = largestBits(coordinate);
    m.growth = largestBits(growth);
    for (int c = 0; c < 3; ++c) m.velocitySum[c] = sum(velocitySum[c]);
    return i;
}
#endif

}  // namespace

std::uint64_t positionSum(const ParticleStore& p, std::size_t n) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < std::min(n, p.size()); ++i)
        for (int c = 0; c < 3; ++c) sum += std::bit_cast<std::uint64_t>(p.position[i][c]);
    return sum;
}

double largestDisplacement(const ParticleStore& p, const std::vector<Vec3>& reference, const Domain& domain) {
    const PeriodicImage image(domain);
    std::uint64_t largest = 0;
    for (std::size_t i = 0; i < std::min(p.size(), reference.size()); ++i) {
        double d[3];
        for (int c = 0; c < 3; ++c) d[c] = nearestOf(p.position[i][c] - reference[i][c], image, c);
        largest = std::max(largest, std::bit_cast<std::uint64_t>(squaredNorm(d[0], d[1], d[2])));
    }
    return std::sqrt(std::bit_cast<double>(largest));
}

void startFirstHalf(ParticleStore& p, std::vector<Vec3>& previousForce, std::vector<SweepPoint>& points) {
    const std::size_t n = p.size();
    previousForce.swap(p.force);  // the last step's forces; p.force is refilled by the pass
    p.force.resize(n);
    p.torque.resize(n);
    points.resize(n);
}

namespace {

// The pass over slots [first, last), kicking with oldForce (Close: twice, keeping it in keptForce).
template <bool Close>
DriftPassResult driftPass(ParticleStore& p, const double* oldForce, double* keptForce, const Domain& domain,
                          const std::vector<Vec3>* reference, const Vec3& gravity, const Vec3& frameVelocity, double dt,
                          std::vector<SweepPoint>& points, std::size_t first, std::size_t last) {
    DriftPassResult result;
    result.moves = {0, 0, true};
    if (first >= last) return result;
    const OneParticle one{p.position[0].data(),
                          p.velocity[0].data(),
                          p.angularVelocity[0].data(),
                          oldForce,
                          p.force[0].data(),
                          keptForce,
                          p.torque[0].data(),
                          p.invMass.data(),
                          p.invInertia.data(),
                          p.mass.data(),
                          p.radius.data(),
                          reference ? (*reference)[0].data() : nullptr,
                          p.fixed.data(),
                          points.data(),
                          domain,
                          PeriodicImage(domain),
                          gravity,
                          frameVelocity,
                          0.5 * dt,
                          dt};
    Maxima m;
    std::size_t i = first;
#if TALUS_LANES_WIDTH > 1
    i = inParticleLanes<Close, lanes::ParticleLanes>(one, domain, p, m, first, last);
#endif
    for (; i < last; ++i) one.operator()<Close>(i, m);
    result.moves = {std::bit_cast<double>(m.displacement2), std::bit_cast<double>(m.speed2),
                    saneMotion(std::bit_cast<double>(m.speed2), std::bit_cast<double>(m.coordinate))};
    result.growth = std::bit_cast<double>(m.growth);
    result.mobile = m.mobile;
    result.positionsBefore = m.positionsBefore, result.positionsAfter = m.positionsAfter;
    for (int c = 0; c < 3; ++c) result.velocitySum[c] = m.velocitySum[c];
    const Vec3 mean = Vec3(m.velocitySum[0], m.velocitySum[1], m.velocitySum[2]) / static_cast<double>(std::max<std::size_t>(m.mobile, 1));
    result.meanVelocity = mean.allFinite() ? mean : Vec3::Zero();
    return result;
}

}  // namespace

DriftPassResult kickDriftAndStartForces(ParticleStore& p, const std::vector<Vec3>& previousForce, const Domain& domain,
                                        const std::vector<Vec3>* reference, const Vec3& gravity,
                                        const Vec3& frameVelocity, double dt, std::vector<SweepPoint>& points,
                                        std::size_t first, std::size_t last) {
    // (The arrays' starts without an element: they may be empty.)
    return driftPass<false>(p, reinterpret_cast<const double*>(previousForce.data()), nullptr, domain, reference,
                            gravity, frameVelocity, dt, points, first, last);
}

DriftPassResult closeKickDriftAndStartForces(ParticleStore& p, std::vector<Vec3>& previousForce, const Domain& domain,
                                             const std::vector<Vec3>* reference, const Vec3& gravity,
                                             const Vec3& frameVelocity, double dt, std::vector<SweepPoint>& points,
                                             std::size_t first, std::size_t last) {
    return driftPass<true>(p, reinterpret_cast<const double*>(p.force.data()),
                           reinterpret_cast<double*>(previousForce.data()), domain, reference, gravity, frameVelocity,
                           dt, points, first, last);
}

const DriftPassKernels driftPassKernels{positionSum, startFirstHalf, largestDisplacement, kickDriftAndStartForces,
                                        closeKickDriftAndStartForces};

}  // namespace talus::TALUS_LANES

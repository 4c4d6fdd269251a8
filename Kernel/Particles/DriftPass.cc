// Particles/DriftPass.h in the lanes of one form: compiled once per form (Math/LaneKernels.h).
#include "Particles/DriftPass.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "Contacts/PairSweepLanes.h"
#include "Math/EightParticleLanes.h"
#include "Math/FourParticleLanes.h"
#include "Math/LaneKernels.h"
#include "Math/LaneNamespace.h"
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

// One particle, as the separate passes do it (the lanes below do the same for eight).
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

#if defined(TALUS_AVX512_LANES) || defined(TALUS_AVX2_LANES)
// The box as the lanes below compare with it, axis by axis: the wrap's bounds (lo and hi along
// the periodic axes, -inf and +inf along the others: never outside), and the nearest image's
// lengths and half lengths.
struct BoxPerAxis {
    double low[3], high[3], length[3], half[3];
    BoxPerAxis(const Domain& domain, const PeriodicImage& image) {
        const Domain::WrapBounds bounds = domain.wrapBounds();
        for (int a = 0; a < 3; ++a) {
            low[a] = bounds.low[a], high[a] = bounds.high[a];
            length[a] = image.length(a), half[a] = image.halfLength(a);
        }
    }
};
template <class Lanes>
void perAxis(const double (&value)[3], Lanes (&out)[3]) {
    lanes::perAxis(value[0], value[1], value[2], out);
}
#endif

#ifdef TALUS_AVX512_LANES
// The eight particles' values of one axis (0: x, 1: y, 2: z) from the three vectors that hold
// their coordinates in storage order (EightParticleLanes.h).
inline __m512d axisOf(const __m512d (&a)[3], int axis) {
    const __m512i first = axis == 0   ? _mm512_set_epi64(0, 0, 15, 12, 9, 6, 3, 0)
                          : axis == 1 ? _mm512_set_epi64(0, 0, 0, 13, 10, 7, 4, 1)
                                      : _mm512_set_epi64(0, 0, 0, 14, 11, 8, 5, 2);
    const __m512i second = axis == 0   ? _mm512_set_epi64(13, 10, 5, 4, 3, 2, 1, 0)
                           : axis == 1 ? _mm512_set_epi64(14, 11, 8, 4, 3, 2, 1, 0)
                                       : _mm512_set_epi64(15, 12, 9, 4, 3, 2, 1, 0);
    return _mm512_permutex2var_pd(_mm512_permutex2var_pd(a[0], first, a[1]), second, a[2]);
}

// The eight particles' |a|^2 (squaredNorm's rounding).
inline __m512d squaredNorms(const __m512d (&a)[3]) {
    const __m512d x = axisOf(a, 0), y = axisOf(a, 1), z = axisOf(a, 2);
    return _mm512_fmadd_pd(z, z, _mm512_fmadd_pd(y, y, _mm512_mul_pd(x, x)));
}

inline __m512i bitsOf(__m512d v) { return _mm512_castpd_si512(v); }

// (The zero-masking forms of max and sqrt below, and these reductions by hand: GCC 12 warns,
// wrongly, of uninitialised operands in the plain ones, as EightParticleLanes.h notes.)
inline __m512i largerOf(__m512i a, __m512i b) { return _mm512_maskz_max_epu64(0xff, a, b); }
inline std::uint64_t largestOf(__m512i a) {
    alignas(64) std::uint64_t lanes[8];
    _mm512_store_si512(lanes, a);
    return *std::max_element(lanes, lanes + 8);
}
// The sum of the eight 64-bit lanes, modulo 2^64 (a checksum: the same in any order). Not
// _mm512_reduce_add_epi64, which adds them as signed numbers (an overflow, for UBSan).
inline std::uint64_t checksumOf(__m512i a) {
    alignas(64) std::uint64_t lanes[8];
    _mm512_store_si512(lanes, a);
    std::uint64_t sum = 0;
    for (const std::uint64_t lane : lanes) sum += lane;
    return sum;
}
inline double sumOf(__m512d a) {
    alignas(64) double lanes[8];
    _mm512_store_pd(lanes, a);
    return ((lanes[0] + lanes[1]) + (lanes[2] + lanes[3])) + ((lanes[4] + lanes[5]) + (lanes[6] + lanes[7]));
}

// The eight sweep points (x, y, z, grown radius) from the positions' three vectors and the
// grown radii: two points per vector.
inline void storePoints(const __m512d (&x)[3], __m512d grown, double* out) {
    const __m512i pick[4] = {_mm512_set_epi64(0, 5, 4, 3, 0, 2, 1, 0), _mm512_set_epi64(0, 11, 10, 9, 0, 8, 7, 6),
                             _mm512_set_epi64(0, 9, 8, 7, 0, 6, 5, 4), _mm512_set_epi64(0, 7, 6, 5, 0, 4, 3, 2)};
    const __m512d low[4] = {x[0], x[0], x[1], x[2]}, high[4] = {x[1], x[1], x[2], x[2]};
    for (int k = 0; k < 4; ++k) {
        const __m512d coordinates = _mm512_permutex2var_pd(low[k], pick[k], high[k]);
        const __m512i radii = _mm512_set_epi64(2 * k + 1, 0, 0, 0, 2 * k, 0, 0, 0);
        _mm512_storeu_pd(out + 8 * k, _mm512_mask_permutexvar_pd(coordinates, 0x88, radii, grown));
    }
}

// The blocks of eight particles of the pass; returns where the scalar loop goes on.
// Slots [first, n) while whole groups are left; returns where it stopped.
template <bool Close>
std::size_t inEightParticleLanes(const OneParticle& one, const Domain& domain, ParticleStore& p, Maxima& m, std::size_t first,
                                std::size_t n) {
    std::size_t i = first;
    const BoxPerAxis box(domain, one.image);
    __m512d low[3], high[3], length[3], halfLength[3], g[3], u[3];
    perAxis(box.low, low), perAxis(box.high, high), perAxis(box.length, length), perAxis(box.half, halfLength);
    lanes::perAxis(one.gravity.x(), one.gravity.y(), one.gravity.z(), g);
    lanes::perAxis(one.frame.x(), one.frame.y(), one.frame.z(), u);
    const __m512d drift = _mm512_set1_pd(one.dt), half = _mm512_set1_pd(one.half), zero = _mm512_setzero_pd();
    const __m512d reach = _mm512_set1_pd(reachMargin * one.dt), margin = _mm512_set1_pd(radiusMargin);
    __m512i displacement2 = _mm512_setzero_si512(), speed2 = displacement2, coordinate = displacement2,
            growth = displacement2;
    __m512d velocitySum[3] = {_mm512_setzero_pd(), _mm512_setzero_pd(), _mm512_setzero_pd()};
    __m512i positionsBefore = _mm512_setzero_si512(), positionsAfter = positionsBefore;
    const __m512i magnitude = _mm512_set1_epi64(0x7fffffffffffffff);  // (all bits but the sign)
    for (; i + 8 <= n; i += 8) {
        const lanes::MobileLanes kick(one.fixed + i, one.half, one.invMass + i);
        m.mobile += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(kick.of[0])) +  // (three lanes a particle)
                                             std::popcount(static_cast<unsigned>(kick.of[1])) +
                                             std::popcount(static_cast<unsigned>(kick.of[2]))) / 3;
        __m512d turn[3], weight[3];
        lanes::spread(_mm512_mul_pd(half, _mm512_loadu_pd(one.invInertia + i)), turn);
        lanes::spread(_mm512_loadu_pd(one.mass + i), weight);
        __m512d x[3], v[3];
        for (int c = 0; c < 3; ++c) {
            const std::size_t at = 3 * i + 8 * c;
            const __m512d f = _mm512_loadu_pd(one.oldForce + at), t = _mm512_loadu_pd(one.torque + at);
            v[c] = _mm512_loadu_pd(one.v + at);
            __m512d w = _mm512_loadu_pd(one.w + at);
            if constexpr (Close) {
                v[c] = kick.advance(v[c], kick.factor[c], f, c);
                w = kick.advance(w, turn[c], t, c);
                _mm512_storeu_pd(one.keptForce + at, f);
            }
            v[c] = kick.advance(v[c], kick.factor[c], f, c);
            _mm512_storeu_pd(one.v + at, v[c]);
            velocitySum[c] = _mm512_mask_add_pd(velocitySum[c], kick.of[c], velocitySum[c], v[c]);
            const __m512d before = _mm512_loadu_pd(one.x + at);
            positionsBefore = _mm512_add_epi64(positionsBefore, _mm512_castpd_si512(before));
            x[c] = kick.advance(before, drift, v[c], c);
            _mm512_storeu_pd(one.w + at, kick.advance(w, turn[c], t, c));
            _mm512_storeu_pd(one.torque + at, zero);
            _mm512_storeu_pd(one.force + at, _mm512_maskz_mul_pd(kick.of[c], weight[c], g[c]));
        }
        __mmask8 outside = 0;
        for (int c = 0; c < 3; ++c) {
            _mm512_storeu_pd(one.x + 3 * i + 8 * c, x[c]);
            outside |= _mm512_cmp_pd_mask(x[c], high[c], _CMP_GE_OQ) | _mm512_cmp_pd_mask(x[c], low[c], _CMP_LT_OQ);
        }
        if (outside) [[unlikely]] {  // (few blocks a step: wrapped one by one, then read back)
            domain.wrap(p.position.data() + i, 8);
            for (int c = 0; c < 3; ++c) x[c] = _mm512_loadu_pd(one.x + 3 * i + 8 * c);
        }
        for (int c = 0; c < 3; ++c) positionsAfter = _mm512_add_epi64(positionsAfter, _mm512_castpd_si512(x[c]));
        if (one.reference) {
            __m512d d[3];
            for (int c = 0; c < 3; ++c) {
                const __m512d raw = _mm512_sub_pd(x[c], _mm512_loadu_pd(one.reference + 3 * i + 8 * c));
                const __mmask8 above = _mm512_cmp_pd_mask(raw, halfLength[c], _CMP_GT_OQ);
                const __mmask8 below =
                    _mm512_cmp_pd_mask(raw, _mm512_sub_pd(zero, halfLength[c]), _CMP_LT_OQ);
                d[c] = _mm512_mask_add_pd(_mm512_mask_sub_pd(raw, above, raw, length[c]), below, raw, length[c]);
            }
            displacement2 = largerOf(displacement2, bitsOf(squaredNorms(d)));
        }
        const __m512d s2 = squaredNorms(v);
        speed2 = largerOf(speed2, bitsOf(s2));
        for (int c = 0; c < 3; ++c) coordinate = largerOf(coordinate, _mm512_and_si512(bitsOf(x[c]), magnitude));
        __m512d relative[3];
        for (int c = 0; c < 3; ++c) relative[c] = _mm512_sub_pd(v[c], u[c]);
        const __m512d radius = _mm512_loadu_pd(one.radius + i);
        const __m512d grown =
            _mm512_fmadd_pd(reach, _mm512_maskz_sqrt_pd(0xff, squaredNorms(relative)), _mm512_mul_pd(radius, margin));
        storePoints(x, grown, reinterpret_cast<double*>(one.points + i));
        // (max(0, g) is g for a NaN g, as std::max(g, 0.0) is.)
        growth = largerOf(growth, bitsOf(_mm512_maskz_max_pd(0xff, zero, _mm512_sub_pd(grown, radius))));
    }
    m.displacement2 = largestOf(displacement2);
    m.positionsBefore += checksumOf(positionsBefore);
    m.positionsAfter += checksumOf(positionsAfter);
    m.speed2 = largestOf(speed2);
    m.coordinate = largestOf(coordinate);
    m.growth = largestOf(growth);
    for (int axis = 0; axis < 3; ++axis) m.velocitySum[axis] = sumOf(axisOf(velocitySum, axis));
    return i;
}
#endif

#ifdef TALUS_AVX2_LANES
// The same for blocks of four particles in AVX2 lanes (Math/FourParticleLanes.h): the kicks,
// the drift and the forces in storage order, the norms and the sweep points per axis.
// Slots [first, n) while whole groups are left; returns where it stopped.
template <bool Close>
std::size_t inFourParticleLanes(const OneParticle& one, const Domain& domain, ParticleStore& p, Maxima& m, std::size_t first,
                                std::size_t n) {
    std::size_t i = first;
    const BoxPerAxis box(domain, one.image);
    __m256d low[3], high[3], length[3], halfLength[3], g[3];
    perAxis(box.low, low), perAxis(box.high, high), perAxis(box.length, length), perAxis(box.half, halfLength);
    lanes::perAxis(one.gravity.x(), one.gravity.y(), one.gravity.z(), g);
    const __m256d u[3] = {_mm256_set1_pd(one.frame.x()), _mm256_set1_pd(one.frame.y()), _mm256_set1_pd(one.frame.z())};
    const __m256d drift = _mm256_set1_pd(one.dt), half = _mm256_set1_pd(one.half), zero = _mm256_setzero_pd();
    const __m256d reach = _mm256_set1_pd(reachMargin * one.dt), margin = _mm256_set1_pd(radiusMargin);
    __m256i displacement2 = _mm256_setzero_si256(), speed2 = displacement2, coordinate = displacement2,
            growth = displacement2;
    __m256d velocitySum[3] = {zero, zero, zero};
    __m256i positionsBefore = _mm256_setzero_si256(), positionsAfter = positionsBefore;
    const __m256i magnitude = _mm256_set1_epi64x(0x7fffffffffffffff);  // (all bits but the sign)
    for (; i + 4 <= n; i += 4) {
        const __m256d mobile = lanes::mobileOf(one.fixed + i);
        m.mobile += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(_mm256_movemask_pd(mobile))));
        __m256d moves[3], kick[3], turn[3], weight[3];
        lanes::spread(mobile, moves);
        lanes::spread(_mm256_mul_pd(half, _mm256_loadu_pd(one.invMass + i)), kick);
        lanes::spread(_mm256_mul_pd(half, _mm256_loadu_pd(one.invInertia + i)), turn);
        lanes::spread(_mm256_loadu_pd(one.mass + i), weight);
        __m256d x[3], v[3];
        for (int c = 0; c < 3; ++c) {
            const std::size_t at = 3 * i + 4 * c;
            const __m256d f = _mm256_loadu_pd(one.oldForce + at), t = _mm256_loadu_pd(one.torque + at);
            v[c] = _mm256_loadu_pd(one.v + at);
            __m256d w = _mm256_loadu_pd(one.w + at);
            if constexpr (Close) {
                v[c] = lanes::advance(v[c], kick[c], f, moves[c]);
                w = lanes::advance(w, turn[c], t, moves[c]);
                _mm256_storeu_pd(one.keptForce + at, f);
            }
            v[c] = lanes::advance(v[c], kick[c], f, moves[c]);
            _mm256_storeu_pd(one.v + at, v[c]);
            const __m256d before = _mm256_loadu_pd(one.x + at);
            positionsBefore = _mm256_add_epi64(positionsBefore, _mm256_castpd_si256(before));
            x[c] = lanes::advance(before, drift, v[c], moves[c]);
            _mm256_storeu_pd(one.w + at, lanes::advance(w, turn[c], t, moves[c]));
            _mm256_storeu_pd(one.torque + at, zero);
            _mm256_storeu_pd(one.force + at, _mm256_and_pd(_mm256_mul_pd(weight[c], g[c]), moves[c]));
        }
        __m256d outside = zero;
        for (int c = 0; c < 3; ++c) {
            _mm256_storeu_pd(one.x + 3 * i + 4 * c, x[c]);
            outside = _mm256_or_pd(outside, _mm256_or_pd(_mm256_cmp_pd(x[c], high[c], _CMP_GE_OQ),
                                                         _mm256_cmp_pd(x[c], low[c], _CMP_LT_OQ)));
        }
        if (_mm256_movemask_pd(outside)) [[unlikely]] {  // (few blocks a step: wrapped one by one, then read back)
            domain.wrap(p.position.data() + i, 4);
            for (int c = 0; c < 3; ++c) x[c] = _mm256_loadu_pd(one.x + 3 * i + 4 * c);
        }
        for (int c = 0; c < 3; ++c) positionsAfter = _mm256_add_epi64(positionsAfter, _mm256_castpd_si256(x[c]));
        if (one.reference) {
            __m256d d[3], dAxis[3];
            for (int c = 0; c < 3; ++c) {  // PeriodicImage::nearest
                const __m256d raw = _mm256_sub_pd(x[c], _mm256_loadu_pd(one.reference + 3 * i + 4 * c));
                const __m256d above = _mm256_cmp_pd(raw, halfLength[c], _CMP_GT_OQ);
                const __m256d below = _mm256_cmp_pd(raw, _mm256_sub_pd(zero, halfLength[c]), _CMP_LT_OQ);
                d[c] = _mm256_blendv_pd(_mm256_blendv_pd(raw, _mm256_sub_pd(raw, length[c]), above),
                                        _mm256_add_pd(raw, length[c]), below);
            }
            lanes::toAxes(d, dAxis);
            displacement2 = lanes::largerBits(displacement2, _mm256_castpd_si256(lanes::squaredNorms(dAxis)));
        }
        __m256d vAxis[3], xAxis[3], relative[3];
        lanes::toAxes(v, vAxis);
        lanes::toAxes(x, xAxis);
        speed2 = lanes::largerBits(speed2, _mm256_castpd_si256(lanes::squaredNorms(vAxis)));
        for (int c = 0; c < 3; ++c) {
            coordinate = lanes::largerBits(coordinate, _mm256_and_si256(_mm256_castpd_si256(x[c]), magnitude));
            velocitySum[c] = _mm256_add_pd(velocitySum[c], _mm256_and_pd(vAxis[c], mobile));
            relative[c] = _mm256_sub_pd(vAxis[c], u[c]);
        }
        const __m256d radius = _mm256_loadu_pd(one.radius + i);
        const __m256d grown =
            _mm256_fmadd_pd(reach, _mm256_sqrt_pd(lanes::squaredNorms(relative)), _mm256_mul_pd(radius, margin));
        // The four points (x, y, z, grown radius): a 4 x 4 transposition.
        const __m256d xy0 = _mm256_unpacklo_pd(xAxis[0], xAxis[1]), xy1 = _mm256_unpackhi_pd(xAxis[0], xAxis[1]);
        const __m256d zr0 = _mm256_unpacklo_pd(xAxis[2], grown), zr1 = _mm256_unpackhi_pd(xAxis[2], grown);
        double* points = reinterpret_cast<double*>(one.points + i);
        _mm256_storeu_pd(points, _mm256_permute2f128_pd(xy0, zr0, 0x20));
        _mm256_storeu_pd(points + 4, _mm256_permute2f128_pd(xy1, zr1, 0x20));
        _mm256_storeu_pd(points + 8, _mm256_permute2f128_pd(xy0, zr0, 0x31));
        _mm256_storeu_pd(points + 12, _mm256_permute2f128_pd(xy1, zr1, 0x31));
        // (max(0, g) is g for a NaN g, as std::max(g, 0.0) is.)
        growth = lanes::largerBits(growth, _mm256_castpd_si256(_mm256_max_pd(zero, _mm256_sub_pd(grown, radius))));
    }
    m.displacement2 = lanes::largestBits(displacement2);
    m.positionsBefore += lanes::sumOfLanes(positionsBefore);
    m.positionsAfter += lanes::sumOfLanes(positionsAfter);
    m.speed2 = lanes::largestBits(speed2);
    m.coordinate = lanes::largestBits(coordinate);
    m.growth = lanes::largestBits(growth);
    for (int axis = 0; axis < 3; ++axis) {
        alignas(32) double sums[4];
        _mm256_store_pd(sums, velocitySum[axis]);
        m.velocitySum[axis] = (sums[0] + sums[1]) + (sums[2] + sums[3]);
    }
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
#if defined(TALUS_AVX512_LANES)
    i = inEightParticleLanes<Close>(one, domain, p, m, first, last);
#elif defined(TALUS_AVX2_LANES)
    i = inFourParticleLanes<Close>(one, domain, p, m, first, last);
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

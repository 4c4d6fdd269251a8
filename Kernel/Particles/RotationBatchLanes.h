// RotationBatch::flush in the lanes of one form (Math/LaneKernels.h): the batch's lanes turned
// in one loop of plain numbers that the compiler vectorises (Particles/RotationBatch.h).
#pragma once

#include "Math/LaneNamespace.h"
#include "Particles/RotationBatch.h"

namespace talus::TALUS_LANES {

// One particle's turn: L += kick torque, then (drift > 0) the drift, then omega.
template <class SinCos>
[[gnu::always_inline]] inline void turnRigidBody(RotationLane& r, double tx, double ty, double tz, double kick,
                                                 double drift, SinCos sinCos) {
    r.Lx += kick * tx, r.Ly += kick * ty, r.Lz += kick * tz;
    r.largestAngle = 0;
    if (drift > 0) driftOrientation(r, drift, sinCos);
    turnedSpin(r);
}

template <bool withDrift>
[[gnu::noinline]] void turnLanes(RotationBatch& b, double kick, double drift) {
    for (int l = 0; l < b.count(); ++l) {
        RotationLane r = b.lane(l);
        turnRigidBody(r, b.tx[l], b.ty[l], b.tz[l], kick, withDrift ? drift : 0.0, talus::detail::smallSinCos);
        b.store(r, l);
    }
}

// Every lane turned, written back to the particles.
inline void flush(RotationBatch& b, ParticleStore& p, double kick, double drift) {
    if (drift > 0)
        turnLanes<true>(b, kick, drift);
    else
        turnLanes<false>(b, kick, drift);
    for (int l = 0; l < b.count(); ++l) {
        const std::uint32_t i = b.slots[l];
        if (!(b.large[l] <= talus::detail::smallAngle)) [[unlikely]] {  // again, from the saved state, with the library's sine and cosine
            RotationLane r = b.lane(l);
            turnRigidBody(r, b.tx[l], b.ty[l], b.tz[l], kick, drift,
                          [](double x, double& s, double& c) { talus::detail::sinCos(x, s, c); });
            b.store(r, l);
        }
        p.orientation[i] = Quat(b.outQw[l], b.outQx[l], b.outQy[l], b.outQz[l]);
        p.angularMomentum[i] = Vec3(b.outLx[l], b.outLy[l], b.outLz[l]);
        p.angularVelocity[i] = Vec3(b.wx[l], b.wy[l], b.wz[l]);
    }
    b.clear();
}

// The whole pass in this form, the gathering into lanes included (Particles/RotationBatch.h).
inline void turnShapedParticles(ParticleStore& p, double kick, double drift) {
    RotationBatch batch;
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.fixed[i] || p.shape[i] < 0) continue;
        batch.add(static_cast<std::uint32_t>(i), p);
        if (batch.full()) flush(batch, p, kick, drift);
    }
    flush(batch, p, kick, drift);
}

}  // namespace talus::TALUS_LANES

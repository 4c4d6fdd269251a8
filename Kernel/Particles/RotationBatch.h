// The rigid-body rotation of the non-spherical particles (Particles/RigidBodyRotation.h), a batch
// of particles at a time: a half kick of the angular momentum by the torque, the torque-free
// drift of the orientation (drift > 0), the angular velocity the contacts see. Per particle it is
// one long chain of dependent arithmetic (the sines and cosines of three or four rotations, as
// many quaternion products, L turned into the body frame and back, a renormalisation) that the
// core cannot overlap with the next particle's; in lanes of plain numbers side by side the
// compiler vectorises it (as ContactBatch.h does the contacts). A lane that turned by more than
// the small-angle series covers in one piece (|omega| dt / 2 > 1/16, far beyond a resolved
// contact) is done again from its saved state with the library's sine and cosine.
#pragma once

#include <cstdint>

#include "Particles/ParticleStore.h"
#include "Particles/RigidBodyRotation.h"

namespace talus {

// One particle's turn: L += kick torque, then (drift > 0) the drift, then omega.
template <class SinCos>
[[gnu::always_inline]] inline void turnRigidBody(RotationLane& r, double tx, double ty, double tz, double kick,
                                                 double drift, SinCos sinCos) {
    r.Lx += kick * tx, r.Ly += kick * ty, r.Lz += kick * tz;
    r.largestAngle = 0;
    if (drift > 0) driftOrientation(r, drift, sinCos);
    turnedSpin(r);
}

class RotationBatch {
public:
    static constexpr int size = 16;

    bool full() const { return count_ == size; }

    void add(std::uint32_t slot, const ParticleStore& p) {
        const int l = count_++;
        slot_[l] = slot;
        const Quat& q = p.orientation[slot];
        qw_[l] = q.w(), qx_[l] = q.x(), qy_[l] = q.y(), qz_[l] = q.z();
        const Vec3 &L = p.angularMomentum[slot], &t = p.torque[slot];
        Lx_[l] = L.x(), Ly_[l] = L.y(), Lz_[l] = L.z(), tx_[l] = t.x(), ty_[l] = t.y(), tz_[l] = t.z();
        const RotationAxes a = rotationAxesOf(p.principalInertia[slot]);
        medianRate_[l] = a.medianRate, outerRate_[l] = a.outerRate, innerRate_[l] = a.innerRate;
        for (int k = 0; k < 3; ++k) outer_[k][l] = a.outer[k], inner_[k][l] = a.inner[k], inverseInertia_[k][l] = a.inverseInertia[k];
    }

    // Every lane turned, written back to the particles.
    void flush(ParticleStore& p, double kick, double drift) {
        if (drift > 0)
            compute<true>(kick, drift);
        else
            compute<false>(kick, drift);
        for (int l = 0; l < count_; ++l) {
            const std::uint32_t i = slot_[l];
            if (!(large_[l] <= detail::smallAngle)) [[unlikely]] {  // again, from the saved state, with the library's sine and cosine
                RotationLane r = lane(l);
                turnRigidBody(r, tx_[l], ty_[l], tz_[l], kick, drift,
                              [](double x, double& s, double& c) { detail::sinCos(x, s, c); });
                store(r, l);
            }
            p.orientation[i] = Quat(outQw_[l], outQx_[l], outQy_[l], outQz_[l]);
            p.angularMomentum[i] = Vec3(outLx_[l], outLy_[l], outLz_[l]);
            p.angularVelocity[i] = Vec3(wx_[l], wy_[l], wz_[l]);
        }
        count_ = 0;
    }

private:
    template <bool withDrift>
    [[gnu::noinline]] void compute(double kick, double drift) {
        for (int l = 0; l < count_; ++l) {
            RotationLane r = lane(l);
            turnRigidBody(r, tx_[l], ty_[l], tz_[l], kick, withDrift ? drift : 0.0, detail::smallSinCos);
            store(r, l);
        }
    }

    [[gnu::always_inline]] RotationLane lane(int l) const {
        const RotationAxes a{medianRate_[l],
                             {outer_[0][l], outer_[1][l], outer_[2][l]},
                             outerRate_[l],
                             {inner_[0][l], inner_[1][l], inner_[2][l]},
                             innerRate_[l],
                             {inverseInertia_[0][l], inverseInertia_[1][l], inverseInertia_[2][l]}};
        return {qw_[l], qx_[l], qy_[l], qz_[l], Lx_[l], Ly_[l], Lz_[l], a, 0, 0, 0, 0};
    }
    [[gnu::always_inline]] void store(const RotationLane& r, int l) {
        outQw_[l] = r.qw, outQx_[l] = r.qx, outQy_[l] = r.qy, outQz_[l] = r.qz;
        outLx_[l] = r.Lx, outLy_[l] = r.Ly, outLz_[l] = r.Lz;
        wx_[l] = r.wx, wy_[l] = r.wy, wz_[l] = r.wz;
        large_[l] = r.largestAngle;
    }

    int count_ = 0;
    std::uint32_t slot_[size];
    double qw_[size], qx_[size], qy_[size], qz_[size], Lx_[size], Ly_[size], Lz_[size], tx_[size], ty_[size], tz_[size];
    double medianRate_[size], outerRate_[size], innerRate_[size];  // (RotationAxes, lane by lane)
    double outer_[3][size], inner_[3][size], inverseInertia_[3][size];
    double outQw_[size], outQx_[size], outQy_[size], outQz_[size], outLx_[size], outLy_[size], outLz_[size];
    double wx_[size], wy_[size], wz_[size], large_[size];
};

}  // namespace talus

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

class RotationBatch {
public:
    static constexpr int size = 16;

    bool full() const { return count_ == size; }

    void add(std::uint32_t slot, const ParticleStore& p) {
        const int l = count_++;
        slots[l] = slot;
        const Quat& q = p.orientation[slot];
        qw[l] = q.w(), qx[l] = q.x(), qy[l] = q.y(), qz[l] = q.z();
        const Vec3 &L = p.angularMomentum[slot], &t = p.torque[slot];
        Lx[l] = L.x(), Ly[l] = L.y(), Lz[l] = L.z(), tx[l] = t.x(), ty[l] = t.y(), tz[l] = t.z();
        // (The axes depend on the inertia alone, and neighbouring slots mostly share it: one shape
        // and species. Worked out again only when it changes, the pass costs a sixth less.)
        const Vec3& inertia = p.principalInertia[slot];
        if (inertia != lastInertia_) lastInertia_ = inertia, lastAxes_ = rotationAxesOf(inertia);
        const RotationAxes& a = lastAxes_;
        medianRate[l] = a.medianRate, outerRate[l] = a.outerRate, innerRate[l] = a.innerRate;
        for (int k = 0; k < 3; ++k) outer[k][l] = a.outer[k], inner[k][l] = a.inner[k], inverseInertia[k][l] = a.inverseInertia[k];
    }

    // Lane l as one particle's numbers, and back (for the form's pass).
    [[gnu::always_inline]] RotationLane lane(int l) const {
        const RotationAxes a{medianRate[l],
                             {outer[0][l], outer[1][l], outer[2][l]},
                             outerRate[l],
                             {inner[0][l], inner[1][l], inner[2][l]},
                             innerRate[l],
                             {inverseInertia[0][l], inverseInertia[1][l], inverseInertia[2][l]}};
        return {qw[l], qx[l], qy[l], qz[l], Lx[l], Ly[l], Lz[l], a, 0, 0, 0, 0};
    }
    [[gnu::always_inline]] void store(const RotationLane& r, int l) {
        outQw[l] = r.qw, outQx[l] = r.qx, outQy[l] = r.qy, outQz[l] = r.qz;
        outLx[l] = r.Lx, outLy[l] = r.Ly, outLz[l] = r.Lz;
        wx[l] = r.wx, wy[l] = r.wy, wz[l] = r.wz;
        large[l] = r.largestAngle;
    }

    int count() const { return count_; }
    void clear() { count_ = 0; }

    // The lanes, by particle number l: the slot, orientation, angular momentum and torque, the
    // rotation axes (RotationAxes), and the turned orientation, momentum and spin.
    std::uint32_t slots[size];
    double qw[size], qx[size], qy[size], qz[size], Lx[size], Ly[size], Lz[size], tx[size], ty[size], tz[size];
    double medianRate[size], outerRate[size], innerRate[size];  // (RotationAxes, lane by lane)
    double outer[3][size], inner[3][size], inverseInertia[3][size];
    double outQw[size], outQx[size], outQy[size], outQz[size], outLx[size], outLy[size], outLz[size];
    double wx[size], wy[size], wz[size], large[size];

private:
    int count_ = 0;
    Vec3 lastInertia_ = Vec3::Zero();  // (zero: no particle's, rotationAxesOf needs it positive)
    RotationAxes lastAxes_{};
};

// Every owned, free, non-spherical particle turned: a kick of its angular momentum by `kick` times
// its torque, then (drift > 0) the torque-free drift of its orientation, and its angular
// velocity, in batches of lanes of the form in use (Particles/RotationBatchLanes.h).
void turnShapedParticles(ParticleStore& p, double kick, double drift);

}  // namespace talus

// The batch of lasting sphere contacts of the force loop (Contacts/ContactForces.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "Contacts/ContactHistory.h"
#include "Particles/ParticleStore.h"
#include "Species/LinearSpringDashpot.h"

namespace talus {

// Contacts inside a lasting contact, gathered in batches of `size` and computed lane by lane in
// one loop of plain numbers that the compiler vectorises (LinearSpringDashpot::lastingContact):
// the arithmetic of a contact then costs a fraction of the scalar path's, and only gathering and
// scattering stay scalar (Documentation/Performance.md). Only the linear law has the batched
// form (`batched = true`).
struct ContactBatch {
    static constexpr int size = 64;
    int count = 0;
    std::uint32_t k[size], i[size], j[size];
    // In: separation, radii, relative velocity, spins, 1/mi + 1/mj, last accelerations
    // (difference), the pair's last normal force, its spring (updated in place), its law.
    double dx[size], dy[size], dz[size], ri[size], rj[size], vx[size], vy[size], vz[size];
    double wix[size], wiy[size], wiz[size], wjx[size], wjy[size], wjz[size], inverseMassSum[size];
    double ax[size], ay[size], az[size], lastNormalForce[size], sx[size], sy[size], sz[size];
    double kn[size], gn[size], kt[size], gt[size], mu[size];
    // Out: force on i, torques on i and j, normal force, overlap.
    double fx[size], fy[size], fz[size], tix[size], tiy[size], tiz[size], tjx[size], tjy[size], tjz[size];
    double fn[size], overlap[size];

    bool full() const { return count == size; }
    LinearSpringDashpot law(int l) const { return {kn[l], gn[l], kt[l], gt[l], mu[l]}; }

    void add(std::size_t pair, std::uint32_t a, std::uint32_t b, const Vec3& d, const ParticleStore& p,
             const std::vector<Vec3>& previousForce, const ContactHistories& history, const LinearSpringDashpot& pairLaw) {
        const int l = count++;
        k[l] = static_cast<std::uint32_t>(pair), i[l] = a, j[l] = b;
        dx[l] = d.x(), dy[l] = d.y(), dz[l] = d.z();
        ri[l] = p.radius[a], rj[l] = p.radius[b];
        const Vec3 v = p.velocity[a] - p.velocity[b];
        vx[l] = v.x(), vy[l] = v.y(), vz[l] = v.z();
        const Vec3 &wi = p.angularVelocity[a], &wj = p.angularVelocity[b];
        wix[l] = wi.x(), wiy[l] = wi.y(), wiz[l] = wi.z(), wjx[l] = wj.x(), wjy[l] = wj.y(), wjz[l] = wj.z();
        inverseMassSum[l] = p.invMass[a] + p.invMass[b];
        const Vec3 acceleration = previousForce[a] * p.invMass[a] - previousForce[b] * p.invMass[b];
        ax[l] = acceleration.x(), ay[l] = acceleration.y(), az[l] = acceleration.z();
        lastNormalForce[l] = history.lastNormalForceOf(pair);
        const Vec3& spring = history.springOf(pair);
        sx[l] = spring.x(), sy[l] = spring.y(), sz[l] = spring.z();
        kn[l] = pairLaw.normalStiffness, gn[l] = pairLaw.normalDamping, kt[l] = pairLaw.tangentialStiffness;
        gt[l] = pairLaw.tangentialDamping, mu[l] = pairLaw.friction;
        // The flush adds to j's force and torque up to a batch later; once the arrays outgrow the
        // caches those loads miss (half of the flush at 10^5 particles), so they are asked for now.
        __builtin_prefetch(p.force.data() + b, 1);
        __builtin_prefetch(p.torque.data() + b, 1);
    }

    // The kinematics of contactKinematics (SPEC.md 1: arms ri - dn/2, vt = v - vn n - (ai wi + aj wj) x n)
    // and the law's lasting-contact step, for every lane.
    [[gnu::noinline]] void compute(double dt) {
        for (int l = 0; l < count; ++l) {
            const double distance = std::sqrt(dx[l] * dx[l] + dy[l] * dy[l] + dz[l] * dz[l]), inverse = 1 / distance;
            LinearSpringDashpot::Lane c;
            c.nx = dx[l] * inverse, c.ny = dy[l] * inverse, c.nz = dz[l] * inverse;
            c.overlap = ri[l] + rj[l] - distance;
            const double armI = ri[l] - 0.5 * c.overlap, armJ = rj[l] - 0.5 * c.overlap;
            c.vx = vx[l], c.vy = vy[l], c.vz = vz[l];
            c.normalVelocity = c.vx * c.nx + c.vy * c.ny + c.vz * c.nz;
            const double wx = armI * wix[l] + armJ * wjx[l], wy = armI * wiy[l] + armJ * wjy[l],
                         wz = armI * wiz[l] + armJ * wjz[l];
            c.tx = c.vx - c.normalVelocity * c.nx - (wy * c.nz - wz * c.ny);
            c.ty = c.vy - c.normalVelocity * c.ny - (wz * c.nx - wx * c.nz);
            c.tz = c.vz - c.normalVelocity * c.nz - (wx * c.ny - wy * c.nx);
            c.inverseReducedMass = inverseMassSum[l];
            c.otherAcceleration = ax[l] * c.nx + ay[l] * c.ny + az[l] * c.nz - lastNormalForce[l] * inverseMassSum[l];
            c.inverseDistance = inverse;
            c.sx = sx[l], c.sy = sy[l], c.sz = sz[l];
            law(l).lastingContact(c, dt);
            sx[l] = c.sx, sy[l] = c.sy, sz[l] = c.sz;
            fn[l] = c.normalForce;
            overlap[l] = c.overlap;
            fx[l] = c.normalForce * c.nx + c.fx, fy[l] = c.normalForce * c.ny + c.fy, fz[l] = c.normalForce * c.nz + c.fz;
            const double turnX = c.ny * c.fz - c.nz * c.fy, turnY = c.nz * c.fx - c.nx * c.fz,
                         turnZ = c.nx * c.fy - c.ny * c.fx;  // n x ft
            tix[l] = -armI * turnX, tiy[l] = -armI * turnY, tiz[l] = -armI * turnZ;
            tjx[l] = -armJ * turnX, tjy[l] = -armJ * turnY, tjz[l] = -armJ * turnZ;
        }
    }
};

}  // namespace talus

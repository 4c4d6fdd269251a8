// The batch of lasting sphere contacts of the force loop (Contacts/ContactForces.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "Contacts/ContactHistory.h"
#include "Particles/ParticleStore.h"
#include "Species/LinearSpringDashpot.h"
#include "Math/LaneNamespace.h"

namespace talus::TALUS_LANES {

// Contacts inside a lasting contact, gathered in batches of `size` and computed lane by lane in
// one loop of plain numbers that the compiler vectorises (LinearSpringDashpot::lastingContact):
// the arithmetic of a contact then costs a fraction of the scalar path's, and only gathering and
// scattering stay scalar (Documentation/Performance.md). The laws with the batched form
// (`batched = true`: the linear law and Hertz-Mindlin) give their numbers as a LaneLaw and their
// step as Law::lastingContactInLane.
struct ContactBatch {
    static constexpr int size = 64;
    int count = 0;
    std::uint32_t k[size], i[size], j[size];
    // In: separation, radii, relative velocity, spins, 1/mi + 1/mj, last accelerations
    // (difference), the pair's last normal force, its spring (updated in place), its law.
    double dx[size], dy[size], dz[size], ri[size], rj[size], vx[size], vy[size], vz[size];
    double wix[size], wiy[size], wiz[size], wjx[size], wjy[size], wjz[size], inverseMassSum[size];
    double ax[size], ay[size], az[size], lastNormalForce[size], sx[size], sy[size], sz[size];
    double law[5][size];  // the pair's LaneLaw
    // Out: force on i, torques on i and j, normal force, overlap.
    double fx[size], fy[size], fz[size], tix[size], tiy[size], tiz[size], tjx[size], tjy[size], tjz[size];
    double fn[size], overlap[size];

    bool full() const { return count == size; }

    // Whether every lane's law has no friction. Its contacts then have no tangential force, no
    // spring and no torque, exactly (the full step clears them: Theory/ContactLaws.md eq. (14) at
    // mu = 0), and gather, compute and the application leave out the spins, the tangential
    // kinematics and the torques (`frictionless` template arguments), to the same bits.
    // (Left at the first lane with friction: a frictional scene pays one comparison a batch.)
    template <class Law>
    bool frictionless() const {
        for (int l = 0; l < count; ++l)
            if (law[Law::laneFriction][l] != 0) return false;
        return true;
    }

    // A lasting contact into the next lane: the pair, its separation and radii, its law. The
    // particles' velocities, spins and last forces and the pair's history come in later, for
    // all lanes at once (gather).
    void add(std::size_t pair, std::uint32_t a, std::uint32_t b, const Vec3& d, double radiusA, double radiusB,
             const LaneLaw& pairLaw) {
        const int l = count++;
        k[l] = static_cast<std::uint32_t>(pair), i[l] = a, j[l] = b;
        dx[l] = d.x(), dy[l] = d.y(), dz[l] = d.z();
        ri[l] = radiusA, rj[l] = radiusB;
        for (int q = 0; q < 5; ++q) law[q][l] = pairLaw[q];
    }

    // The rest of every lane's input, from the particle arrays and the histories, in one loop of
    // its own before compute: in the contact pass, among its branches, the same loads and stores
    // left the compiler short of registers (their 30 loads and stores a contact were most of the
    // pass's instructions in a profile of the settled bed).
    template <bool frictionless = false>
    void gather(const ParticleStore& p, const std::vector<Vec3>& previousForce, const ContactHistories& history) {
        const double* __restrict velocity = p.velocity[0].data();
        const double* __restrict spin = p.angularVelocity[0].data();
        const double* __restrict invMass = p.invMass.data();
        const double* __restrict lasting = history.lastingRecords();
        for (int l = 0; l < count; ++l) {
            const std::size_t a = i[l], b = j[l], a3 = 3 * a, b3 = 3 * b;
            vx[l] = velocity[a3] - velocity[b3], vy[l] = velocity[a3 + 1] - velocity[b3 + 1];
            vz[l] = velocity[a3 + 2] - velocity[b3 + 2];
            if constexpr (!frictionless) {
                wix[l] = spin[a3], wiy[l] = spin[a3 + 1], wiz[l] = spin[a3 + 2];
                wjx[l] = spin[b3], wjy[l] = spin[b3 + 1], wjz[l] = spin[b3 + 2];
            }
            const double ma = invMass[a], mb = invMass[b];
            inverseMassSum[l] = ma + mb;
            // (As Eigen's expression, so that the compiler contracts it as the scalar path's.)
            const Vec3 acceleration = previousForce[a] * ma - previousForce[b] * mb;
            ax[l] = acceleration.x(), ay[l] = acceleration.y(), az[l] = acceleration.z();
            const double* record = lasting + 4 * std::size_t{k[l]};
            sx[l] = record[0], sy[l] = record[1], sz[l] = record[2], lastNormalForce[l] = record[3];
            // The application adds to j's force and torque after compute; once the arrays outgrow
            // the caches those loads miss (half of the application at 10^5 particles), so they
            // are asked for now.
            __builtin_prefetch(p.force.data() + b, 1);
            if constexpr (!frictionless) __builtin_prefetch(p.torque.data() + b, 1);
        }
    }

    // The kinematics of contactKinematics (Theory/ContactLaws.md eq. (4): arms ri - dn/2,
    // vt = v - vn n - (ai wi + aj wj) x n) and the law's lasting-contact step, for every lane.
    template <class Law, bool frictionless = false>
    [[gnu::noinline]] void compute(double dt) {
        for (int l = 0; l < count; ++l) {
            const double distance = std::sqrt(dx[l] * dx[l] + dy[l] * dy[l] + dz[l] * dz[l]), inverse = 1 / distance;
            LinearSpringDashpot::Lane c;
            c.nx = dx[l] * inverse, c.ny = dy[l] * inverse, c.nz = dz[l] * inverse;
            c.overlap = ri[l] + rj[l] - distance;
            const double armI = ri[l] - 0.5 * c.overlap, armJ = rj[l] - 0.5 * c.overlap;
            c.vx = vx[l], c.vy = vy[l], c.vz = vz[l];
            c.normalVelocity = c.vx * c.nx + c.vy * c.ny + c.vz * c.nz;
            if constexpr (!frictionless) {
                const double wx = armI * wix[l] + armJ * wjx[l], wy = armI * wiy[l] + armJ * wjy[l],
                             wz = armI * wiz[l] + armJ * wjz[l];
                c.tx = c.vx - c.normalVelocity * c.nx - (wy * c.nz - wz * c.ny);
                c.ty = c.vy - c.normalVelocity * c.ny - (wz * c.nx - wx * c.nz);
                c.tz = c.vz - c.normalVelocity * c.nz - (wx * c.ny - wy * c.nx);
            }
            c.inverseReducedMass = inverseMassSum[l];
            c.otherAcceleration = ax[l] * c.nx + ay[l] * c.ny + az[l] * c.nz - lastNormalForce[l] * inverseMassSum[l];
            c.inverseDistance = inverse;
            c.sx = sx[l], c.sy = sy[l], c.sz = sz[l];
            const double laneLaw[5] = {law[0][l], law[1][l], law[2][l], law[3][l], law[4][l]};
            const double effectiveRadius = Law::usesEffectiveRadius ? ri[l] * rj[l] / (ri[l] + rj[l]) : 0;
            Law::template lastingContactInLane<frictionless>(c, dt, laneLaw, effectiveRadius);
            sx[l] = c.sx, sy[l] = c.sy, sz[l] = c.sz;
            fn[l] = c.normalForce;
            overlap[l] = c.overlap;
            if constexpr (frictionless) {
                fx[l] = c.normalForce * c.nx, fy[l] = c.normalForce * c.ny, fz[l] = c.normalForce * c.nz;
                continue;
            }
            fx[l] = c.normalForce * c.nx + c.fx, fy[l] = c.normalForce * c.ny + c.fy, fz[l] = c.normalForce * c.nz + c.fz;
            const double turnX = c.ny * c.fz - c.nz * c.fy, turnY = c.nz * c.fx - c.nx * c.fz,
                         turnZ = c.nx * c.fy - c.ny * c.fx;  // n x ft
            tix[l] = -armI * turnX, tiy[l] = -armI * turnY, tiz[l] = -armI * turnZ;
            tjx[l] = -armJ * turnX, tjy[l] = -armJ * turnY, tjz[l] = -armJ * turnZ;
        }
    }
};

}  // namespace talus::TALUS_LANES

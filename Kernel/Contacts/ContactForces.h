// The force loop: contact forces and torques of every listed pair and wall candidate, compiled
// once per contact law (no dispatch, search or allocation per contact; DESIGN.md).
// Geometry and kinematics follow SPEC.md 1: n from j to i, dn = ri + rj - rij, branch vectors
// bij = -(ri - dn/2) n and bji = (rj - dn/2) n to the middle of the overlap.
#pragma once

#include <cstdint>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/PairList.h"
#include "Particles/ParticleStore.h"
#include "Species/SpeciesTable.h"
#include "Walls/PlaneWall.h"
#include "Walls/PrescribedMotion.h"

namespace talus {

// One contact as written to .fstat (Documentation/FileFormats/fstat.md); recorded only on
// output steps.
struct ContactRecord {
    std::uint32_t i;
    std::int64_t j;          // partner slot, or -(wall + 1)
    Vec3 contactPoint;       // middle of the overlap, next to particle i
    double overlap;
    double springLength;     // |xi|
    double normalForce;      // signed, along normal
    Vec3 normal;             // from j (or the wall) to i
    Vec3 tangentialForce;    // on i
    double elasticEnergy;
};

// What the force loop learned about the contacts of this step.
struct ContactSummary {
    std::size_t contacts = 0;
    double maxOverlapFraction = 0;  // largest dn / min(ri, rj) (walls: dn / ri)
    std::uint64_t worstA = 0, worstB = 0;  // global ids (worstB = -1 for a wall)
    bool worstIsWall = false;
};

template <class Law>
void addContactForces(ParticleStore& p, PairList& list, const std::vector<PlaneWall>& walls,
                      const std::vector<PrescribedMotion>& motions, const PairTable<Law>& laws, const Domain& domain,
                      double dt, ContactSummary& summary, std::vector<ContactRecord>* records) {
    auto noteOverlap = [&summary](double fraction, std::uint64_t a, std::uint64_t b, bool wall) {
        if (fraction <= summary.maxOverlapFraction) return;
        summary.maxOverlapFraction = fraction;
        summary.worstA = a;
        summary.worstB = b;
        summary.worstIsWall = wall;
    };

    for (std::size_t k = 0; k < list.pairs.size(); ++k) {
        const std::uint32_t i = list.pairs[k].i, j = list.pairs[k].j;
        const Vec3 d = domain.nearestImage(p.position[i] - p.position[j]);
        const double sumR = p.radius[i] + p.radius[j];
        const double r2 = d.squaredNorm();
        Vec3& spring = list.springs[k];
        const Law& law = laws(p.species[i], p.species[j]);
        if (r2 >= sumR * sumR) {
            spring.setZero();  // SPEC.md 1: the spring lives from the first time of contact
            if (list.touching[k]) {  // separated during the last step
                list.touching[k] = 0;
                const double distance = std::sqrt(r2);
                const Vec3 n = d / distance;
                const Vec3 force = law.separationForce(distance - sumR, (p.velocity[i] - p.velocity[j]).dot(n), dt) * n;
                p.force[i] += force;
                p.force[j] -= force;
            }
            continue;
        }
        ContactKinematics c;
        c.distance = std::sqrt(r2);
        c.normal = d / c.distance;
        c.overlap = sumR - c.distance;
        const Vec3 bij = -(p.radius[i] - 0.5 * c.overlap) * c.normal;
        const Vec3 bji = (p.radius[j] - 0.5 * c.overlap) * c.normal;
        c.relativeVelocity = p.velocity[i] - p.velocity[j];
        c.normalVelocity = c.relativeVelocity.dot(c.normal);
        c.tangentialVelocity = c.relativeVelocity - c.normalVelocity * c.normal +
                               p.angularVelocity[i].cross(bij) - p.angularVelocity[j].cross(bji);
        c.reducedMass = 1.0 / (p.invMass[i] + p.invMass[j]);
        c.effectiveRadius = p.radius[i] * p.radius[j] / sumR;
        const ContactForce f = law.force(c, spring, dt, !list.touching[k]);
        list.touching[k] = 1;
        const Vec3 force = f.normalForce * c.normal + f.tangentialForce;
        p.force[i] += force;
        p.force[j] -= force;
        p.torque[i] += bij.cross(force);
        p.torque[j] -= bji.cross(force);
        ++summary.contacts;
        noteOverlap(c.overlap / std::min(p.radius[i], p.radius[j]), p.id[i], p.id[j], false);
        if (records)
            records->push_back({i, static_cast<std::int64_t>(j), p.position[i] + bij, c.overlap, spring.norm(),
                                f.normalForce, c.normal, f.tangentialForce, law.elasticEnergy(c, spring)});
    }

    for (std::size_t k = 0; k < list.wallPairs.size(); ++k) {
        const std::uint32_t i = list.wallPairs[k].particle;
        const PlaneWall& wall = walls[list.wallPairs[k].wall];
        const double distance = wall.signedDistance(p.position[i]);
        Vec3& spring = list.wallSprings[k];
        const Law& law = laws(p.species[i], wall.species);
        if (distance >= p.radius[i]) {
            spring.setZero();
            if (list.wallTouching[k]) {
                list.wallTouching[k] = 0;
                const Vec3 contactPoint = p.position[i] - p.radius[i] * wall.normal;
                const Vec3 wallVelocity =
                    wall.motion >= 0 ? motions[wall.motion].pointVelocity(contactPoint) : Vec3::Zero();
                p.force[i] += law.separationForce(distance - p.radius[i],
                                                  (p.velocity[i] - wallVelocity).dot(wall.normal), dt) * wall.normal;
            }
            continue;
        }
        ContactKinematics c;
        c.distance = 0;  // a wall: the spring is projected, not rotated (ContactKinematics.h)
        c.normal = wall.normal;
        c.overlap = p.radius[i] - distance;
        const Vec3 bij = -(p.radius[i] - 0.5 * c.overlap) * c.normal;
        const Vec3 contactPoint = p.position[i] + bij;
        const Vec3 wallVelocity = wall.motion >= 0 ? motions[wall.motion].pointVelocity(contactPoint) : Vec3::Zero();
        c.relativeVelocity = p.velocity[i] - wallVelocity;
        c.normalVelocity = c.relativeVelocity.dot(c.normal);
        c.tangentialVelocity =
            c.relativeVelocity - c.normalVelocity * c.normal + p.angularVelocity[i].cross(bij);
        c.reducedMass = p.mass[i];
        c.effectiveRadius = p.radius[i];
        const ContactForce f = law.force(c, spring, dt, !list.wallTouching[k]);
        list.wallTouching[k] = 1;
        const Vec3 force = f.normalForce * c.normal + f.tangentialForce;
        p.force[i] += force;
        p.torque[i] += bij.cross(force);
        ++summary.contacts;
        noteOverlap(c.overlap / p.radius[i], p.id[i], list.wallPairs[k].wall, true);
        if (records)
            records->push_back({i, -static_cast<std::int64_t>(list.wallPairs[k].wall) - 1, contactPoint, c.overlap,
                                spring.norm(), f.normalForce, c.normal, f.tangentialForce,
                                law.elasticEnergy(c, spring)});
    }
}

}  // namespace talus

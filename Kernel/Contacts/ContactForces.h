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

// Kinematics of particle i against a partner at distance rij along the unit normal n (SPEC.md 1);
// overlap = ri + rj - rij may be negative for a pair that just separated. The branch vectors are
// bij = -armI n and bji = armJ n with arms ri - dn/2 and rj - dn/2 (rj = 0 for walls), so the
// spin part of the tangential velocity, wi x bij - wj x bji, is -(armI wi + armJ wj) x n.
struct Arms {
    double i, j;
};
inline ContactKinematics contactKinematics(const Vec3& n, double overlap, double radiusI, double radiusJ,
                                           const Vec3& relativeVelocity, const Vec3& spinI, const Vec3& spinJ,
                                           Arms& arms) {
    arms = {radiusI - 0.5 * overlap, radiusJ - 0.5 * overlap};
    ContactKinematics c;
    c.normal = n;
    c.overlap = overlap;
    c.relativeVelocity = relativeVelocity;
    c.normalVelocity = relativeVelocity.dot(n);
    c.tangentialVelocity = relativeVelocity - c.normalVelocity * n - (arms.i * spinI + arms.j * spinJ).cross(n);
    return c;
}

// The force loop over the listed pairs and wall candidates of one step, for one contact law.
// Its parts are member functions so that the compiler inlines the common case (a pair inside a
// contact) whole and keeps the rare ones (the ends of a contact, output records) out of the way.
template <class Law>
class ContactForceLoop {
public:
    ContactForceLoop(ParticleStore& p, const PairTable<Law>& laws, double dt, double maxSpeed,
                     const std::vector<Vec3>& previousForce, ContactSummary& summary,
                     std::vector<ContactRecord>* records)
        : p_(p), laws_(laws), dt_(dt), closing_(2 * maxSpeed * dt), previousForce_(previousForce), summary_(summary),
          records_(records) {}

    void particlePairs(PairList& list, const Domain& domain) {
        const PeriodicImage image(domain);
        // Two passes: a branch-free sweep over all listed pairs picks those that need work
        // (touching, about to touch within the next step, or just separated), then the contacts
        // are computed for those alone.
        std::vector<std::uint32_t>& active = list.activeScratch;
        active.resize(list.pairs.size());
        std::size_t activeCount = 0;
        for (std::size_t k = 0; k < list.pairs.size(); ++k) {
            const std::uint32_t i = list.pairs[k].i, j = list.pairs[k].j;
            const Vec3 d = image.nearest(p_.position[i] - p_.position[j]);
            const double limit = p_.radius[i] + p_.radius[j] + closing_;
            active[activeCount] = static_cast<std::uint32_t>(k);
            activeCount += (d.squaredNorm() < limit * limit) | (list.history.state(k) != ContactHistory::apart);
        }
        for (std::size_t a = 0; a < activeCount; ++a) {
            const std::size_t k = active[a];
            const std::uint32_t i = list.pairs[k].i, j = list.pairs[k].j;
            const Vec3 d = image.nearest(p_.position[i] - p_.position[j]);
            const double sumR = p_.radius[i] + p_.radius[j];
            const double r2 = d.squaredNorm();
            const bool touching = r2 < sumR * sumR;
            const double distance = std::sqrt(r2), inverseDistance = 1 / distance;
            const Vec3 n = d * inverseDistance, relativeVelocity = p_.velocity[i] - p_.velocity[j];
            // Apart with nothing pending, and not closing the gap within the next step at the
            // present speed: no force (approachForce would push nothing), and no work beyond
            // noting that the pair applied no force this step.
            if (!touching && list.history.state(k) == ContactHistory::apart) {
                const double u = relativeVelocity.dot(n);
                if (!(u < 0 && distance - sumR < -u * dt_)) {
                    list.history.clearLastNormalForce(k);
                    continue;
                }
            }
            ContactHistory history = list.history.get(k);
            Arms arms;
            ContactKinematics c = contactKinematics(n, sumR - distance, p_.radius[i], p_.radius[j], relativeVelocity,
                                                    p_.angularVelocity[i], p_.angularVelocity[j], arms);
            c.inverseDistance = inverseDistance;
            const double inverseMassSum = p_.invMass[i] + p_.invMass[j];
            c.inverseReducedMass = inverseMassSum;
            // The last step's forces on i and j, less this pair's own (ContactKinematics.h).
            c.otherAcceleration = previousForce_[i].dot(c.normal) * p_.invMass[i] -
                                  previousForce_[j].dot(c.normal) * p_.invMass[j] -
                                  history.lastNormalForce * inverseMassSum;
            if constexpr (Law::usesEffectiveRadius) c.effectiveRadius = p_.radius[i] * p_.radius[j] / sumR;
            const Law& law = laws_(p_.species[i], p_.species[j]);
            if (touching)
                touch(i, j, c, arms, history, law, std::min(p_.radius[i], p_.radius[j]));
            else
                history = apart(i, j, c, arms, history, law);
            list.history.set(k, history);
        }
    }

    void wallPairs(PairList& list, const std::vector<PlaneWall>& walls, const std::vector<PrescribedMotion>& motions) {
        for (std::size_t k = 0; k < list.wallPairs.size(); ++k) {
            const std::uint32_t i = list.wallPairs[k].particle;
            const PlaneWall& wall = walls[list.wallPairs[k].wall];
            const double distance = wall.signedDistance(p_.position[i]);
            const bool touching = distance < p_.radius[i];
            // (A moving wall may close in faster than the particles: no shortcut for it.)
            if (!touching && list.wallHistory.state(k) == ContactHistory::apart && wall.motion < 0 &&
                distance - p_.radius[i] >= closing_)
                continue;
            ContactHistory history = list.wallHistory.get(k);
            const double overlap = p_.radius[i] - distance;
            const Vec3 contactPoint = p_.position[i] - (p_.radius[i] - 0.5 * overlap) * wall.normal;
            const Vec3 wallVelocity =
                wall.motion >= 0 ? motions[wall.motion].pointVelocity(contactPoint) : Vec3::Zero();
            Arms arms;
            ContactKinematics c = contactKinematics(wall.normal, overlap, p_.radius[i], 0, p_.velocity[i] - wallVelocity,
                                                    p_.angularVelocity[i], Vec3::Zero(), arms);
            c.inverseDistance = 0;  // a wall: the spring is projected, not rotated (ContactKinematics.h)
            c.inverseReducedMass = p_.invMass[i];
            c.otherAcceleration = (previousForce_[i].dot(c.normal) - history.lastNormalForce) * p_.invMass[i];
            c.effectiveRadius = p_.radius[i];
            const Law& law = laws_(p_.species[i], wall.species);
            const std::int64_t wallIndex = -static_cast<std::int64_t>(list.wallPairs[k].wall) - 1;
            if (touching)
                touch(i, wallIndex, c, arms, history, law, p_.radius[i]);
            else
                history = apart(i, wallIndex, c, arms, history, law);
            list.wallHistory.set(k, history);
        }
    }

private:
    // Force and torque on i (and j, unless it is a wall, j < 0) of one contact, or of the
    // separation impulse of a pair that stopped touching during the last step. The torques are
    // bij x f = -armI n x f and -bji x f = -armJ n x f.
    [[gnu::always_inline]] void apply(std::uint32_t i, std::int64_t j, const ContactForce& f, const Vec3& n,
                                      const Arms& arms) {
        const Vec3 force = f.normalForce * n + f.tangentialForce;
        const Vec3 turn = n.cross(f.tangentialForce);  // n x force
        p_.force[i] += force;
        p_.torque[i] -= arms.i * turn;
        if (j >= 0) {
            p_.force[j] -= force;
            p_.torque[j] -= arms.j * turn;
        }
    }

    [[gnu::always_inline]] void touch(std::uint32_t i, std::int64_t j, const ContactKinematics& c, const Arms& arms,
                                      ContactHistory& history, const Law& law, double smallerRadius) {
        const ContactForce f = law.force(c, history, dt_);
        history.state = ContactHistory::touching;
        history.lastNormalForce = f.normalForce;
        apply(i, j, f, c.normal, arms);
        ++summary_.contacts;
        if (c.overlap > summary_.maxOverlapFraction * smallerRadius) [[unlikely]] {
            summary_.maxOverlapFraction = c.overlap / smallerRadius;
            summary_.worstA = p_.id[i];
            summary_.worstB = j >= 0 ? p_.id[j] : static_cast<std::uint64_t>(-j - 1);  // wall index
            summary_.worstIsWall = j < 0;
        }
        if (records_) [[unlikely]]
            record(i, j, c, arms, history, law, f);
    }

    [[gnu::noinline]] void record(std::uint32_t i, std::int64_t j, ContactKinematics c, Arms arms,
                                  ContactHistory history, const Law& law, ContactForce f) {
        records_->push_back({i, j, p_.position[i] - arms.i * c.normal, c.overlap, history.spring.norm(),
                             f.normalForce, c.normal, f.tangentialForce, law.elasticEnergy(c, history.spring)});
    }

    // Apart now: a pair that stopped touching during the last step gets its separation impulse,
    // one that will touch within the next step its push ahead (LinearSpringDashpot.h).
    // (Everything by value, so that the caller's copies stay in registers; returns the new history.)
    [[gnu::noinline]] ContactHistory apart(std::uint32_t i, std::int64_t j, ContactKinematics c, Arms arms,
                                           ContactHistory history, const Law& law) {
        double normalForce = 0;
        if (history.isTouching()) {
            const ContactForce f = law.separationForce(c, history, dt_);
            apply(i, j, f, c.normal, arms);
            normalForce = f.normalForce;
            history = ContactHistory{};  // SPEC.md 1: the spring lives from the first time of contact
        }
        const double push = law.approachForce(c, history, dt_);
        if (push != 0) apply(i, j, {push, Vec3::Zero()}, c.normal, arms);
        history.lastNormalForce = normalForce + push;
        return history;
    }

    ParticleStore& p_;
    const PairTable<Law>& laws_;
    const double dt_, closing_;
    const std::vector<Vec3>& previousForce_;
    ContactSummary& summary_;
    std::vector<ContactRecord>* records_;
};

template <class Law>
void addContactForces(ParticleStore& p, PairList& list, const std::vector<PlaneWall>& walls,
                      const std::vector<PrescribedMotion>& motions, const PairTable<Law>& laws, const Domain& domain,
                      double dt, double maxSpeed, const std::vector<Vec3>& previousForce, ContactSummary& summary,
                      std::vector<ContactRecord>* records) {
    ContactForceLoop<Law> loop(p, laws, dt, maxSpeed, previousForce, summary, records);
    loop.particlePairs(list, domain);
    loop.wallPairs(list, walls, motions);
}

}  // namespace talus
